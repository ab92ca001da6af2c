//! `tmc429 spi`: the virtual chip driven through its pins by a datagram script.

use std::io::Write;
use std::path::PathBuf;

use tmc429_model::host::Host;
use tmc429_model::script::{self, RunOptions};

use super::common::{chip_in, parse_package, read_input, ChipArgs};
use crate::{Outcome, UserError};

#[derive(clap::Args)]
pub struct Args {
    /// Script file (default: standard input).
    pub script: Option<PathBuf>,
    #[command(flatten)]
    pub chip: ChipArgs,
    /// Package: the pins it lacks are tied off, its absent REFR inputs read high (C90).
    /// tmc428: sop24 (default), dil20, ssop16; tmc429: qfn32 (default), sop24, ssop16;
    /// tmc4210: ssop16.
    #[arg(long, value_parser = parse_package)]
    pub package: Option<tmc429_model::Package>,
    /// CLK cycles per SCK_C half period (at least 3, TMC428 Table 6-1).
    #[arg(long, default_value_t = 4)]
    pub sck_half: u32,
    /// Prefix each line with the CLK cycle at which nSCS_C rose.
    #[arg(long)]
    pub timestamps: bool,
    /// Add the register name and its decoded fields.
    #[arg(long)]
    pub decode: bool,
    /// Also print pin-level events in cycle order: `chain <cycle> <nbits> <hex>`,
    /// `step <cycle> <motor> <+|->`, `int <cycle> <0|1>`.
    #[arg(long)]
    pub events: bool,
}

pub fn run(a: Args) -> Result<Outcome, UserError> {
    let (name, text) = read_input(a.script.as_deref())?;
    let lines = script::parse(&text, &name).map_err(|errs| UserError(errs.iter().map(|e| e.to_string()).collect::<Vec<_>>().join("\n")))?;
    let mut host = Host::from_chip(chip_in(a.chip.chip, a.package)?);
    host.set_sck_half(a.sck_half).map_err(|e| UserError(format!("--sck-half: {e}")))?;
    let opts = RunOptions { timestamps: a.timestamps, decode: a.decode, events: a.events };
    let stdout = std::io::stdout();
    let mut out = std::io::BufWriter::new(stdout.lock());
    match script::run(&mut host, &lines, opts, &mut out).and_then(|_| out.flush()) {
        Ok(()) => Ok(Outcome::Ok),
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(Outcome::Ok),
        Err(e) => Err(UserError(format!("writing output: {e}"))),
    }
}
