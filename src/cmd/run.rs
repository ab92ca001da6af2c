//! `tmc429 run`: a scenario file (docs/scenarios.md) on the model, the RTL or both.

use std::path::{Path, PathBuf};

use tmc429_scenario::{gtkw, plot, run as srun, vectors as svectors, Engine, Options, Report, Scenario};

use super::common::{check_output, read_input, Progress};
use crate::{Outcome, UserError};

#[derive(clap::Args)]
pub struct Args {
    /// Scenario file (TOML, docs/scenarios.md); - for standard input.
    pub file: PathBuf,
    /// model (golden model, fast), rtl (Verilated RTL) or cosim (both in lock-step, compared
    /// every cycle).
    #[arg(long, default_value = "model", value_parser = parse_engine)]
    pub engine: Engine,
    /// Write a VCD of the run (and a GTKWave save file beside it, FILE with .gtkw).
    #[arg(long, value_name = "FILE")]
    pub vcd: Option<PathBuf>,
    /// Plot position, velocity and acceleration per motor: FILE.svg or FILE.png.
    #[arg(long, value_name = "FILE")]
    pub plot: Option<PathBuf>,
    /// Write the golden model's test vectors of the scenario to DIR (created if missing): chip
    /// pins and the CSV of SPI frames, ramp ticks and driver-chain datagrams (docs/vectors.md).
    #[arg(long, value_name = "DIR")]
    pub vectors: Option<PathBuf>,
}

pub fn parse_engine(s: &str) -> Result<Engine, String> {
    s.parse()
}

pub fn run(a: Args) -> Result<Outcome, UserError> {
    let (name, text) = read_input(Some(&a.file))?;
    let sc = tmc429_scenario::parse(&text, &name)
        .map_err(|errs| UserError(errs.iter().map(|e| e.to_string()).collect::<Vec<_>>().join("\n")))?;
    let (report, vectors) = execute(&sc, a.engine, a.vcd.as_deref(), a.plot.as_deref(), a.vectors.as_deref(), "run")?;
    print!("{}", report.summary());
    for f in &vectors {
        println!("vectors: {}", f.display());
    }
    Ok(conclude(&report))
}

/// Checks the outputs, runs, writes the plot, the save file and the vectors (whose paths it
/// returns).
pub fn execute(
    sc: &Scenario,
    engine: Engine,
    vcd: Option<&Path>,
    plot_file: Option<&Path>,
    vectors_dir: Option<&Path>,
    label: &str,
) -> Result<(Report, Vec<PathBuf>), UserError> {
    if engine != Engine::Model {
        tmc429_testbench::rtl::require("or use --engine model").map_err(UserError)?;
    }
    if let Some(p) = plot_file {
        match p.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase).as_deref() {
            Some("svg") | Some("png") => {}
            _ => return Err(UserError(format!("--plot {}: expected a file name ending in .svg or .png", p.display()))),
        }
        check_output("--plot", p)?;
    }
    if let Some(v) = vcd {
        check_output("--vcd", v)?;
    }
    if let Some(d) = vectors_dir {
        std::fs::create_dir_all(d).map_err(|e| UserError(format!("--vectors {}: cannot create: {e}", d.display())))?;
        check_output("--vectors", &d.join("vectors"))?;
    }
    let mut opt = Options::new(engine);
    opt.vcd = vcd.map(Path::to_path_buf);
    // the model's own run gives the vectors' stimulus; other engines run the model again
    opt.record_pins = vectors_dir.is_some() && engine == Engine::Model;
    let mut progress = Progress::new(&format!("{label} {} ({})", sc.name, engine.name()));
    let report = srun(sc, &opt, &mut |d, t| progress.update(d, t)).map_err(UserError)?;
    progress.finish();
    if let Some(v) = vcd {
        let save = v.with_extension("gtkw");
        let vcd_name = v.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
        let end_ps = report.cycles * tmc429_testbench::rtl::period_ps(sc.fclk);
        let motors = report.motors.len();
        let text = gtkw::save_file(
            &vcd_name,
            &format!("tmc429 {label} {}: {} on {}", sc.name, sc.chip, engine.name()),
            motors,
            engine == Engine::Cosim,
            end_ps,
        );
        write_atomic(&save, text.as_bytes())?;
    }
    if let Some(p) = plot_file {
        plot::write(&report, p).map_err(UserError)?;
    }
    let mut report = report;
    let files = match vectors_dir {
        Some(d) => svectors::write(sc, report.pins.take(), d).map_err(UserError)?,
        None => Vec::new(),
    };
    Ok((report, files))
}

/// Exit 1 with the failed expectations (and a mismatch) named on stderr.
pub fn conclude(r: &Report) -> Outcome {
    if r.ok() {
        return Outcome::Ok;
    }
    for e in r.failed() {
        eprintln!("tmc429: expectation failed: {}:{}: {} ({})", r.file, e.line, e.name, e.detail);
    }
    if r.mismatch.is_some() {
        eprintln!("tmc429: the model and the RTL disagree (see the mismatch report above)");
    }
    Outcome::Failed
}

/// Writes `bytes` as the whole file `p` (temporary file, renamed when complete).
pub fn write_atomic(p: &Path, bytes: &[u8]) -> Result<(), UserError> {
    tmc429_testbench::vectors::files::write_whole(p, bytes).map_err(UserError)
}
