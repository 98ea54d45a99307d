//! Golden model of encspeed.
//!
//! Layer 1 (float ideal): [`plant`] turns shaft motion into exact A/B/Z edge instants and
//! clock samples; [`ideal`] runs Rairán's estimator and the classical PC/ET estimators in
//! continuous time; [`mt`] is the M/T estimator (groundwork for the hardware M/T);
//! [`rairan`] holds the paper's error bounds and the hardware's error budget.
//! Layer 2 (bit-true): [`core`] computes, cycle for cycle and in the hardware's integer
//! widths, what `encspeed_core` computes, from the blocks' bit-true models ([`bittrue`] is
//! Rairán's Table 1, [`frontend`], [`speed_calc`], [`pc_counter`], [`et_timer`],
//! [`mt_counter`]). [`params`] is the one validated parameter type
//! shared by the golden model, the HDL constructors and the generated manifest.
//!
//! This crate never depends on rust-hdl.

pub mod baseline_speeds;
pub mod bittrue;
pub mod core;
pub mod divider;
pub mod ecc_delta;
pub mod ecc_mt_speed;
pub mod ecc_n3;
pub mod ecc_regmap;
pub mod ecc_regs;
pub mod ecc_top;
pub mod ecc_wb_top;
pub mod eccentric;
pub mod et_timer;
pub mod freqresp;
pub mod frontend;
pub mod ideal;
pub mod ident_gatherer;
pub mod latest_request;
pub mod line_tap;
pub mod mt;
pub mod mt_corrector;
pub mod mt_counter;
pub mod n3_corrector;
pub mod params;
pub mod pc_counter;
pub mod plant;
pub mod ports;
pub mod rairan;
pub mod regmap;
pub mod sine_rom;
pub mod smallsignal;
pub mod span_delta;
pub mod speed_calc;
pub mod splitmix;
pub mod wb_regs;
pub mod wb_top;
