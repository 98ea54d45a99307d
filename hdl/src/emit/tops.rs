// SPDX-License-Identifier: MIT OR Apache-2.0
//! The shipped tops: the one list that `encspeed generate`, `encspeed docs`, `encspeed synth`
//! and the tests that prove `generated/` current iterate over.
//!
//! A new top is added here (its module, its files, whether it needs the eccentricity
//! corrector's parameters) and every command and test that walks [`Top::ALL`] takes it up.

use super::prefix::Prefix;
use golden::params::Params;
use golden::provenance::{generate_command, preamble, Comment};
use golden::top::ports::Port;

/// One shipped top-level module and the files generated with it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Top {
    /// `encspeed_core`: the quadrature front end, Rairán's estimator and the baselines
    /// (`encspeed_core.v` and its manifest `encspeed_core.toml`).
    Core,
    /// `encspeed_wb`: the core behind a Wishbone B4 slave (`encspeed_wb.v`,
    /// `encspeed_regs.h`).
    Wb,
    /// `encspeed_ecc`: the core with the eccentricity-corrected speeds and the online
    /// identification (`encspeed_ecc.v`).
    Ecc,
    /// `encspeed_ecc_wb`: `encspeed_ecc` behind one Wishbone window (`encspeed_ecc_wb.v`,
    /// `encspeed_ecc_regs.h`).
    EccWb,
}

impl Top {
    /// Every shipped top, in the order `generate` writes them.
    pub const ALL: [Top; 4] = [Top::Core, Top::Wb, Top::Ecc, Top::EccWb];

    /// The Verilog module name, which is also the stem of its file.
    pub fn module(self) -> &'static str {
        match self {
            Top::Core => super::TOP_MODULE,
            Top::Wb => golden::top::wb_top::TOP_MODULE,
            Top::Ecc => crate::sim::ecc_sim::ECC_TOP_MODULE,
            Top::EccWb => golden::top::ecc_wb_top::ECC_WB_TOP_MODULE,
        }
    }

    /// The Verilog file's name, `<module>.v`.
    pub fn verilog_file(self) -> String {
        format!("{}.v", self.module())
    }

    /// True for the tops with the eccentricity corrector, which exist only where
    /// [`golden::top::ecc_top::check`] accepts the parameters (a multiple of 4 lines).
    pub fn has_ecc(self) -> bool {
        matches!(self, Top::Ecc | Top::EccWb)
    }

    /// Whether this top can be generated for `p`: Ok, or why not.
    pub fn check(self, p: &Params) -> Result<(), String> {
        if self == Top::EccWb && p.channels() > 1 {
            return Err(format!(
                "channels = {}: encspeed_ecc_wb has one encoder channel (several channels \
                 are encspeed_wb's)",
                p.channels()
            ));
        }
        if self.has_ecc() {
            golden::top::ecc_top::check(p)
        } else {
            Ok(())
        }
    }

    /// Every port of this top, in the order of its Verilog module header.
    pub fn ports(self, p: &Params) -> Vec<Port> {
        match self {
            Top::Core => golden::top::ports::core_ports(p.counter_bits()),
            Top::Wb if p.channels() > 1 => {
                golden::top::wb_channels::wb_channels_ports(p.channels())
            }
            Top::Wb | Top::EccWb => golden::top::wb_top::wb_top_ports(),
            Top::Ecc => golden::top::ports::ecc_ports(p.counter_bits()),
        }
    }

    /// The Verilator lint waivers of this top ([`super::waivers::waivers`]), the text of
    /// `<module>.vlt` after its first two comment lines.
    pub fn waivers(self) -> String {
        super::waivers::waivers(self)
    }

    /// Every file of this top for `p` as (file name, contents), the Verilog first, then
    /// its other files in this order: the C header (bus tops), the manifest
    /// `<module>.toml`, the instantiation template `<module>_inst.v` and the lint waivers
    /// `<module>.vlt`. Deterministic: a pure function of `p`. An error where [`Top::check`]
    /// refuses `p`.
    pub fn files(self, p: &Params) -> Result<Vec<(String, String)>, String> {
        self.files_prefixed(p, &Prefix::none())
    }

    /// [`Top::files`] with every generated name carrying `prefix` ([`Prefix::apply`]).
    pub fn files_prefixed(
        self,
        p: &Params,
        prefix: &Prefix,
    ) -> Result<Vec<(String, String)>, String> {
        self.check(p)?;
        let named = |v: Vec<(&'static str, String)>| -> Vec<(String, String)> {
            v.into_iter().map(|(n, t)| (n.to_string(), t)).collect()
        };
        let command = generate_command(p);
        let module = self.module();
        let mut files = match self {
            Top::Core => vec![(self.verilog_file(), super::emit_core(p).verilog)],
            Top::Wb => named(super::wb::emit_wb(p)),
            Top::Ecc => vec![(self.verilog_file(), super::emit_ecc(p)?)],
            Top::EccWb => named(super::wb::emit_ecc_wb(p)?),
        };
        files.push((format!("{module}.toml"), super::manifest::manifest(self, p)));
        files.push((
            format!("{module}_inst.v"),
            super::inst::template(module, &self.ports(p), &command, &self.connect_notes(p)),
        ));
        files.push((
            format!("{module}.vlt"),
            preamble(Comment::Slashes, &command) + &self.waivers(),
        ));
        Ok(files
            .into_iter()
            .map(|(name, text)| (prefix.file_name(&name), prefix.apply(&text, &command)))
            .collect())
    }

    /// What the instantiation template says about connecting this top.
    fn connect_notes(self, p: &Params) -> Vec<String> {
        let mut notes = vec![
            format!(
                "Generated for {}: see {}.toml for the latencies and the error budget.",
                p.summary(),
                self.module()
            ),
            "enc_a, enc_b, enc_z may be asynchronous (synchronised inside by two flip-flops); every other port is synchronous to the rising edge of clock; reset is synchronous and active high.".into(),
        ];
        notes.push(match self {
            Top::Core | Top::Ecc => "cfg_* are sampled at every edge: tie them to constants or drive them from registers (0 on cfg_dt and cfg_timeout selects the generated defaults).".into(),
            Top::Wb | Top::EccWb => format!(
                "The configuration is in registers: see {} and docs/registers.md.",
                super::wb::HEADER_FILE
            ),
        });
        notes
    }

    /// The Verilog of this top for `p` (the first of [`Top::files`]).
    pub fn verilog(self, p: &Params) -> Result<String, String> {
        let mut files = self.files(p)?;
        Ok(files.swap_remove(0).1)
    }
}
