//! The two-thread pair (`tmc429_testbench::pair`, used by `run` without a VCD) gives exactly
//! the outcome of the single-thread loop: cycles, transactions, coverage, and on a mismatch the
//! same first cycle and report.
#![cfg(not(tmc429_no_rtl))] // needs Verilator (testbench/build.rs)

use tmc429_model::{Chip, Tmc429};
use tmc429_testbench::cosim::run_one_thread;
use tmc429_testbench::pair::run_pair;
use tmc429_testbench::rtl::Expected;
use tmc429_testbench::signals::Compare;
use tmc429_testbench::stimulus::{Driver, Profile, Stimulus};
use tmc429_testbench::{run, Config, Variant};

/// One edge of the model side as the tests alter it: its inputs and the model's outputs and
/// probes after it (handed to the pair as [`Expected`]).
#[derive(Clone, Copy)]
struct Step {
    inp: tmc429_model::Inputs,
    out: tmc429_model::Outputs,
    probes: tmc429_model::Probes,
}

fn expected(s: &Step) -> Expected {
    Expected::new(&s.inp, &s.out, &s.probes)
}

/// The model's reset state and its first `n` edges on the stimulus of `profile` and `seed`.
fn model_steps(chip: Chip, profile: Profile, seed: u64, n: usize) -> (Reset, Vec<Step>) {
    let mut stim = Stimulus::new(chip, profile, seed);
    let mut drv = Driver::default();
    let mut model = Tmc429::new(chip);
    let reset = (model.outputs(), model.probes());
    let steps = (0..n)
        .map(|_| {
            if drv.ready() {
                drv.start(stim.next_txn());
            }
            let inp = drv.step().0;
            let out = model.tick(&inp);
            Step { inp, out, probes: model.probes() }
        })
        .collect();
    (reset, steps)
}

type Reset = (tmc429_model::Outputs, tmc429_model::Probes);

/// `run_pair` on `steps`, handed over `chunk` edges per call, every signal compared.
fn pair_first(chip: Chip, reset: Reset, steps: &[Step], chunk: usize) -> Option<u64> {
    let mut rest = steps.chunks(chunk);
    run_pair(Variant::Chip(chip), Compare::all(), reset, |buf| match rest.next() {
        Some(c) => {
            buf.extend(c.iter().map(expected));
            true
        }
        None => false,
    })
    .unwrap()
}

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
    // batches of an odd size, so that the disagreement falls inside one
    let pair = |v: Vec<Step>, reset| pair_first(chip, reset, &v, 777);
    assert_eq!(pair(steps(None), reset), None);
    assert_eq!(pair(steps(Some(0)), reset), Some(1));
    assert_eq!(pair(steps(Some(12_345)), reset), Some(12_346));
    assert_eq!(pair(steps(Some(19_999)), reset), Some(20_000));
    // a difference masked out is no disagreement
    let mask = Compare::all().without("motor2.x_actual");
    let mut rest = steps(Some(500)).into_iter();
    let masked = run_pair(Variant::Chip(chip), mask, reset, |buf| {
        buf.extend(rest.by_ref().take(1000).map(|s| expected(&s)));
        !buf.is_empty()
    })
    .unwrap();
    assert_eq!(masked, None);
    let mut bad_reset = reset;
    bad_reset.1.status ^= 0x80;
    assert_eq!(pair(steps(None), bad_reset), Some(0));
}

/// Flips the lowest bit of signal `k` (the order of `signals::SIGNALS`).
fn poke(o: &mut tmc429_model::Outputs, p: &mut tmc429_model::Probes, k: usize) {
    let pins = [
        &mut o.nint_sdo_c,
        &mut o.sdoz_c,
        &mut o.sdoz_c_oe,
        &mut o.nscs_s,
        &mut o.sck_s,
        &mut o.sdo_s,
        &mut o.sdi_s_o,
        &mut o.sdi_s_oe,
        &mut o.nscs2,
        &mut o.nscs3,
        &mut o.poscmp,
    ];
    if k < 11 {
        *pins[k] ^= true;
        return;
    }
    if k < 11 + 27 {
        let m = &mut p.motor[(k - 11) / 9];
        match (k - 11) % 9 {
            0 => m.x_target ^= 1,
            1 => m.x_actual ^= 1,
            2 => m.v_internal ^= 1,
            3 => m.v_target ^= 1,
            4 => m.a_actual ^= 1,
            5 => m.ustep ^= 1,
            6 => m.step ^= 1,
            7 => m.dir ^= 1,
            _ => m.pulse_acc ^= 1,
        }
        return;
    }
    let c = &mut p.chain;
    match k {
        38 => c.state ^= 1,
        39 => c.cell ^= 1,
        40 => c.motor ^= 1,
        41 => c.bit_count ^= 1,
        42 => c.pending ^= 1,
        43 => c.cover_waiting ^= 1,
        44 => c.readback ^= 1,
        45 => p.prescaler ^= 1,
        46 => p.power_down ^= 1,
        _ => p.status ^= 1,
    }
}

/// Every compared signal is compared by the two-thread pair (inside the bridge): a one-bit
/// difference in any of them, in a cycle where the comparison counts it (tri-state data only
/// while enabled), is found in that cycle.
#[test]
fn run_pair_compares_every_signal() {
    use tmc429_testbench::signals::{diff, flatten, N_SIGNALS};
    let chip = Chip::Tmc429;
    let (reset, steps) = model_steps(chip, Profile::Drivers, 1, 60_000);
    let mut tested = 0;
    for k in 0..N_SIGNALS {
        // the first cycle from 1000 on in which the flipped bit counts as a difference
        let found = (1000..steps.len()).find_map(|j| {
            let (mut o, mut p) = (steps[j].out, steps[j].probes);
            poke(&mut o, &mut p, k);
            let d = diff(Compare::all(), &flatten(&steps[j].out, &steps[j].probes), &flatten(&o, &p));
            (!d.is_empty()).then_some((j, o, p))
        });
        let Some((j, o, p)) = found else { continue };
        let mut v = steps[..=j].to_vec();
        v[j].out = o;
        v[j].probes = p;
        let first = pair_first(chip, reset, &v, 1000);
        assert_eq!(first, Some(j as u64 + 1), "signal {}", tmc429_testbench::signals::SIGNALS[k].name);
        tested += 1;
    }
    // sdi_s_o counts only while SDI_S is driven (the readback): every other signal is tested
    assert!(tested >= N_SIGNALS - 1, "{tested} of {N_SIGNALS} signals tested");
}

/// The pair compares each signal's bits of its width, as the single-thread loop does
/// (`signals::flatten`: a signed value as its two's complement): a model value that differs
/// from the RTL's only above its port's width agrees, one that differs within it does not.
#[test]
fn run_pair_compares_the_bits_of_each_width() {
    let chip = Chip::Tmc429;
    let (reset, steps) = model_steps(chip, Profile::Motion, 3, 3000);
    type Poke = fn(&mut tmc429_model::Probes);
    let cases: [(Poke, Option<u64>); 8] = [
        (|p| p.motor[1].v_internal += 1 << 20, None),
        (|p| p.motor[1].v_internal ^= 1 << 19, Some(2223)),
        (|p| p.motor[0].a_actual -= 1 << 12, None),
        (|p| p.motor[0].a_actual ^= 1 << 11, Some(2223)),
        (|p| p.motor[2].ustep += 256, None),
        (|p| p.motor[2].ustep ^= 128, Some(2223)),
        (|p| p.motor[0].x_target += 1 << 24, None),
        (|p| p.chain.readback ^= 1 << 47, Some(2223)),
    ];
    for (k, (poke, first)) in cases.into_iter().enumerate() {
        let mut v = steps.clone();
        poke(&mut v[2222].probes);
        assert_eq!(pair_first(chip, reset, &v, 500), first, "case {k}");
    }
}
