//! `tmc429`: the command-line tool of the tmc429 reference implementation.
//! It parses arguments and calls the crates; exit 0 = success, 1 = a check failed,
//! 2 = bad usage or bad input.

use std::process::ExitCode;

use clap::{Parser, Subcommand};

mod cmd;

#[derive(Parser)]
#[command(name = "tmc429", version, about = "Bit-exact reference of the TMC428/TMC429/TMC4210 motion controllers")]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Drive the virtual chip through its SPI pins from a datagram script.
    Spi(cmd::spi::Args),
    /// Print the register map (Markdown, C header, JSON, the sigrok table, the RTL's headers).
    Regmap(cmd::regmap::Args),
    /// Run the golden model and the Verilated RTL in lock-step on random stimulus.
    Cosim(cmd::cosim::Args),
    /// Export test vectors from the golden model (pin level and transaction level).
    Vectors(cmd::vectors::Args),
    /// TMCL module layer: serve a virtual TMCM-3110, assemble and run TMCL programs.
    Tmcl(cmd::tmcl::Args),
    /// Run a scenario file (docs/scenarios.md) and check its expectations.
    Run(cmd::run::Args),
    /// The three-axis demo: co-simulated, with VCD, GTKWave view, plots and a summary.
    Demo(cmd::demo::Args),
    /// Registers from speed and acceleration, or Hz, Hz/s and braking distance from registers.
    Calc(cmd::calc::Args),
    /// Logic-analyzer captures: export a simulation's pins, compare a chip's capture with the model.
    Capture(cmd::capture::Args),
}

/// Exit status of a command.
pub enum Outcome {
    Ok,
    /// A check failed (exit 1).
    Failed,
}

/// A user error: printed as `tmc429: error: …`, exit 2.
pub struct UserError(pub String);

impl<E: std::fmt::Display> From<E> for UserError {
    fn from(e: E) -> Self {
        UserError(e.to_string())
    }
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let res = match cli.command {
        Command::Spi(a) => cmd::spi::run(a),
        Command::Regmap(a) => cmd::regmap::run(a),
        Command::Cosim(a) => cmd::cosim::run(a),
        Command::Tmcl(a) => cmd::tmcl::run(a),
        Command::Vectors(a) => cmd::vectors::run(a),
        Command::Run(a) => cmd::run::run(a),
        Command::Demo(a) => cmd::demo::run(a),
        Command::Calc(a) => cmd::calc::run(a),
        Command::Capture(a) => cmd::capture::run(a),
    };
    match res {
        Ok(Outcome::Ok) => ExitCode::SUCCESS,
        Ok(Outcome::Failed) => ExitCode::from(1),
        Err(UserError(msg)) => {
            // Messages quote input; whatever they quote reaches the terminal escaped.
            for line in msg.lines() {
                eprintln!("tmc429: error: {}", tmc429_model::text::escaped(line));
            }
            ExitCode::from(2)
        }
    }
}
