// SPDX-License-Identifier: MIT OR Apache-2.0
//! The paper's VCO experiment in simulation: the frequency response of the speed
//! estimators, measured on the golden models and set beside their small-signal models.
//!
//! Vázquez-Gutiérrez et al. (2019), Section III, drive a DSP's encoder peripheral with a
//! voltage-controlled oscillator whose frequency is modulated by a network analyser, and
//! compare the speed the DSP computes (written to a DAC every T_s) with the modulation.
//! Here the same experiment runs on the plant and estimator models:
//!
//! 1. **Input.** The shaft speed is n(t) = n̄ + ñ·sin(2πft), t from 0, in r/min at the
//!    interface ([`BodeSpec::rpm`], [`BodeSpec::amplitude`] = ñ/n̄) and in rev/s inside
//!    ([`Segment::Sine`](crate::ideal::plant::Segment::Sine)). The disc has `lines` lines; an estimator counts
//!    R = lines·`edges` transitions per revolution: `edges` = 1 counts rising edges of A,
//!    2 both edges of A, 4 every edge of A and B (quadrature ×4). The paper's R is this R
//!    (its Table I: 1, 2 or 4 times the lines).
//! 2. **Estimators**, each producing one value y_k per control sample t_k = k·T_s (k ≥ 1),
//!    in rev/s, the latest estimate at t_k as a sampled controller reads it (the float
//!    estimators and n3; the hardware PC, ET, M/T are read at their strobe, below):
//!    - [`Estimator::Pc`], fixed time: transitions counted in the window from t_(k−1)
//!      (included) to t_k (excluded) ([`ideal::fixed_time`](crate::ideal::fixed_time)), divided by R·T_s.
//!    - [`Estimator::Et`], fixed space: the time between the last two transitions before
//!      t_k counted in periods of a clock of `clock_hz` ([`ideal::fixed_space`](crate::ideal::fixed_space)).
//!    - [`Estimator::N3`], Rairán's synchronised estimator: the bit-true core
//!      ([`CoreModel`](crate::top::core::CoreModel)) stepped at `clock_hz` with dt = T_s, fed with the levels of A
//!      (so R = lines, `edges` = 1); n3(Nep1, Ndt1)·ω_lim read at the clock edge of t_k.
//!    - [`Estimator::Mt`], M/T ([`mt::mt_estimates`](crate::ideal::mt::mt_estimates)): transitions since the last
//!      measurement over the time between the first and last of them, timestamps
//!      quantised to the clock.
//! 3. **Analysis** ([`Experiment::plan`], [`Experiment::analyse`]). A settling transient
//!    of `settle` samples is discarded; the next N samples span exactly P periods of the
//!    modulation (the frequency is moved to f = P/(N·T_s), the nearest such frequency, and
//!    reported). The single DFT bin of the output at f is divided by the same bin of the
//!    input sampled at the same instants:
//!    H_sampled(f) = Σ y_k·e^(−j2πf·t_k) / Σ ñ·sin(2πf·t_k)·e^(−j2πf·t_k), the sums over
//!    the window, f·t_k = P·k/N reduced in integers. This is what a controller sampling at
//!    t_k sees: an estimate equal to the speed delayed by D measures e^(−j2πfD), so a pure
//!    delay of T_s/2 measures −180°·f·T_s.
//! 4. **Convention of the models.** The paper's models include the sample-and-hold of the
//!    control loop, ZOH(s, T_s) (eqs. 15, 16, 24), because its analyser compared the
//!    continuous DAC staircase with the continuous input. The Fourier coefficient at f of
//!    that staircase (y_k held from t_k to t_k + T_s) over the window, divided by the one
//!    of n(t), is exactly H(f) = H_sampled(f)·ZOH(j2πf, T_s). [`Measurement::h`] is this
//!    H and is what is compared with the models; [`Measurement::h_sampled`] is kept. The
//!    measured phase is reported on the model's branch (the difference wrapped into
//!    (−180°, 180°]).
//!
//! **On the hardware** ([`Source::Hardware`]; n3 always). The bit-true core
//! ([`CoreModel`](crate::top::core::CoreModel)) is stepped at `clock_hz` on the sampled levels of A, B and Z (cycle c
//! carries the levels at t = c/f_clk; 3 cycles of reset; `cfg_dt` = dt = T_s·f_clk;
//! `cfg_mode` x1, x2, x4 for `edges` 1, 2, 4). PC, ET and M/T are the outputs
//! `speed_pc`, `speed_et`, `speed_mt` (Q(N).F in units of ω_lim, one line per dt), whose
//! windows are those of the free-running `cfg_dt` time base; they are **read at their
//! `baseline_strobe`**, the cycle k·dt + 3 + L ([`Experiment::read_offset_cycles`], L =
//! [`baseline_latency_cycles`]), not at k·T_s: the strobe is periodic with T_s, it is the
//! earliest instant the estimate exists, and a controller that takes its samples from it
//! sees exactly this; a controller sampling at other instants adds the age of the last
//! strobe, a pure delay it knows. The analysis puts each value at the instant it was read
//! (the bin is rotated by e^{−j2πf·c}, c the read offset), so the measurement is the
//! estimator's window response times the hardware's delay from window end to strobe,
//! D = [`window_to_strobe_cycles`] (about 70 cycles), and the model compared is the float
//! estimator's model × e^{−sD} ([`FreqModel::delayed`]). The clock quantises each
//! transition to the next clock edge: PC's window stays an exact interval of plant time
//! (no effect in expectation); ET's period and M/T's span are whole cycles, within one
//! cycle of the truth and unbiased when the encoder phase against the clock is uniform,
//! so what is left is an error of ±1 cycle per period (±1/P relative for a period of P
//! cycles), a pattern of the encoder phase against the clock, not white noise, whose
//! share in the DFT bin falls as 1/ñ. M/T on the hardware needs a step in
//! every window (an empty window gives `speed_mt` = 0): l·(1 − ñ/n̄) ≥ 1
//! ([`FreqRespError::MtEmptyWindows`]).
//!
//! **Asynchrony (why the mean speed is detuned).** The small-signal models describe the
//! response averaged over the phase of the encoder relative to the sample instants (the
//! paper's Appendix B and Fig. 5: a delay "uniformly distributed"). In the laboratory the
//! VCO and the DSP clock are independent, so that phase drifts. In a simulation with
//! l = n̄·R·T_s/60 an integer or a simple fraction (3600 r/min, R = 500, T_s = 1 ms is
//! exactly 30 transitions per sample) it does not: the phase is frozen, a PC count with
//! a position modulation below one transition never changes, and ET sees the age of the
//! last transition take a few values only. The mean speed is therefore simulated at
//! n̄·(1 + ε), ε = [`BodeSpec::detune`] (default [`DEFAULT_DETUNE`]): the encoder phase
//! slips against the sample grid by ε·l transitions per sample, and the window N is a
//! whole number of slips of one transition ([`Experiment::samples_per_slip`]), so that
//! every phase is visited equally (n3 at high speed also needs a long window:
//! [`Experiment::min_window`]). Every model is evaluated at the simulated speed.
//! ε = 0 reproduces the synchronous case.
//!
//! **Amplitude.** With the phase averaged, PC, ET and M/T are linear in expectation for
//! any ñ (their outputs are windowed means of the speed); ñ only has to stay well below n̄
//! (no reversal; the second-order terms, such as the choice of the last transition or the
//! decay rule of M/T, small) and well above the residual quantisation noise of a finite
//! window, which falls as 1/ñ. The default ñ/n̄ = 2 % does both; `golden/tests/freqresp.rs`
//! checks that the measurement moves by less than 0.5° from 0.5 % to 5 %. Rairán's n3 is
//! different: its windows start at encoder pulses, so its quantisation is never dithered
//! by asynchrony and its output is a quantiser of step ω_lim. Its gain depends on ñ/ω_lim
//! (a describing function), its phase hardly; hence a default of 20 %
//! ([`DEFAULT_AMPLITUDE_N3`]). docs/frequency-response.md has the figures.

pub mod csv;
pub mod experiment;
pub mod model;
pub mod spec;

pub use csv::{log_spaced, to_csv, CSV_HEADER};
pub use experiment::*;
pub use model::*;
pub use spec::*;
