//! Lock-step random regression: model and RTL agree on every pin and (masked) probe.

use tmc429_model::Chip;
use tmc429_testbench::{run, Config};

fn regression(chip: Chip, seed: u64, cycles: u64) {
    let cfg = Config::new(chip, seed, cycles);
    let out = run(&cfg).expect("co-simulation runs");
    if let Some(m) = &out.mismatch {
        panic!("{}", out.report(m));
    }
    assert_eq!(out.cycles, cycles);
    assert!(out.frames > cycles / 2000, "{} frames in {} cycles", out.frames, cycles);
}

fn cycles() -> u64 {
    std::env::var("TMC429_COSIM_CYCLES").ok().and_then(|s| s.parse().ok()).unwrap_or(1_000_000)
}

#[test]
fn lockstep_tmc428() {
    regression(Chip::Tmc428, 1, cycles());
}

#[test]
fn lockstep_tmc429() {
    regression(Chip::Tmc429, 1, cycles());
}

#[test]
fn lockstep_tmc4210() {
    regression(Chip::Tmc4210, 1, cycles());
}
