//! `tmc429 run`: a scenario file (docs/scenarios.md) on the model, the RTL or both.

use std::path::{Path, PathBuf};

use tmc429_scenario::{gtkw, plot, run as srun, Engine, Options, Report, Scenario};

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
}

pub fn parse_engine(s: &str) -> Result<Engine, String> {
    s.parse()
}

pub fn run(a: Args) -> Result<Outcome, UserError> {
    let (name, text) = read_input(Some(&a.file))?;
    let sc = tmc429_scenario::parse(&text, &name)
        .map_err(|errs| UserError(errs.iter().map(|e| e.to_string()).collect::<Vec<_>>().join("\n")))?;
    let report = execute(&sc, a.engine, a.vcd.as_deref(), a.plot.as_deref(), "run")?;
    print!("{}", report.summary());
    Ok(conclude(&report))
}

/// Checks the outputs, runs, writes the plot and the save file.
pub fn execute(sc: &Scenario, engine: Engine, vcd: Option<&Path>, plot_file: Option<&Path>, label: &str) -> Result<Report, UserError> {
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
    let mut opt = Options::new(engine);
    opt.vcd = vcd.map(Path::to_path_buf);
    let mut progress = Progress::new(&format!("{label} {} ({})", sc.name, engine.name()));
    let report = srun(sc, &opt, &mut |d, t| progress.update(d, t)).map_err(UserError)?;
    progress.finish();
    if let Some(v) = vcd {
        let save = v.with_extension("gtkw");
        let vcd_name = v.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
        let end_ps = report.cycles * tmc429_testbench::rtl::period_ps(sc.fclk);
        let motors = report.motors.len();
        let text = gtkw::save_file(&vcd_name, &format!("tmc429 {label} {}: {} on {}", sc.name, sc.chip, engine.name()), motors, engine == Engine::Cosim, end_ps);
        write_atomic(&save, text.as_bytes())?;
    }
    if let Some(p) = plot_file {
        plot::write(&report, p).map_err(UserError)?;
    }
    Ok(report)
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

pub fn write_atomic(p: &Path, bytes: &[u8]) -> Result<(), UserError> {
    let tmp = tmc429_scenario::run::tmp_path(p);
    std::fs::write(&tmp, bytes)
        .and_then(|_| std::fs::rename(&tmp, p))
        .map_err(|e| {
            let _ = std::fs::remove_file(&tmp);
            UserError(format!("{}: cannot write: {e}", p.display()))
        })
}
