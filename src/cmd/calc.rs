//! `tmc429 calc`: registers from a speed and an acceleration, or physical units from
//! registers (TMC429 §8.1.13, §8.1.7.1.1, §8.1.10.2.3; tmc429_scenario::calc).

use tmc429_scenario::calc::{self, Request};

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
    let r = Request {
        fclk: a.chip.fclk() as f64,
        microsteps: a.microsteps,
        usrs: a.usrs,
        speed: a.speed,
        rpm: a.rpm,
        steps_per_rev: a.steps_per_rev,
        accel: a.accel,
        p_reduction: a.p_reduction,
        pulse_div: a.pulse_div,
        ramp_div: a.ramp_div,
        v_max: a.v_max,
        a_max: a.a_max,
    };
    print!("{}", calc::answer(&r).map_err(UserError)?);
    Ok(Outcome::Ok)
}
