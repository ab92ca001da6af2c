//! Verilator lint of rtl/ (`verilator --lint-only -Wall`, every CHIP): no warning at all.
#![cfg(not(tmc429_no_rtl))] // needs Verilator (testbench/build.rs)

#[test]
fn rtl_lint_is_clean() {
    let script = concat!(env!("CARGO_MANIFEST_DIR"), "/../scripts/rtl-lint");
    let out = std::process::Command::new("bash").arg(script).output().expect("run scripts/rtl-lint");
    assert!(out.status.success(), "rtl-lint failed:\n{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
}
