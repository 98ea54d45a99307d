//! The emitted `encspeed_wb.v` (core + Wishbone register file), compiled by Verilator with
//! the harness `tb/verilator/wb_harness.cpp`: the same pattern as [`crate::verilator`]
//! (built by [`tools::verilator_build`], cached by content under
//! `target/verilator/<module>-<hash>/`, inputs and outputs streamed one line per cycle). A missing `verilator` is an error, never a skip: `.ci/run` installs it.

use crate::stream_harness;
use golden::top::ecc_wb_top::ECC_WB_TOP_MODULE;
use golden::top::wb_top::{WbTopInputs, WbTopOutputs, TOP_MODULE};
use std::path::{Path, PathBuf};

const HARNESS: &str = include_str!("../verilator/wb_harness.cpp");
/// The top's own lint waivers (each one explained in the file).
pub const WB_WAIVERS: &str = include_str!("../verilator/wb_waivers.vlt");
/// `encspeed_ecc_wb`'s own lint waivers (each one explained in the file).
pub const ECC_WB_WAIVERS: &str = include_str!("../verilator/ecc_wb_waivers.vlt");

/// The waivers that apply to `encspeed_wb.v`: the core's ([`crate::verilator::WAIVERS`]),
/// retargeted from `encspeed_core.v` to this file (the top contains the core unchanged, so
/// the same block outputs are unused under the same names), then the top's own.
pub fn waivers() -> String {
    format!(
        "{}\n// ---- encspeed_wb's own (wb_waivers.vlt) ----\n{}",
        crate::verilator::WAIVERS.replace("*encspeed_core.v", "*encspeed_wb.v"),
        WB_WAIVERS.trim_start_matches("`verilator_config")
    )
}

/// `verilator --lint-only -Wall` on `encspeed_wb.v` with the documented waivers; Ok on a
/// clean lint (a warning fails the run).
pub fn lint(verilog: &str) -> Result<String, String> {
    lint_top(verilog, TOP_MODULE, &waivers())
}

/// `verilator --lint-only -Wall` on `verilog`, top module `module`, with `waivers`; Ok on a
/// clean lint (a warning fails the run).
pub fn lint_top(verilog: &str, module: &str, waivers: &str) -> Result<String, String> {
    let dir = tools::work_dir(
        "verilator",
        &format!(
            "{module}-lint-{:016x}",
            tools::content_hash(&[verilog, waivers])
        ),
    )?;
    let v = format!("{module}.v");
    tools::stage(&dir, &[(&v, verilog), ("waivers.vlt", waivers)])?;
    tools::verilator_lint(&dir, module, &["waivers.vlt", &v])
}

/// The waivers of `encspeed_ecc_wb.v`: `encspeed_ecc`'s
/// ([`crate::ecc_verilator::waivers_for`]) and the top's own (`ecc_wb_waivers.vlt`).
pub fn ecc_wb_waivers() -> String {
    format!(
        "{}\n// ---- encspeed_ecc_wb's own (ecc_wb_waivers.vlt) ----\n{}",
        crate::ecc_verilator::waivers_for(ECC_WB_TOP_MODULE),
        ECC_WB_WAIVERS.trim_start_matches("`verilator_config")
    )
}

/// A compiled simulator of one emitted `encspeed_wb` (or of a top with its ports).
pub struct VerilatedWb {
    exe: PathBuf,
}

impl VerilatedWb {
    /// Compile `verilog` (top module `encspeed_wb`) with the harness, or reuse the build.
    pub fn build(verilog: &str) -> Result<VerilatedWb, String> {
        VerilatedWb::build_top(verilog, TOP_MODULE, &waivers())
    }

    /// Compile `verilog` whose top module `module` has the ports of `encspeed_wb` (as
    /// `encspeed_ecc_wb` has) with the harness and the lint `waivers`, or reuse the build.
    pub fn build_top(verilog: &str, module: &str, waivers: &str) -> Result<VerilatedWb, String> {
        if !verilog.contains(&format!("module {module}(")) {
            return Err(format!("the Verilog has no module {module}"));
        }
        let v = format!("{module}.v");
        let harness = HARNESS.replace("Vencspeed_wb", &format!("V{module}"));
        let exe = tools::verilator_build(
            &format!("{module}-"),
            module,
            &[
                ("wb_waivers.vlt", waivers),
                (&v, verilog),
                ("wb_harness.cpp", &harness),
            ],
        )?;
        Ok(VerilatedWb { exe })
    }

    /// Path of the compiled harness.
    pub fn exe(&self) -> &Path {
        &self.exe
    }

    /// Run `inputs` through the compiled Verilog, one clock edge per input; optionally write
    /// a VCD of every signal to `vcd`.
    pub fn run(
        &self,
        inputs: &[WbTopInputs],
        vcd: Option<&Path>,
    ) -> Result<Vec<WbTopOutputs>, String> {
        let text: String = inputs
            .iter()
            .map(|i| {
                let b = &i.bus;
                format!(
                    "{} {} {} {} {} {} {} {} {} {}\n",
                    u8::from(i.reset),
                    u8::from(i.enc_a),
                    u8::from(i.enc_b),
                    u8::from(i.enc_z),
                    u8::from(b.wb_cyc_i),
                    u8::from(b.wb_stb_i),
                    u8::from(b.wb_we_i),
                    b.wb_adr_i,
                    b.wb_dat_i,
                    b.wb_sel_i
                )
            })
            .collect();
        let rows = stream_harness::stream(&self.exe, text, vcd, 3)?;
        let mut outs = Vec::with_capacity(inputs.len());
        for f in rows {
            if f[1] > u64::from(u32::MAX) {
                return Err(format!("bad harness output: wb_dat_o = {}", f[1]));
            }
            outs.push(WbTopOutputs {
                wb_ack_o: f[0] != 0,
                wb_dat_o: f[1] as u32,
                irq: f[2] != 0,
            });
        }
        Ok(outs)
    }
}
