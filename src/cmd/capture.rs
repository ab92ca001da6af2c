//! `tmc429 capture`: logic-analyzer captures of the chip's pins (docs/bench.md): `export` makes
//! one from a simulation, `compare` compares a real chip's capture with the golden model.

use std::path::PathBuf;

use tmc429_scenario::capture::{self, compare, export, pins};
use tmc429_scenario::Engine;

use super::common::{parse_fclk, read_input, ChipArgs};
use crate::{Outcome, UserError};

#[derive(clap::Args)]
pub struct Args {
    #[command(subcommand)]
    pub cmd: Cmd,
}

#[derive(clap::Subcommand)]
pub enum Cmd {
    /// The chip's pins of a scenario (.toml) or an SPI script (.spi) as a logic analyzer
    /// captures them: a sigrok session file (.sr) or a pin-only VCD (.vcd).
    Export(ExportArgs),
    /// Compare a capture of a chip's pins (.sr or .vcd) with the golden model: exit 0 when the
    /// chip agrees, 1 with the differences, 2 for a capture that cannot be used.
    Compare(CompareArgs),
}

#[derive(clap::Args)]
pub struct ExportArgs {
    /// Scenario file (.toml, docs/scenarios.md) or SPI script (.spi, `tmc429 spi`).
    pub source: PathBuf,
    /// Output: FILE.sr (sigrok session) or FILE.vcd.
    #[arg(short, long, value_name = "FILE")]
    pub output: PathBuf,
    /// Sample rate of the capture.
    #[arg(long, default_value = "100MHz", value_parser = parse_fclk)]
    pub rate: u64,
    /// model (golden model) or rtl (the Verilated RTL).
    #[arg(long, default_value = "model", value_parser = parse_engine)]
    pub engine: Engine,
    /// Random sampling phase, µC edge times within the CLK cycle, and an idle lead-in before the
    /// source with the trigger inside it, from this seed (default: none of these).
    #[arg(long)]
    pub seed: Option<u64>,
    /// Peak sampling jitter in ns (uniform; at most 0.45 sample periods).
    #[arg(long, default_value_t = 0.0)]
    pub jitter: f64,
    /// Plant a difference in the chip's pins: reply-bit, missing-step or datagram.
    #[arg(long)]
    pub plant: Option<export::Plant>,
    /// For an SPI script: chip and CLK (a scenario names its own).
    #[command(flatten)]
    pub chip: ChipArgs,
    /// For an SPI script: CLK cycles per SCK_C half period (at least 3, TMC428 Table 6-1).
    #[arg(long, default_value_t = 4)]
    pub sck_half: u32,
}

#[derive(clap::Args)]
pub struct CompareArgs {
    /// Capture file: sigrok session (.sr) or VCD (.vcd).
    pub file: PathBuf,
    #[command(flatten)]
    pub chip: ChipArgs,
    /// Which channel holds which pin: PIN=CHANNEL, several separated by commas or repeated
    /// (e.g. --pin nSCS_C=D0,SCK_C=D1,SDI_C=D2,SDOZ_C=D3). Channels named like a pin need none.
    #[arg(long, value_name = "PIN=CHANNEL")]
    pub pin: Vec<String>,
    /// Timing tolerance in ns (default: two samples and two CLK periods).
    #[arg(long, value_name = "NS")]
    pub tolerance: Option<f64>,
    /// Differences listed at most.
    #[arg(long, default_value_t = 20)]
    pub max_differences: usize,
}

fn parse_engine(s: &str) -> Result<Engine, String> {
    match s {
        "model" => Ok(Engine::Model),
        "rtl" => Ok(Engine::Rtl),
        _ => Err(format!("unknown engine '{s}': expected model or rtl")),
    }
}

pub fn run(a: Args) -> Result<Outcome, UserError> {
    match a.cmd {
        Cmd::Export(e) => run_export(e),
        Cmd::Compare(c) => run_compare(c),
    }
}

fn source(a: &ExportArgs) -> Result<export::Source, UserError> {
    let (name, text) = read_input(Some(&a.source))?;
    let errs = |v: Vec<String>| UserError(v.join("\n"));
    match a.source.extension().and_then(|e| e.to_str()) {
        Some("toml") => {
            let sc = tmc429_scenario::parse(&text, &name).map_err(|e| errs(e.iter().map(|x| x.to_string()).collect()))?;
            Ok(export::Source::Scenario(Box::new(sc)))
        }
        Some("spi") => {
            let lines = tmc429_model::script::parse(&text, &name).map_err(|e| errs(e.iter().map(|x| x.to_string()).collect()))?;
            Ok(export::Source::Script { chip: a.chip.chip, fclk: a.chip.fclk(), sck_half: a.sck_half, lines })
        }
        _ => Err(UserError(format!("{name}: expected a scenario (.toml) or an SPI script (.spi)"))),
    }
}

fn run_export(a: ExportArgs) -> Result<Outcome, UserError> {
    capture::Format::of(&a.output).map_err(|e| UserError(e.0))?;
    if a.engine == Engine::Rtl {
        tmc429_testbench::rtl::require("or use --engine model").map_err(UserError)?;
    }
    if !(0.0..1e6).contains(&a.jitter) {
        return Err(UserError(format!("--jitter {}: expected 0 or more ns", a.jitter)));
    }
    let src = source(&a)?;
    let mut tr = export::trace(&src, a.engine, a.seed).map_err(UserError)?;
    let planted = match a.plant {
        Some(p) => Some(tr.plant(p).map_err(|e| UserError(format!("--plant: {e}")))?),
        None => None,
    };
    let sampling = export::Sampling { rate: a.rate, seed: a.seed, jitter_ns: a.jitter };
    let cap = tr.sample(&sampling);
    capture::write(&a.output, &cap).map_err(|e| UserError(e.0))?;
    println!(
        "{}: {} of a {} at {}: {} samples at {} ({}), {} channels",
        a.output.display(),
        if a.engine == Engine::Rtl { "the RTL's pins" } else { "the golden model's pins" },
        tr.chip,
        capture::fmt_hz(tr.fclk as f64),
        cap.length,
        capture::fmt_hz(cap.samplerate as f64),
        capture::fmt_ms(cap.seconds(cap.length)),
        cap.channels.len()
    );
    if let Some((what, at)) = planted {
        println!("planted: {what} at {}", capture::fmt_ms((at - tr.start(&sampling)) * 1e-9));
    }
    Ok(Outcome::Ok)
}

fn run_compare(a: CompareArgs) -> Result<Outcome, UserError> {
    let assign = pins::parse_assignments(&a.pin).map_err(UserError)?;
    if let Some(t) = a.tolerance {
        if !(t > 0.0 && t < 1e9) {
            return Err(UserError(format!("--tolerance {t}: expected a positive time in ns")));
        }
    }
    let opt = compare::Options { chip: a.chip.chip, fclk: a.chip.fclk(), assign, tolerance_ns: a.tolerance };
    let out = compare::compare(&a.file, &opt).map_err(|e| UserError(e.0))?;
    print!("{}", out.text(a.max_differences));
    Ok(if out.agrees() { Outcome::Ok } else { Outcome::Failed })
}
