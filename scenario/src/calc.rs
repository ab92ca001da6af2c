//! `tmc429 calc` behind its command line: the request (registers from a speed and an
//! acceleration, or physical units from registers; TMC429 §8.1.13, §8.1.7.1.1, §8.1.10.2.3)
//! checked and answered as the text the command prints ([`crate::units`] does the arithmetic).
//! Every number printed is finite: a request whose answer would not be is an error.

use crate::units::{self, Profile};

/// What the user asked, as the options of `tmc429 calc` give it.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Request {
    pub fclk: f64,
    /// Microsteps per full step (SPI mode: 2^usrs; Step/Dir: the driver's setting).
    pub microsteps: u32,
    /// usrs (0..6), instead of `microsteps`.
    pub usrs: Option<u32>,
    /// Full-step rate [Hz].
    pub speed: Option<f64>,
    /// Speed [rpm] (with `steps_per_rev`, default 200).
    pub rpm: Option<f64>,
    /// Full steps per revolution (≥ 1).
    pub steps_per_rev: Option<u32>,
    /// Full-step acceleration [Hz/s].
    pub accel: Option<f64>,
    pub p_reduction: f32,
    pub pulse_div: Option<u32>,
    pub ramp_div: Option<u32>,
    pub v_max: Option<u32>,
    pub a_max: Option<u32>,
}

/// The answer to `r` as `tmc429 calc` prints it, or why there is none.
pub fn answer(r: &Request) -> Result<String, String> {
    let microsteps = match r.usrs {
        Some(u) if u <= 6 => 1 << u,
        Some(u) => return Err(format!("--usrs {u}: expected 0..6 (TMC428 Table 8-10)")),
        None => r.microsteps,
    };
    if !(0.0..=0.5).contains(&r.p_reduction) {
        return Err(format!("--p-reduction {}: expected 0.00 .. 0.50", r.p_reduction));
    }
    if r.steps_per_rev == Some(0) {
        return Err("--steps-per-rev 0: expected at least 1 full step per revolution".into());
    }
    let forward = r.speed.is_some() || r.rpm.is_some() || r.accel.is_some();
    let reverse = r.pulse_div.is_some() || r.ramp_div.is_some() || r.v_max.is_some() || r.a_max.is_some();
    let profile =
        match (forward, reverse) {
            (true, false) => {
                let hz = match (r.speed, r.rpm) {
                    (Some(s), None) => s,
                    (None, Some(rpm)) => rpm / 60.0 * r.steps_per_rev.unwrap_or(200) as f64,
                    _ => return Err("give --speed HZ or --rpm RPM --steps-per-rev N".into()),
                };
                let Some(acc) = r.accel else {
                    return Err("give the acceleration: --accel HZ_PER_S (full steps)".into());
                };
                units::solve(r.fclk, microsteps, hz, acc, r.p_reduction)?
            }
            (false, true) => {
                let (Some(pd), Some(rd), Some(v), Some(am)) = (r.pulse_div, r.ramp_div, r.v_max, r.a_max) else {
                    return Err("from registers: give --pulse-div, --ramp-div, --v-max and --a-max".into());
                };
                units::from_registers(r.fclk, microsteps, pd, rd, v, am, r.p_reduction)?
            }
            (true, true) => return Err("give either a speed and an acceleration, or registers, not both".into()),
            (false, false) => return Err(
                "give --speed HZ (or --rpm RPM --steps-per-rev N) and --accel HZ_PER_S, or --pulse-div, --ramp-div, --v-max and --a-max"
                    .into(),
            ),
        };
    Ok(render(&profile, r.steps_per_rev))
}

fn render(p: &Profile, steps_per_rev: Option<u32>) -> String {
    use std::fmt::Write as _;
    let mut s = String::new();
    let _ = writeln!(s, "fclk          {} Hz, {} microsteps per full step", p.fclk, p.microsteps);
    let _ = writeln!(s, "pulse_div     {}", p.pulse_div);
    let _ = writeln!(s, "ramp_div      {}", p.ramp_div);
    let _ = writeln!(s, "v_max         {}", p.v_max);
    let _ = writeln!(s, "a_max         {}", p.a_max);
    let pm = &p.pmul;
    match pm.register_value() {
        Some(reg) => {
            let _ = writeln!(
                s,
                "pmul_pdiv     p_mul {}, p_div {} (register ${reg:06X}); p = {:.6} (ideal {:.6}, reduced by {} to {:.6})",
                pm.p_mul, pm.p_div, pm.p_best, pm.p_ideal, p.p_reduction, pm.p_reduced
            );
        }
        None => {
            let _ = writeln!(s, "pmul_pdiv     none: p = {:.6} is not representable (p_mul −1, p_div −1)", pm.p_ideal);
        }
    }
    let _ = writeln!(s, "a_max limits  {} .. {} (TMC429 §8.1.7.1.1)", p.lower_limit(), p.upper_limit());
    let _ = writeln!(s, "step rate     {:.2} Hz microsteps, {:.2} Hz full steps", p.rate_hz(), p.fullstep_rate_hz());
    if let Some(n) = steps_per_rev {
        let _ = writeln!(s, "speed         {:.2} rpm at {n} full steps per revolution", p.fullstep_rate_hz() * 60.0 / n as f64);
    }
    let _ = writeln!(s, "acceleration  {:.2} Hz/s microsteps, {:.2} Hz/s full steps", p.accel_hz_per_s(), p.fullstep_accel_hz_per_s());
    if p.a_max == 0 {
        // no ramp: the velocity never changes (its steps and time would be infinite)
        let _ = writeln!(s, "braking       none: a_max = 0 never changes the velocity");
    } else {
        let _ = writeln!(
            s,
            "braking       {} microsteps ({} full steps) from v_max to 0, in {:.6} s",
            trim(p.braking_steps()),
            trim(p.braking_steps() / p.microsteps as f64),
            p.ramp_time_s()
        );
    }
    let w = p.warnings();
    if w.is_empty() {
        let _ = writeln!(s, "check         ok");
    }
    for x in w {
        let _ = writeln!(s, "warning       {x}");
    }
    s
}

fn trim(x: f64) -> String {
    let t = format!("{x:.3}");
    t.trim_end_matches('0').trim_end_matches('.').to_string()
}
