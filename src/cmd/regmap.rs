//! `tmc429 regmap`: the register map from its one source.

use std::io::Write;

use tmc429_model::{regmap_render, regmap_sigrok, regmap_verilog, schedule_verilog};

use crate::{Outcome, UserError};

#[derive(Clone, Copy, clap::ValueEnum)]
pub enum Format {
    Md,
    C,
    Json,
    /// The register table of the sigrok decoder (sigrok/tmc429/regmap.py).
    Sigrok,
    /// The Verilog header of the RTL's register decode (rtl/tmc429_regmap.vh).
    Verilog,
    /// The Verilog header of the RTL's frame schedule slots (rtl/tmc429_schedule.vh).
    VerilogSchedule,
}

#[derive(clap::Args)]
pub struct Args {
    /// Output format.
    #[arg(long, value_enum, default_value = "md")]
    pub format: Format,
}

pub fn run(a: Args) -> Result<Outcome, UserError> {
    let text = match a.format {
        Format::Md => regmap_render::markdown(),
        Format::C => regmap_render::c_header(),
        Format::Json => regmap_render::json(),
        Format::Sigrok => regmap_sigrok::python(),
        Format::Verilog => regmap_verilog::header(),
        Format::VerilogSchedule => schedule_verilog::header(),
    };
    let mut out = std::io::stdout().lock();
    match out.write_all(text.as_bytes()) {
        Ok(()) => Ok(Outcome::Ok),
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(Outcome::Ok),
        Err(e) => Err(UserError(format!("writing output: {e}"))),
    }
}
