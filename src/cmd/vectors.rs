//! `tmc429 vectors`: test vectors from the golden model (docs/vectors.md).

use std::path::{Path, PathBuf};

use tmc429_testbench::vectors::{self, scenario, Format, Unit};

use super::common::ChipArgs;
use crate::{Outcome, UserError};

#[derive(clap::Args)]
pub struct Args {
    /// Unit boundary: spi, ramp, lut, chain or chip.
    #[arg(long, value_parser = parse_unit)]
    pub unit: Unit,
    /// A built-in scenario (see --list) or a scenario file (a `tmc429 spi` datagram script).
    #[arg(long, required_unless_present = "list")]
    pub scenario: Option<String>,
    /// Output directory (created if missing).
    #[arg(long, required_unless_present = "list")]
    pub out: Option<PathBuf>,
    /// pins (.hex + .cols + .meta), csv (transaction level) or all the unit has.
    #[arg(long, default_value = "all", value_parser = parse_format)]
    pub format: Format,
    #[command(flatten)]
    pub chip: ChipArgs,
    /// Seed of the `random` scenario.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// CLK cycles of the `random` scenario.
    #[arg(long, default_value_t = 100_000, value_parser = clap::value_parser!(u64).range(1..))]
    pub cycles: u64,
    /// CLK cycles per SCK_C half period for a scenario file (at least 3, TMC428 Table 6-1).
    #[arg(long, default_value_t = scenario::SCK_HALF, value_parser = clap::value_parser!(u32).range(3..))]
    pub sck_half: u32,
    /// List the built-in scenarios and exit.
    #[arg(long)]
    pub list: bool,
}

fn parse_unit(s: &str) -> Result<Unit, String> {
    s.parse()
}

fn parse_format(s: &str) -> Result<Format, String> {
    s.parse()
}

pub fn run(a: Args) -> Result<Outcome, UserError> {
    if a.list {
        for (name, what) in scenario::BUILTIN {
            println!("{name:<18} {what}");
        }
        return Ok(Outcome::Ok);
    }
    let (Some(name), Some(out)) = (a.scenario.as_deref(), a.out.as_deref()) else {
        return Err(UserError("--scenario and --out are required".into()));
    };
    let forms = vectors::forms(a.unit, a.format).map_err(UserError)?;
    let chip = a.chip.chip;
    let fclk = a.chip.fclk();
    let sc = match scenario::builtin(name, chip, fclk, a.seed, a.cycles) {
        Some(sc) => sc,
        None if Path::new(name).is_file() => scenario::from_file(Path::new(name), chip, fclk, a.sck_half).map_err(UserError)?,
        None => {
            let names: Vec<&str> = scenario::BUILTIN.iter().map(|(n, _)| *n).collect();
            return Err(UserError(format!(
                "--scenario {name}: neither a built-in scenario ({}) nor a readable file",
                names.join(", ")
            )));
        }
    };
    std::fs::create_dir_all(out).map_err(|e| UserError(format!("--out {}: cannot create: {e}", out.display())))?;
    let files = vectors::export(a.unit, &sc, &forms, out).map_err(UserError)?;
    for f in files {
        println!("{}", f.display());
    }
    Ok(Outcome::Ok)
}
