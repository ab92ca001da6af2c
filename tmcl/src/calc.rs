//! pmul/pdiv for the module's a_max and dividers (TMC429 datasheet method, spec digest §5.5).

/// p reduction the module applies (the TMC429 datasheet recommends about 1 %).
pub const P_REDUCTION: f64 = 0.01;

/// Returns (p_mul, pdiv) for the register (p_mul includes bit 7), or `None` when no pdiv
/// 0..13 can represent p.
pub fn pmul_pdiv(a_max: i32, ramp_div: i32, pulse_div: i32) -> Option<(u8, u8)> {
    if !(0..=2047).contains(&a_max) || !(0..=13).contains(&ramp_div) || !(0..=13).contains(&pulse_div) {
        return None;
    }
    let r = tmc429_model_pmulpdiv(a_max as u32, ramp_div as u32, pulse_div as u32, P_REDUCTION);
    r
}

fn tmc429_model_pmulpdiv(a_max: u32, rd: u32, pd: u32, red: f64) -> Option<(u8, u8)> {
    let p = a_max as f64 / (128.0 * 2f64.powi(rd as i32 - pd as i32));
    let p_red = p * (1.0 - red);
    let mut best = None;
    for pdiv in 0..=13u32 {
        let pmul = (p_red * 8.0 * 2f64.powi(pdiv as i32)) as i64 - 128;
        if (0..=127).contains(&pmul) {
            best = Some(((pmul + 128) as u8, pdiv as u8));
        }
    }
    best
}
