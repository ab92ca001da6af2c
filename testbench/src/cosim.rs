//! The lock-step co-simulation: the same inputs go to the golden model and the Verilated RTL
//! every CLK cycle; outputs and probes are compared every cycle under a [`Compare`] mask.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use tmc429_model::{Chip, Inputs, Outputs, Probes};
use tmc429_verif::lockstep::Reference;

use crate::coverage::Coverage;
use crate::pair::{run_pair, BATCH};
use crate::rtl::{Expected, Rtl, Variant};
use crate::signals::{agree, diff, flatten, Compare};
use crate::stimulus::Profile;
use crate::trace::TraceWriter;

pub use tmc429_verif::lockstep::{Mismatch, TxnRecord, HISTORY};

/// Cycles traced when `--vcd` is given and nothing mismatches.
pub const VCD_CYCLES_WITHOUT_MISMATCH: u64 = 20_000;

/// A co-simulation run.
#[derive(Clone, Debug)]
pub struct Config {
    pub variant: Variant,
    pub seed: u64,
    /// CLK cycles to run.
    pub cycles: u64,
    pub profile: Profile,
    pub compare: Compare,
    /// CLK frequency for the VCD time scale.
    pub fclk: u64,
    /// VCD of model and RTL side by side (a window around the first mismatch, or the first
    /// [`VCD_CYCLES_WITHOUT_MISMATCH`] cycles); Verilator's trace of the RTL goes beside it
    /// with the extension `.rtl.vcd`.
    pub vcd: Option<PathBuf>,
    /// Cycles traced before and after the first mismatch.
    pub window: (u64, u64),
}

impl Config {
    /// The regression of the complete RTL for a chip: the motion profile (everything moves),
    /// every pin and probe compared.
    pub fn new(chip: Chip, seed: u64, cycles: u64) -> Config {
        Config {
            variant: Variant::Chip(chip),
            seed,
            cycles,
            profile: Profile::Motion,
            compare: Compare::all(),
            fclk: chip.default_fclk(),
            vcd: None,
            window: (400, 100),
        }
    }
}

/// Result of a run.
#[derive(Clone, Debug)]
pub struct Outcome {
    pub variant: Variant,
    pub seed: u64,
    /// Cycles run (up to and including the mismatching one).
    pub cycles: u64,
    /// SPI frames started.
    pub frames: u64,
    /// Pin-change transactions.
    pub pin_changes: u64,
    pub mismatch: Option<Mismatch>,
    pub coverage: Coverage,
    /// VCD files written.
    pub vcd_files: Vec<PathBuf>,
}

impl Outcome {
    /// The outcome of a run of `cfg` before its first edge: nothing counted, no mismatch.
    fn empty(cfg: &Config) -> Outcome {
        Outcome {
            variant: cfg.variant,
            seed: cfg.seed,
            cycles: 0,
            frames: 0,
            pin_changes: 0,
            mismatch: None,
            coverage: Coverage::default(),
            vcd_files: Vec::new(),
        }
    }

    pub fn mismatches(&self) -> u64 {
        self.mismatch.is_some() as u64
    }

    /// The one-paragraph summary (and the mismatch report, if any).
    pub fn summary(&self) -> String {
        let mut s = String::new();
        let _ = writeln!(s, "cosim {}: seed {}", self.variant, self.seed);
        let _ = writeln!(s, "cycles:       {}", self.cycles);
        let _ = writeln!(s, "transactions: {} SPI frames, {} pin changes", self.frames, self.pin_changes);
        let _ = writeln!(s, "mismatches:   {}", self.mismatches());
        if let Some(m) = &self.mismatch {
            s.push_str(&self.report(m));
        }
        for f in &self.vcd_files {
            let _ = writeln!(s, "vcd: {}", f.display());
        }
        s
    }

    /// The mismatch report: cycle, differing signals, last transactions.
    pub fn report(&self, m: &Mismatch) -> String {
        m.report(&self.variant.to_string(), self.variant.chip(), self.seed)
    }
}

/// Verilator's trace beside the VCD: name.vcd -> name.rtl.vcd, other names get .rtl.vcd appended.
fn rtl_trace_path(vcd: &Path) -> PathBuf {
    match vcd.extension() {
        Some(e) if e == "vcd" => vcd.with_extension("rtl.vcd"),
        _ => {
            let mut s = vcd.as_os_str().to_owned();
            s.push(".rtl.vcd");
            PathBuf::from(s)
        }
    }
}

/// Runs model and RTL in lock-step on one thread. Stops at the first mismatch. `trace`: write a
/// VCD of the ticks `from..to` (0-based tick index) to this path.
fn simulate(cfg: &Config, trace: Option<(&Path, u64, u64)>) -> Result<Outcome, String> {
    let chip = cfg.variant.chip();
    // Verilator's trace code slows every cycle: only the traced run uses the model that has it
    let mut rtl = if trace.is_some() { Rtl::try_new_traced(cfg.variant)? } else { Rtl::try_new(cfg.variant)? };
    let mut side = Reference::new(chip, cfg.profile, cfg.seed);
    let mut out = Outcome::empty(cfg);
    let mut ro = rtl.outputs();

    // the reset states must agree before the first edge
    let (mo, mp0, rp0) = (side.outputs(), side.model().probes(), rtl.probes());
    if !agree(cfg.compare, &mo, &mp0, &ro, &rp0) {
        let diffs = diff(cfg.compare, &flatten(&mo, &mp0), &flatten(&ro, &rp0));
        return Ok(Outcome { mismatch: Some(Mismatch { cycle: 0, diffs, history: Vec::new() }), coverage: side.into_coverage(), ..out });
    }

    let mut window = trace.map(|(path, from, to)| TraceWindow { path, from, to, writer: None });
    // cycles, frames and pin changes up to the first mismatch (the trace may run on)
    let mut counted = (0u64, 0u64, 0u64);
    let t_to = trace.map(|(_, _, b)| b).unwrap_or(0);

    for n in 0..cfg.cycles {
        if let Some(w) = window.as_mut() {
            w.open_at(n, cfg, &mut rtl)?;
        }
        let (inp, mp, ended) = side.step(Some(&ro));
        let mo = side.outputs();
        ro = rtl.tick(&inp);
        let rp = rtl.probes();
        let ok = agree(cfg.compare, &mo, &mp, &ro, &rp);
        if let Some(w) = window.as_mut() {
            let txt = ended.map(|c| c.short(chip));
            w.record(n, (&inp, &mo, &mp, &ro, &rp), !ok, txt.as_deref(), &mut rtl)?;
        }
        out.cycles = n + 1;
        if !ok && out.mismatch.is_none() {
            let history = side.source().history();
            out.mismatch = Some(Mismatch { cycle: n + 1, diffs: diff(cfg.compare, &flatten(&mo, &mp), &flatten(&ro, &rp)), history });
            counted = (n + 1, side.source().frames(), side.source().pin_changes());
            if trace.is_none() || n + 1 >= t_to {
                break;
            }
        }
        if out.mismatch.is_some() && n + 1 >= t_to {
            break;
        }
    }
    if let Some(w) = window.as_mut() {
        w.close(&mut rtl)?;
    }
    (out.frames, out.pin_changes) = (side.source().frames(), side.source().pin_changes());
    if out.mismatch.is_some() {
        (out.cycles, out.frames, out.pin_changes) = counted;
    }
    out.coverage = side.into_coverage();
    Ok(out)
}

/// The VCD of the ticks `from..to` of a single-thread run, with Verilator's own trace beside it.
struct TraceWindow<'a> {
    path: &'a Path,
    from: u64,
    to: u64,
    writer: Option<TraceWriter>,
}

impl TraceWindow<'_> {
    /// Opens both traces before tick `n` when it is the first of the window.
    fn open_at(&mut self, n: u64, cfg: &Config, rtl: &mut Rtl) -> Result<(), String> {
        if n == self.from {
            let title = format!("tmc429 cosim {} seed {}: model and RTL", cfg.variant, cfg.seed);
            let path = self.path;
            self.writer = Some(TraceWriter::create(path, cfg.fclk, &title).map_err(|e| format!("{}: {e}", path.display()))?);
            rtl.trace_open(&rtl_trace_path(path), cfg.fclk)?;
        }
        Ok(())
    }

    /// Tick `n` with the pins and probes of both sides; closes the traces after the window's last.
    fn record(
        &mut self,
        n: u64,
        (inp, mo, mp, ro, rp): (&Inputs, &Outputs, &Probes, &Outputs, &Probes),
        bad: bool,
        txn: Option<&str>,
        rtl: &mut Rtl,
    ) -> Result<(), String> {
        if let Some(w) = self.writer.as_mut() {
            w.tick(n, inp, mo, mp, ro, rp, bad, txn).map_err(|e| format!("writing VCD: {e}"))?;
            if n + 1 >= self.to {
                self.close(rtl)?;
            }
        }
        Ok(())
    }

    /// Finishes the VCD and closes Verilator's trace, if they are open.
    fn close(&mut self, rtl: &mut Rtl) -> Result<(), String> {
        if let Some(w) = self.writer.take() {
            w.finish().map_err(|e| format!("writing VCD: {e}"))?;
            rtl.trace_close();
        }
        Ok(())
    }
}

/// Runs model and RTL in lock-step on two threads ([`crate::pair::run_pair`]): the model side
/// on this thread, the RTL and the comparison on a second one. Without a mismatch the outcome
/// is the model side's (cycles, transactions, coverage), which does not depend on the RTL; on a
/// mismatch the run is made again by the single-thread loop [`simulate`] (the stimulus is
/// seeded), which stops at the same first mismatch and gives the report: the outcome is the
/// same as [`simulate`]'s either way.
fn simulate_pair(cfg: &Config) -> Result<Outcome, String> {
    let mut side = Reference::new(cfg.variant.chip(), cfg.profile, cfg.seed);
    let reset = (side.outputs(), side.model().probes());
    let mut n = 0u64;
    let first = run_pair(cfg.variant, cfg.compare, reset, |buf| {
        let end = (n + BATCH as u64).min(cfg.cycles);
        while n < end {
            let (inp, probes, _) = side.step(None);
            buf.push(Expected::new(&inp, &side.outputs(), &probes));
            n += 1;
        }
        n < cfg.cycles
    })?;
    if first.is_some() {
        return simulate(cfg, None);
    }
    let (frames, pin_changes) = (side.source().frames(), side.source().pin_changes());
    Ok(Outcome { cycles: cfg.cycles, frames, pin_changes, coverage: side.into_coverage(), ..Outcome::empty(cfg) })
}

/// The co-simulation on one thread, without VCD (`cfg.vcd` is ignored): the loop the mismatch
/// report comes from. Gives the same outcome as [`run`] without `vcd`, which runs the pair on
/// two threads (tests/pair.rs).
pub fn run_one_thread(cfg: &Config) -> Result<Outcome, String> {
    simulate(cfg, None)
}

/// Runs the co-simulation: without `cfg.vcd` on two threads ([`crate::pair`]); with it on one
/// (the traced RTL model), and on a mismatch again (the stimulus is seeded) to write the VCD
/// window around the mismatch.
pub fn run(cfg: &Config) -> Result<Outcome, String> {
    let Some(vcd) = cfg.vcd.as_deref() else {
        return simulate_pair(cfg);
    };
    let first = simulate(cfg, Some((vcd, 0, VCD_CYCLES_WITHOUT_MISMATCH.min(cfg.cycles))))?;
    let mut out = match &first.mismatch {
        Some(m) if m.cycle > VCD_CYCLES_WITHOUT_MISMATCH.min(cfg.cycles) => {
            // the mismatch lies past the traced start: trace its window on a second run
            let from = m.cycle.saturating_sub(cfg.window.0);
            let to = m.cycle + cfg.window.1;
            let mut again = cfg.clone();
            again.cycles = to.min(cfg.cycles.max(m.cycle));
            let second = simulate(&again, Some((vcd, from, to)))?;
            // the report is the first run's (same stimulus, same first mismatch)
            debug_assert_eq!(second.mismatch.as_ref().map(|x| x.cycle), Some(m.cycle));
            first.clone()
        }
        _ => first,
    };
    out.vcd_files = vec![vcd.to_path_buf(), rtl_trace_path(vcd)];
    Ok(out)
}
