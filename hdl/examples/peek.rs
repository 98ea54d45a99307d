fn main() {
    let p = golden::params::Params::new(golden::params::Spec {
        counter_bits: 8,
        dt_cycles: 10,
        timeout_s: 1e-6 * 100.0,
        clock_hz: 1e6,
        lines: 4,
    })
    .unwrap();
    let e = hdl::emit_core(&p);
    print!("{}", e.verilog);
    print!("{}", e.manifest);
}
