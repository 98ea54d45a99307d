//! rust-hdl description of the encspeed core, one hardware block per file.
//!
//! | block | file | what it does |
//! |---|---|---|
//! | [`EncspeedCore`] | `core.rs` | top: wires the blocks below, ports of `encspeed_core` |
//! | [`TwoFlopSync`] | `two_flop_sync.rs` | two-flop synchroniser of one encoder channel |
//! | [`Startup`] | `startup.rs` | holds the decoder and position counter until the filters hold real samples |
//! | [`GlitchFilter`] | `glitch_filter.rs` | passes a level after `cfg_filter` stable cycles, flags and counts rejected pulses |
//! | [`QuadratureDecoder`] | `quadrature_decoder.rs` | x1/x2/x4 steps with direction, illegal-transition flag and counter |
//! | [`PositionCounter`] | `position_counter.rs` | position modulo counts per revolution, Z reset/latch, revolution check |
//! | [`Timebase`] | `timebase.rs` | ts/dt time base with runtime dt and timeout |
//! | [`SyncEstimator`] | `sync_estimator.rs` | Table 1 registers Cep, Nep1, Ndt1, update, primed |
//! | [`SpeedCalc`] | `speed_calc.rs` | Rairán n1, n2, n3 as signed fixed point (sequential divider and multiplier) |
//! | [`ModeScale`] | `mode_scale.rs` | steps per dt to lines per dt (÷1, 2, 4, rounded) |
//! | [`SpeedHold`] | `speed_hold.rs` | speed registers, strobe and "has a speed", cleared at a reversal |
//! | [`PcCounter`] | `pc_counter.rs` | fixed-time baseline: net signed steps per window of `cfg_dt` cycles (free-running), saturating |
//! | [`EtTimer`] | `et_timer.rs` | fixed-space baseline: cycles between steps of one direction, saturating, `stalled` |
//! | [`MtCounter`] | `mt_counter.rs` | M/T: per window, steps m and cycles T between the anchor and the last step |
//! | [`BaselineSpeeds`] | `baseline_speeds.rs` | PC, ET and M/T speeds as signed fixed point (shared divider) |
//! | [`FaultFlags`] | `fault_flags.rs` | sticky fault flags and the glitch counter |
//! | [`WbRegs`] | `wb_regs.rs` | Wishbone B4 classic register file of the core (map in `golden::bus::regmap`) |
//! | `EncspeedWb` | `wishbone_top.rs` | top `encspeed_wb`: the core behind its Wishbone register file |
//!
//! Blocks built and verified on their own (rust-hdl and Icarus against their golden models)
//! and not part of `encspeed_core`:
//!
//! | block | file | what it does |
//! |---|---|---|
//! | [`SeqDivider`] | `seq_divider.rs` | unsigned radix-2 divider, one quotient bit per clock |
//! | [`SineRom`] | `sine_rom.rs` | sine table of K entries at (m + m0) mod K, registered read |
//! | [`EccDelta`] | `ecc_delta.rs` | eccentricity correction δ of a span (fractional positions, exact θ0), sequential, 68 cycles |
//! | [`EccDeltaArith`] | `ecc_delta_arith.rs` | `EccDelta`'s datapath: decode, interpolation, shift-add step (custom Verilog) |
//! | [`EccMtSpeed`] | `ecc_mt_speed.rs` | the M/T speed of the corrected count, ±round((m − δ)·dt·2^(F−s)/t), 2N + F + 4 cycles |
//! | [`EccN3`] | `ecc_n3.rs` | Rairán's n3 with the correction δ of its span: n3·(1 − δ) at Nep1 = 1, n3 − δ at Ndt1 = 1; 20 cycles |
//! | [`IdentGatherer`] | `ident_gatherer.rs` | between two Z pulses: N, T_min/T_max and positions, Σ T, Σ T·sin, Σ T·cos; sticky `done` |
//! | [`IdentMac`] | `ident_mac.rs` | the gatherer's two T × 24-bit multiply-adds (custom Verilog) |
//! | [`LineTap`] | `line_tap.rs` | `encspeed_ecc`'s line edges for the gatherer: forward line steps, line number, period |
//!
//! [`build_core`] turns validated [`Params`](golden::params::Params) into a core of the right
//! counter width behind the [`CoreSim`] trait (rust-hdl widths are const generics).

pub mod arith;
pub mod baselines;
pub mod bus;
pub mod ecc;
pub mod emit;
pub mod estimator;
pub mod frontend;
pub mod sim;
#[cfg(test)]
mod test_support;
pub mod top;
pub mod verilog;

pub use arith::seq_divider::{seq_divider_verilog, SeqDivider};
pub use baselines::baseline_speeds::{baseline_speeds_verilog, BaselineSpeeds};
pub use baselines::et_timer::{et_timer_verilog, EtTimer};
pub use baselines::mt_counter::{mt_counter_verilog, MtCounter};
pub use baselines::pc_counter::{pc_counter_verilog, PcCounter};
pub use bus::ecc_regs::EccRegs;
pub use bus::wb_regs::{wb_regs_verilog, WbRegs};
pub use ecc::ecc_delta::{ecc_delta_verilog, EccDelta};
pub use ecc::ecc_delta_arith::EccDeltaArith;
pub use ecc::ecc_mt_speed::{ecc_mt_speed_verilog, EccMtSpeed};
pub use ecc::ecc_n3::{ecc_n3_verilog, EccN3};
pub use ecc::ident_gatherer::{ident_gatherer_verilog, IdentGatherer};
pub use ecc::ident_mac::IdentMac;
pub use ecc::line_tap::LineTap;
pub use ecc::mt_corrector::MtCorrector;
pub use ecc::n3_corrector::N3Corrector;
pub use ecc::sine_rom::{sine_rom_verilog, SineRom};
pub use ecc::span_delta::SpanDelta;
pub use ecc::table_rom::TableRom;
pub use emit::wb::emit_wb;
pub use emit::{emit_core, emit_ecc, EmitInfo};
pub use estimator::mode_scale::ModeScale;
pub use estimator::speed_calc::{speed_calc_verilog, SpeedCalc};
pub use estimator::speed_hold::SpeedHold;
pub use estimator::sync_estimator::SyncEstimator;
pub use estimator::timebase::Timebase;
pub use frontend::glitch_filter::{glitch_filter_verilog, GlitchFilter};
pub use frontend::position_counter::{position_counter_verilog, PositionCounter};
pub use frontend::quadrature_decoder::{quadrature_decoder_verilog, QuadratureDecoder};
pub use frontend::startup::Startup;
pub use frontend::two_flop_sync::TwoFlopSync;
pub use sim::core_sim::{build_core, CoreSim};
pub use sim::ecc_wb_sim::{build_ecc_wb, EccWbSim};
pub use sim::wb_sim::{build_wb, WbSim};
pub use top::core::EncspeedCore;
pub use top::ecc_top::EncspeedEcc;
pub use top::ecc_wb_top::EncspeedEccWb;
pub use top::fault_flags::FaultFlags;
pub use top::wb_top::EncspeedWb;
