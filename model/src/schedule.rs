//! The frame schedule (`rtl/tmc429_schedule.v`, the same unit): the pre-divider counter C, its
//! phase and frame, and the slots of the 32-cycle frame in which the
//! target velocities are snapshot and committed and the ramp and pulse ticks fall (TMC428 §8.7,
//! §8.13; TMC429 §8.1.7; docs/model-contract.md C40, C41).

use crate::motor_regs::Motor;

/// Width of the pre-divider counter C (C40): 5 phase bits + 15 frame bits cover every
/// pulse_div and ramp_div.
pub const PRESCALER_BITS: u32 = 20;
pub(crate) const PRESCALER_MASK: u32 = (1 << PRESCALER_BITS) - 1;

/// Phases of the 32-cycle frame (C41), motor m's lane 7·m after motor 0's: target snapshot,
/// commit of that target (also the condition slot of the switch stop, stop at target, latch and
/// interrupts, C52, C61–C63), ramp tick, pulse tick.
pub const PHASE_SNAPSHOT: [u32; 3] = [0, 7, 14];
pub const PHASE_COMMIT: [u32; 3] = [14, 21, 28];
pub const PHASE_RAMP: [u32; 3] = [16, 23, 30];
pub const PHASE_PULSE: [u32; 3] = [17, 24, 31];
/// The phase of the edge in which the Step/Dir unit takes motor m's step (C95): the motor steps
/// in the edge after its pulse tick (C53), and its step flag, the old state of the edge after
/// that, is read there. A pulse, space or DIR set-up lasts 16·(1 + STPDIV) edges (C93, C94), so
/// each change of the motor's Step/Dir state falls at this phase or 16 after it, and the RTL's
/// one Step/Dir unit serves the motors in turn in those slots (`rtl/tmc429_stepdir.v`).
pub const PHASE_STEPDIR: [u32; 3] = [(PHASE_PULSE[0] + 2) % 32, (PHASE_PULSE[1] + 2) % 32, (PHASE_PULSE[2] + 2) % 32];
/// The phase before each condition slot: the edge that takes the slot's conditions (C52).
pub const PHASE_SAMPLE: [u32; 3] = [PHASE_COMMIT[0] - 1, PHASE_COMMIT[1] - 1, PHASE_COMMIT[2] - 1];

/// The phases in which some motor's snapshot, commit, ramp tick or pulse tick falls or its
/// condition slot's conditions are taken, bit p = phase p: in the other phases the motion core
/// only follows its switches and writes.
pub const SLOT_PHASES: u32 =
    lane_mask(&PHASE_SNAPSHOT) | lane_mask(&PHASE_COMMIT) | lane_mask(&PHASE_RAMP) | lane_mask(&PHASE_PULSE) | lane_mask(&PHASE_SAMPLE);

const fn lane_mask(p: &[u32; 3]) -> u32 {
    1 << p[0] | 1 << p[1] | 1 << p[2]
}

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

/// The edge of `c` is motor `m`'s condition slot: its commit phase, in every frame (C41, C52,
/// C61–C63).
#[inline]
pub fn cond_tick(c: u32, m: usize) -> bool {
    phase(c) == PHASE_COMMIT[m]
}

/// The edge that leaves the pre-divider at `c_next` takes motor `m`'s conditions for its
/// condition slot (C52): the edge before the slot, also while powered down (the slot's conditions
/// are those of the old state of the edge before it, whatever that edge did).
#[inline]
pub fn sample_tick(c_next: u32, m: usize) -> bool {
    cond_tick(c_next, m)
}

/// The edge of `c` is a ramp tick of motor `m` with `ramp_div` (its ramp phase of a due frame).
#[inline]
pub fn ramp_tick(c: u32, m: usize, ramp_div: u8) -> bool {
    phase(c) == PHASE_RAMP[m] && due(c, ramp_div)
}

/// The edge of `c` is a pulse tick of motor `m` with `pulse_div` (its pulse phase of a due
/// frame).
#[inline]
pub fn pulse_tick(c: u32, m: usize, pulse_div: u8) -> bool {
    phase(c) == PHASE_PULSE[m] && due(c, pulse_div)
}

/// The motor whose lane has `phase` as its slot in `lane` (one of the `PHASE_*` arrays).
#[inline]
pub fn lane_of(lane: &[u32; 3], phase: u32) -> Option<usize> {
    // Three comparisons written out: with a constant lane they are three immediates.
    if lane[0] == phase {
        Some(0)
    } else if lane[1] == phase {
        Some(1)
    } else if lane[2] == phase {
        Some(2)
    } else {
        None
    }
}

/// The ramp ticks of the edge of `c`, bit m = motor m (at most one motor per edge).
#[inline]
pub fn ramp_ticks(c: u32, motors: &[Motor; 3]) -> u8 {
    match lane_of(&PHASE_RAMP, phase(c)) {
        Some(m) => (due(c, motors[m].ramp_div) as u8) << m,
        None => 0,
    }
}

/// The pre-divider after one running edge.
#[inline]
pub fn next(c: u32) -> u32 {
    (c + 1) & PRESCALER_MASK
}
