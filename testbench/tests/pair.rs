//! The two-thread pair (`tmc429_testbench::pair`, used by `run` without a VCD) gives exactly
//! the outcome of the single-thread loop: cycles, transactions, coverage, and on a mismatch the
//! same first cycle and report.
#![cfg(not(tmc429_no_rtl))] // needs Verilator (testbench/build.rs)

use tmc429_model::{Chip, Tmc429};
use tmc429_testbench::cosim::run_one_thread;
use tmc429_testbench::pair::{run_pair, Step};
use tmc429_testbench::signals::Compare;
use tmc429_testbench::stimulus::{Driver, Profile, Stimulus};
use tmc429_testbench::{run, Config, Variant};

#[test]
fn two_threads_equal_one_thread() {
    for chip in Chip::ALL {
        for profile in [Profile::Motion, Profile::Drivers] {
            let mut cfg = Config::new(chip, 2, 300_000);
            cfg.profile = profile;
            let two = run(&cfg).unwrap();
            let one = run_one_thread(&cfg).unwrap();
            assert!(one.mismatch.is_none(), "{}", one.summary());
            assert_eq!(two.summary(), one.summary(), "{chip} {profile:?}");
            assert_eq!((two.cycles, two.frames, two.pin_changes), (one.cycles, one.frames, one.pin_changes));
            assert!(one.frames > 0 && one.pin_changes > 0);
            assert_eq!(two.coverage.bins(), one.coverage.bins(), "{chip} {profile:?}");
        }
    }
}

#[test]
fn two_threads_report_the_planted_bug_like_one_thread() {
    let mut cfg = Config::new(Chip::Tmc429, 1, 2_000_000);
    cfg.variant = Variant::PlantedStatusBug;
    let two = run(&cfg).unwrap();
    let one = run_one_thread(&cfg).unwrap();
    let m = two.mismatch.as_ref().expect("the planted bug is caught");
    assert_eq!(two.cycles, m.cycle);
    assert!(m.diffs.iter().any(|d| d.signal.name == "status"));
    assert_eq!(two.summary(), one.summary());
    assert_eq!(two.coverage.bins(), one.coverage.bins());
}

/// `run_pair` itself: the cycle of the first disagreement, counted from 1 (0: the reset states).
#[test]
fn run_pair_finds_the_first_disagreeing_cycle() {
    let chip = Chip::Tmc429;
    let mut stim = Stimulus::new(chip, Profile::Motion, 1);
    let mut drv = Driver::default();
    let inputs: Vec<_> = (0..20_000)
        .map(|_| {
            if drv.ready() {
                drv.start(stim.next_txn());
            }
            drv.step().0
        })
        .collect();
    let steps = |bad: Option<usize>| {
        let mut model = Tmc429::new(chip);
        let mut v: Vec<Step> = inputs
            .iter()
            .map(|i| {
                let out = model.tick(i);
                Step { inp: *i, out, probes: model.probes() }
            })
            .collect();
        if let Some(k) = bad {
            v[k].probes.motor[2].x_actual ^= 1;
        }
        v
    };
    let reset = {
        let m = Tmc429::new(chip);
        (m.outputs(), m.probes())
    };
    let pair = |v: Vec<Step>, reset| {
        // batches of an odd size, so that the disagreement falls inside one
        let mut rest = v.chunks(777);
        run_pair(Variant::Chip(chip), Compare::all(), reset, |buf| match rest.next() {
            Some(c) => {
                buf.extend_from_slice(c);
                true
            }
            None => false,
        })
        .unwrap()
    };
    assert_eq!(pair(steps(None), reset), None);
    assert_eq!(pair(steps(Some(0)), reset), Some(1));
    assert_eq!(pair(steps(Some(12_345)), reset), Some(12_346));
    assert_eq!(pair(steps(Some(19_999)), reset), Some(20_000));
    // a difference masked out is no disagreement
    let mask = Compare::all().without("motor2.x_actual");
    let mut rest = steps(Some(500)).into_iter();
    let masked = run_pair(Variant::Chip(chip), mask, reset, |buf| {
        buf.extend(rest.by_ref().take(1000));
        !buf.is_empty()
    })
    .unwrap();
    assert_eq!(masked, None);
    let mut bad_reset = reset;
    bad_reset.1.status ^= 0x80;
    assert_eq!(pair(steps(None), bad_reset), Some(0));
}
