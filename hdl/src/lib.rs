// SPDX-License-Identifier: MIT OR Apache-2.0
//! rust-hdl description of the encspeed IP, one hardware block per file, in subsystem
//! folders that mirror the golden model's (`golden/src`): each block's bit-true model has
//! the same file name there. docs/architecture.md has the block index (every block's
//! hardware, model, bench and latency) and the dependency order.
//!
//! | folder | what lives there |
//! |---|---|
//! | [`frontend`] | synchronisers, glitch filters, start-up hold, quadrature decoder, position counter |
//! | [`estimator`] | time base, Rairán's Table 1 registers, request tag, n1/n2/n3 calculator, mode scaling, speed hold |
//! | [`baselines`] | PC, ET and M/T counters and their speed calculator |
//! | [`arith`] | the division step, the sequential divider, the adder with a registered low half |
//! | [`ecc`] | eccentricity correction (tables, δ of a span, corrected M/T and n3) and identification |
//! | [`board`] | the board tops (`encspeed_wb` behind a UART bridge, power-on reset, LEDs) and their UART-to-Wishbone bridge: UART receiver and transmitter, protocol engine |
//! | [`bus`] | Wishbone register files of the core and of the eccentricity window |
//! | [`top`] | the shipped tops `encspeed_core`, `encspeed_wb`, `encspeed_ecc`, `encspeed_ecc_wb` and the fault flags |
//! | [`sim`] | drivers that build a top for validated parameters and step it cycle by cycle |
//! | [`emit`] | the generated files, and [`emit::tops::Top`], the list of shipped tops |
//! | [`verilog`] | the leaf every block emits its Verilog through |
//!
//! Dependencies run one way: `verilog` ← the block folders ← `top` ← `sim` ← `emit`; no
//! block imports the emitter or a top (the one exception is `board::board_top`, a top
//! over `top::wb_top` that lives beside its bridge). [`build_core`] turns validated
//! [`Params`](golden::params::Params) into a core of the right counter width behind the
//! [`CoreSim`] trait (rust-hdl widths are const generics).

pub mod arith;
pub mod baselines;
pub mod board;
pub mod bus;
pub mod ecc;
pub mod emit;
pub mod estimator;
pub mod frontend;
pub mod sim;
pub mod top;
pub mod verilog;

pub use arith::seq_divider::{seq_divider_verilog, SeqDivider};
pub use arith::two_cycle_adder::{two_cycle_adder_verilog, TwoCycleAdder};
pub use baselines::baseline_speeds::{baseline_speeds_verilog, BaselineSpeeds};
pub use baselines::et_timer::{et_timer_verilog, EtTimer};
pub use baselines::mt_counter::{mt_counter_verilog, MtCounter};
pub use baselines::pc_counter::{pc_counter_verilog, PcCounter};
pub use board::board_top::EncspeedBoard;
pub use board::uart_rx::{uart_rx_verilog, UartRx};
pub use board::uart_tx::{uart_tx_verilog, UartTx};
pub use board::uart_wb_bridge::{uart_wb_bridge_verilog, UartWbBridge};
pub use board::uart_wishbone::{uart_wishbone_verilog, UartWishbone};
pub use bus::const_cell::ConstCell;
pub use bus::ecc_regs::EccRegs;
pub use bus::ecc_snapshot::EccSnapshot;
pub use bus::irq_cell::IrqCell;
pub use bus::pulse_cell::PulseCell;
pub use bus::read_cell::ReadCell;
pub use bus::read_data::ReadData;
pub use bus::reg_file::RegFile;
pub use bus::rw_cell::RwCell;
pub use bus::shadow_cell::ShadowCell;
pub use bus::wb_front::WbFront;
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
pub use emit::prefix::Prefix;
pub use emit::tops::Top;
pub use emit::wb::emit_wb;
pub use emit::{emit_core, emit_ecc, EmitInfo};
pub use estimator::speed_calc::{speed_calc_verilog, SpeedCalc};
pub use estimator::sync_estimator::SyncEstimator;
pub use estimator::timebase::Timebase;
pub use frontend::glitch_filter::{glitch_filter_verilog, GlitchFilter};
pub use frontend::position_counter::{position_counter_verilog, PositionCounter};
pub use frontend::quadrature_decoder::{quadrature_decoder_verilog, QuadratureDecoder};
pub use frontend::startup::Startup;
pub use frontend::two_flop_sync::TwoFlopSync;
pub use sim::board_sim::{build_board, BoardSim};
pub use sim::core_sim::{build_core, CoreSim};
pub use sim::ecc_wb_sim::{build_ecc_wb, EccWbSim};
pub use sim::wb_sim::{build_wb, WbSim};
pub use top::core::EncspeedCore;
pub use top::ecc_top::EncspeedEcc;
pub use top::ecc_wb_top::EncspeedEccWb;
pub use top::fault_flags::FaultFlags;
pub use top::wb_channels::EncspeedWbChannels;
pub use top::wb_top::EncspeedWb;
