//! The target velocity (`rtl/tmc429_vtarget.v`): each motor's target velocity from its
//! registers, snapshot in the motor's slot of the frame and committed for all motors at once
//! (TMC428 §8.7–§8.11, TMC429 §8.1.10; docs/model-contract.md C41, C43, C50).

use crate::motor_regs::*;
use crate::schedule::{lane_of, PHASE_COMMIT, PHASE_SNAPSHOT};

/// |dx| limit of the ramp generator (TMC428 §8.7.1).
pub const DX_LIMIT: u32 = (1 << 19) - 1;

/// Integer square root (floor).
#[inline]
pub fn isqrt(n: u64) -> u64 {
    if n == 0 {
        return 0;
    }
    let mut r = (n as f64).sqrt() as u64;
    while r * r > n {
        r -= 1;
    }
    while (r + 1) * (r + 1) <= n {
        r += 1;
    }
    r
}

/// The RAMP_MODE braking law (C50): the largest velocity from which the motor still comes
/// down to v_min without passing the target, `(isqrt(Y) − h) >> 2` (0 below h) with
/// Y = (p_mul·(|dx|−1)·2^12) >> pdiv and h = ⌈a_max/128⌉ when ramp_div ≥ pulse_div, else 0.
///
/// √Y is 4·√(2048·p·(|dx|−1)), p = p_mul/2^(3+pdiv) (TMC429 §8.1.10): 4 times the velocity from which
/// the continuous deceleration p stands for ends at rest one step before the target (the step
/// of margin is the pulse accumulator's phase). The chip's velocity changes only at ramp
/// ticks, by a = a_max/256 each (TMC429 §8.1.10.2), and holds for the 2^(ramp_div −
/// pulse_div) pulse ticks between them; braking from v in those steps covers up to
/// (v + a/2)²/(2048·p) steps, so the law aims a/2 lower: isqrt(Y) is that velocity to a
/// quarter, and h = ⌈a_max/128⌉ is 4·a/2 rounded up. With ramp_div < pulse_div no correction
/// is needed (h = 0: the law is isqrt(Y >> 4)). `adx` is |dx| limited to 2^19 − 1 (C43), ≥ 1.
pub fn braking_velocity(p_mul: u32, pdiv: u8, adx: u32, a_max: u16, pulse_div: u8, ramp_div: u8) -> u32 {
    let y = ((p_mul as u64) * (adx as u64 - 1)) << 12 >> pdiv;
    let h = if ramp_div >= pulse_div { (a_max as u32).div_ceil(128) } else { 0 };
    (isqrt(y) as u32).saturating_sub(h) >> 2
}

impl Motor {
    /// Target velocity of the current mode (C50), from the current state.
    pub fn target_velocity(&self) -> i32 {
        let p_mul = 128 + (self.pmul & 0x7F) as u64;
        let v_min = self.v_min as i64;
        let v_max = self.v_max as i64;
        let clamp = |v: i64| -> i64 { v.max(v_min).min(v_max) };
        match self.rm {
            RAMP_MODE | SOFT_MODE => {
                let dx = self.dx();
                if dx == 0 {
                    return 0;
                }
                let adx = (dx.unsigned_abs()).min(DX_LIMIT) as u64;
                let mag = if self.rm == RAMP_MODE {
                    braking_velocity(p_mul as u32, self.pdiv, adx as u32, self.a_max, self.pulse_div, self.ramp_div) as i64
                } else {
                    ((p_mul * adx) >> (3 + self.pdiv as u32)) as i64
                };
                let v = clamp(mag) as i32;
                if dx < 0 {
                    -v
                } else {
                    v
                }
            }
            VELOCITY_MODE => {
                let vt = sext12(self.v_target as u32).max(-2047);
                let mag = (vt.unsigned_abs() as i64).min(v_max) as i32;
                if vt < 0 {
                    -mag
                } else {
                    mag
                }
            }
            _ => 0,
        }
    }
}

/// The target-velocity edge of motor `m` (slot `slot`) at `phase` (C41): the snapshot at its
/// phase computes `vt_next` from the old state; its commit makes it the `vt` the ramp and pulse
/// generator use from the next edge on.
#[inline]
pub(crate) fn edge(m: &mut Motor, slot: usize, phase: u32) {
    if phase == PHASE_SNAPSHOT[slot] {
        m.vt_next = m.target_velocity();
    }
    if phase == PHASE_COMMIT[slot] {
        m.vt = m.vt_next;
    }
}

/// The target-velocity edge of the `n` motors at `phase` changes nothing: no snapshot gives a
/// new target, no commit a new `vt`.
#[inline]
pub(crate) fn quiet(motors: &[Motor; 3], n: usize, phase: u32) -> bool {
    let commit = match lane_of(&PHASE_COMMIT, phase) {
        Some(i) if i < n => motors[i].vt_next == motors[i].vt,
        _ => true,
    };
    commit
        && match lane_of(&PHASE_SNAPSHOT, phase) {
            Some(i) if i < n => motors[i].target_velocity() == motors[i].vt_next,
            _ => true,
        }
}
