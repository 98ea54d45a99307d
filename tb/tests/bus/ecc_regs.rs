// SPDX-License-Identifier: MIT OR Apache-2.0
//! `EccRegs` (the eccentricity window's Wishbone slave) against its cycle model
//! `golden::bus::ecc_regs::EccRegsModel`, every cycle, at the narrowest and widest speeds of
//! `encspeed_ecc` (S = 25 for N = 8, S = 49 for N = 32) and the default (S = 41): random
//! classic accesses (reads and writes of the window's offsets and of any other offset, with
//! random byte lanes: staged coefficients, loads and arms with other bits set, W1C and
//! enables, LO-then-HI pairs), cycles of arbitrary bus signals, resets, and random status
//! inputs (strobes, `ident_done` rising and falling, speeds and 72-bit sums with their
//! corner values), and the snapshot's `snap_take` strobes with `snap_sampled` toggling
//! (speed pairs read from the snapshot). Seeded, so the coverage figures asserted at the end are the same on
//! every run.

use crate::common;

use common::SplitMix;
use golden::bus::ecc_regmap::{self as m, ECC_SPEEDS, LAYOUT};
use golden::bus::ecc_regs::{EccRegsInputs, EccRegsModel, EccRegsOutputs, EccStatus};
use golden::bus::reg_file::WbBus;
use hdl::EccRegs;
use rust_hdl::prelude::*;

/// One rising edge of the rust-hdl block with `inp` applied; the outputs after it.
fn step<const S: usize>(uut: &mut EccRegs<S>, inp: &EccRegsInputs) -> EccRegsOutputs {
    let (b, s) = (&inp.bus, &inp.status);
    let g = &s.ident;
    let sum = |v: i128| -> Bits<72> {
        let raw = (v as u128) & ((1u128 << 72) - 1);
        let mut bits = Bits::<72>::default();
        for i in 0..72 {
            bits = bits.replace_bit(i, raw >> i & 1 == 1);
        }
        bits
    };
    uut.reset.next = inp.reset;
    uut.snap_take.next = inp.snap_take;
    uut.snap_sampled.next = inp.snap_sampled;
    uut.wb_cyc_i.next = b.wb_cyc_i;
    uut.wb_stb_i.next = b.wb_stb_i;
    uut.wb_we_i.next = b.wb_we_i;
    uut.wb_adr_i.next = u64::from(b.wb_adr_i).into();
    uut.wb_dat_i.next = u64::from(b.wb_dat_i).into();
    uut.wb_sel_i.next = u64::from(b.wb_sel_i).into();
    uut.speed_mtc.next = s.speed_mtc.into();
    uut.mtc_strobe.next = s.mtc_strobe;
    uut.speed_n3c.next = s.speed_n3c.into();
    uut.n3c_strobe.next = s.n3c_strobe;
    uut.ident_done.next = g.done;
    uut.ident_overflow.next = g.overflow;
    uut.ident_count.next = g.count.into();
    uut.ident_t_min.next = g.t_min.into();
    uut.ident_t_max.next = g.t_max.into();
    uut.ident_p_min.next = g.p_min.into();
    uut.ident_p_max.next = g.p_max.into();
    uut.ident_sum_t.next = sum(g.sum_t);
    uut.ident_sum_sin.next = sum(g.sum_sin);
    uut.ident_sum_cos.next = sum(g.sum_cos);
    common::edge(uut, |u, c| u.clock.next = Clock { clk: c });
    EccRegsOutputs {
        wb_ack_o: uut.wb_ack_o.val(),
        wb_dat_o: uut.wb_dat_o.val().to_u64() as u32,
        irq: uut.irq.val(),
        ecc_c: uut.ecc_c.val().to_u64() as u32,
        ecc_d: uut.ecc_d.val().to_u64() as u32,
        ident_arm: uut.ident_arm.val(),
    }
}

/// What the stimulus reached.
#[derive(Debug, Default)]
struct Coverage {
    reads: usize,
    writes: usize,
    arms: usize,
    loads: usize,
    irq_cycles: usize,
    negative_top_words: usize,
    resets: usize,
    /// Snapshots taken, and speed LO reads while the pairs read the snapshot.
    snapshots: usize,
    sampled_speed_reads: usize,
}

/// A value of `bits` bits: random, or one of its corner cases.
fn corner(r: &mut SplitMix, bits: u32) -> u64 {
    let max = if bits == 64 {
        u64::MAX
    } else {
        (1 << bits) - 1
    };
    match r.next() % 6 {
        0 => 0,
        1 => max,
        2 => max >> 1,
        3 => (max >> 1) + 1,
        _ => r.next() & max,
    }
}

/// A 72-bit two's complement sum: random, or a corner case.
fn sum(r: &mut SplitMix) -> i128 {
    let top = 1i128 << 71;
    match r.next() % 6 {
        0 => 0,
        1 => -1,
        2 => top - 1,
        3 => -top,
        _ => {
            let v = (i128::from(r.next()) << 8) | i128::from(r.next() & 0xFF);
            (v << 56) >> 56
        }
    }
}

fn run<const S: usize>(seed: u64, cycles: usize) -> Coverage {
    let mut r = SplitMix(seed);
    let mut model = EccRegsModel::new(S as u32);
    let mut uut = EccRegs::<S>::new();
    uut.connect_all();
    let mut cov = Coverage::default();
    let mut status = EccStatus::default();
    let mut bus = WbBus::default();
    let mut held = false;
    let mut snap_sampled = false;
    for k in 0..cycles {
        // The core register file's snapshot strobe and CTRL.SAMPLED.
        let snap_take = r.next().is_multiple_of(40);
        if r.next().is_multiple_of(200) {
            snap_sampled = !snap_sampled;
        }
        // Status: strobes, a done level, and values that change now and then.
        status.mtc_strobe = r.next().is_multiple_of(20);
        status.n3c_strobe = r.next().is_multiple_of(20);
        if r.next().is_multiple_of(50) {
            status.ident.done = !status.ident.done;
        }
        if r.next().is_multiple_of(30) {
            status.speed_mtc = corner(&mut r, S as u32);
            status.speed_n3c = corner(&mut r, S as u32);
            let g = &mut status.ident;
            g.overflow = r.next().is_multiple_of(4);
            g.count = corner(&mut r, 17);
            g.t_min = corner(&mut r, 32);
            g.t_max = corner(&mut r, 32);
            g.p_min = corner(&mut r, 16);
            g.p_max = corner(&mut r, 16);
            g.sum_t = sum(&mut r);
            g.sum_sin = sum(&mut r);
            g.sum_cos = sum(&mut r);
        }
        // Bus: a classic master holds its request through the ack; otherwise a new access,
        // an idle cycle or (rarely) arbitrary signals.
        let (acked, busy) = (model.outputs().wb_ack_o, model.busy());
        if held && acked {
            held = false;
            bus = WbBus::default();
        } else if !held {
            let x = r.next();
            bus = WbBus::default();
            if x % 100 < 45 {
                let adr = if x.is_multiple_of(5) {
                    ((x >> 8) & 0xFF) as u32
                } else {
                    LAYOUT[((x >> 8) % LAYOUT.len() as u64) as usize].1 | ((x >> 16) & 3) as u32
                };
                let we = (x >> 20).is_multiple_of(3);
                bus = WbBus {
                    wb_cyc_i: true,
                    wb_stb_i: true,
                    wb_we_i: we,
                    wb_adr_i: adr,
                    wb_dat_i: if (x >> 24).is_multiple_of(2) {
                        r.next() as u32
                    } else {
                        0b11
                    },
                    wb_sel_i: if (x >> 26).is_multiple_of(2) {
                        0xF
                    } else {
                        ((x >> 28) & 0xF) as u8
                    },
                };
                held = true;
            } else if x % 100 < 48 {
                let y = r.next();
                bus = WbBus {
                    wb_cyc_i: y & 1 == 1,
                    wb_stb_i: y & 2 == 2,
                    wb_we_i: y & 4 == 4,
                    wb_adr_i: ((y >> 8) & 0xFF) as u32,
                    wb_dat_i: (y >> 32) as u32,
                    wb_sel_i: ((y >> 16) & 0xF) as u8,
                };
            }
        }
        let reset = k < 2 || r.next().is_multiple_of(3000);
        let inp = EccRegsInputs {
            reset,
            bus,
            status,
            snap_take,
            snap_sampled,
        };
        let req = bus.wb_cyc_i && bus.wb_stb_i && !busy && !reset;
        let want = model.step(&inp);
        let got = step(&mut uut, &inp);
        assert_eq!(got, want, "S = {S}, seed {seed:#x}, cycle {k}: {inp:?}");
        cov.reads += usize::from(req && !bus.wb_we_i);
        cov.writes += usize::from(req && bus.wb_we_i);
        cov.arms += usize::from(want.ident_arm);
        cov.loads += usize::from(
            req && bus.wb_we_i
                && bus.wb_adr_i & !3 == m::ECC_CTRL
                && bus.wb_dat_i & 2 != 0
                && bus.wb_sel_i & 1 != 0,
        );
        cov.irq_cycles += usize::from(want.irq);
        cov.negative_top_words += usize::from(want.wb_ack_o && want.wb_dat_o >> 8 == 0x00FF_FFFF);
        cov.resets += usize::from(reset);
        cov.snapshots += usize::from(snap_take && !reset);
        cov.sampled_speed_reads += usize::from(
            req && !bus.wb_we_i
                && snap_sampled
                && ECC_SPEEDS.iter().any(|&(lo, _, _)| bus.wb_adr_i & !3 == lo),
        );
    }
    cov
}

fn check(cov: &Coverage) {
    assert!(
        cov.reads > 1000
            && cov.writes > 400
            && cov.arms > 20
            && cov.loads > 20
            && cov.irq_cycles > 100
            && cov.negative_top_words > 5
            && cov.resets > 3
            && cov.snapshots > 200
            && cov.sampled_speed_reads > 20,
        "stimulus coverage {cov:?}"
    );
}

#[test]
fn rust_hdl_equals_the_model_at_the_default_speed_width() {
    let cov = run::<41>(0xECC_0041, 60_000);
    println!("{cov:?}");
    check(&cov);
}

#[test]
fn rust_hdl_equals_the_model_at_the_narrowest_and_widest_speeds() {
    for (seed, cov) in [
        (0xECC_0025, run::<25>(0xECC_0025, 30_000)),
        (0xECC_0049, run::<49>(0xECC_0049, 30_000)),
    ] {
        println!("{seed:#x}: {cov:?}");
        check(&cov);
    }
}
