//! `tmc429 calc`: registers from a speed and an acceleration, or physical units from
//! registers (TMC429 §8.1.13, §8.1.7.1.1, §8.1.10.2.3; tmc429_scenario::units).

use tmc429_scenario::units::{self, Profile};

use super::common::ChipArgs;
use crate::{Outcome, UserError};

#[derive(clap::Args)]
pub struct Args {
    #[command(flatten)]
    pub chip: ChipArgs,
    /// Microsteps per full step (SPI mode: 2^usrs; Step/Dir: the driver's setting).
    #[arg(long, default_value_t = 1, conflicts_with = "usrs")]
    pub microsteps: u32,
    /// Microstep resolution as the usrs field (0..6): 2^usrs microsteps per full step.
    #[arg(long)]
    pub usrs: Option<u32>,
    /// Wanted full-step rate [Hz] (registers from units).
    #[arg(long, conflicts_with_all = ["rpm", "v_max"])]
    pub speed: Option<f64>,
    /// Wanted speed [rpm] (with --steps-per-rev).
    #[arg(long, requires = "steps_per_rev", conflicts_with = "v_max")]
    pub rpm: Option<f64>,
    /// Full steps per revolution (for rpm in and out).
    #[arg(long)]
    pub steps_per_rev: Option<u32>,
    /// Wanted full-step acceleration [Hz/s] (registers from units).
    #[arg(long, conflicts_with = "a_max")]
    pub accel: Option<f64>,
    /// p reduction of pmul/pdiv (the datasheet's pmulpdiv.c -pr; 0.00 .. 0.10).
    #[arg(long, default_value_t = 0.01)]
    pub p_reduction: f32,
    /// pulse_div (units from registers).
    #[arg(long)]
    pub pulse_div: Option<u32>,
    /// ramp_div (units from registers).
    #[arg(long)]
    pub ramp_div: Option<u32>,
    /// v_max (units from registers).
    #[arg(long)]
    pub v_max: Option<u32>,
    /// a_max (units from registers).
    #[arg(long)]
    pub a_max: Option<u32>,
}

pub fn run(a: Args) -> Result<Outcome, UserError> {
    let fclk = a.chip.fclk() as f64;
    let microsteps = match a.usrs {
        Some(u) if u <= 6 => 1 << u,
        Some(u) => return Err(UserError(format!("--usrs {u}: expected 0..6 (TMC428 Table 8-10)"))),
        None => a.microsteps,
    };
    if !(0.0..=0.5).contains(&a.p_reduction) {
        return Err(UserError(format!("--p-reduction {}: expected 0.00 .. 0.50", a.p_reduction)));
    }
    let forward = a.speed.is_some() || a.rpm.is_some() || a.accel.is_some();
    let reverse = a.pulse_div.is_some() || a.ramp_div.is_some() || a.v_max.is_some() || a.a_max.is_some();
    let profile =
        match (forward, reverse) {
            (true, false) => {
                let hz = match (a.speed, a.rpm) {
                    (Some(s), None) => s,
                    (None, Some(r)) => r / 60.0 * a.steps_per_rev.unwrap_or(200) as f64,
                    _ => return Err(UserError("give --speed HZ or --rpm RPM --steps-per-rev N".into())),
                };
                let Some(acc) = a.accel else {
                    return Err(UserError("give the acceleration: --accel HZ_PER_S (full steps)".into()));
                };
                units::solve(fclk, microsteps, hz, acc, a.p_reduction).map_err(UserError)?
            }
            (false, true) => {
                let (Some(pd), Some(rd), Some(v), Some(am)) = (a.pulse_div, a.ramp_div, a.v_max, a.a_max) else {
                    return Err(UserError("from registers: give --pulse-div, --ramp-div, --v-max and --a-max".into()));
                };
                units::from_registers(fclk, microsteps, pd, rd, v, am, a.p_reduction).map_err(UserError)?
            }
            (true, true) => return Err(UserError("give either a speed and an acceleration, or registers, not both".into())),
            (false, false) => return Err(UserError(
                "give --speed HZ (or --rpm RPM --steps-per-rev N) and --accel HZ_PER_S, or --pulse-div, --ramp-div, --v-max and --a-max"
                    .into(),
            )),
        };
    print!("{}", render(&profile, a.steps_per_rev));
    Ok(Outcome::Ok)
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
    let _ = writeln!(
        s,
        "braking       {} microsteps ({} full steps) from v_max to 0, in {:.6} s",
        trim(p.braking_steps()),
        trim(p.braking_steps() / p.microsteps as f64),
        p.ramp_time_s()
    );
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
