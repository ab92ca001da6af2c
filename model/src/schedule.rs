//! The frame schedule (the pre-divider and tick logic of `rtl/tmc429_regfile.v`): the
//! pre-divider counter C, its phase and frame, and the slots of the 32-cycle frame in which the
//! target velocities are snapshot and committed and the ramp and pulse ticks fall (TMC428 §8.7,
//! §8.13; TMC429 §8.1.7; docs/model-contract.md C40, C41).

use crate::motor::Motor;

/// Width of the pre-divider counter C (C40): 5 phase bits + 15 frame bits cover every
/// pulse_div and ramp_div.
pub const PRESCALER_BITS: u32 = 20;
pub(crate) const PRESCALER_MASK: u32 = (1 << PRESCALER_BITS) - 1;

/// Phases of the 32-cycle frame (C41): target snapshot of motor m, commit of all targets,
/// ramp tick, pulse tick.
pub const PHASE_SNAPSHOT: [u32; 3] = [0, 7, 14];
pub const PHASE_COMMIT: u32 = 29;
pub const PHASE_RAMP: u32 = 30;
pub const PHASE_PULSE: u32 = 31;

/// The phase of the pre-divider value `c`: its low 5 bits.
#[inline]
pub fn phase(c: u32) -> u32 {
    c & 31
}

/// The frame of `c` is one whose divider `div` ticks: F mod 2^div = 2^div − 1 (C40).
#[inline]
pub fn due(c: u32, div: u8) -> bool {
    let mask = (1u32 << div) - 1;
    (c >> 5) & mask == mask
}

/// The edge of `c` is a ramp tick of a motor with `ramp_div` (phase 30 of a due frame).
#[inline]
pub fn ramp_tick(c: u32, ramp_div: u8) -> bool {
    phase(c) == PHASE_RAMP && due(c, ramp_div)
}

/// The edge of `c` is a pulse tick of a motor with `pulse_div` (phase 31 of a due frame).
#[inline]
pub fn pulse_tick(c: u32, pulse_div: u8) -> bool {
    phase(c) == PHASE_PULSE && due(c, pulse_div)
}

/// The ramp ticks of the edge of `c`, bit m = motor m.
#[inline]
pub fn ramp_ticks(c: u32, motors: &[Motor; 3]) -> u8 {
    if phase(c) != PHASE_RAMP {
        return 0;
    }
    motors.iter().enumerate().fold(0, |t, (m, mo)| t | (due(c, mo.ramp_div) as u8) << m)
}

/// The pre-divider after one running edge.
#[inline]
pub fn next(c: u32) -> u32 {
    (c + 1) & PRESCALER_MASK
}
