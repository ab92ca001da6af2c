//! `tmc429 vectors`: test vectors from the golden model (docs/vectors.md).

use std::path::{Path, PathBuf};

use tmc429_model::Chip;
use tmc429_scenario::vectors as svectors;
use tmc429_testbench::vectors::{self, scenario, Form, Format, Unit};

use super::common::{parse_chip, parse_fclk, parse_package, read_input};
use crate::{Outcome, UserError};

#[derive(clap::Args)]
pub struct Args {
    /// Unit boundary: spi, ramp, lut, chain or chip.
    #[arg(long, value_parser = parse_unit)]
    pub unit: Unit,
    /// A built-in scenario (see --list), a scenario file FILE.toml (docs/scenarios.md; it names
    /// its chip and fclk) or a `tmc429 spi` datagram script.
    #[arg(long, required_unless_present = "list")]
    pub scenario: Option<String>,
    /// Output directory (created if missing).
    #[arg(long, required_unless_present = "list")]
    pub out: Option<PathBuf>,
    /// pins (.hex + .cols + .meta), csv (transaction level), all (pins and csv, as the unit has
    /// them), or a form of the chip's pins for testers and simulators: stil (IEEE 1450), evcd
    /// (extended VCD, $dumpports) or vcd (four-state VCD of the pins).
    #[arg(long, default_value = "all", value_parser = parse_format)]
    pub format: Format,
    /// Chip variant: tmc428, tmc429 (default) or tmc4210. A TOML scenario names its own.
    #[arg(long, value_parser = parse_chip)]
    pub chip: Option<Chip>,
    /// Package (C90): tmc428 sop24 (default), dil20, ssop16; tmc429 qfn32 (default), sop24,
    /// ssop16; tmc4210 ssop16. The files get `-PACKAGE` after the chip when it lacks pins of the
    /// variant. Not for a TOML scenario (it runs in the variant's full package).
    #[arg(long, value_parser = parse_package)]
    pub package: Option<tmc429_model::Package>,
    /// CLK frequency in Hz (default: 16 MHz for the TMC428, 32 MHz otherwise). A TOML scenario
    /// names its own.
    #[arg(long, value_parser = parse_fclk)]
    pub fclk: Option<u64>,
    /// Seed of the `random` scenario.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// CLK cycles of the `random` scenario.
    #[arg(long, default_value_t = 100_000, value_parser = clap::value_parser!(u64).range(1..))]
    pub cycles: u64,
    /// CLK cycles per SCK_C half period for a datagram script (at least 3, TMC428 Table 6-1;
    /// default 3). A TOML scenario names its own (`sck_half`).
    #[arg(long, value_parser = clap::value_parser!(u32).range(3..))]
    pub sck_half: Option<u32>,
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
    if name.ends_with(".toml") {
        if let Some(p) = a.package {
            return Err(UserError(format!("--package {p}: a scenario file runs in its variant's full package; leave --package out")));
        }
        return toml_scenario(&a, Path::new(name), out, &forms);
    }
    let chip = a.chip.unwrap_or(Chip::Tmc429);
    let package = match a.package {
        Some(p) => p.check(chip).map_err(|e| UserError(format!("--package: {e}")))?,
        None => tmc429_model::Package::full(chip),
    };
    let fclk = a.fclk.unwrap_or_else(|| chip.default_fclk());
    let sck_half = a.sck_half.unwrap_or(scenario::SCK_HALF);
    let mut sc = match scenario::builtin(name, chip, fclk, a.seed, a.cycles) {
        Some(sc) => sc,
        None if Path::new(name).is_file() => scenario::from_file(Path::new(name), chip, fclk, sck_half).map_err(UserError)?,
        None => {
            let names: Vec<&str> = scenario::BUILTIN.iter().map(|(n, _)| *n).collect();
            return Err(UserError(format!("--scenario {name}: neither a built-in scenario ({}) nor a readable file", names.join(", "))));
        }
    };
    sc.package = package;
    std::fs::create_dir_all(out).map_err(|e| UserError(format!("--out {}: cannot create: {e}", out.display())))?;
    let files = vectors::export(a.unit, &sc, &forms, out).map_err(UserError)?;
    for f in files {
        println!("{}", f.display());
    }
    Ok(Outcome::Ok)
}

/// A TOML scenario file (docs/scenarios.md): run once on the golden model for its pins, then
/// exported like any scenario. Its chip, fclk and sck_half are the file's; an option that
/// contradicts them is an error.
fn toml_scenario(a: &Args, path: &Path, out: &Path, forms: &[Form]) -> Result<Outcome, UserError> {
    let (name, text) = read_input(Some(path))?;
    let sc = tmc429_scenario::parse(&text, &name)
        .map_err(|errs| UserError(errs.iter().map(|e| e.to_string()).collect::<Vec<_>>().join("\n")))?;
    let given = [
        ("--chip", a.chip.map(|c| c.to_string()), sc.chip.to_string(), "chip"),
        ("--fclk", a.fclk.map(|f| f.to_string()), sc.fclk.to_string(), "fclk"),
        ("--sck-half", a.sck_half.map(|h| h.to_string()), sc.sck_half.to_string(), "sck_half"),
    ];
    for (opt, want, has, key) in given {
        if let Some(w) = want.filter(|w| *w != has) {
            return Err(UserError(format!(
                "{opt} {w}: the scenario file {name} runs with {key} {has}; change it in the file or leave {opt} out"
            )));
        }
    }
    svectors::unit_ok(a.unit).map_err(UserError)?;
    std::fs::create_dir_all(out).map_err(|e| UserError(format!("--out {}: cannot create: {e}", out.display())))?;
    let v = svectors::record(&sc).map_err(UserError)?;
    let files = vectors::export_units(&v, &[(a.unit, forms.to_vec())], out).map_err(UserError)?;
    for f in files {
        println!("{}", f.display());
    }
    Ok(Outcome::Ok)
}
