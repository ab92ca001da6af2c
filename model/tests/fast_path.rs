//! The fast paths of `Tmc429::tick` change nothing: a chip with them and one without, fed the
//! same pins, agree on every output and probe in every cycle; and an edge `Tmc429::tick_changes`
//! reports as quiet changes no pin, no INT and no probe but the pre-divider.

mod common;
use common::*;

use std::sync::{Arc, Mutex};

use proptest::prelude::*;
use tmc429_model::pmulpdiv;
use tmc429_model::{Chip, Inputs, Outputs, Probes, Tmc429};

#[derive(Clone, Debug)]
enum Op {
    Write(u8, u8, u32),
    Wait(u64),
    Refs(bool, bool, bool),
}

fn ops() -> impl Strategy<Value = Vec<Op>> {
    let op = prop_oneof![
        (0u8..3, 0u8..16, any::<u32>()).prop_map(|(m, i, d)| Op::Write(m, i, d & 0xFF_FFFF)),
        (0u8..3, prop::sample::select(vec![0u8, 1, 3, 4, 6, 10, 12]), 0u32..4096).prop_map(|(m, i, d)| Op::Write(m, i, d)),
        (1u64..20_000).prop_map(Op::Wait),
        (any::<bool>(), any::<bool>(), any::<bool>()).prop_map(|(a, b, c)| Op::Refs(a, b, c)),
    ];
    prop::collection::vec(op, 1..40)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, ..ProptestConfig::default() })]
    #[test]
    fn fast_path_is_exact(chip in prop::sample::select(Chip::ALL.to_vec()), ops in ops()) {
        let trace = motion_trace(chip, &ops);
        let mut slow = Tmc429::new(chip);
        slow.set_fast_path(false);
        // The same pins packed, through `tick_changes`: `None` only for an edge that changes no
        // pin, no INT and no probe but the pre-divider.
        let mut packed = Tmc429::new(chip);
        let (mut last, mut last_probes) = (packed.outputs(), packed.probes());
        let mut quiet = 0;
        for (n, (i, o, pr)) in trace.iter().enumerate() {
            let so = slow.tick(i);
            prop_assert_eq!(so, *o, "outputs differ at cycle {}", n);
            prop_assert_eq!(slow.probes(), *pr, "probes differ at cycle {}", n);
            let int_before = packed.int();
            match packed.tick_changes(tmc429_model::sync::pack(i)) {
                Some(po) => prop_assert_eq!(po, so, "tick_changes outputs differ at cycle {}", n),
                None => {
                    quiet += 1;
                    prop_assert_eq!(packed.outputs(), last, "a quiet edge changed a pin at cycle {}", n);
                    prop_assert_eq!(packed.int(), int_before, "a quiet edge changed INT at cycle {}", n);
                    let mut p = packed.probes();
                    p.prescaler = last_probes.prescaler;
                    prop_assert_eq!(p, last_probes, "a quiet edge changed a probe at cycle {}", n);
                }
            }
            prop_assert_eq!(packed.probes(), *pr, "tick_changes probes differ at cycle {}", n);
            (last, last_probes) = (packed.outputs(), packed.probes());
        }
        prop_assert!(quiet > 0, "no quiet edge in {} cycles", trace.len());
    }

    /// `Tmc429::skip_quiet` runs exactly the edges for which `tick_changes` says `None`, up to
    /// its limit, and leaves the chip as those edges one by one do.
    #[test]
    fn skip_quiet_runs_the_fast_paths_edges(chip in prop::sample::select(Chip::ALL.to_vec()), ops in ops()) {
        let trace = motion_trace(chip, &ops);
        prop_assert_eq!(replay_skip_quiet(chip, &trace), Ok(()));
    }
}

/// A TMC4210 at rest in HOLD_MODE with its pins held has nothing to do in any edge (C41: no
/// ramp tick in HOLD_MODE, no pulse tick adds at V = 0): `skip_quiet` runs every edge asked
/// for, and the chip is then as after the same edges one by one.
#[test]
fn skip_quiet_runs_a_chip_at_rest() {
    let mut h = host(Chip::Tmc4210);
    wr(&mut h, 0, REF_CONF_RM, 3);
    h.wait(100);
    let pins = tmc429_model::sync::pack(h.pins_mut());
    let (mut bulk, mut one) = (h.chip().clone(), h.chip().clone());
    assert_eq!(bulk.skip_quiet(pins, 100_000), 100_000);
    for _ in 0..100_000 {
        assert_eq!(one.tick_changes(pins), None, "an edge at rest changes something at cycle {}", one.cycle());
    }
    assert_eq!((bulk.cycle(), bulk.probes(), bulk.outputs()), (one.cycle(), one.probes(), one.outputs()));
}

/// The chip's pins, outputs and probes in every cycle of a run that sets the three axes moving
/// and then applies `ops`.
fn motion_trace(chip: Chip, ops: &[Op]) -> Vec<(Inputs, Outputs, Probes)> {
    let trace: Arc<Mutex<Vec<(Inputs, Outputs, Probes)>>> = Arc::default();
    let mut h = host(chip);
    let t = trace.clone();
    h.set_observer(Box::new(move |c: &Tmc429, i: &Inputs, o: &Outputs| t.lock().unwrap().push((*i, *o, c.probes()))));
    // Moving axes to begin with.
    let p = pmulpdiv::calc(500, 2, 1, 0.01).register_value().unwrap();
    for m in 0..3 {
        motion_setup(&mut h, m, 1, 2, 1, 1500, 500, p, 0);
        wr(&mut h, m, X_TARGET, 3000 * (m as u32 + 1));
    }
    for op in ops {
        match *op {
            Op::Write(m, i, d) => wr(&mut h, m, i, d),
            Op::Wait(n) => h.wait(n),
            Op::Refs(a, b, c) => {
                let p = h.pins_mut();
                p.ref1 = a;
                p.ref2 = b;
                p.ref3 = c;
            }
        }
    }
    drop(h);
    Arc::try_unwrap(trace).unwrap().into_inner().unwrap()
}

/// The position-compare flag raises INT without touching the motors; the nINT pin follows one
/// edge later (C11, C65) on the fast path as well.
#[test]
fn fast_path_registers_a_position_compare_int() {
    let trace: Arc<Mutex<Vec<(Inputs, Outputs, Probes)>>> = Arc::default();
    let mut h = host(Chip::Tmc429);
    let t = trace.clone();
    h.set_observer(Box::new(move |c: &Tmc429, i: &Inputs, o: &Outputs| t.lock().unwrap().push((*i, *o, c.probes()))));
    h.write(tmc429_model::regmap::global_a7(5), 5); // pos_comp 5: no match at x_actual 0
    h.write(tmc429_model::regmap::global_a7(6), 0x100); // M = 1
    h.write(tmc429_model::regmap::global_a7(5), 0); // match: I set, INT
    h.wait(200);
    assert!(!h.outputs().nint_sdo_c, "nINT low after the position compare event");
    let mut slow = Tmc429::new(Chip::Tmc429);
    slow.set_fast_path(false);
    for (n, (i, o, pr)) in trace.lock().unwrap().iter().enumerate() {
        assert_eq!(slow.tick(i), *o, "outputs differ at cycle {n}");
        assert_eq!(slow.probes(), *pr, "probes differ at cycle {n}");
    }
}

/// A ramp tick at rest after the is_v0 delay still selects is_v0 once is_agtat and is_aleat
/// become > 0 (TMC429 §8.1.9 footnote *2, C75): the fast path must not skip it. Every motor in
/// HOLD_MODE, so that the ramp ticks between µC writes are fast-path candidates.
#[test]
fn fast_path_keeps_the_rest_current_selection() {
    let trace: Arc<Mutex<Vec<(Inputs, [u8; 3])>>> = Arc::default();
    let mut h = host(Chip::Tmc429);
    let t = trace.clone();
    h.set_observer(Box::new(move |c: &Tmc429, i: &Inputs, _o: &Outputs| {
        t.lock().unwrap().push((*i, [0, 1, 2].map(|m| c.current_scale(m).sel)))
    }));
    for m in 0..3 {
        wr(&mut h, m, REF_CONF_RM, 3);
        wr(&mut h, m, CURRENT, 1 << 12); // is_v0 only: is_aleat stays selected
    }
    h.wait(10_000);
    wr(&mut h, 0, CURRENT, 7 << 20 | 7 << 16 | 1 << 12);
    h.wait(1_000);
    assert_eq!(h.chip().current_scale(0).sel, tmc429_model::current::SEL_V0);
    let mut slow = Tmc429::new(Chip::Tmc429);
    slow.set_fast_path(false);
    for (n, (i, sel)) in trace.lock().unwrap().iter().enumerate() {
        slow.tick(i);
        assert_eq!([0, 1, 2].map(|m| slow.current_scale(m).sel), *sel, "selection differs at cycle {n}");
    }
}
