//! Physical units of the motion registers and the unit calculator behind `tmc429 calc`
//! (TMC429 §8.1.13, §8.1.10.2.3, §8.1.7.1.1, TMC428 §8.14).
//!
//! - step rate `R[Hz] = fCLK · velocity / (2^pulse_div · 2048 · 32)` (TMC429 §8.1.13.1);
//! - its change `ΔR[Hz/s] = fCLK² · a_max / 2^(pulse_div + ramp_div + 29)`;
//! - steps of a linear ramp `S = ½ · v² / a_max · 2^ramp_div / 2^pulse_div / 2^3` (§8.1.13.2);
//! - a_max limits (TMC429 §8.1.7.1.1) and p_mul/p_div by the datasheet's `pmulpdiv.c`
//!   ([`tmc429_model::pmulpdiv`]).

use tmc429_model::pmulpdiv::{self, PmulPdiv};

/// Largest velocity and acceleration register values (11 bits).
pub const V_REG_MAX: u32 = 2047;
pub const A_REG_MAX: u32 = 2047;
/// Largest pulse_div / ramp_div the datasheet defines (division by 8192).
pub const DIV_MAX: u32 = 13;
/// V_MAX at or below which the a_max lower limit halves: 2048/√2 (TMC429 §8.1.7.1.1).
pub const V_MAX_HALF_LIMIT: u32 = 1448;

/// Step (microstep) rate in Hz of a velocity register value (TMC429 §8.1.13.1).
pub fn step_rate_hz(fclk: f64, velocity: f64, pulse_div: u32) -> f64 {
    fclk * velocity / (2f64.powi(pulse_div as i32) * 2048.0 * 32.0)
}

/// Change of the step rate in Hz/s of an acceleration value (TMC429 §8.1.13.1; 2^29 =
/// 32·32·256·2048).
pub fn accel_hz_per_s(fclk: f64, a: f64, pulse_div: u32, ramp_div: u32) -> f64 {
    fclk * fclk * a / 2f64.powi((pulse_div + ramp_div + 29) as i32)
}

/// Steps of a linear ramp from 0 to `v` (or braking from `v` to 0) at `a_max`
/// (TMC429 §8.1.13.2).
pub fn ramp_steps(v: f64, a_max: f64, pulse_div: u32, ramp_div: u32) -> f64 {
    0.5 * v * v / a_max * 2f64.powi(ramp_div as i32) / 2f64.powi(pulse_div as i32) / 8.0
}

/// A_MAX_LOWER_LIMIT = 2^(ramp_div − pulse_div − 1); 1 when the exponent is ≤ 0; half of it
/// with v_max ≤ 1448 (TMC429 §8.1.7.1.1).
pub fn a_max_lower_limit(ramp_div: u32, pulse_div: u32, v_max: u32) -> u32 {
    let e = ramp_div as i32 - pulse_div as i32 - 1;
    if e <= 0 {
        return 1;
    }
    let l = 1u32 << e;
    if v_max <= V_MAX_HALF_LIMIT {
        (l / 2).max(1)
    } else {
        l
    }
}

/// A_MAX_UPPER_LIMIT = 2^(ramp_div − pulse_div + 12) − 1 (TMC429 §8.1.7.1.1); a_max may take
/// any value up to 2047 when it exceeds that.
pub fn a_max_upper_limit(ramp_div: u32, pulse_div: u32) -> u64 {
    let e = ramp_div as i32 - pulse_div as i32 + 12;
    if e <= 0 {
        0
    } else {
        (1u64 << e) - 1
    }
}

/// Register values of one motion profile with everything derived from them.
#[derive(Clone, Debug, PartialEq)]
pub struct Profile {
    pub fclk: f64,
    /// Microsteps per full step (2^usrs in SPI mode, the driver's setting in Step/Dir mode).
    pub microsteps: u32,
    pub pulse_div: u32,
    pub ramp_div: u32,
    pub v_max: u32,
    pub a_max: u32,
    /// p_mul/p_div by the datasheet's method with this reduction.
    pub p_reduction: f32,
    pub pmul: PmulPdiv,
}

impl Profile {
    /// Microstep rate at v_max [Hz].
    pub fn rate_hz(&self) -> f64 {
        step_rate_hz(self.fclk, self.v_max as f64, self.pulse_div)
    }
    /// Full-step rate at v_max [Hz].
    pub fn fullstep_rate_hz(&self) -> f64 {
        self.rate_hz() / self.microsteps as f64
    }
    /// Microstep acceleration [Hz/s].
    pub fn accel_hz_per_s(&self) -> f64 {
        accel_hz_per_s(self.fclk, self.a_max as f64, self.pulse_div, self.ramp_div)
    }
    /// Full-step acceleration [Hz/s].
    pub fn fullstep_accel_hz_per_s(&self) -> f64 {
        self.accel_hz_per_s() / self.microsteps as f64
    }
    /// Microsteps to brake from v_max to 0 (= to accelerate from 0 to v_max).
    pub fn braking_steps(&self) -> f64 {
        if self.a_max == 0 {
            return f64::INFINITY;
        }
        ramp_steps(self.v_max as f64, self.a_max as f64, self.pulse_div, self.ramp_div)
    }
    /// Time to reach v_max from rest [s].
    pub fn ramp_time_s(&self) -> f64 {
        self.rate_hz() / self.accel_hz_per_s()
    }
    pub fn lower_limit(&self) -> u32 {
        a_max_lower_limit(self.ramp_div, self.pulse_div, self.v_max)
    }
    pub fn upper_limit(&self) -> u64 {
        a_max_upper_limit(self.ramp_div, self.pulse_div)
    }
    /// Problems with the a_max limits and p_mul/p_div, in words (empty when there are none).
    pub fn warnings(&self) -> Vec<String> {
        let mut w = Vec::new();
        if self.a_max == 0 {
            w.push("a_max = 0: the motor cannot change its velocity (TMC429 §8.1.7)".into());
            return w;
        }
        if self.a_max < self.lower_limit() {
            w.push(format!(
                "a_max {} is below A_MAX_LOWER_LIMIT {}: targets may be reached with oscillations (TMC429 §8.1.7.1.1)",
                self.a_max,
                self.lower_limit()
            ));
        }
        if self.a_max as u64 > self.upper_limit() {
            w.push(format!("a_max {} is above A_MAX_UPPER_LIMIT {} (TMC429 §8.1.7.1.1)", self.a_max, self.upper_limit()));
        }
        if !self.pmul.valid() {
            w.push(format!(
                "no p_mul/p_div represents p = {} (0 ≤ pmul ≤ 127 for some pdiv 0..13): RAMP and SOFT mode cannot brake",
                self.pmul.p_ideal
            ));
        }
        w
    }
}

/// From register values (the reverse direction of `tmc429 calc`).
pub fn from_registers(
    fclk: f64,
    microsteps: u32,
    pulse_div: u32,
    ramp_div: u32,
    v_max: u32,
    a_max: u32,
    p_reduction: f32,
) -> Result<Profile, String> {
    check_div("pulse_div", pulse_div)?;
    check_div("ramp_div", ramp_div)?;
    if v_max > V_REG_MAX {
        return Err(format!("v_max {v_max} out of range 0..2047"));
    }
    if a_max > A_REG_MAX {
        return Err(format!("a_max {a_max} out of range 0..2047"));
    }
    check_microsteps(microsteps)?;
    let pmul = pmulpdiv::calc(a_max as i32, ramp_div as i32, pulse_div as i32, p_reduction);
    Ok(Profile { fclk, microsteps, pulse_div, ramp_div, v_max, a_max, p_reduction, pmul })
}

fn check_div(name: &str, v: u32) -> Result<(), String> {
    if v > DIV_MAX {
        return Err(format!("{name} {v} out of range 0..13"));
    }
    Ok(())
}

fn check_microsteps(m: u32) -> Result<(), String> {
    if m == 0 || m > 256 {
        return Err(format!("microsteps {m} out of range 1..256"));
    }
    Ok(())
}

/// The forward direction of `tmc429 calc`: registers for a full-step rate [Hz] and a
/// full-step acceleration [Hz/s].
///
/// Method: pulse_div is the largest (finest velocity resolution) for which v_max =
/// round(R · 2^pulse_div · 2^16 / fCLK) fits 11 bits; ramp_div the largest (finest
/// acceleration resolution) for which a_max = round(ΔR · 2^(pulse_div + ramp_div + 29) / fCLK²)
/// fits 11 bits and lies within the a_max limits; then p_mul/p_div by the datasheet's
/// `pmulpdiv.c` with `p_reduction`.
pub fn solve(fclk: f64, microsteps: u32, fullstep_hz: f64, fullstep_accel: f64, p_reduction: f32) -> Result<Profile, String> {
    check_microsteps(microsteps)?;
    if !(fullstep_hz > 0.0 && fullstep_hz.is_finite()) {
        return Err(format!("speed {fullstep_hz} Hz: expected a positive number"));
    }
    if !(fullstep_accel > 0.0 && fullstep_accel.is_finite()) {
        return Err(format!("acceleration {fullstep_accel} Hz/s: expected a positive number"));
    }
    let r = fullstep_hz * microsteps as f64;
    let dr = fullstep_accel * microsteps as f64;
    let v_of = |pd: u32| (r * 2f64.powi(pd as i32) * 65536.0 / fclk).round();
    let Some(pulse_div) = (0..=DIV_MAX).rev().find(|&pd| v_of(pd) <= V_REG_MAX as f64) else {
        return Err(format!(
            "{r:.2} Hz (microsteps) is faster than the chip can step at fCLK {fclk} Hz: at most {:.2} Hz (v = 2047, pulse_div 0)",
            step_rate_hz(fclk, 2047.0, 0)
        ));
    };
    let v_max = v_of(pulse_div) as u32;
    if v_max == 0 {
        return Err(format!(
            "{r:.4} Hz (microsteps) is slower than the slowest rate at fCLK {fclk} Hz: {:.4} Hz (v = 1, pulse_div 13)",
            step_rate_hz(fclk, 1.0, DIV_MAX)
        ));
    }
    let a_of = |rd: u32| (dr * 2f64.powi((pulse_div + rd + 29) as i32) / (fclk * fclk)).round();
    let mut last_err = String::new();
    for rd in (0..=DIV_MAX).rev() {
        let a = a_of(rd);
        if a > A_REG_MAX as f64 || a < 1.0 {
            continue;
        }
        let a = a as u32;
        if a < a_max_lower_limit(rd, pulse_div, v_max) {
            last_err = format!(
                "with pulse_div {pulse_div}, ramp_div {rd} the acceleration needs a_max {a}, below A_MAX_LOWER_LIMIT {}",
                a_max_lower_limit(rd, pulse_div, v_max)
            );
            continue;
        }
        if a as u64 > a_max_upper_limit(rd, pulse_div) {
            last_err = format!(
                "with pulse_div {pulse_div}, ramp_div {rd} the acceleration needs a_max {a}, above A_MAX_UPPER_LIMIT {}",
                a_max_upper_limit(rd, pulse_div)
            );
            continue;
        }
        return from_registers(fclk, microsteps, pulse_div, rd, v_max, a, p_reduction);
    }
    if last_err.is_empty() {
        last_err = format!("no ramp_div 0..13 gives a_max in 1..2047 for {dr:.2} Hz/s (microsteps) with pulse_div {pulse_div}");
    }
    Err(last_err)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn r2(x: f64) -> f64 {
        (x * 100.0).round() / 100.0
    }

    /// TMC429 §8.1.13.1–§8.1.13.2: R, ΔR and S at 16 MHz.
    #[test]
    fn formula_vectors() {
        let f = 16e6;
        assert_eq!(r2(step_rate_hz(f, 2047.0, 0)), 499755.86);
        assert_eq!(r2(step_rate_hz(f, 1.0, 0)), 244.14);
        assert_eq!(r2(step_rate_hz(f, 1000.0, 7)), 1907.35);
        assert_eq!((accel_hz_per_s(f, 1000.0, 0, 0) * 10.0).round() / 10.0, 476837158.2);
        assert_eq!(r2(accel_hz_per_s(f, 1000.0, 7, 7)), 29103.83);
        assert_eq!(ramp_steps(1000.0, 100.0, 7, 7), 625.0);
    }

    /// TMC429 §8.1.7.1.1: a_max limits.
    #[test]
    fn a_max_limits() {
        assert_eq!(a_max_lower_limit(5, 0, 2047), 16);
        assert_eq!(a_max_lower_limit(1, 0, 2047), 1);
        assert_eq!(a_max_lower_limit(0, 0, 2047), 1);
        assert_eq!(a_max_lower_limit(5, 0, 1448), 8);
        assert_eq!(a_max_upper_limit(5, 0), 131071);
        assert_eq!(a_max_upper_limit(0, 1), 2047);
        assert_eq!(a_max_upper_limit(0, 3), 511);
        // consistency: S(v_max = 2047, a = 16, rd − pd = 5) ≤ 2^19, S(1448) is half of 2^19
        assert_eq!(ramp_steps(2047.0, 16.0, 0, 5), 523776.125);
        assert_eq!(ramp_steps(1448.0, 16.0, 0, 5).floor(), 262088.0);
    }

    #[test]
    fn reverse_and_forward_agree() {
        let p = from_registers(16e6, 1, 7, 7, 1000, 100, 0.05).unwrap();
        assert_eq!(r2(p.rate_hz()), 1907.35);
        assert_eq!(p.braking_steps(), 625.0);
        assert_eq!((p.pmul.p_mul, p.pmul.p_div), (189, 5));
        assert!(p.warnings().is_empty());
        // forward from the rate and acceleration of those registers: the finest resolution that
        // fits is one divider step further, with the same rate and acceleration exactly
        let q = solve(16e6, 1, p.rate_hz(), p.accel_hz_per_s(), 0.05).unwrap();
        assert_eq!((q.pulse_div, q.ramp_div, q.v_max, q.a_max), (8, 10, 2000, 1600));
        assert_eq!(q.rate_hz(), p.rate_hz());
        assert_eq!(q.accel_hz_per_s(), p.accel_hz_per_s());
    }

    #[test]
    fn forward_errors() {
        assert!(solve(16e6, 1, 600_000.0, 1000.0, 0.01).unwrap_err().contains("faster than the chip"));
        assert!(solve(16e6, 1, 0.001, 1000.0, 0.01).unwrap_err().contains("slower than the slowest"));
        assert!(solve(16e6, 0, 1.0, 1.0, 0.01).is_err());
    }
}
