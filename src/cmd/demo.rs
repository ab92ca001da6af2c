//! `tmc429 demo`: the built-in three-axis scenario (examples/scenarios/demo.toml), co-simulated
//! by default; writes a VCD with a GTKWave save file, the motion plots and the test vectors,
//! prints a summary.

use std::path::PathBuf;

use tmc429_scenario::demo::{DEMO_FILE, DEMO_TOML};
use tmc429_scenario::Engine;

use super::run::{conclude, execute, parse_engine};
use crate::{Outcome, UserError};

#[derive(clap::Args)]
pub struct Args {
    /// Directory for demo.vcd, demo.gtkw, demo.svg, demo.png and the test vectors (created if
    /// missing).
    #[arg(long, default_value = "demo-out")]
    pub out: PathBuf,
    /// cosim (model and RTL in lock-step, the default), model or rtl.
    #[arg(long, default_value = "cosim", value_parser = parse_engine)]
    pub engine: Engine,
    /// Print the demo's scenario file and exit.
    #[arg(long)]
    pub print: bool,
}

pub fn run(a: Args) -> Result<Outcome, UserError> {
    if a.print {
        print!("{DEMO_TOML}");
        return Ok(Outcome::Ok);
    }
    if a.engine != Engine::Model {
        tmc429_testbench::rtl::require("or run the demo on the golden model alone: tmc429 demo --engine model").map_err(UserError)?;
    }
    let sc = tmc429_scenario::parse(DEMO_TOML, DEMO_FILE)
        .map_err(|errs| UserError(errs.iter().map(|e| e.to_string()).collect::<Vec<_>>().join("\n")))?;
    std::fs::create_dir_all(&a.out).map_err(|e| UserError(format!("--out {}: cannot create: {e}", a.out.display())))?;
    let vcd = a.out.join("demo.vcd");
    let svg = a.out.join("demo.svg");
    let png = a.out.join("demo.png");
    let (report, vectors) = execute(&sc, a.engine, Some(&vcd), Some(&svg), Some(&a.out), "demo")?;
    tmc429_scenario::plot::write(&report, &png).map_err(UserError)?;
    print!("{}", report.summary());
    println!("gtkw: {}", a.out.join("demo.gtkw").display());
    println!("plot: {}", svg.display());
    println!("plot: {}", png.display());
    for f in &vectors {
        println!("vectors: {}", f.display());
    }
    println!("view: gtkwave {}", a.out.join("demo.gtkw").display());
    Ok(conclude(&report))
}
