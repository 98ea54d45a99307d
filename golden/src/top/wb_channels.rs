// SPDX-License-Identifier: MIT OR Apache-2.0
//! Cycle model of `encspeed_wb` generated with several encoder channels (`channels` > 1;
//! the block `hdl::EncspeedWbChannels`): `channels` copies of the one-channel top
//! ([`WbTopModel`]: a core and its register file each) behind one Wishbone B4 classic slave.
//!
//! ```text
//! enc_a[c], enc_b[c], enc_z[c] ─► channel c (core + register window c) ─► irq[c]
//! wb_adr_i[A-1:8] = c: channel c sees wb_stb_i and wb_adr_i[7:0]
//! wb_dat_o = OR of the channels' wb_dat_o, wb_ack_o = OR of their wb_ack_o
//! ```
//!
//! # Address map
//!
//! `wb_adr_i` is A = [`ADDR_BITS`] + B bits, B = [`channel_bits`] (the fewest that number
//! the channels). Channel c's registers are at byte offset c · [`SPAN_BYTES`] + the offset of
//! the one-channel map ([`crate::bus::regmap`]): the channel is `wb_adr_i >> 8`, and channel
//! c sees `wb_stb_i` only while it is addressed (`wb_cyc_i`, `wb_we_i`, `wb_dat_i`,
//! `wb_sel_i` and the low 8 address bits go to every channel). Where `channels` is not a
//! power of two, the windows above the last channel answer like an unmapped offset of a
//! channel: acknowledged with the same timing (three cycles per access), reads return 0,
//! writes are ignored, so a master never hangs on them.
//!
//! # Outputs and timing
//!
//! Each channel's `wb_dat_o` is 0 except in the ack cycle of its own read, and only the
//! addressed window answers, so `wb_dat_o` is the OR of the channels' and `wb_ack_o` the OR
//! of their acks: registers through one or two LUT levels, no path from an input. `irq` has
//! one bit per channel (`irq[c]` is channel c's interrupt; OR them for one line). `clock`,
//! `reset` and `sample` are shared: one `sample` strobe snapshots every channel at the same
//! edge, a coherent picture of all axes. Every channel keeps the one-channel top's timing
//! and latencies ([`crate::top::wb_top`]); channel c's model is exactly a [`WbTopModel`]
//! stepped with its own encoder inputs and its gated bus.

use crate::bus::reg_file::WbBus;
use crate::bus::regmap::{ADDR_BITS, DATA_BITS, SPAN_BYTES};
use crate::params::{Params, MAX_CHANNELS};
use crate::top::port_fields::{port_struct, visit_fields, PortFields, PortValue};
use crate::top::ports::Port;
use crate::top::wb_top::{WbTopInputs, WbTopModel, WbTopOutputs};

/// Address bits that number `channels` channels: ⌈log2 `channels`⌉ (0 for one channel).
pub fn channel_bits(channels: u32) -> u32 {
    assert!(
        (1..=MAX_CHANNELS).contains(&channels),
        "channels = {channels} outside 1..={MAX_CHANNELS}"
    );
    u32::BITS - (channels - 1).leading_zeros()
}

/// Width of `wb_adr_i` of the top with `channels` channels.
pub fn address_bits(channels: u32) -> u32 {
    ADDR_BITS as u32 + channel_bits(channels)
}

/// Byte address of channel `c`'s register window.
pub fn channel_base(c: u32) -> u32 {
    c * SPAN_BYTES
}

/// Inputs of the several-channel `encspeed_wb` during one clock cycle; bit c of `enc_a`,
/// `enc_b` and `enc_z` is channel c's encoder.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct WbChannelsInputs {
    /// Synchronous active-high reset of every channel.
    pub reset: bool,
    /// Encoder channels A (asynchronous), bit c for channel c.
    pub enc_a: u8,
    /// Encoder channels B (asynchronous), bit c for channel c.
    pub enc_b: u8,
    /// Encoder indexes Z (asynchronous), bit c for channel c.
    pub enc_z: u8,
    /// Snapshot strobe of every channel (synchronous).
    pub sample: bool,
    /// Wishbone inputs; `wb_adr_i` has [`address_bits`] bits.
    pub bus: WbBus,
}

impl PortFields for WbChannelsInputs {
    fn visit_ports(&mut self, visit: &mut dyn FnMut(&'static str, &mut dyn PortValue)) {
        visit_fields!(visit, self, "": reset, enc_a, enc_b, enc_z, sample);
        visit_fields!(visit, self.bus, "":
            wb_cyc_i, wb_stb_i, wb_we_i, wb_adr_i, wb_dat_i, wb_sel_i);
    }
}

port_struct! {
    /// Outputs of the several-channel `encspeed_wb` after a rising clock edge.
    #[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
    pub struct WbChannelsOutputs {
        /// Wishbone read data (0 unless `wb_ack_o` of a read).
        pub wb_dat_o: u32,
        /// Wishbone acknowledge.
        pub wb_ack_o: bool,
        /// Interrupt requests, bit c for channel c.
        pub irq: u8,
    }
}

/// The answer of the windows above the last channel: acknowledge with a channel's timing
/// (request at edge k, `wb_ack_o` after edge k + 1), no data, no effect.
#[derive(Clone, Copy, Debug, Default)]
struct EmptyWindow {
    pending: bool,
    ack: bool,
}

impl EmptyWindow {
    fn step(&mut self, reset: bool, bus: &WbBus, addressed: bool) {
        let req = bus.wb_cyc_i && bus.wb_stb_i && addressed && !self.ack && !self.pending;
        self.ack = self.pending && !reset;
        self.pending = req && !reset;
    }
}

/// Cycle model of `encspeed_wb` with [`Params::channels`] channels.
#[derive(Clone, Debug)]
pub struct WbChannelsModel {
    channels: Vec<WbTopModel>,
    empty: EmptyWindow,
}

impl WbChannelsModel {
    /// The model of `p` (`p.channels()` channels) in the state the hardware has after reset.
    pub fn new(p: &Params) -> WbChannelsModel {
        WbChannelsModel {
            channels: (0..p.channels()).map(|_| WbTopModel::new(p)).collect(),
            empty: EmptyWindow::default(),
        }
    }

    /// Number of channels.
    pub fn count(&self) -> u32 {
        self.channels.len() as u32
    }

    /// The inputs channel `c` sees in a cycle with the top's inputs `inp`.
    pub fn channel_inputs(&self, c: u32, inp: &WbChannelsInputs) -> WbTopInputs {
        let addressed = inp.bus.wb_adr_i >> ADDR_BITS == c;
        WbTopInputs {
            reset: inp.reset,
            enc_a: inp.enc_a >> c & 1 == 1,
            enc_b: inp.enc_b >> c & 1 == 1,
            enc_z: inp.enc_z >> c & 1 == 1,
            sample: inp.sample,
            bus: WbBus {
                wb_stb_i: inp.bus.wb_stb_i && addressed,
                wb_adr_i: inp.bus.wb_adr_i & (SPAN_BYTES - 1),
                ..inp.bus
            },
        }
    }

    /// One rising clock edge with `inp` applied; the outputs after it.
    pub fn step(&mut self, inp: &WbChannelsInputs) -> WbChannelsOutputs {
        let count = self.count();
        assert!(
            inp.bus.wb_adr_i >> address_bits(count) == 0
                && inp.enc_a >> count == 0
                && inp.enc_b >> count == 0
                && inp.enc_z >> count == 0,
            "input out of range for {count} channels: {inp:?}"
        );
        for c in 0..count {
            let ci = self.channel_inputs(c, inp);
            self.channels[c as usize].step(&ci);
        }
        let above_last = inp.bus.wb_adr_i >> ADDR_BITS >= count;
        self.empty.step(inp.reset, &inp.bus, above_last);
        self.outputs()
    }

    /// The outputs as they stand.
    pub fn outputs(&self) -> WbChannelsOutputs {
        let mut out = WbChannelsOutputs {
            wb_ack_o: self.empty.ack,
            ..Default::default()
        };
        for (c, ch) in self.channels.iter().enumerate() {
            let o: WbTopOutputs = ch.outputs();
            out.wb_dat_o |= o.wb_dat_o;
            out.wb_ack_o |= o.wb_ack_o;
            out.irq |= u8::from(o.irq) << c;
        }
        out
    }

    /// Channel `c`'s model (its core and register file).
    pub fn channel(&self, c: u32) -> &WbTopModel {
        &self.channels[c as usize]
    }

    /// True while an access is in progress (a request taken, its ack not yet given): a
    /// test master holds its request until `wb_ack_o`, as every classic master does.
    pub fn busy(&self) -> bool {
        self.empty.pending || self.empty.ack || self.channels.iter().any(|ch| ch.regs().busy())
    }
}

/// Every port of `encspeed_wb` with `channels` (≥ 2) channels, in the order of its Verilog
/// module header.
pub fn wb_channels_ports(channels: u32) -> Vec<Port> {
    let (i, o) = (Port::input, Port::output);
    let n = channels;
    vec![
        i("clock", 1, "clock of every channel and of the bus; everything happens at its rising edge"),
        i("reset", 1, "synchronous, active high: resets every channel's registers at the edge that samples it, and its core (which registers it) at the edge after; the cores also reset at the first edge after power-up"),
        i("enc_a", n, "encoder channels A, bit c for channel c, asynchronous (two-flop synchronised inside)"),
        i("enc_b", n, "encoder channels B, bit c for channel c, asynchronous; forward = A leads B by 90 degrees"),
        i("enc_z", n, "encoder indexes Z, bit c for channel c, asynchronous"),
        i("sample", 1, "synchronous strobe: at the edge that samples it high every channel takes its snapshot (unless its CTRL.HOLD), all from the same cycle; tie to 0 if unused"),
        i("wb_cyc_i", 1, "Wishbone B4 classic: bus cycle"),
        i("wb_stb_i", 1, "Wishbone: strobe (this slave is addressed)"),
        i("wb_we_i", 1, "Wishbone: 1 = write, 0 = read"),
        i(
            "wb_adr_i",
            address_bits(n),
            "Wishbone: byte address; bits above 7 select the channel (channel c's registers at c * 0x100 + offset), windows above the last channel read 0; bits 1:0 ignored",
        ),
        i("wb_dat_i", DATA_BITS as u32, "Wishbone: write data"),
        i(
            "wb_sel_i",
            4,
            "Wishbone: byte lanes of a write (lane j = bits 8j+7..8j)",
        ),
        o(
            "wb_dat_o",
            DATA_BITS as u32,
            "Wishbone: read data, valid with wb_ack_o (0 otherwise): the OR of the channels' registered read data",
        ),
        o(
            "wb_ack_o",
            1,
            "Wishbone: acknowledge, high for one cycle from the edge after the request edge (OR of the windows' registered acks)",
        ),
        o(
            "irq",
            n,
            "interrupt requests, level, bit c = channel c's (IRQ_STATUS & IRQ_ENABLE) != 0, registers",
        ),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bus::regmap;
    use crate::params::Spec;

    fn params(channels: u32) -> Params {
        Params::new(Spec {
            clock_hz: 1e6,
            lines: 100,
            dt_cycles: 200,
            counter_bits: 12,
            timeout_s: 20.0 * 200.0 / 1e6,
            channels,
            ..Spec::default()
        })
        .unwrap()
    }

    #[test]
    fn channel_address_bits_by_hand() {
        let bits: Vec<u32> = (1..=8).map(channel_bits).collect();
        assert_eq!(bits, [0, 1, 2, 2, 3, 3, 3, 3]);
        assert_eq!(address_bits(3), 10);
        assert_eq!(channel_base(5), 0x500);
    }

    /// A read of `adr` held until ack; the data and the cycles from request to ack.
    fn read(m: &mut WbChannelsModel, adr: u32) -> (u32, u32) {
        let mut inp = WbChannelsInputs {
            bus: WbBus {
                wb_cyc_i: true,
                wb_stb_i: true,
                wb_adr_i: adr,
                wb_sel_i: 0xF,
                ..Default::default()
            },
            ..Default::default()
        };
        for cycles in 1..10 {
            let o = m.step(&inp);
            if o.wb_ack_o {
                inp.bus = WbBus::default();
                m.step(&inp);
                return (o.wb_dat_o, cycles);
            }
        }
        panic!("no ack for 0x{adr:X}");
    }

    #[test]
    fn each_window_answers_with_its_channels_registers_and_the_empty_ones_with_zero() {
        let mut m = WbChannelsModel::new(&params(3));
        for c in 0..3 {
            let (id, cycles) = read(&mut m, channel_base(c) + regmap::offset("ID").unwrap());
            assert_eq!((id, cycles), (regmap::ID_MAGIC, 2), "channel {c}");
        }
        // Window 3 is above the last channel: acknowledged like a channel, reads 0.
        assert_eq!(
            read(&mut m, channel_base(3) + regmap::offset("ID").unwrap()),
            (0, 2)
        );
        assert_eq!(m.outputs().irq, 0);
    }

    #[test]
    fn ports_widen_with_the_channels() {
        let ports = wb_channels_ports(5);
        let width = |n: &str| ports.iter().find(|p| p.name == n).unwrap().width;
        assert_eq!(
            (width("enc_a"), width("wb_adr_i"), width("irq")),
            (5, 11, 5)
        );
    }
}
