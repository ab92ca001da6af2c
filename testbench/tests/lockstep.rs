//! Lock-step random regression: model and RTL agree on every pin and (masked) probe, and
//! every coverage bin of the blocks built so far is hit (10 M CLK cycles per variant, seed 1,
//! as `tmc429 cosim --chip X --seed 1 --cycles 10000000`).
//! `TMC429_COSIM_CYCLES` overrides the length (the coverage check needs the full run).
#![cfg(not(tmc429_no_rtl))] // needs Verilator (testbench/build.rs)

use tmc429_model::Chip;
use tmc429_testbench::{run, Config};

const FULL: u64 = 10_000_000;

fn cycles() -> u64 {
    std::env::var("TMC429_COSIM_CYCLES").ok().and_then(|s| s.parse().ok()).unwrap_or(FULL)
}

fn regression(chip: Chip) {
    let n = cycles();
    let cfg = Config::new(chip, 1, n);
    let out = run(&cfg).expect("co-simulation runs");
    if let Some(m) = &out.mismatch {
        panic!("{}", out.report(m));
    }
    assert_eq!(out.mismatches(), 0);
    assert_eq!(out.cycles, n);
    // about one SPI frame per 600 cycles (frames, idle time, power down, pin changes)
    assert!(out.frames > n / 1000, "{} frames in {} cycles", out.frames, n);
    if n >= FULL {
        let missed = out.coverage.missed();
        assert!(missed.is_empty(), "{chip}: bins never hit: {missed:?}\n{}", out.coverage.table());
    }
}

#[test]
fn lockstep_tmc428() {
    regression(Chip::Tmc428);
}

#[test]
fn lockstep_tmc429() {
    regression(Chip::Tmc429);
}

#[test]
fn lockstep_tmc4210() {
    regression(Chip::Tmc4210);
}

/// Other seeds, shorter runs: still no mismatch.
#[test]
fn lockstep_more_seeds() {
    for chip in Chip::ALL {
        for seed in [2u64, 3, 1234] {
            let out = run(&Config::new(chip, seed, 300_000)).expect("co-simulation runs");
            if let Some(m) = &out.mismatch {
                panic!("{}", out.report(m));
            }
        }
    }
}
