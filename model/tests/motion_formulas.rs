//! TMC428 §8.14 (TMC429 §8.1.13) formulas measured on the running model: step rate R, velocity
//! slope ΔR, acceleration distance S.

mod common;
use common::*;

use tmc429_model::{Chip, Inputs};

const FCLK: f64 = 16e6;

fn run(h: &mut tmc429_model::host::Host, cycles: u64) {
    let idle = Inputs::default();
    let c = h.chip_mut();
    for _ in 0..cycles {
        c.tick(&idle);
    }
}

/// Runs until motor 0's v_actual equals `v` (at most `limit` cycles); returns the cycles taken.
fn run_until_velocity(h: &mut tmc429_model::host::Host, v: i32, limit: u64) -> u64 {
    let idle = Inputs::default();
    let c = h.chip_mut();
    for n in 0..limit {
        if c.motor(0).v_actual() == v {
            return n;
        }
        c.tick(&idle);
    }
    panic!("velocity {v} not reached in {limit} cycles (at {})", c.motor(0).v_actual());
}

/// R[Hz] = fCLK·v/(2^pulse_div·2048·32): the steps counted over a window in VELOCITY_MODE match
/// within one step, for several pulse_div and velocities.
#[test]
fn velocity_mode_step_rate() {
    for pd in [0u32, 1, 3, 5] {
        for v in [1i32, 7, 100, 1000, 2047, -1000, -2047] {
            let mut h = host(Chip::Tmc428);
            motion_setup(&mut h, 0, pd, 0, 0, 2047, 2047, 0, 2);
            wr(&mut h, 0, V_TARGET, (v as u32) & 0xFFF);
            run_until_velocity(&mut h, v, 1 << 20);
            let window: u64 = 32 * 2048 * (1 << pd) * 4;
            let x0 = s24(h.chip().motor(0).x_actual);
            run(&mut h, window);
            let x1 = s24(h.chip().motor(0).x_actual);
            let r = FCLK * v as f64 / ((1u64 << pd) as f64 * 2048.0 * 32.0);
            let expected = r * window as f64 / FCLK;
            let got = (x1 - x0) as f64;
            assert!((got - expected).abs() <= 1.0, "pd {pd} v {v}: {got} steps, R predicts {expected}");
        }
    }
}

/// TMC429 §8.1.13.1: R at 16 MHz for (pd 0, v 2047), (pd 0, v 1), (pd 7, v 1000), measured.
#[test]
fn step_rate_examples() {
    for (pd, v, hz) in [(0u32, 2047i32, 499755.86), (0, 1, 244.14), (7, 1000, 1907.35)] {
        let mut h = host(Chip::Tmc428);
        motion_setup(&mut h, 0, pd, 0, 0, 2047, 2047, 0, 2);
        wr(&mut h, 0, V_TARGET, v as u32);
        run_until_velocity(&mut h, v, 1 << 20);
        let window = 16_000_000u64 / 4; // 0.25 s
        let x0 = s24(h.chip().motor(0).x_actual);
        run(&mut h, window);
        let steps = (s24(h.chip().motor(0).x_actual) - x0) as f64;
        assert!((steps * 4.0 - hz).abs() <= 4.0, "pd {pd} v {v}: {} Hz vs {hz}", steps * 4.0);
    }
}

/// ΔR[Hz/s] = fCLK²·a_max/2^(pulse_div+ramp_div+29): the velocity grows by a_max/256 per ramp
/// tick of 32·2^ramp_div CLK.
#[test]
fn velocity_slope() {
    for (pd, rd, a_max) in [(0u32, 0u32, 1000u32), (7, 7, 1000), (2, 4, 37), (3, 1, 2047)] {
        let mut h = host(Chip::Tmc428);
        motion_setup(&mut h, 0, pd, rd, 0, 2047, a_max, 0, 2);
        wr(&mut h, 0, V_TARGET, 2047);
        let tick = 32u64 << rd;
        // Align to a frame start, then measure over many ramp ticks.
        run(&mut h, tick * 3);
        let v0 = h.chip().motor(0).v;
        let ticks = (2047 * 256 / a_max as u64 / 2).min(2000);
        run(&mut h, tick * ticks);
        let v1 = h.chip().motor(0).v;
        assert_eq!((v1 - v0) as u64, a_max as u64 * ticks, "pd {pd} rd {rd} a_max {a_max}");
        // The same in Hz/s.
        let dr_measured = ((v1 - v0) as f64 / 256.0) * FCLK / ((1u64 << pd) as f64 * 65536.0) / ((tick * ticks) as f64 / FCLK);
        let dr = FCLK * FCLK * a_max as f64 / 2f64.powi((pd + rd + 29) as i32);
        assert!((dr_measured / dr - 1.0).abs() < 1e-9, "{dr_measured} vs {dr}");
    }
}

/// TMC429 §8.1.13.1: ΔR at 16 MHz, a_max 1000: 476837158.2 Hz/s (pd = rd = 0), 29103.83 Hz/s (7, 7).
#[test]
fn velocity_slope_examples() {
    let dr = |pd: i32, rd: i32| FCLK * FCLK * 1000.0 / 2f64.powi(pd + rd + 29);
    assert!((dr(0, 0) - 476837158.2).abs() < 0.1);
    assert!((dr(7, 7) - 29103.83).abs() < 0.01);
}

/// S = ½·v²/a_max·2^ramp_div/2^pulse_div/2^3 steps to accelerate from 0 to v. The discrete ramp
/// differs by at most v·2^ramp_div/2^(11+pulse_div) + 1 steps, and the pulse generator, which adds
/// the 11 integer bits of V (contract C53), loses less than one velocity unit: at most 2S/v steps.
#[test]
fn acceleration_distance() {
    for (v, a_max, pd, rd) in [(1000i32, 100u32, 7u32, 7u32), (2047, 1000, 0, 0), (500, 20, 2, 5), (1500, 2047, 4, 3)] {
        let mut h = host(Chip::Tmc428);
        motion_setup(&mut h, 0, pd, rd, 0, v as u32, a_max, 0, 2);
        wr(&mut h, 0, V_TARGET, v as u32);
        let x0 = s24(h.chip().motor(0).x_actual);
        run_until_velocity(&mut h, v, 1 << 32);
        let steps = (s24(h.chip().motor(0).x_actual) - x0) as f64;
        let s = 0.5 * (v as f64).powi(2) / a_max as f64 * 2f64.powi(rd as i32) / 2f64.powi(pd as i32) / 8.0;
        let tol = v as f64 * 2f64.powi(rd as i32 - 11 - pd as i32) + 1.0;
        assert!(steps <= s + tol && steps >= s - tol - 2.0 * s / v as f64, "v {v} a {a_max} pd {pd} rd {rd}: {steps} steps, S = {s}");
    }
    // TMC429 §8.1.13.2: v 1000, a_max 100, rd = pd = 7 → 625 steps.
    assert_eq!(0.5 * 1000f64.powi(2) / 100.0 / 8.0, 625.0);
}
