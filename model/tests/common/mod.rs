//! Helpers shared by the model's integration tests: register writes go through the pins.
#![allow(dead_code)]

use tmc429_model::host::Host;
use tmc429_model::regmap::{global_a7, motor_a7};
use tmc429_model::Chip;

pub mod frames;
pub mod rtl;

pub use tmc429_model::regmap::idx::*;
/// Short name of idx::CURRENT_SCALING.
pub const CURRENT: u8 = CURRENT_SCALING;
/// Short name of idx::DX_REF_TOLERANCE.
pub const DX_REF_TOL: u8 = DX_REF_TOLERANCE;

pub fn host(chip: Chip) -> Host {
    Host::new(chip)
}

pub fn wr(h: &mut Host, m: u8, idx: u8, data: u32) {
    h.write(motor_a7(m, idx), data);
}

pub fn rd(h: &mut Host, m: u8, idx: u8) -> u32 {
    h.read(motor_a7(m, idx))
}

pub fn wrg(h: &mut Host, jdx: u8, data: u32) {
    h.write(global_a7(jdx), data);
}

pub fn rdg(h: &mut Host, jdx: u8) -> u32 {
    h.read(global_a7(jdx))
}

/// Sign-extends a 24-bit register value.
pub fn s24(v: u32) -> i32 {
    ((v << 8) as i32) >> 8
}

/// Sign-extends a 12-bit register value.
pub fn s12(v: u32) -> i32 {
    ((v << 20) as i32) >> 20
}

/// Configures motor `m` for motion: dividers, v_min/v_max, a_max and pmul/pdiv, ramp mode.
pub fn motion_setup(h: &mut Host, m: u8, pulse_div: u32, ramp_div: u32, v_min: u32, v_max: u32, a_max: u32, pmul_pdiv: u32, rm: u32) {
    wr(h, m, CLK_CONFIG, pulse_div << 12 | ramp_div << 8);
    wr(h, m, V_MIN, v_min);
    wr(h, m, V_MAX, v_max);
    wr(h, m, A_MAX, a_max);
    wr(h, m, PMUL_PDIV, pmul_pdiv);
    wr(h, m, REF_CONF_RM, rm);
}

/// Replays the pins of `trace` (pins, outputs and probes of each cycle from reset) through
/// `Tmc429::skip_quiet` where the pins hold, with limits that cut some stretches short, and
/// through `tick_changes` elsewhere: the edges it runs must be exactly those `tick_changes`
/// reports as quiet, and the chip after them as in the trace. The first difference, if any.
pub fn replay_skip_quiet(chip: Chip, trace: &[(tmc429_model::Inputs, tmc429_model::Outputs, tmc429_model::Probes)]) -> Result<(), String> {
    use tmc429_model::{sync, Tmc429};
    let pins: Vec<u16> = trace.iter().map(|(i, _, _)| sync::pack(i)).collect();
    let mut one = Tmc429::new(chip);
    let quiet: Vec<bool> = pins.iter().map(|&p| one.tick_changes(p).is_none()).collect();
    let mut bulk = Tmc429::new(chip);
    let mut n = 0;
    while n < trace.len() {
        let held = pins[n..].iter().take_while(|&&p| p == pins[n]).count() as u64;
        let max = held.min(1 + (n as u64 * 7919) % 61);
        let run = quiet[n..].iter().take(max as usize).take_while(|&&q| q).count() as u64;
        let ran = bulk.skip_quiet(pins[n], max);
        if ran != run {
            return Err(format!("{chip}: skip_quiet ran {ran} edges from cycle {n}, tick_changes has {run} quiet"));
        }
        if ran == 0 {
            bulk.tick_changes(pins[n]);
            n += 1;
        } else {
            n += ran as usize;
        }
        let (_, o, pr) = &trace[n - 1];
        if bulk.outputs() != *o || bulk.probes() != *pr || bulk.cycle() != n as u64 {
            return Err(format!("{chip}: outputs or probes differ at cycle {}", n - 1));
        }
    }
    Ok(())
}
