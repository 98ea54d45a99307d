// SPDX-License-Identifier: MIT OR Apache-2.0
//! The boards the IP ships a top for (`hdl::board::board_top`): each board's clock, serial
//! line, FPGA and the parameters its `encspeed_wb` is generated with, as data that the
//! hardware, the `encspeed monitor` host program, the benches and docs/boards.md share.
//!
//! Every board top runs the IP at the board's own oscillator (12 MHz on both iCE40 boards,
//! 25 MHz on the ULX3S: no PLL is needed, and the default 1 ms dt is then 12 000 or 25 000
//! cycles), talks 115 200 baud 8N1 through the board's USB UART, and takes the encoder on
//! three pins with the FPGA's pull-ups on (open-collector encoders work without external
//! resistors).

use crate::board::uart::UartTiming;
use crate::params::{ParamError, Params, Spec, SpeedOutput};
use crate::top::port_fields::port_struct;
use crate::top::ports::Port;

/// The serial line speed of every board top.
pub const BOARD_BAUD: u64 = 115_200;

/// A board with a shipped top.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Board {
    /// Lattice iCE40-HX8K breakout board (iCE40HX8K-CT256, 12 MHz oscillator, FT2232H
    /// channel B as the UART).
    Hx8kBreakout,
    /// 1BitSquared iCEBreaker (iCE40UP5K-SG48, 12 MHz oscillator, FT2232H channel B as the
    /// UART, encoder on PMOD 1A, LEDs on the PMOD 2 snap-off board).
    Icebreaker,
    /// Radiona ULX3S with the ECP5-85F (LFE5U-85F-6BG381C, 25 MHz oscillator, FT231X as
    /// the UART, encoder on header J1's first PMOD position, LEDs 0-3 of its eight).
    Ulx3s,
}

/// The FPGA family of a board: which place-and-route tool and pin-constraint format its
/// bitstream takes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Family {
    /// Lattice iCE40: nextpnr-ice40, PCF pins, icepack.
    Ice40,
    /// Lattice ECP5: nextpnr-ecp5, LPF pins, ecppack.
    Ecp5,
}

impl Board {
    /// Every board, in the order `encspeed generate` writes them.
    pub const ALL: [Board; 3] = [Board::Hx8kBreakout, Board::Icebreaker, Board::Ulx3s];

    /// The board's name: the FuseSoC target, the stem of its pin constraints file in
    /// `constraints/` and the suffix of its top module.
    pub fn name(self) -> &'static str {
        match self {
            Board::Hx8kBreakout => "hx8k_breakout",
            Board::Icebreaker => "icebreaker",
            Board::Ulx3s => "ulx3s",
        }
    }

    /// The board with this [`Board::name`].
    pub fn from_name(name: &str) -> Option<Board> {
        Board::ALL.into_iter().find(|b| b.name() == name)
    }

    /// The top module (and the stem of its file in `generated/`).
    pub fn module(self) -> String {
        format!("encspeed_board_{}", self.name())
    }

    /// The board's FPGA family.
    pub fn family(self) -> Family {
        match self {
            Board::Hx8kBreakout | Board::Icebreaker => Family::Ice40,
            Board::Ulx3s => Family::Ecp5,
        }
    }

    /// The board's oscillator, Hz: the clock of the whole top.
    pub fn clock_hz(self) -> u64 {
        match self {
            Board::Hx8kBreakout | Board::Icebreaker => 12_000_000,
            Board::Ulx3s => 25_000_000,
        }
    }

    /// The UART bit timing: [`BOARD_BAUD`] at the board clock (12 MHz / 115 200 → 104
    /// cycles a bit, +0.16 %; 25 MHz → 217, +0.01 %).
    pub fn uart(self) -> UartTiming {
        UartTiming::new(self.clock_hz(), BOARD_BAUD).expect("115 200 baud fits every board's clock")
    }

    /// The parameters of the board's `encspeed_wb` for the user's `spec`: `spec` at the
    /// board clock, dt kept at the same time (dt_cycles scaled by the clock ratio and
    /// rounded; the default 1 ms is 12 000 cycles at 12 MHz). The iCEBreaker's UP5K holds
    /// the IP with n3 alone ([`Board::estimators`]). An error where the scaled parameters
    /// are not valid (say, a dt too short for the slower clock).
    pub fn params(self, spec: &Spec) -> Result<Params, ParamError> {
        let clock_hz = self.clock_hz() as f64;
        let dt_cycles = (spec.dt_cycles as f64 * clock_hz / spec.clock_hz).round() as u64;
        Params::new(Spec {
            clock_hz,
            dt_cycles,
            estimators: self.estimators().unwrap_or_else(|| spec.estimators.clone()),
            ..spec.clone()
        })
    }

    /// The speed outputs a board's FPGA holds, where it cannot hold those asked: the
    /// iCE40UP5K takes n3 alone (with all six, `encspeed_wb` and the bridge were 4 985 of
    /// its 5 280 logic cells before the snapshot, and nextpnr-ice40 found no legal
    /// placement on some runs; the snapshot adds some 570).
    pub fn estimators(self) -> Option<Vec<SpeedOutput>> {
        match self {
            Board::Hx8kBreakout | Board::Ulx3s => None,
            Board::Icebreaker => Some(vec![SpeedOutput::N3]),
        }
    }

    /// The device options of the board's nextpnr ([`Board::nextpnr`]).
    pub fn nextpnr_device(self) -> &'static [&'static str] {
        match self {
            Board::Hx8kBreakout => &["--hx8k", "--package", "ct256"],
            Board::Icebreaker => &["--up5k", "--package", "sg48"],
            Board::Ulx3s => &["--85k", "--package", "CABGA381"],
        }
    }

    /// The place-and-route tool of the board's family.
    pub fn nextpnr(self) -> &'static str {
        match self.family() {
            Family::Ice40 => "nextpnr-ice40",
            Family::Ecp5 => "nextpnr-ecp5",
        }
    }

    /// The pin constraints file, relative to the repository root: PCF for the iCE40
    /// boards, LPF for the ECP5.
    pub fn constraints_file(self) -> String {
        let ext = match self.family() {
            Family::Ice40 => "pcf",
            Family::Ecp5 => "lpf",
        };
        format!("constraints/{}.{ext}", self.name())
    }

    /// The file name of the bitstream the board's FuseSoC target leaves: icepack's `.bin`
    /// or ecppack's `.bit`.
    pub fn bitstream_extension(self) -> &'static str {
        match self.family() {
            Family::Ice40 => "bin",
            Family::Ecp5 => "bit",
        }
    }
}

port_struct! {
    /// Inputs of a board top during one clock cycle, named as its ports.
    #[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
    pub struct BoardInputs {
        /// Serial line from the host (idle 1).
        pub rx: bool,
        /// Encoder channel A.
        pub enc_a: bool,
        /// Encoder channel B.
        pub enc_b: bool,
        /// Encoder index Z.
        pub enc_z: bool,
    }
}

port_struct! {
    /// Outputs of a board top after a rising clock edge, named as its ports.
    #[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
    pub struct BoardOutputs {
        /// Serial line to the host.
        pub tx: bool,
        /// The four LEDs, `led[0]` in bit 0: heartbeat (bit 23 of a free-running counter,
        /// about 0.7 Hz at 12 MHz, 1.5 Hz at 25 MHz: the bitstream runs), irq, encoder A,
        /// encoder B.
        pub led: u8,
    }
}

/// The ports of every board top, in the order of its Verilog module header.
pub fn board_ports() -> Vec<Port> {
    vec![
        Port::input("clock", 1, "the board oscillator"),
        Port::input(
            "rx",
            1,
            "serial line from the host, 8N1 (asynchronous, idle 1)",
        ),
        Port::input("enc_a", 1, "encoder channel A (asynchronous)"),
        Port::input("enc_b", 1, "encoder channel B (asynchronous)"),
        Port::input("enc_z", 1, "encoder index Z (asynchronous)"),
        Port::output("tx", 1, "serial line to the host, 8N1 (idle 1)"),
        Port::output(
            "led",
            4,
            "led[0] heartbeat, led[1] irq, led[2] A, led[3] B (registers)",
        ),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn boards_run_at_their_oscillator_and_115200_baud() {
        // (board, clock, 1 ms dt in cycles, UART divisor), by hand: 12e6 / 115 200 =
        // 104.17 → 104 cycles a bit; 25e6 / 115 200 = 217.01 → 217.
        let want = [
            (
                Board::Hx8kBreakout,
                12e6,
                12_000,
                104,
                "constraints/hx8k_breakout.pcf",
            ),
            (
                Board::Icebreaker,
                12e6,
                12_000,
                104,
                "constraints/icebreaker.pcf",
            ),
            (Board::Ulx3s, 25e6, 25_000, 217, "constraints/ulx3s.lpf"),
        ];
        assert_eq!(want.map(|w| w.0), Board::ALL);
        for (b, clock, dt, divisor, pins) in want {
            let p = b.params(&Spec::default()).unwrap();
            assert_eq!(p.clock_hz(), clock);
            assert_eq!(p.dt_cycles(), dt);
            assert_eq!(b.uart().divisor(), divisor);
            assert_eq!(b.constraints_file(), pins);
            assert_eq!(Board::from_name(b.name()), Some(b));
        }
        assert_eq!(Board::from_name("orangecrab"), None);
        // 10 cycles at 100 MHz is 0.1 µs: 1.2 → 1 cycle at 12 MHz, below the 2 a dt needs.
        let short = Spec {
            dt_cycles: 10,
            ..Spec::default()
        };
        assert!(Board::Icebreaker.params(&short).is_err());
        assert_eq!(Board::Hx8kBreakout.module(), "encspeed_board_hx8k_breakout");
        assert_eq!(Board::Ulx3s.nextpnr(), "nextpnr-ecp5");
        assert_eq!(Board::Ulx3s.bitstream_extension(), "bit");
    }
}
