// SPDX-License-Identifier: MIT OR Apache-2.0
//! Rairán's n3 on an eccentric disc, and the correction of its count (layer 1, f64).
//!
//! n3 is computed from Nep1 and Ndt1, whose spans of disc angle are known from Table 1
//! ([`crate::ideal::RairanIdeal`]) and the positions of the pulses:
//! - **Nep1 ≥ 2** (n1 ≥ 1, Ndt1 = 1 in steady state): the window of dt that wrote Nep1
//!   started at a restart pulse x_w and held the pulses x_w … x_w + Nep1 − 1; the angle
//!   travelled in it is in [Nep1 − 1, Nep1) lines, and n3 ≈ Nep1 − ½ is its estimate. The
//!   span is therefore taken as [x_w, x_w + Nep1 − ½] (a half line: the end of the window
//!   is not a pulse; the residue is the ceiling's, which n3 already carries).
//! - **Nep1 = 1** (below ω_lim): n3 = 2/(2·Ndt1 + 1) measures the pulse period that ended
//!   at the restart pulse x_r which wrote Ndt1: the span [x_r − 1, x_r].
//!
//! The eccentricity correction of a span [x_a, x_b] (lines, fractional allowed) is
//! δ = Σₖ Eₖ·(Sₖ(x_b) − Sₖ(x_a)) ([`Correction::wobble`]), the corrected count is
//! ΔM − δ, and the corrected n3 is n3·(ΔM − δ)/ΔM ([`N3Sample::n3_corrected`]), exact to
//! first order for any n3 that is proportional to its count. Hardware forms
//! ([`N3Sample::n3_hardware_rule`]) avoid the division: n3 − δ when Nep1 ≥ 2 and Ndt1 = 1
//! (dn3/dNep1 = 1 + 1/(2(2·Nep1 − 1)²) ≈ 1), n3·(1 − δ) when Nep1 = 1, n3 unchanged
//! otherwise (Nep1 ≥ 2 with Ndt1 ≥ 2 happens only in a speed transient).

use super::correct::Correction;
use crate::ideal::{n3, RairanIdeal, Update};

/// One n3 estimate on an eccentric disc.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct N3Sample {
    /// Instant of the register write (s).
    pub t: f64,
    /// Nep1.
    pub nep1: u64,
    /// Ndt1.
    pub ndt1: u64,
    /// n3 (units of ω_lim, one line per dt).
    pub n3: f64,
    /// Span of disc angle (lines) the estimate measures (module docs).
    pub span: (f64, f64),
    /// The correction δ of that span (lines).
    pub delta: f64,
}

impl N3Sample {
    /// n3·(ΔM − δ)/ΔM: the corrected estimate, first order, any regime.
    pub fn n3_corrected(&self) -> f64 {
        let dm = self.span.1 - self.span.0;
        self.n3 * (dm - self.delta) / dm
    }

    /// The division-free form a hardware corrector uses (module docs).
    pub fn n3_hardware_rule(&self) -> f64 {
        if self.nep1 == 1 {
            self.n3 * (1.0 - self.delta)
        } else if self.ndt1 == 1 {
            self.n3 - self.delta
        } else {
            self.n3
        }
    }
}

/// Run Table 1 (continuous time, time base `dt` s) on the forward line crossings
/// `line_times` = (line, instant) of a disc of `lines` lines, and give every n3 estimate
/// with its span and the correction `corr` of that span. Estimates before the first
/// restart (whose spans are not measured from pulses) are left out.
///
/// # Panics
/// If the crossings are not consecutive forward lines in time order.
pub fn n3_on_disc(
    line_times: &[(i64, f64)],
    dt: f64,
    lines: u32,
    corr: &Correction,
) -> Vec<N3Sample> {
    assert!(
        line_times
            .windows(2)
            .all(|w| w[1].0 == w[0].0 + 1 && w[1].1 >= w[0].1),
        "n3_on_disc: crossings must be consecutive forward lines in time order"
    );
    let pulses: Vec<f64> = line_times.iter().map(|l| l.1).collect();
    let t_end = pulses.last().copied().unwrap_or(0.0);
    let updates: Vec<Update> = RairanIdeal::new(dt, lines)
        .expect("valid dt and lines")
        .run(&pulses, t_end)
        .expect("valid pulses");
    // The line of the pulse at instant t (a restart is at a pulse instant exactly).
    let line_at = |t: f64| -> f64 {
        let i = pulses.partition_point(|&p| p < t);
        line_times[i.min(pulses.len() - 1)].0 as f64
    };
    let mut restart: Option<f64> = None; // line of the last restart pulse
    let mut ndt_end: Option<f64> = None; // line of the restart that wrote Ndt1
    let mut window: Option<f64> = None; // start line of the window that wrote Nep1
    let mut out = Vec::new();
    for u in &updates {
        if u.wrote_ndt {
            let x = line_at(u.t);
            ndt_end = Some(x);
            // A tick cancelled by this restart wrote nothing: the window that writes the
            // next Nep1 starts here.
            restart = Some(x);
        }
        if u.wrote_nep {
            window = restart;
        }
        let span = if u.nep1 == 1 {
            ndt_end.map(|x| (x - 1.0, x))
        } else {
            window.map(|x| (x, x + u.nep1 as f64 - 0.5))
        };
        if let Some(span) = span {
            if u.nep1 == 0 {
                continue;
            }
            out.push(N3Sample {
                t: u.t,
                nep1: u.nep1,
                ndt1: u.ndt1,
                n3: n3(u.nep1, u.ndt1),
                span,
                delta: corr.wobble(span.0, span.1),
            });
        }
    }
    out
}
