//! The magnitude of the target velocity before its clamp (`rtl/tmc429_vroot.v`, stage B of the
//! target-velocity unit): RAMP_MODE's braking law through the integer square root, SOFT_MODE's
//! proportional law (TMC428 §8.7–§8.10, TMC429 §8.1.10; docs/model-contract.md C50). The unit's
//! mode selection, clamp and sign are [`crate::vtarget`].

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

/// The SOFT_MODE law (C50): `(p_mul·|dx|) >> (3 + pdiv)`, `adx` = |dx| limited to 2^19 − 1 (C43).
pub fn soft_velocity(p_mul: u32, pdiv: u8, adx: u32) -> u64 {
    ((p_mul as u64) * (adx as u64)) >> (3 + pdiv as u32)
}
