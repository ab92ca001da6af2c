//! One motor's ramp generator and pulse generator (`rtl/tmc429_ramp.v`): switch stop, stop at
//! target, position latch and interrupt conditions in the motor's condition slot, ramp tick and
//! pulse tick (TMC428 §8.6–§8.16, TMC429 §8.1; docs/model-contract.md C42–C44, C51–C54,
//! C61–C63, C3), with its port-level boundary for test vectors.

use crate::accel;
use crate::motor_regs::*;

/// One edge of motor `m`'s ramp and pulse generator from the old state (C1): in the edge before
/// the motor's condition slot (`sample_tick`) the conditions of the switch stop, stop at target,
/// latch and interrupts are taken into registers ([`evaluate`]); in the slot (`cond_tick`, its
/// commit phase, C41) they act ([`conditions`]; the interrupt events are returned, 0 outside the
/// slot); the ramp tick (C51, with `ramp_tick` in any mode; HOLD_MODE makes none), whose V and
/// a_actual are stored in the next running edge, and the pulse tick (C53) under the stop actions
/// of the old state. `vt` is the committed target velocity of the old state (C41), `l` and `r`
/// the motor's switches after mapping (C60). The ramp tick's arithmetic is [`accel::tick`]
/// (`rtl/tmc429_accel.v`, shared by the three motors).
#[inline]
#[allow(clippy::too_many_arguments)]
pub fn edge(m: &mut Motor, vt: i32, sample_tick: bool, cond_tick: bool, ramp_tick: bool, pulse_tick: bool, l: bool, r: bool) -> u8 {
    let v_old = m.v;
    // The stop actions of this edge are the registered conditions of the last slot (C52, C61).
    let (stop_hard, stop_soft) = (m.stop_hard, m.stop_soft);
    let sampled = if sample_tick { Some(evaluate(m, vt, l, r)) } else { None };
    let events = if cond_tick { conditions(m) } else { 0 };
    if let Some(c) = sampled {
        m.cond_next = c;
    }
    // The results of the last ramp tick are stored in the next running edge (C51).
    if let Some(v) = m.v_due.take() {
        m.v = v;
    }
    if let Some(a) = m.a_due.take() {
        m.a_actual = a;
    }
    if ramp_tick && m.rm != HOLD_MODE {
        // The arithmetic is the unit shared by the motors' staggered ticks (C41); its V is not
        // taken while the hard stop action holds.
        let (v_new, a_actual) = accel::tick(v_old, vt, stop_soft, m.a_max);
        m.a_due = Some(a_actual);
        if !stop_hard {
            m.v_due = Some(v_new);
        }
        if m.rm <= SOFT_MODE {
            m.v_target = (vt as u32 & 0xFFF) as u16;
        }
    }
    if stop_hard {
        m.v = 0;
    }
    // The step of the last pulse tick's carry (C53).
    m.step = false;
    if m.step_due {
        m.step_due = false;
        m.do_step(m.step_neg);
    }
    // Pulse tick (C53): V of this edge, with a ramp tick's V stored in it; taken as 0 while the
    // hard stop action holds. A carry is a step due in the next running edge.
    if pulse_tick {
        let v_eff = if stop_hard { 0 } else { m.v };
        let sum = m.acc + (v_eff.unsigned_abs() >> 8) as u16;
        m.acc = sum & 0x7FF;
        if sum > 0x7FF {
            m.step_due = true;
            m.step_neg = v_eff < 0;
        }
    }
    events
}

/// The conditions of motor `m` from its old state, `vt`, `l`, `r` as in [`edge`] (nothing
/// changes): what its condition slot applies when taken in the edge before it (C52, C61–C63).
#[inline]
pub fn evaluate(m: &Motor, vt: i32, l: bool, r: bool) -> Conditions {
    let sel = if m.ref_conf & REF_RNL != 0 { r } else { l };
    // The tolerance window masks the stop of both switches (C61).
    let (tol_ok, stop) = switch_stop(m.x_actual, m.v, vt, m.ref_conf, m.dx_ref_tolerance, l, r);
    let soft = m.ref_conf & SOFT_STOP != 0;
    let at_target = m.x_actual == m.x_target;
    let stop_at_target = m.rm <= SOFT_MODE && at_target && (m.v.unsigned_abs() >> 8) <= m.v_min as u32;
    let cond = ((at_target as u8) * INT_POS_END)
        | (((sel && !tol_ok) as u8) * INT_REF_WRONG)
        | (((m.x_actual == 0 && !sel) as u8) * INT_REF_MISS)
        | ((stop as u8) * INT_STOP)
        | ((!l as u8) * INT_STOP_LEFT_LOW)
        | ((!r as u8) * INT_STOP_RIGHT_LOW)
        | ((l as u8) * INT_STOP_LEFT_HIGH)
        | ((r as u8) * INT_STOP_RIGHT_HIGH);
    // Latch (C62): "takes effect only during motion (when V_ACTUAL ≠ 0)".
    let latch = m.lp && m.v_actual() != 0 && sel != m.ref_prev;
    Conditions { cond, sel, latch, stop_hard: stop_at_target || (stop && !soft), stop_soft: stop && soft }
}

/// Whether the edge before motor `m`'s condition slot would take the conditions it holds
/// already (nothing changes).
#[inline]
pub fn sample_settled(m: &Motor, vt: i32, l: bool, r: bool) -> bool {
    evaluate(m, vt, l, r) == m.cond_next
}

/// Whether motor `m`'s condition slot would change nothing: the conditions taken before it are
/// those the last slot registered (no event, no latch, the same stop actions).
#[inline]
pub fn settled(m: &Motor) -> bool {
    let c = m.cond_next;
    !c.latch && c.cond == m.cond_prev && c.sel == m.ref_prev && c.stop_hard == m.stop_hard && c.stop_soft == m.stop_soft
}

/// Motor `m`'s condition slot (C52, C61–C63), from the conditions taken in the edge before it:
/// the interrupt conditions' rising edges against the last slot's (C63, returned), the latch
/// (C62: x_latched := x_actual of the slot's old state) and the stop actions registered for
/// the edges up to the next slot (C52, C61).
#[inline]
pub fn conditions(m: &mut Motor) -> u8 {
    let c = m.cond_next;
    let events = c.cond & !m.cond_prev;
    m.cond_prev = c.cond;
    if c.latch {
        m.x_latched = m.x_actual;
        m.lp = false;
    }
    m.ref_prev = c.sel;
    m.stop_hard = c.stop_hard;
    m.stop_soft = c.stop_soft;
    events
}

/// The switch-stop condition (C61) and the tolerance window: `(tol_ok, stop)` for the left and
/// right switch levels `l`, `r`, position `x_actual`, internal velocity `v`, committed target
/// velocity `vt`, `ref_conf` and `dx_ref_tolerance`. stop_L = ¬DISABLE_STOP_L ∧ L ∧ moving
/// negative ∧ ¬tol_ok, stop_R symmetric; tol_ok = |x_actual| < dx_ref_tolerance. The window
/// masks both switches: DX_REF_TOLERANCE "disables automatic stopping by a switch around the
/// origin" (TMC429 §8.1.14) and REF_RnL "has no effect on the stop function" (§8.1.11.2).
#[inline]
pub fn switch_stop(x_actual: u32, v: i32, vt: i32, ref_conf: u8, dx_ref_tolerance: u16, l: bool, r: bool) -> (bool, bool) {
    let tol_ok = sext24(x_actual).unsigned_abs() < dx_ref_tolerance as u32;
    let moving_neg = v < 0 || (v == 0 && vt < 0);
    let moving_pos = v > 0 || (v == 0 && vt > 0);
    let stop_l = ref_conf & DISABLE_STOP_L == 0 && l && moving_neg && !tol_ok;
    let stop_r = ref_conf & DISABLE_STOP_R == 0 && r && moving_pos && !tol_ok;
    (tol_ok, stop_l || stop_r)
}

/// The inputs of one motor's ramp and pulse generator at its RTL boundary (`tmc429_ramp`,
/// rtl/README.md "The ramp unit"): levels of the old state, presented before a CLK edge.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct RampInputs {
    /// The motion core runs (not powered down, C66).
    pub run: bool,
    /// The next edge is the motor's condition slot: this edge takes the conditions the slot
    /// applies (C52; phase 7·m + 13, or while powered down the slot's phase itself).
    pub sample_tick: bool,
    /// The motor's condition slot, its commit phase 7·m + 14 of every frame (C41, C52, C61–C63).
    pub cond_tick: bool,
    /// The motor's ramp phase 7·m + 16 of a frame F with F mod 2^ramp_div = 2^ramp_div − 1 (C40,
    /// C41); any ramp mode.
    pub ramp_tick: bool,
    /// The motor's pulse phase 7·m + 17 of a frame F with F mod 2^pulse_div = 2^pulse_div − 1
    /// (C41, C53).
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
