//! The datasheet's method for p_mul and p_div (TMC429 §8.1.10.2.3 `pmulpdiv.c`, TMC428 §8.11,
//! §19), reproduced in the same floating-point arithmetic so results agree to the bit.

/// Result of [`calc`]. `p_mul`, `p_div` are −1 when no pair is representable.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PmulPdiv {
    /// p_mul = 128 + pmul (128..255), the value of register bits 15..8.
    pub p_mul: i32,
    /// p_div: the register's pdiv field (0..13).
    pub p_div: i32,
    /// p = a_max / (128·2^(ramp_div − pulse_div)).
    pub p_ideal: f64,
    /// p_mul / 2^(3 + p_div).
    pub p_best: f64,
    /// p reduced by p_reduction.
    pub p_reduced: f64,
    /// a_max_lower_limit = (int) 2^(ramp_div − pulse_div − 1) (TMC428 §8.7.1).
    pub a_max_lower_limit: i64,
    /// a_max_upper_limit = (int) 2^(12 + ramp_div − pulse_div) − 1.
    pub a_max_upper_limit: i64,
}

impl PmulPdiv {
    pub fn valid(&self) -> bool {
        self.p_mul >= 0
    }
    /// The 24-bit data word of the pmul/pdiv register (IDX 9), when valid.
    pub fn register_value(&self) -> Option<u32> {
        self.valid().then_some(((self.p_mul as u32) << 8) | self.p_div as u32)
    }
}

/// `CalcPMulPDiv` of the datasheet: the largest p_div whose p_mul (truncated toward 0) lies in
/// 128..255. `p_reduction` is a C `float` as in the original (promoted to double).
pub fn calc(a_max: i32, ramp_div: i32, pulse_div: i32, p_reduction: f32) -> PmulPdiv {
    let (mut pm, mut pd) = (-1i32, -1i32);
    let scale = 2f64.powi(ramp_div - pulse_div);
    let p_ideal = a_max as f64 / (scale * 128.0);
    let p = a_max as f64 / (128.0 * scale);
    let p_reduced = p * (1.0 - p_reduction as f64);
    for pdiv in 0..=13 {
        let pmul = (p_reduced * 8.0 * 2f64.powi(pdiv)) as i32 - 128;
        if (0..=127).contains(&pmul) {
            pm = pmul + 128;
            pd = pdiv;
        }
    }
    let p_best = pm as f64 / 2f64.powi(pd + 3);
    let e = ramp_div - pulse_div;
    PmulPdiv {
        p_mul: pm,
        p_div: pd,
        p_ideal,
        p_best,
        p_reduced,
        a_max_lower_limit: 2f64.powi(e - 1) as i64,
        a_max_upper_limit: (2f64.powi(12 + e) as i64) - 1,
    }
}
