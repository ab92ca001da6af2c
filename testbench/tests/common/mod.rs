//! Shared by the unit tests that run one `rtl/` module under Icarus Verilog against vectors of
//! the model's unit.

use proptest::strategy::{Strategy, ValueTree};
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};
use std::path::Path;
use std::process::Command;
use std::sync::atomic::{AtomicUsize, Ordering};

/// Compiles the test bench `bench` (its `NVEC` replaced by the number of `lines`) with
/// `rtl/<module>.v`, runs it on `lines` as `vectors.hex` in a scratch directory and returns what
/// it printed.
#[allow(dead_code)] // a test crate may call icarus_modules alone
pub fn icarus_unit(module: &str, bench: &str, lines: &[String]) -> String {
    icarus_modules(&[module], bench, lines)
}

/// As [`icarus_unit`], with the modules `rtl/<module>.v` of `modules` (the first names the
/// scratch directory, a count of the calls keeps the tests of one process that run at the same
/// time apart) and `rtl/` as the include path of the register map and frame schedule.
pub fn icarus_modules(modules: &[&str], bench: &str, lines: &[String]) -> String {
    static CALLS: AtomicUsize = AtomicUsize::new(0);
    let call = CALLS.fetch_add(1, Ordering::Relaxed);
    let dir = std::env::temp_dir().join(format!("tmc429-{}-{}-{call}", modules[0], std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let hex: String = lines.iter().map(|l| format!("{l}\n")).collect();
    std::fs::write(dir.join("vectors.hex"), hex).unwrap();
    std::fs::write(dir.join("tb.v"), bench.replace("NVEC", &lines.len().to_string())).unwrap();
    let rtl = Path::new(env!("CARGO_MANIFEST_DIR")).join("../rtl");
    let st = Command::new("iverilog")
        .args(["-g2005", "-Wall", "-o", "sim"])
        .arg(format!("-I{}", rtl.display()))
        .arg("tb.v")
        .args(modules.iter().map(|m| rtl.join(format!("{m}.v"))))
        .current_dir(&dir)
        .status()
        .expect("iverilog (scripts/setup installs it)");
    assert!(st.success(), "iverilog failed");
    let out = Command::new("vvp").args(["-n", "sim"]).current_dir(&dir).output().expect("vvp");
    let text = String::from_utf8_lossy(&out.stdout).to_string();
    let _ = std::fs::remove_dir_all(&dir);
    text
}

/// A reproducible stream of numbers for a unit test's stimulus, from a seed: `draw(n)` is
/// uniform in 0..n.
#[allow(dead_code)] // not every test crate draws
pub fn draws(seed: u64) -> impl FnMut(u32) -> u32 {
    let mut key = [0u8; 32];
    key[..8].copy_from_slice(&seed.to_le_bytes());
    let mut runner = TestRunner::new_with_rng(Config::default(), TestRng::from_seed(RngAlgorithm::ChaCha, &key));
    move |n| (0..n).new_tree(&mut runner).unwrap().current()
}
