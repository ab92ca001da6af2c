//! pmul/pdiv for the module's a_max and dividers, by the datasheet's method
//! (TMC429 §8.1.10.2.3 `pmulpdiv.c`, reproduced in `tmc429_model::pmulpdiv`).

/// p reduction the module applies (the TMC429 datasheet recommends about 1 %).
pub const P_REDUCTION: f32 = 0.01;

/// Returns (p_mul, pdiv) for the register (p_mul includes bit 7), or `None` when no pdiv
/// 0..13 can represent p.
pub fn pmul_pdiv(a_max: i32, ramp_div: i32, pulse_div: i32) -> Option<(u8, u8)> {
    if !(1..=2047).contains(&a_max) || !(0..=13).contains(&ramp_div) || !(0..=13).contains(&pulse_div) {
        return None;
    }
    let r = tmc429_model::pmulpdiv::calc(a_max, ramp_div, pulse_div, P_REDUCTION);
    r.valid().then_some((r.p_mul as u8, r.p_div as u8))
}
