// SPDX-License-Identifier: MIT OR Apache-2.0
//! The M/T estimator (Ohmae 1982; what hostmot2 and Beckhoff EL51xx do), layer 1.
//!
//! At each sample instant k·dt of a free-running grid, m = encoder pulses since the
//! previous estimate's last pulse and T = time from that pulse to the last pulse before the
//! sample; the estimate is r = m·dt/T in units of ω_lim = 1/(lines·dt). Both ends of T are
//! pulses, so at constant speed the only error is the timestamp quantisation: with pulse
//! times taken at the first clock edge at or after the pulse (what a timestamp register
//! latched by the edge detector holds), T in cycles is off by less than one cycle and
//! |r̂/r − 1| = |T/T̂ − 1| < 1/T̂ ([`mt_error_bound`]), far below Rairán's eq. (13) bound
//! when T spans many clocks.
//!
//! A window without a new pulse gives no measurement; the estimate then falls to the speed
//! at which one pulse would have come by the sample, dt/(t_sample − t_last), if that is
//! lower than the last estimate (so that a stopping shaft reads a decaying speed, not the
//! last one forever).

/// One M/T output at a sample instant.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MtEstimate {
    /// Sample instant (s).
    pub t: f64,
    /// Pulses in the measurement (0: no new pulse, decayed estimate).
    pub m: u64,
    /// Measured time between the first and last pulse of the measurement (s, quantised).
    pub span: f64,
    /// Estimated speed, units of ω_lim.
    pub r: f64,
}

/// Quantise a pulse instant to the first clock edge at or after it (`q` = clock period, s;
/// q = 0 keeps exact times).
fn stamp(t: f64, q: f64) -> f64 {
    if q > 0.0 {
        (t / q).ceil() * q
    } else {
        t
    }
}

/// Run the M/T estimator on time-ordered `pulses` (s) with windows of `dt` (s) up to
/// `t_end`, timestamps quantised to `q` (s, 0 for exact). The first estimate comes at the
/// first sample after the second pulse.
pub fn mt_estimates(pulses: &[f64], dt: f64, q: f64, t_end: f64) -> Vec<MtEstimate> {
    assert!(
        dt > 0.0 && q >= 0.0 && t_end.is_finite(),
        "bad M/T arguments"
    );
    let mut out = Vec::new();
    let mut p = 0usize;
    // Timestamp and count index of the pulse that closed the previous measurement.
    let mut anchor: Option<(f64, usize)> = None;
    let mut last_r = 0.0;
    for k in 1u64.. {
        let ts = k as f64 * dt;
        if ts > t_end {
            break;
        }
        while p < pulses.len() && stamp(pulses[p], q) <= ts {
            p += 1;
        }
        // p pulses have been seen by the sample; the last is p − 1.
        let Some(last) = p.checked_sub(1) else {
            continue;
        };
        let t_last = stamp(pulses[last], q);
        match anchor {
            None => anchor = Some((t_last, last)),
            Some((t_a, i_a)) if last > i_a => {
                let m = (last - i_a) as u64;
                let span = t_last - t_a;
                last_r = m as f64 * dt / span;
                out.push(MtEstimate {
                    t: ts,
                    m,
                    span,
                    r: last_r,
                });
                anchor = Some((t_last, last));
            }
            Some((t_a, _)) => {
                let decayed = dt / (ts - t_a);
                if decayed < last_r {
                    last_r = decayed;
                }
                out.push(MtEstimate {
                    t: ts,
                    m: 0,
                    span: ts - t_a,
                    r: last_r,
                });
            }
        }
    }
    out
}

/// Worst-case relative error of an M/T estimate with m > 0 at constant speed, when the
/// measured span is `span_cycles` clock cycles: each timestamp lies in [t, t + 1) cycles,
/// so the true span differs from the measured one by less than one cycle.
pub fn mt_error_bound(span_cycles: f64) -> f64 {
    1.0 / span_cycles
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exact_times_give_exact_speed() {
        // Pulses every 0.3 s, dt = 1 s: r = 1/0.3. By hand: sample 1 sees pulses 0, 0.3,
        // 0.6, 0.9 (anchor 0.9); sample 2 sees 1.2, 1.5, 1.8: m = 3, T = 0.9 → r = 3.333…
        let pulses: Vec<f64> = (0..20).map(|i| 0.3 * i as f64).collect();
        let e = mt_estimates(&pulses, 1.0, 0.0, 5.0);
        assert_eq!(e[0].m, 3);
        assert!((e[0].r - 1.0 / 0.3).abs() < 1e-12);
        assert!(e.iter().all(|x| (x.r - 1.0 / 0.3).abs() < 1e-9));
    }

    #[test]
    fn quantised_times_stay_within_the_bound() {
        // Pulses every 33.3 clock cycles (q = 1), dt = 1000 cycles: r = 1000/33.3.
        let pulses: Vec<f64> = (0..3000).map(|i| 0.17 + 33.3 * i as f64).collect();
        let r = 1000.0 / 33.3;
        for x in mt_estimates(&pulses, 1000.0, 1.0, 90_000.0) {
            let err = (x.r - r).abs() / r;
            assert!(err < mt_error_bound(x.span), "{x:?}: {err}");
        }
    }

    #[test]
    fn decays_after_a_stop() {
        // Pulses at 0, 1, 2 s, then nothing; dt = 0.5 s. By hand: samples at 0.5 (anchor 0),
        // 1.0 (m = 1, T = 1 → r = 0.5), 1.5 (no pulse; dt/(1.5 − 1) = 1 > 0.5: holds 0.5),
        // 2.0 (m = 1 → 0.5), 2.5 (0.5/0.5 = 1: holds), 3.0 (0.5/1 = 0.5: holds),
        // 3.5 (0.5/1.5 = 1/3), 4.0 (0.5/2 = 0.25).
        let e = mt_estimates(&[0.0, 1.0, 2.0], 0.5, 0.0, 4.0);
        let r: Vec<f64> = e.iter().map(|x| x.r).collect();
        assert_eq!(r, vec![0.5, 0.5, 0.5, 0.5, 0.5, 0.5 / 1.5, 0.25]);
    }
}
