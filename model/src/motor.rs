//! One motor's registers and motion state: ramp generator and pulse generator
//! (TMC428 §8, TMC429 §8.1; contract C40–C54, C61–C63).

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
/// |dx| limit of the ramp generator (TMC428 §8.7.1).
pub const DX_LIMIT: u32 = (1 << 19) - 1;

const MASK24: u32 = 0xFF_FFFF;

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
    /// Target velocity of this frame's snapshot, committed to `vt` at phase 29 (C41).
    pub vt_next: i32,
    /// Pulse accumulator (11 bit).
    pub acc: u16,
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
            step: false,
            dir: false,
            cond_prev: COND_RESET,
            ref_prev: false,
            stop_hard: false,
            stop_soft: false,
        }
    }

    /// dx = sext24(x_target − x_actual) (C43).
    #[inline]
    pub fn dx(&self) -> i32 {
        sext24(self.x_target.wrapping_sub(self.x_actual) & MASK24)
    }

    /// The v_actual readout: sign(V)·(|V| >> 8) (C42).
    #[inline]
    pub fn v_actual(&self) -> i32 {
        if self.v < 0 {
            -((-self.v) >> 8)
        } else {
            self.v >> 8
        }
    }

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
                    isqrt((p_mul * (adx - 1)) << 8 >> self.pdiv) as i64
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

    /// V after a ramp tick toward target T (1/256 units), a_max per tick (C51).
    #[inline]
    pub fn approach(v: i32, t: i32, a_max: u16) -> i32 {
        let a = a_max as i32;
        if v < t {
            (v + a).min(t)
        } else {
            (v - a).max(t)
        }
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

/// The switch-stop condition (C61) and the tolerance window: `(tol_ok, stop)` for the left and
/// right switch levels `l`, `r`, position `x_actual`, internal velocity `v`, committed target
/// velocity `vt`, `ref_conf` and `dx_ref_tolerance`. stop_L = ¬DISABLE_STOP_L ∧ L ∧ moving
/// negative ∧ (REF_RnL ∨ ¬tol_ok), stop_R symmetric; the tolerance window masks only the
/// REF_RnL-selected switch; tol_ok = |x_actual| < dx_ref_tolerance.
#[inline]
pub fn switch_stop(x_actual: u32, v: i32, vt: i32, ref_conf: u8, dx_ref_tolerance: u16, l: bool, r: bool) -> (bool, bool) {
    let tol_ok = sext24(x_actual).unsigned_abs() < dx_ref_tolerance as u32;
    let rnl = ref_conf & REF_RNL != 0;
    let moving_neg = v < 0 || (v == 0 && vt < 0);
    let moving_pos = v > 0 || (v == 0 && vt > 0);
    let stop_l = ref_conf & DISABLE_STOP_L == 0 && l && moving_neg && (rnl || !tol_ok);
    let stop_r = ref_conf & DISABLE_STOP_R == 0 && r && moving_pos && (!rnl || !tol_ok);
    (tol_ok, stop_l || stop_r)
}

/// The inputs of one motor's ramp and pulse generator at its RTL boundary (`tmc429_ramp`,
/// rtl/README.md "The ramp unit"): levels of the old state, presented before a CLK edge.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct RampInputs {
    /// The motion core runs (not powered down, C66).
    pub run: bool,
    /// Phase 30 of a frame F with F mod 2^ramp_div = 2^ramp_div − 1 (C40, C41); any ramp mode.
    pub ramp_tick: bool,
    /// Phase 31 of a frame F with F mod 2^pulse_div = 2^pulse_div − 1 (C53).
    pub pulse_tick: bool,
    pub rm: u8,
    pub x_target: u32,
    pub v_min: u16,
    pub a_max: u16,
    /// [`DISABLE_STOP_L`], [`DISABLE_STOP_R`], [`SOFT_STOP`], [`REF_RNL`].
    pub ref_conf: u8,
    pub usrs: u8,
    pub dx_ref_tolerance: u16,
    /// Committed target velocity (C41), integer units.
    pub vt: i32,
    /// Left and right switch after mapping (C60).
    pub sw_l: bool,
    pub sw_r: bool,
    /// A µC write to this motor's register `widx` executes in this edge (C12).
    pub we: bool,
    pub widx: u8,
    pub wdata: u32,
}

/// The outputs of the ramp unit: its registers after an edge, and the conditions of those
/// registers with the edge's inputs `RampInputs` (what the RTL's combinational outputs show
/// while that line's inputs are applied).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct RampPorts {
    pub x_actual: u32,
    /// Internal velocity V, 20-bit two's complement (1/256 units).
    pub v: u32,
    pub v_target: u16,
    /// a_actual, 12-bit two's complement (C25).
    pub a_actual: u16,
    pub ustep: u8,
    pub acc: u16,
    pub step: bool,
    pub dir: bool,
    pub x_latched: u32,
    pub lp: bool,
    /// x_actual = x_target.
    pub xeqt: bool,
    /// Switch-stop condition ([`switch_stop`], C61, C63).
    pub stop: bool,
    /// |x_actual| < dx_ref_tolerance.
    pub tol_ok: bool,
    /// v_actual readout sign(V)·(|V| >> 8), 12-bit two's complement (C42).
    pub v_actual: u16,
}

/// The ramp unit's outputs for the motor state `m` (after an edge) and the inputs `i` of that
/// edge ([`RampPorts`]).
pub fn ramp_ports(m: &Motor, i: &RampInputs) -> RampPorts {
    let (tol_ok, stop) = switch_stop(m.x_actual, m.v, i.vt, i.ref_conf, i.dx_ref_tolerance, i.sw_l, i.sw_r);
    RampPorts {
        x_actual: m.x_actual & MASK24,
        v: (m.v as u32) & 0xF_FFFF,
        v_target: m.v_target & 0xFFF,
        a_actual: (m.a_actual as u32 & 0xFFF) as u16,
        ustep: m.ustep,
        acc: m.acc & 0x7FF,
        step: m.step,
        dir: m.dir,
        x_latched: m.x_latched & MASK24,
        lp: m.lp,
        xeqt: m.x_actual == i.x_target,
        stop,
        tol_ok,
        v_actual: (m.v_actual() as u32 & 0xFFF) as u16,
    }
}
