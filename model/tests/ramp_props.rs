//! Property tests of the ramp generator with whole register-write sequences sent through the
//! pins (not random pins): RAMP_MODE moves end exactly on x_target without passing it, within
//! v_max and a_max; VELOCITY_MODE reaches v_target with slope a_max and holds it.

mod common;
use common::*;

use proptest::prelude::*;
use tmc429_model::pmulpdiv;
use tmc429_model::{Chip, Inputs};

/// Cycle budget of one case's ramp, so the suite stays fast.
const BUDGET: u64 = 1_500_000;

#[derive(Clone, Debug)]
struct Move {
    motor: u8,
    pd: u32,
    rd: u32,
    v_min: u32,
    v_max: u32,
    a_max: u32,
    reduction: f32,
    start: i32,
    dx: i32,
}

fn moves() -> impl Strategy<Value = Move> {
    (0u8..3, 0u32..=3, -1i32..=3, 32u32..=2047, prop::bool::ANY)
        .prop_flat_map(|(motor, pd, drd, v_max, five)| {
            let rd = (pd as i32 + drd).max(0) as u32;
            let e = rd as i32 - pd as i32;
            // TMC428 §8.7.1: 2^(rd−pd−1) ≤ a_max ≤ 2^(12+rd−pd) − 1 (lower limit halved for
            // v_max ≤ 2048/√2), and a ramp that fits the budget.
            let mut lo = if e - 1 > 0 { 1u32 << (e - 1) } else { 1 };
            if v_max <= 1448 {
                lo = (lo / 2).max(1);
            }
            let hi = ((1u64 << (12 + e)) - 1).min(2047) as u32;
            let fast = ((v_max as u64 * 256 * (32u64 << rd)).div_ceil(BUDGET / 2)) as u32;
            let lo = lo.max(fast).min(hi);
            let reach = (BUDGET as u64 / 2 * v_max as u64 >> (16 + pd)).max(2) as i32;
            (
                Just(motor),
                Just(pd),
                Just(rd),
                1u32..=4,
                Just(v_max),
                lo..=hi,
                Just(if five { 0.05f32 } else { 0.01 }),
                -100_000i32..100_000,
                1..=reach,
                prop::bool::ANY,
            )
        })
        .prop_map(|(motor, pd, rd, v_min, v_max, a_max, reduction, start, dist, neg)| Move {
            motor,
            pd,
            rd,
            v_min,
            v_max,
            a_max,
            reduction,
            start,
            dx: if neg { -dist } else { dist },
        })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 96, ..ProptestConfig::default() })]

    #[test]
    fn ramp_mode_moves_end_on_target(mv in moves()) {
        let p = pmulpdiv::calc(mv.a_max as i32, mv.rd as i32, mv.pd as i32, mv.reduction);
        prop_assume!(p.valid());
        let mut h = host(Chip::Tmc429);
        let m = mv.motor;
        let target = mv.start + mv.dx;
        wr(&mut h, m, X_ACTUAL, mv.start as u32 & 0xFF_FFFF);
        wr(&mut h, m, X_TARGET, mv.start as u32 & 0xFF_FFFF);
        motion_setup(&mut h, m, mv.pd, mv.rd, mv.v_min, mv.v_max, mv.a_max, p.register_value().unwrap(), 0);
        wr(&mut h, m, X_TARGET, target as u32 & 0xFF_FFFF);

        let idle = Inputs::default();
        let limit = 4 * BUDGET + (3u64 << (16 + mv.pd));
        let c = h.chip_mut();
        let mut v_prev = c.motor(m as usize).v;
        let mut done_at = None;
        for n in 0..limit {
            c.tick(&idle);
            let mo = c.motor(m as usize);
            let x = s24(mo.x_actual);
            let v = mo.v;
            prop_assert!((x - target).signum() != mv.dx.signum(), "passed the target: x {x} target {target} at cycle {n}");
            prop_assert!(mo.v_actual().unsigned_abs() <= mv.v_max, "v {} above v_max {}", mo.v_actual(), mv.v_max);
            if v != v_prev {
                let stop = v == 0 && (v_prev.unsigned_abs() >> 8) <= mv.v_min;
                prop_assert!(stop || (v - v_prev).unsigned_abs() <= mv.a_max, "velocity step {} > a_max {}", v - v_prev, mv.a_max);
                prop_assert!(v.signum() * mv.dx.signum() >= 0, "moved away from the target");
            }
            v_prev = v;
            if x == target && v == 0 {
                done_at = Some(n);
                break;
            }
        }
        prop_assert!(done_at.is_some(), "did not stop on the target within {limit} cycles: x {}", s24(c.motor(m as usize).x_actual));
        // And stays there.
        for _ in 0..(64u64 << mv.rd.max(mv.pd)) {
            c.tick(&idle);
        }
        prop_assert_eq!(s24(c.motor(m as usize).x_actual), target);
        prop_assert_eq!(c.motor(m as usize).v, 0);
    }

    #[test]
    fn velocity_mode_reaches_and_holds(pd in 0u32..=4, rd in 0u32..=5, a_max in 64u32..=2047, v0 in -2047i32..=2047, v1 in -2047i32..=2047) {
        let mut h = host(Chip::Tmc428);
        motion_setup(&mut h, 0, pd, rd, 0, 2047, 2047, 0, 2);
        wr(&mut h, 0, V_TARGET, v0 as u32 & 0xFFF);
        let idle = Inputs::default();
        let tick = 32u64 << rd;
        for _ in 0..(2047 * 256 / 2047 + 4) * tick {
            h.chip_mut().tick(&idle);
        }
        prop_assert_eq!(h.chip().motor(0).v, v0 * 256);
        wr(&mut h, 0, A_MAX, a_max);
        wr(&mut h, 0, V_TARGET, v1 as u32 & 0xFFF);
        let c = h.chip_mut();
        let goal = v1 * 256;
        let mut prev = c.motor(0).v;
        let mut ticks = 0u64;
        let mut last_change = 0u64;
        let need = ((goal - prev).unsigned_abs() as u64).div_ceil(a_max as u64);
        let total = (need + 3) * tick;
        for n in 0..total {
            c.tick(&idle);
            let v = c.motor(0).v;
            if v != prev {
                ticks += 1;
                last_change = n;
                // Slope a_max toward the target, landing exactly on it.
                let expect = if prev < goal { (prev + a_max as i32).min(goal) } else { (prev - a_max as i32).max(goal) };
                prop_assert_eq!(v, expect);
                // Ramp ticks only: V is stored in the edge after the tick's (C51).
                prop_assert_eq!(c.probes().prescaler & 31, tmc429_model::PHASE_RAMP[0] + 2, "change outside the edge after motor 0's ramp phase");
            }
            prev = v;
        }
        prop_assert_eq!(prev, goal);
        prop_assert_eq!(ticks, need);
        let _ = last_change;
        prop_assert_eq!(c.motor(0).v_actual(), v1);
    }
}
