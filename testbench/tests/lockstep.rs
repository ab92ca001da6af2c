//! Lock-step random regression: model and RTL agree on every pin and (masked) probe, and
//! every coverage bin of the blocks built so far is hit (10 M CLK cycles per variant, seed 1,
//! as `tmc429 cosim --chip X --seed 1 --cycles 10000000`).
//! `TMC429_COSIM_CYCLES` overrides the length (the coverage check needs the full run).
#![cfg(not(tmc429_no_rtl))] // needs Verilator (testbench/build.rs)

use tmc429_model::Chip;
use tmc429_testbench::stimulus::Profile;
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

/// The motion core in lock-step: the `motion-core` profile (moves in every mode, retargeting,
/// mode changes, reference searches with switch stops and latching, power down, register
/// traffic) with only the driver-chain pins and probes masked, 10 M cycles per variant
/// (`TMC429_COSIM_CYCLES` overrides). The run must move the motors: steps both ways, moves that
/// end on their target, switch stops and latches.
fn motion_regression(chip: Chip) {
    let n = cycles();
    let mut cfg = Config::new(chip, 1, n);
    cfg.profile = Profile::MotionCore;
    let out = run(&cfg).expect("co-simulation runs");
    if let Some(m) = &out.mismatch {
        panic!("{}", out.report(m));
    }
    assert_eq!(out.cycles, n);
    if n >= FULL {
        let bins = out.coverage.bins();
        for b in [
            "step positive",
            "step negative",
            "RAMP_MODE: move ends at x_target",
            "VELOCITY_MODE: v_actual reaches v_target",
            "mode change during motion",
            "x_target change during motion",
            "switch stop, hard",
            "switch stop, soft",
            "latch on a rising switch edge",
            "latch on a falling switch edge",
            "interrupt flag STOP set",
        ] {
            assert!(bins.get(b).copied().unwrap_or(0) > 0, "{chip}: bin {b} never hit\n{}", out.coverage.table());
        }
    }
}

#[test]
fn lockstep_motion_tmc428() {
    motion_regression(Chip::Tmc428);
}

#[test]
fn lockstep_motion_tmc429() {
    motion_regression(Chip::Tmc429);
}

#[test]
fn lockstep_motion_tmc4210() {
    motion_regression(Chip::Tmc4210);
}
