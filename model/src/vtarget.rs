//! The target velocity (`rtl/tmc429_vtarget.v`): each motor's target velocity from its
//! registers, snapshot in the motor's slot of the frame and committed in its lane 14 cycles later
//! (TMC428 §8.7–§8.11, TMC429 §8.1.10; docs/model-contract.md C41, C43, C50).

use crate::motor_regs::*;
use crate::schedule::{lane_of, PHASE_COMMIT, PHASE_SNAPSHOT};
use crate::vroot::{braking_velocity, soft_velocity};

/// |dx| limit of the ramp generator (TMC428 §8.7.1).
pub const DX_LIMIT: u32 = (1 << 19) - 1;

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
                    soft_velocity(p_mul as u32, self.pdiv, adx as u32) as i64
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
