// SPDX-License-Identifier: MIT OR Apache-2.0
//! `encspeed_wb` generated with several encoder channels (`--channels N`, N = 2..=8): N
//! copies of the one-channel top [`EncspeedWb`] (a core and its register file each) behind
//! one Wishbone B4 classic slave, channel c's registers at byte address c · 0x100 + the
//! offset of the one-channel map. Its cycle model is
//! [`golden::top::wb_channels::WbChannelsModel`], whose module docs give the address map,
//! the answer of the windows above the last channel and the timing.
//!
//! ```text
//! enc_a[c], enc_b[c], enc_z[c] ─► channels[c] (EncspeedWb) ─► irq[c]
//! wb_adr_i[A-1:8] → one-hot `hit` → wb_stb_i of the addressed channel only
//! wb_dat_o = OR of channels[c].wb_dat_o, wb_ack_o = OR of the acks (and the empty window's)
//! ```
//!
//! # Parameters
//! N, P, S as [`EncspeedWb`]; CH the channels (2..=8); B = ⌈log2 CH⌉ the channel bits;
//! A = 8 + B the width of `wb_adr_i`. Stable Rust cannot compute B and A from CH, so they are
//! parameters too, checked by [`EncspeedWbChannels::new`]
//! ([`build_wb_channels`](crate::sim::wb_channels_sim::build_wb_channels) picks them).
//!
//! # Ports
//! `clock`, `reset`, `enc_a[CH-1:0]`, `enc_b[CH-1:0]`, `enc_z[CH-1:0]` (bit c: channel c,
//! asynchronous), `sample` (every channel's snapshot strobe), `wb_cyc_i`, `wb_stb_i`,
//! `wb_we_i`, `wb_adr_i[A-1:0]`, `wb_dat_i[31:0]`, `wb_sel_i[3:0]`, `wb_dat_o[31:0]`,
//! `wb_ack_o`, `irq[CH-1:0]` ([`golden::top::wb_channels::wb_channels_ports`] describes each).
//!
//! # Why it is built this way
//! Only the addressed channel sees `wb_stb_i`, so only it takes the request and answers;
//! every channel's `wb_dat_o` is 0 outside its own read's ack cycle, so the read data is a
//! plain OR of registers (no multiplexer on the channel bits, and no path from an input to
//! an output). The decode is a one-hot shift of the channel bits, which is also how the
//! windows above the last channel are found (no bit of `hit` set): a comparison with the
//! last channel would be constant when CH is a power of two, which Verilator flags. Those
//! windows get a two-flip-flop answer with a channel's timing, so a master never waits for
//! ever on them.

use crate::top::wb_top::EncspeedWb;
use golden::bus::regmap::ADDR_BITS;
use golden::params::Params;
use rust_hdl::prelude::*;

/// `CH` encoder channels behind one Wishbone slave (see the module docs for the parameters).
#[derive(LogicBlock)]
pub struct EncspeedWbChannels<
    const N: usize,
    const P: usize,
    const S: usize,
    const CH: usize,
    const B: usize,
    const A: usize,
> {
    /// Clock of every channel and of the bus.
    pub clock: Signal<In, Clock>,
    /// Synchronous active-high reset of every channel.
    pub reset: Signal<In, Bit>,
    /// Encoder channels A (asynchronous), bit c for channel c.
    pub enc_a: Signal<In, Bits<CH>>,
    /// Encoder channels B (asynchronous), bit c for channel c.
    pub enc_b: Signal<In, Bits<CH>>,
    /// Encoder indexes Z (asynchronous), bit c for channel c.
    pub enc_z: Signal<In, Bits<CH>>,
    /// Snapshot strobe of every channel (synchronous).
    pub sample: Signal<In, Bit>,
    /// Wishbone: bus cycle.
    pub wb_cyc_i: Signal<In, Bit>,
    /// Wishbone: strobe.
    pub wb_stb_i: Signal<In, Bit>,
    /// Wishbone: 1 write, 0 read.
    pub wb_we_i: Signal<In, Bit>,
    /// Wishbone: byte address; bits A-1:8 select the channel (bits 1:0 ignored).
    pub wb_adr_i: Signal<In, Bits<A>>,
    /// Wishbone: write data.
    pub wb_dat_i: Signal<In, Bits<32>>,
    /// Wishbone: byte lanes of a write.
    pub wb_sel_i: Signal<In, Bits<4>>,
    /// Wishbone: read data (0 outside a read's ack cycle).
    pub wb_dat_o: Signal<Out, Bits<32>>,
    /// Wishbone: acknowledge.
    pub wb_ack_o: Signal<Out, Bit>,
    /// Interrupt requests, bit c for channel c.
    pub irq: Signal<Out, Bits<CH>>,
    /// The channels (their ports are readable in simulation).
    pub channels: Vec<EncspeedWb<N, P, S>>,
    /// The window above the last channel took a request at the last edge.
    empty_pending: DFF<Bit>,
    /// The window above the last channel acknowledges.
    empty_ack: DFF<Bit>,
    /// The addressed channel: `wb_adr_i[A-1:8]`.
    chan: Signal<Local, Bits<B>>,
    /// One-hot of `chan` (all 0 above the last channel).
    hit: Signal<Local, Bits<CH>>,
    empty_req: Signal<Local, Bit>,
    dat: Signal<Local, Bits<32>>,
    ack: Signal<Local, Bit>,
    irq_bits: Signal<Local, Bits<CH>>,
    one: Constant<Bits<CH>>,
    /// Bit CH − 1.
    top: Constant<Bits<CH>>,
    none: Constant<Bits<CH>>,
    sh_one: Constant<Bits<4>>,
    z32: Constant<Bits<32>>,
}

impl<
        const N: usize,
        const P: usize,
        const S: usize,
        const CH: usize,
        const B: usize,
        const A: usize,
    > EncspeedWbChannels<N, P, S, CH, B, A>
{
    /// The `CH` channels of validated parameters `p`; panics unless `CH` is
    /// `p.channels()`, B = ⌈log2 CH⌉ and A = 8 + B (the dispatch in
    /// [`build_wb_channels`](crate::sim::wb_channels_sim::build_wb_channels) guarantees it).
    pub fn new(p: &Params) -> Self {
        assert_eq!(CH as u32, p.channels(), "CH must be the channels of p");
        assert_eq!(
            B as u32,
            golden::top::wb_channels::channel_bits(p.channels()),
            "B must number the channels"
        );
        assert_eq!(ADDR_BITS, 8, "the channel is wb_adr_i[A-1:8]");
        assert_eq!(A, ADDR_BITS + B, "A must be 8 + B");
        Self {
            clock: Default::default(),
            reset: Default::default(),
            enc_a: Default::default(),
            enc_b: Default::default(),
            enc_z: Default::default(),
            sample: Default::default(),
            wb_cyc_i: Default::default(),
            wb_stb_i: Default::default(),
            wb_we_i: Default::default(),
            wb_adr_i: Default::default(),
            wb_dat_i: Default::default(),
            wb_sel_i: Default::default(),
            wb_dat_o: Default::default(),
            wb_ack_o: Default::default(),
            irq: Default::default(),
            channels: (0..CH).map(|_| EncspeedWb::new(p)).collect(),
            empty_pending: Default::default(),
            empty_ack: Default::default(),
            chan: Default::default(),
            hit: Default::default(),
            empty_req: Default::default(),
            dat: Default::default(),
            ack: Default::default(),
            irq_bits: Default::default(),
            one: Constant::new(1u64.into()),
            top: Constant::new((1u64 << (CH - 1)).into()),
            none: Constant::new(0u64.into()),
            sh_one: Constant::new(1u64.into()),
            z32: Constant::new(0u64.into()),
        }
    }
}

impl<
        const N: usize,
        const P: usize,
        const S: usize,
        const CH: usize,
        const B: usize,
        const A: usize,
    > Logic for EncspeedWbChannels<N, P, S, CH, B, A>
{
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, empty_pending, empty_ack);
        // Bit 8 up: `ADDR_BITS` (checked in `new`); hdl_gen copies a name here verbatim.
        self.chan.next = self.wb_adr_i.val().get_bits::<B>(8);
        self.hit.next = self.one.val() << self.chan.val();
        self.dat.next = self.z32.val();
        self.ack.next = self.empty_ack.q.val();
        self.irq_bits.next = self.none.val();
        for i in 0..CH {
            self.channels[i].clock.next = self.clock.val();
            self.channels[i].reset.next = self.reset.val();
            self.channels[i].sample.next = self.sample.val();
            self.channels[i].enc_a.next = self.enc_a.val().get_bit(i);
            self.channels[i].enc_b.next = self.enc_b.val().get_bit(i);
            self.channels[i].enc_z.next = self.enc_z.val().get_bit(i);
            self.channels[i].wb_cyc_i.next = self.wb_cyc_i.val();
            self.channels[i].wb_stb_i.next = self.wb_stb_i.val() & self.hit.val().get_bit(i);
            self.channels[i].wb_we_i.next = self.wb_we_i.val();
            self.channels[i].wb_adr_i.next = self.wb_adr_i.val().get_bits::<ADDR_BITS>(0);
            self.channels[i].wb_dat_i.next = self.wb_dat_i.val();
            self.channels[i].wb_sel_i.next = self.wb_sel_i.val();
            self.dat.next = self.dat.val() | self.channels[i].wb_dat_o.val();
            self.ack.next = self.ack.val() | self.channels[i].wb_ack_o.val();
            // Channel i's bit enters at the top and is shifted down CH − 1 − i times.
            self.irq_bits.next = self.irq_bits.val() >> self.sh_one.val();
            if self.channels[i].irq.val() {
                self.irq_bits.next = self.irq_bits.val() | self.top.val();
            }
        }

        // The windows above the last channel: a channel's acknowledge, nothing else.
        self.empty_req.next = self.wb_cyc_i.val()
            & self.wb_stb_i.val()
            & (self.hit.val() == self.none.val())
            & (!self.empty_ack.q.val())
            & (!self.empty_pending.q.val());
        self.empty_pending.d.next = self.empty_req.val();
        self.empty_ack.d.next = self.empty_pending.q.val();
        if self.reset.val() {
            self.empty_pending.d.next = false;
            self.empty_ack.d.next = false;
        }

        self.wb_dat_o.next = self.dat.val();
        self.wb_ack_o.next = self.ack.val();
        self.irq.next = self.irq_bits.val();
    }
}
