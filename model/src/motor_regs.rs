//! One motor's registers and motion state (`rtl/tmc429_motor_regs.v`, the same unit, with its ramp
//! and pulse generator `ramp.rs`; TMC428 §8, TMC429 §8.1; contract C40–C54, C61–C63).

/// Ramp modes (TMC428 Table 8-3).
pub const RAMP_MODE: u8 = 0;
pub const SOFT_MODE: u8 = 1;
pub const VELOCITY_MODE: u8 = 2;
pub const HOLD_MODE: u8 = 3;

/// ref_conf bits (TMC428 Table 8-4), as stored in [`Motor::ref_conf`] (register bits 11..8).
pub const DISABLE_STOP_L: u8 = 1;
pub const DISABLE_STOP_R: u8 = 2;
pub const SOFT_STOP: u8 = 4;
pub const REF_RNL: u8 = 8;

/// Interrupt bits (TMC428 Table 8-7).
pub const INT_POS_END: u8 = 1;
pub const INT_REF_WRONG: u8 = 2;
pub const INT_REF_MISS: u8 = 4;
pub const INT_STOP: u8 = 8;
pub const INT_STOP_LEFT_LOW: u8 = 16;
pub const INT_STOP_RIGHT_LOW: u8 = 32;
pub const INT_STOP_LEFT_HIGH: u8 = 64;
pub const INT_STOP_RIGHT_HIGH: u8 = 128;

/// Largest magnitude of the internal velocity: 11 integer + 8 fraction bits.
pub const V_MAG_MAX: i32 = (1 << 19) - 1;

pub(crate) const MASK24: u32 = 0xFF_FFFF;

pub use crate::vroot::{braking_velocity, isqrt};
pub use crate::vtarget::DX_LIMIT;

/// Sign-extends a 24-bit value.
#[inline]
pub fn sext24(v: u32) -> i32 {
    ((v << 8) as i32) >> 8
}

/// Sign-extends a 12-bit value.
#[inline]
pub fn sext12(v: u32) -> i32 {
    ((v << 20) as i32) >> 20
}

/// Registers and internal state of one motor. Field names are the datasheet's.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Motor {
    pub x_target: u32,
    pub x_actual: u32,
    pub v_min: u16,
    pub v_max: u16,
    /// 12-bit two's complement register value.
    pub v_target: u16,
    pub a_max: u16,
    /// Velocity change of the last ramp tick (1/256 units).
    pub a_actual: i32,
    pub is_agtat: u8,
    pub is_aleat: u8,
    pub is_v0: u8,
    pub a_threshold: u16,
    /// pmul bits 14..8 (p_mul = 128 + pmul).
    pub pmul: u8,
    pub pdiv: u8,
    /// ref_conf bits 11..8 as [`DISABLE_STOP_L`] etc.
    pub ref_conf: u8,
    pub rm: u8,
    pub lp: bool,
    pub int_mask: u8,
    pub int_flags: u8,
    pub pulse_div: u8,
    pub ramp_div: u8,
    pub usrs: u8,
    pub dx_ref_tolerance: u16,
    pub x_latched: u32,
    /// Full-wave microstep index (ustep_count).
    pub ustep: u8,
    /// Internal velocity V in 1/256 units (sign + 19-bit magnitude).
    pub v: i32,
    /// Target velocity in use (C41, C50), integer units: the last committed snapshot.
    pub vt: i32,
    /// Target velocity of this frame's snapshot, committed to `vt` at the motor's commit phase (C41).
    pub vt_next: i32,
    /// Pulse accumulator (11 bit).
    pub acc: u16,
    /// The last ramp tick's V, stored in the next running edge (C51); none when the tick's V
    /// was not taken (the hard stop action held, or a µC write of V_ACTUAL won).
    pub v_due: Option<i32>,
    /// The last ramp tick's a_actual, stored in the next running edge (C51).
    pub a_due: Option<i32>,
    /// The pulse tick's carry: a step due, made in the next running edge (C53).
    pub step_due: bool,
    /// Its direction, the sign of V at the pulse tick (true = negative).
    pub step_neg: bool,
    /// A step was made in the last cycle.
    pub step: bool,
    /// Direction of the last step (true = negative).
    pub dir: bool,
    /// History flops of the eight interrupt conditions (C63).
    pub cond_prev: u8,
    /// History flop of the reference switch for the latch (C62).
    pub ref_prev: bool,
    /// Registered hard stop action (C52, C61): set from the old state of the last running
    /// cycle when the stop at target or a hard switch stop held; while set, V := 0 and the
    /// pulse tick adds nothing.
    pub stop_hard: bool,
    /// Registered soft stop action (C61): set from the old state of the last running cycle
    /// when a switch stop held with SOFT_STOP; while set, the ramp target T is 0 (C51).
    pub stop_soft: bool,
    /// The conditions taken in the edge before the motor's condition slot, which the slot
    /// applies (C52, C61–C63).
    pub cond_next: Conditions,
}

/// What a motor's condition slot applies, taken from the old state of the edge before the slot
/// (C52, C61–C63): the interrupt conditions (C63), the REF_RnL-selected switch and whether it
/// latches (C62), and the stop actions to register (C52, C61).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Conditions {
    pub cond: u8,
    pub sel: bool,
    /// lp ∧ V_ACTUAL ≠ 0 ∧ the selected switch differs from the last slot's (C62).
    pub latch: bool,
    pub stop_hard: bool,
    pub stop_soft: bool,
}

impl Conditions {
    /// The conditions of the reset state (the history flops' values, C63): no event, no latch,
    /// no stop action.
    pub const RESET: Conditions = Conditions { cond: COND_RESET, sel: false, latch: false, stop_hard: false, stop_soft: false };
}

/// Interrupt conditions of the reset state: POS_END (x_actual = x_target = 0), REF_MISS
/// (x_actual = 0, switch inactive), STOP_LEFT_LOW and STOP_RIGHT_LOW (switches inactive).
pub const COND_RESET: u8 = INT_POS_END | INT_REF_MISS | INT_STOP_LEFT_LOW | INT_STOP_RIGHT_LOW;

impl Motor {
    pub fn reset() -> Self {
        Motor {
            x_target: 0,
            x_actual: 0,
            v_min: 0,
            v_max: 0,
            v_target: 0,
            a_max: 0,
            a_actual: 0,
            is_agtat: 0,
            is_aleat: 0,
            is_v0: 0,
            a_threshold: 0,
            pmul: 0,
            pdiv: 0,
            ref_conf: 0,
            rm: 0,
            lp: false,
            int_mask: 0,
            int_flags: 0,
            pulse_div: 0,
            ramp_div: 0,
            usrs: 0,
            dx_ref_tolerance: 0,
            x_latched: 0,
            ustep: 0,
            v: 0,
            vt: 0,
            vt_next: 0,
            acc: 0,
            v_due: None,
            a_due: None,
            step_due: false,
            step_neg: false,
            step: false,
            dir: false,
            cond_prev: COND_RESET,
            ref_prev: false,
            stop_hard: false,
            stop_soft: false,
            cond_next: Conditions::RESET,
        }
    }

    /// dx = sext24(x_target − x_actual) (C43).
    #[inline]
    pub fn dx(&self) -> i32 {
        sext24(self.x_target.wrapping_sub(self.x_actual) & MASK24)
    }

    /// The v_actual readout: sign(V)·(|V| >> 8) (C42), i.e. V >> 8 plus [`Motor::v_round`].
    #[inline]
    pub fn v_actual(&self) -> i32 {
        (self.v >> 8) + self.v_round() as i32
    }

    /// The rounding of V >> 8 toward 0 in the v_actual readout (C42): a negative V with a
    /// nonzero low byte. The register file hands it to the SPI slave apart from V >> 8.
    #[inline]
    pub fn v_round(&self) -> bool {
        self.v < 0 && self.v & 0xFF != 0
    }

    /// Microstep index increment per step: 2^(6 − usrs), usrs 7 as 6 (C53, contract of part 2).
    #[inline]
    pub fn ustep_increment(&self) -> u8 {
        1 << (6 - self.usrs.min(6))
    }

    /// Makes one step in direction `negative` (C53).
    #[inline]
    pub fn do_step(&mut self, negative: bool) {
        let inc = self.ustep_increment();
        if negative {
            self.x_actual = self.x_actual.wrapping_sub(1) & MASK24;
            self.ustep = self.ustep.wrapping_sub(inc);
        } else {
            self.x_actual = (self.x_actual + 1) & MASK24;
            self.ustep = self.ustep.wrapping_add(inc);
        }
        self.step = true;
        self.dir = negative;
    }
}
