//! `tmc429 cosim`: the golden model and the Verilated RTL in lock-step (docs/cosim.md).

use std::path::PathBuf;

use tmc429_testbench::stimulus::Profile;
use tmc429_testbench::{run as cosim_run, Config, Variant};

use super::common::ChipArgs;
use crate::{Outcome, UserError};

#[derive(clap::Args)]
pub struct Args {
    #[command(flatten)]
    pub chip: ChipArgs,
    /// Seed of the random stimulus (the same seed gives the same run).
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// CLK cycles to run.
    #[arg(long, default_value_t = 1_000_000, value_parser = clap::value_parser!(u64).range(1..))]
    pub cycles: u64,
    /// VCD of model and RTL side by side: a window around the first mismatch, or the first
    /// 20 000 cycles. Verilator's trace of the RTL goes beside it (FILE with .rtl.vcd).
    /// Without this option a mismatch writes cosim-CHIP-seedS.vcd in the current directory.
    #[arg(long, value_name = "FILE")]
    pub vcd: Option<PathBuf>,
    /// Stimulus profile: `motion` (everything moves: moves in every mode, switch events,
    /// driver-chain and Step/Dir configurations, cover datagrams), `motion-core` (`motion`
    /// without the traffic seen only through the driver chain), `drivers` (motors held;
    /// driver-chain datagrams, covers, continuous update, refmux, polarities, Step/Dir),
    /// `registers` (motors held, no driver-chain traffic) or `full` (any register and RAM word
    /// with any data).
    #[arg(long, default_value = "motion", value_parser = ["motion", "motion-core", "drivers", "registers", "full"])]
    pub profile: String,
    /// Print the functional coverage table and the bins never hit.
    #[arg(long)]
    pub coverage: bool,
    /// Run the RTL built with a planted bug instead (proves that the harness catches it):
    /// `status` = the CDGW status bit ignores datagram_low/high writes (TMC429 only).
    #[arg(long, value_name = "BUG", value_parser = ["status"])]
    pub plant_bug: Option<String>,
}

pub fn run(a: Args) -> Result<Outcome, UserError> {
    tmc429_testbench::rtl::require("or run a scenario on the golden model alone: tmc429 run FILE --engine model").map_err(UserError)?;
    let chip = a.chip.chip;
    let mut cfg = Config::new(chip, a.seed, a.cycles);
    cfg.fclk = a.chip.fclk();
    cfg.profile = Profile::parse(&a.profile).expect("clap restricts --profile to the known names");
    if a.plant_bug.is_some() {
        if chip != tmc429_model::Chip::Tmc429 {
            return Err(UserError(format!("--plant-bug: the planted-bug RTL exists for --chip tmc429 only, not {chip}")));
        }
        cfg.variant = Variant::PlantedStatusBug;
    }
    cfg.vcd = a.vcd.clone();
    if let Some(p) = &cfg.vcd {
        check_writable(p)?;
    }
    let mut out = cosim_run(&cfg).map_err(UserError)?;
    if out.mismatch.is_some() && cfg.vcd.is_none() {
        // run again with the trace: the stimulus is seeded, the mismatch repeats
        let p = PathBuf::from(format!("cosim-{}-seed{}.vcd", chip, a.seed));
        cfg.vcd = Some(p);
        let again = cosim_run(&cfg).map_err(UserError)?;
        out.vcd_files = again.vcd_files;
    }
    print!("{}", out.summary());
    if a.coverage {
        print!("{}", out.coverage.table());
    }
    Ok(if out.mismatch.is_some() { Outcome::Failed } else { Outcome::Ok })
}

fn check_writable(p: &std::path::Path) -> Result<(), UserError> {
    std::fs::OpenOptions::new()
        .create(true)
        .truncate(true)
        .write(true)
        .open(p)
        .map(|_| ())
        .map_err(|e| UserError(format!("--vcd {}: cannot write: {e}", p.display())))
}
