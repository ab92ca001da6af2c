//! Physical units on the TMC429 (TMC429 §8.1.13.1, §8.1.7.1.1): a velocity register value v
//! steps at R = fCLK·v / 2^(pulse_div+16) microsteps per second (pps), an acceleration a_max
//! changes R by fCLK²·a_max / 2^(pulse_div+ramp_div+29) pps². The TMCM-1311 personality takes
//! pps and pps² and picks the dividers with these functions.

/// Largest velocity and acceleration register values (11 bits).
const REG_MAX: i64 = 2047;
/// Largest pulse_div / ramp_div.
const DIV_MAX: u8 = 13;

/// Microstep rate [pps] of velocity register value `v` at `pulse_div`.
pub fn pps_of(fclk: u64, v: i32, pulse_div: u8) -> f64 {
    fclk as f64 * v as f64 / 2f64.powi(pulse_div as i32 + 16)
}

/// The velocity register value nearest to `pps` at `pulse_div`.
pub fn v_of(fclk: u64, pps: i64, pulse_div: u8) -> i64 {
    (pps as f64 * 2f64.powi(pulse_div as i32 + 16) / fclk as f64).round() as i64
}

/// The fastest rate the TMC429 steps at (v = 2047, pulse_div 0) [pps, rounded down].
pub fn max_pps(fclk: u64) -> i64 {
    pps_of(fclk, REG_MAX as i32, 0).floor() as i64
}

/// The largest (finest) pulse_div whose velocity register holds `pps`, or `None` when it is
/// faster than [`max_pps`].
pub fn pulse_div_for(fclk: u64, pps: i64) -> Option<u8> {
    if pps.abs() > max_pps(fclk) {
        return None;
    }
    (0..=DIV_MAX).rev().find(|&pd| v_of(fclk, pps.abs(), pd) <= REG_MAX)
}

/// Acceleration [pps²] of `a_max` with the dividers.
pub fn pps2_of(fclk: u64, a_max: i32, pulse_div: u8, ramp_div: u8) -> f64 {
    let f = fclk as f64;
    f * f * a_max as f64 / 2f64.powi((pulse_div + ramp_div) as i32 + 29)
}

/// ramp_div and a_max for an acceleration of `pps2` at `pulse_div` with velocity register
/// `v_max`: the largest (finest) ramp_div whose a_max lies in 1..2047 and within
/// A_MAX_LOWER_LIMIT .. A_MAX_UPPER_LIMIT (TMC429 §8.1.7.1.1), with a p_mul/p_div pair
/// (`crate::calc`). `None` when no ramp_div qualifies.
pub fn ramp_for(fclk: u64, pps2: i64, pulse_div: u8, v_max: i64) -> Option<(u8, i32)> {
    let f = fclk as f64;
    (0..=DIV_MAX).rev().find_map(|rd| {
        let a = (pps2 as f64 * 2f64.powi((pulse_div + rd) as i32 + 29) / (f * f)).round() as i64;
        let e = rd as i32 - pulse_div as i32;
        let lower = if e - 1 <= 0 { 1 } else { (1i64 << (e - 1)) / if v_max <= 1448 { 2 } else { 1 } };
        let upper = if e + 12 <= 0 { 0 } else { (1i64 << (e + 12)) - 1 };
        let fits = (1..=REG_MAX).contains(&a) && a >= lower.max(1) && a <= upper;
        (fits && crate::calc::pmul_pdiv(a as i32, rd as i32, pulse_div as i32).is_some()).then_some((rd, a as i32))
    })
}

/// The dividers and a_max for running up to `pps` at `pps2`: the finest pulse_div that holds
/// `pps` and, with it, a ramp_div for the acceleration ([`ramp_for`]); a coarser pulse_div
/// when the acceleration is too high for the finer one. `None` when no pair qualifies.
pub fn dividers(fclk: u64, pps: i64, pps2: i64) -> Option<(u8, u8, i32)> {
    let finest = pulse_div_for(fclk, pps)?;
    (0..=finest).rev().find_map(|pd| ramp_for(fclk, pps2, pd, v_of(fclk, pps.abs(), pd)).map(|(rd, a)| (pd, rd, a)))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// TMC429 §8.1.13.1 at 16 MHz: v 2047 at pulse_div 0 is 499 755.9 pps, v 1 is 244.14 pps.
    #[test]
    fn rates_at_16_mhz() {
        let f = 16_000_000;
        assert_eq!(max_pps(f), 499_755);
        assert_eq!((pps_of(f, 1, 0) * 100.0).round(), 24414.0);
        // 50 000 pps: v = 50000·2^19/16e6 = 1638.4 → pulse_div 3, v 1638.
        assert_eq!(pulse_div_for(f, 50_000), Some(3));
        assert_eq!(v_of(f, 50_000, 3), 1638);
        assert_eq!(pulse_div_for(f, 499_756), None);
        assert_eq!(pulse_div_for(f, 1), Some(13));
    }

    /// The acceleration round trip stays within half an a_max step; a value below the
    /// datasheet's lower limit at that pulse_div has no ramp_div.
    #[test]
    fn ramp_divisor_choice() {
        let f = 16_000_000;
        let (rd, a) = ramp_for(f, 50_000, 3, 1638).unwrap();
        let back = pps2_of(f, a, 3, rd);
        let step = pps2_of(f, 1, 3, rd);
        assert!((back - 50_000.0).abs() <= step / 2.0, "{rd} {a} {back}");
        assert_eq!(ramp_for(f, 100, 3, 1638), None);
        // At rest (0 pps) a high acceleration takes a coarser pulse_div than 13.
        assert_eq!(ramp_for(f, 51_200, 13, 0), None);
        let (pd, rd, a) = dividers(f, 0, 51_200).unwrap();
        assert!(pd < 13 && ramp_for(f, 51_200, pd, 0) == Some((rd, a)));
    }
}
