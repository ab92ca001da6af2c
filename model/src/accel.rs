//! The ramp tick's arithmetic (`rtl/tmc429_accel.v`), one unit for the three motors: their ramp
//! ticks fall in different phases of the frame (C41), so it serves the motor whose tick it is.
//! V moves toward the target T = 256·vt (0 while the registered soft stop action holds) by at
//! most a_max and lands on T (TMC428 §8.7, §8.11 "accumulates a_max/256"; docs/model-contract.md
//! C51).

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

/// The ramp tick of a motor with internal velocity `v` (1/256 units), committed target velocity
/// `vt` (integer units), registered soft stop action `stop_soft` (C61) and `a_max`: the new V and
/// a_actual, the change of V (C51).
#[inline]
pub fn tick(v: i32, vt: i32, stop_soft: bool, a_max: u16) -> (i32, i32) {
    let t = if stop_soft { 0 } else { vt * 256 };
    let v_new = approach(v, t, a_max);
    (v_new, v_new - v)
}
