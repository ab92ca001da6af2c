//! The target-velocity laws of RAMP_MODE and SOFT_MODE (contract C50) read back through v_target
//! after a ramp tick, and SOFT_MODE's approach.

mod common;
use common::*;

use tmc429_model::Chip;

/// p = p_mul/2^(3+pdiv) = 1 with pmul byte $80 (p_mul 128) and pdiv 4.
const P_ONE: u32 = 0x8004;

fn first_tick(rm: u32, dx: u32, v_min: u32, v_max: u32) -> u32 {
    first_tick_with(rm, dx, v_min, v_max, 1, 0, 0)
}

/// v_target after the first ramp tick of a move of `dx` from 0 with a_max, pulse_div and
/// ramp_div given.
fn first_tick_with(rm: u32, dx: u32, v_min: u32, v_max: u32, a_max: u32, pulse_div: u32, ramp_div: u32) -> u32 {
    let mut h = host(Chip::Tmc428);
    motion_setup(&mut h, 0, pulse_div, ramp_div, v_min, v_max, a_max, P_ONE, rm);
    wr(&mut h, 0, X_TARGET, dx);
    // Two frames later a snapshot and a ramp tick have happened (C41).
    h.wait(64);
    rd(&mut h, 0, V_TARGET)
}

#[test]
fn ramp_mode_square_root_law() {
    // (isqrt(Y) − h) >> 2, Y = p_mul·(|dx|−1)·2^12 >> pdiv = 128·299·4096/16 = 9797632,
    // isqrt(Y) = 3130, h = ⌈a_max/128⌉ = 1 (pulse_div = ramp_div): 3129 >> 2 = 782.
    assert_eq!(first_tick(0, 300, 1, 2047), 782);
    // dx = 1 aims at standstill: v_min carries the motor over the last step.
    assert_eq!(first_tick(0, 1, 3, 2047), 3);
    // Clamped to v_max; negative dx gives a negative target.
    assert_eq!(first_tick(0, 100_000, 1, 500), 500);
    assert_eq!(first_tick(0, (-300i32) as u32 & 0xFF_FFFF, 1, 2047), (-782i32) as u32 & 0xFFF);
    // v_min > v_max: the clamp yields v_max (C50).
    assert_eq!(first_tick(0, 1, 40, 20), 20);
}

#[test]
fn ramp_mode_aims_below_by_half_a_ramp_tick_of_deceleration() {
    // a_max 2047: h = ⌈2047/128⌉ = 16, (3130 − 16) >> 2 = 778 (C50).
    assert_eq!(first_tick_with(0, 300, 1, 2047, 2047, 0, 0), 778);
    // ramp_div above pulse_div: the same h.
    assert_eq!(first_tick_with(0, 300, 1, 2047, 2047, 0, 1), 778);
    // ramp_div below pulse_div: the velocity holds less than a pulse tick, h = 0: 3130 >> 2.
    assert_eq!(first_tick_with(0, 300, 1, 2047, 2047, 1, 0), 782);
    // a_max 128: h = 1; a_max 129: h = 2, (3130 − 2) >> 2 = 782.
    assert_eq!(first_tick_with(0, 300, 1, 2047, 129, 0, 0), 782);
    // dx = 2: Y = 32768, isqrt(Y) = 181, a_max 2047: (181 − 16) >> 2 = 41.
    assert_eq!(first_tick_with(0, 2, 1, 2047, 2047, 0, 0), 41);
    // below h the law gives 0 and v_min carries the motor: dx = 2 with p_mul 128, pdiv 13:
    // Y = 128·4096 >> 13 = 64, isqrt(Y) = 8 < h = 16.
    let mut hs = host(Chip::Tmc428);
    motion_setup(&mut hs, 0, 0, 0, 2, 2047, 2047, 0x800D, 0);
    wr(&mut hs, 0, X_TARGET, 2);
    hs.wait(64);
    assert_eq!(rd(&mut hs, 0, V_TARGET), 2);
}

#[test]
fn soft_mode_linear_law() {
    // (p_mul·|dx|) >> (3+pdiv) = 128·300/128 = 300.
    assert_eq!(first_tick(1, 300, 1, 2047), 300);
    assert_eq!(first_tick(1, 5000, 1, 2047), 2047);
    assert_eq!(first_tick(1, 2, 5, 2047), 5, "v_min below");
}

#[test]
fn soft_mode_ends_on_target() {
    let mut h = host(Chip::Tmc428);
    // p by the datasheet method for a_max 100 (p = 100/128 reduced 5 %).
    let p = tmc429_model::pmulpdiv::calc(100, 0, 0, 0.05).register_value().unwrap();
    motion_setup(&mut h, 0, 0, 0, 2, 2047, 100, p, 1);
    wr(&mut h, 0, X_TARGET, 20_000);
    let mut max_x = 0;
    for _ in 0..200 {
        h.wait(20_000);
        max_x = max_x.max(s24(h.chip().motor(0).x_actual));
    }
    assert_eq!(s24(h.chip().motor(0).x_actual), 20_000);
    assert_eq!(max_x, 20_000, "never passed");
    assert_eq!(h.chip().motor(0).v, 0);
}

/// C52: the stop at target is evaluated in motor 0's condition slot (its commit phase 14) and
/// registered. The step onto x_target (in the edge after motor 0's pulse phase 17, C53: phase
/// 18) leaves V as it is up to the
/// next frame's slot; the slot's edge sees the condition and sets stop_hard, V := 0 one edge
/// later, and no further step follows (the next ramp and pulse ticks come after the slot).
#[test]
fn stop_at_target_acts_from_the_condition_slot() {
    let mut h = host(Chip::Tmc428);
    let p = tmc429_model::pmulpdiv::calc(100, 0, 0, 0.05).register_value().unwrap();
    motion_setup(&mut h, 0, 0, 0, 2, 2047, 100, p, 0);
    wr(&mut h, 0, X_TARGET, 3_000);
    let idle = h.pins();
    let c = h.chip_mut();
    let mut edges = 0;
    while c.motor(0).x_actual != 3_000 {
        c.tick(&idle);
        edges += 1;
        assert!(edges < 2_000_000, "the move ends");
    }
    let m = *c.motor(0);
    assert!(
        m.step && c.probes().prescaler & 31 == tmc429_model::PHASE_PULSE[0] + 2,
        "the step onto the target is made in the edge after motor 0's pulse phase (C53)"
    );
    assert!(m.v != 0 && m.v.unsigned_abs() >> 8 <= 2, "arrives at |v| <= v_min = 2, V moving: {}", m.v);
    // phases 19..31 and 0..13 of the next frame: no slot of motor 0, nothing changes
    for _ in (tmc429_model::PHASE_PULSE[0] + 2)..(32 + tmc429_model::PHASE_COMMIT[0]) {
        c.tick(&idle);
        assert!(!c.motor(0).stop_hard);
        assert_eq!(c.motor(0).v, m.v, "V untouched before the slot");
    }
    assert_eq!(c.probes().prescaler & 31, tmc429_model::PHASE_COMMIT[0]);
    c.tick(&idle);
    assert!(c.motor(0).stop_hard, "the condition of the slot (phase 14) is registered");
    assert_eq!(c.motor(0).v, m.v, "V is untouched in the edge that sees the condition");
    c.tick(&idle);
    assert_eq!(c.motor(0).v, 0, "V := 0 one edge later");
    for _ in 0..64 {
        c.tick(&idle);
        assert_eq!(c.motor(0).x_actual, 3_000);
        assert_eq!(c.motor(0).v, 0);
    }
}

/// C51: the ramp tick computes from the old state of its edge; its V and a_actual are stored in
/// the next running edge, the pulse phase, whose pulse tick adds the new |V|>>8 (C53). While the
/// hard stop action holds, a tick stores its a_actual and no V.
#[test]
fn the_ramp_ticks_results_are_stored_in_the_next_edge() {
    use tmc429_model::{motor_regs::Motor, motor_regs::VELOCITY_MODE, ramp};
    let mut m = Motor::reset();
    m.rm = VELOCITY_MODE;
    m.a_max = 1000;
    // |V| >> 8 = 0
    m.v = 255;
    // the ramp tick toward vt = 100 (T = 25600): V + a_max = 1255 and a_actual 1000, not stored
    ramp::edge(&mut m, 100, false, false, true, false, false, false);
    assert_eq!((m.v, m.a_actual), (255, 0));
    // the next edge stores them, and its pulse tick adds |1255| >> 8 = 4 (not 255 >> 8 = 0)
    ramp::edge(&mut m, 100, false, false, false, true, false, false);
    assert_eq!((m.v, m.a_actual, m.acc), (1255, 1000, 4));
    // the hard stop action: V is 0 from the tick's edge on, the tick's a_actual (a_max 500) is
    // stored in the next edge, its V (1755) is not
    m.stop_hard = true;
    m.a_max = 500;
    ramp::edge(&mut m, 100, false, false, true, false, false, false);
    assert_eq!((m.v, m.a_actual), (0, 1000));
    ramp::edge(&mut m, 100, false, false, false, false, false, false);
    assert_eq!((m.v, m.a_actual), (0, 500));
}

/// C53: a pulse tick's carry is a step made in the next running edge, in the direction V had at
/// the pulse tick and with the usrs of the step's own edge; the accumulator takes its new value
/// in the pulse tick.
#[test]
fn the_step_is_made_in_the_edge_after_the_pulse_tick() {
    use tmc429_model::{motor_regs::Motor, ramp};
    let mut m = Motor::reset();
    m.v = -(2047 << 8); // |V| >> 8 = 2047, moving negative
    m.acc = 5; // 5 + 2047 = 2052: one carry, 4 left
    m.ustep = 0x80;
    // the pulse tick: the accumulator's new value, no step yet
    ramp::edge(&mut m, 0, false, false, false, true, false, false);
    assert_eq!(m.acc, 4);
    assert!(!m.step);
    assert_eq!((m.x_actual, m.ustep), (0, 0x80), "x_actual and ustep wait for the next edge");
    // V turns positive and usrs changes before the next edge: the step keeps the pulse tick's
    // direction and takes the new usrs (6: ±1)
    m.v = 1000 << 8;
    m.usrs = 6;
    ramp::edge(&mut m, 0, false, false, false, false, false, false);
    assert!(m.step && m.dir, "the step, negative");
    assert_eq!(m.x_actual, 0xFF_FFFF);
    assert_eq!(m.ustep, 0x7F);
    // one step per carry: the edge after it makes none
    ramp::edge(&mut m, 0, false, false, false, false, false, false);
    assert!(!m.step);
    assert_eq!((m.x_actual, m.ustep), (0xFF_FFFF, 0x7F));
}
