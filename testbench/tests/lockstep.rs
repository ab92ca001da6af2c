//! Lock-step random regressions: model and RTL agree on every pin and probe, and every coverage
//! bin is hit (10 M CLK cycles per variant and profile, seed 1, as `tmc429 cosim --chip X
//! --profile drivers|motion --seed 1 --cycles 10000000`).
//! `TMC429_COSIM_CYCLES` overrides the length (the coverage check needs the full run).
#![cfg(not(tmc429_no_rtl))] // needs Verilator (testbench/build.rs)

use tmc429_model::Chip;
use tmc429_testbench::coverage::motion_bins;
use tmc429_testbench::stimulus::Profile;
use tmc429_testbench::{run, Config};

const FULL: u64 = 10_000_000;

fn cycles() -> u64 {
    std::env::var("TMC429_COSIM_CYCLES").ok().and_then(|s| s.parse().ok()).unwrap_or(FULL)
}

fn regression(chip: Chip) {
    let n = cycles();
    let mut cfg = Config::new(chip, 1, n);
    cfg.profile = Profile::Drivers;
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
            let out = run(&Config::new(chip, seed, 1_000_000)).expect("co-simulation runs");
            if let Some(m) = &out.mismatch {
                panic!("{}", out.report(m));
            }
        }
    }
}

/// The complete chip in lock-step with everything moving: the `motion` profile (moves in every
/// mode with valid and boundary parameters, retargeting, mode changes, reference searches with
/// switch stops and latching, current scaling, driver-chain configurations, cover datagrams,
/// continuous update, refmux, Step/Dir, power down, register traffic), every pin and probe
/// compared, 10 M cycles per variant (`TMC429_COSIM_CYCLES` overrides). Every motion bin
/// (`coverage::motion_bins`: each mode, stops hard and soft, latch on both edges, each usrs, each
/// current scale, cover, continuous update, Step/Dir with step_half …) and the STOP interrupt
/// must be hit.
fn motion_regression(chip: Chip) {
    let n = cycles();
    let cfg = Config::new(chip, 1, n);
    assert_eq!(cfg.profile, Profile::Motion);
    let out = run(&cfg).expect("co-simulation runs");
    if let Some(m) = &out.mismatch {
        panic!("{}", out.report(m));
    }
    assert_eq!(out.cycles, n);
    if n >= FULL {
        let bins = out.coverage.bins();
        let mut want = motion_bins(chip);
        want.push("interrupt flag STOP set".into());
        let missed: Vec<&String> = want.iter().filter(|b| bins.get(b.as_str()).copied().unwrap_or(0) == 0).collect();
        assert!(missed.is_empty(), "{chip}: motion bins never hit: {missed:?}\n{}", out.coverage.table());
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
