//! The lock-step co-simulation: the same inputs go to the golden model and the Verilated RTL
//! every CLK cycle; outputs and probes are compared every cycle under a [`Compare`] mask.

use std::collections::VecDeque;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use tmc429_model::{Chip, Inputs, Outputs, Probes, Tmc429};

use crate::coverage::{reg_name, Coverage};
use crate::pair::{run_pair, BATCH};
use crate::rtl::{Expected, Rtl, Variant};
use crate::signals::{agree, diff, flatten, format_value, Compare, Diff};
use crate::stimulus::{Driver, Event, Frame, PinLevels, Profile, Stimulus, Txn};
use crate::trace::TraceWriter;

/// Transactions kept for the mismatch report.
pub const HISTORY: usize = 16;

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

/// One SPI frame as the µC saw it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TxnRecord {
    /// Cycle of the first tick of the frame (nSCS_C applied low).
    pub start: u64,
    /// Cycle in which nSCS_C was applied high (0 while in progress).
    pub end: u64,
    pub frame: Frame,
    /// Bits read from the data pin by the model side and the RTL side, first bit in the
    /// most significant position of the `bits` received so far.
    pub reply_model: u64,
    pub reply_rtl: u64,
    pub bits: u8,
}

impl TxnRecord {
    /// One line: cycles, access decoded by register name, replies of both sides.
    pub fn describe(&self, chip: Chip) -> String {
        let f = &self.frame;
        let w = (self.bits as usize).div_ceil(4).max(1);
        let access = if f.executes() {
            if f.is_read() {
                format!("R {}", reg_name(chip, f.a7()))
            } else {
                format!("W {} = ${:06X}", reg_name(chip, f.a7()), f.data())
            }
        } else {
            let sent = if f.nbits <= 32 { (f.datagram as u64) >> (32 - f.nbits as u32) } else { f.datagram as u64 };
            format!("{}-bit frame ${:0w$X} (not executed)", f.nbits, sent, w = (f.nbits.min(32) as usize).div_ceil(4))
        };
        let end = if self.end == 0 { "…".to_string() } else { self.end.to_string() };
        let same = if self.reply_model == self.reply_rtl { "" } else { "  <- replies differ" };
        format!(
            "cycle {:>9}..{:<9} {:<44} reply model ${:0w$X} rtl ${:0w$X}{}",
            self.start, end, access, self.reply_model, self.reply_rtl, same
        )
    }

    /// Short form for the VCD string signal.
    pub fn short(&self, chip: Chip) -> String {
        let f = &self.frame;
        if !f.executes() {
            return format!("{}-bit_frame", f.nbits);
        }
        if f.is_read() {
            format!("R_{}=${:06X}", reg_name(chip, f.a7()), self.reply_model & 0xFF_FFFF)
        } else {
            format!("W_{}=${:06X}", reg_name(chip, f.a7()), f.data())
        }
    }
}

/// The first mismatch.
#[derive(Clone, Debug)]
pub struct Mismatch {
    /// CLK edge (1 = the first after reset) after which the states differ.
    pub cycle: u64,
    pub diffs: Vec<Diff>,
    /// The last transactions, oldest first (the last one may be in progress).
    pub history: Vec<TxnRecord>,
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
        let chip = self.variant.chip();
        let mut s = String::new();
        let _ = writeln!(s, "MISMATCH at cycle {} ({}, seed {}):", m.cycle, self.variant, self.seed);
        let _ = writeln!(s, "  {:<22} {:<20} rtl", "signal", "model");
        for d in &m.diffs {
            let name = format!("{}.{}", d.signal.scope, d.signal.name);
            let _ = writeln!(s, "  {:<22} {:<20} {}", name, format_value(&d.signal, d.model), format_value(&d.signal, d.rtl));
        }
        let _ = writeln!(s, "last {} SPI transactions (oldest first):", m.history.len());
        for t in &m.history {
            let _ = writeln!(s, "  {}", t.describe(chip));
        }
        s
    }
}

/// The data pin the µC reads: SDOZ_C while enabled, else nINT_SDO_C.
#[inline]
fn data_pin(o: &Outputs) -> u64 {
    if o.sdoz_c_oe {
        o.sdoz_c as u64
    } else {
        o.nint_sdo_c as u64
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

/// The model side of a run: stimulus, pin driver, golden model and coverage, and the frame in
/// progress. The same for the single-thread loop ([`simulate`]) and the two-thread pair
/// ([`simulate_pair`]): nothing in it reads the RTL except the RTL's reply bits of the frame in
/// progress, which only the single-thread loop records (for the mismatch report).
struct ModelSide {
    chip: Chip,
    profile: Profile,
    model: Tmc429,
    stim: Stimulus,
    drv: Driver,
    cov: Coverage,
    /// The SPI frame in progress.
    current: Option<TxnRecord>,
    frames: u64,
    pin_changes: u64,
    /// The model's outputs after the last edge.
    mo: Outputs,
}

impl ModelSide {
    fn new(cfg: &Config) -> ModelSide {
        let chip = cfg.variant.chip();
        let model = Tmc429::new(chip);
        let drv = Driver::default();
        let mut cov = Coverage::new(chip, cfg.profile);
        let idle = &drv.inputs;
        cov.set_initial_pins(PinLevels {
            ref_: [idle.ref1, idle.ref2, idle.ref3],
            refr: [idle.refr1, idle.refr2, idle.refr3],
            sdi_s: idle.sdi_s,
        });
        ModelSide {
            chip,
            profile: cfg.profile,
            mo: model.outputs(),
            model,
            stim: Stimulus::new(chip, cfg.profile, cfg.seed),
            drv,
            cov,
            current: None,
            frames: 0,
            pin_changes: 0,
        }
    }

    /// Edge `n` (0-based) of the model side: the next transaction when the driver is ready,
    /// the driver's pins, the data pin sampled by the µC, then the model's edge and the
    /// coverage. `ro`: the RTL's outputs before the edge, for the RTL's reply bits (the
    /// single-thread loop). Returns the inputs, the model's probes after the edge and the frame
    /// that ended with this edge.
    #[inline]
    fn step(&mut self, n: u64, ro: Option<&Outputs>) -> (Inputs, Probes, Option<TxnRecord>) {
        if self.drv.ready() {
            let t = self.stim.next_txn();
            match &t {
                Txn::Frame(f) => {
                    self.frames += 1;
                    self.current = Some(TxnRecord { start: n + 1, end: 0, frame: *f, reply_model: 0, reply_rtl: 0, bits: 0 });
                }
                Txn::Pins { levels, .. } => {
                    self.pin_changes += 1;
                    self.cov.pins(levels);
                }
                Txn::Idle(_) => {}
            }
            self.drv.start(t);
        }
        let (inp, ev) = self.drv.step();
        let mut ended: Option<TxnRecord> = None;
        match ev {
            Event::Sample(_) => {
                if let Some(c) = self.current.as_mut() {
                    c.reply_model = c.reply_model << 1 | data_pin(&self.mo);
                    if let Some(ro) = ro {
                        c.reply_rtl = c.reply_rtl << 1 | data_pin(ro);
                    }
                    c.bits += 1;
                }
            }
            Event::FrameEnd(f) => {
                if let Some(mut c) = self.current.take() {
                    c.end = n + 1;
                    self.cov.frame(self.chip, &f, c.reply_model, &self.model);
                    ended = Some(c);
                }
            }
            Event::None => {}
        }

        self.mo = self.model.tick(&inp);
        let mp = self.model.probes();
        self.cov.cycle(&self.mo, &mp);
        self.cov.model(&self.model, &mp);
        if self.profile == Profile::Drivers {
            self.cov.drivers(self.chip, &self.mo, &mp, &self.model);
        }
        (inp, mp, ended)
    }
}

/// Runs model and RTL in lock-step on one thread. Stops at the first mismatch. `trace`: write a
/// VCD of the ticks `from..to` (0-based tick index) to this path.
fn simulate(cfg: &Config, trace: Option<(&Path, u64, u64)>) -> Result<Outcome, String> {
    let chip = cfg.variant.chip();
    // Verilator's trace code slows every cycle: only the traced run uses the model that has it
    let mut rtl = if trace.is_some() { Rtl::try_new_traced(cfg.variant)? } else { Rtl::try_new(cfg.variant)? };
    let mut side = ModelSide::new(cfg);
    let mut history: VecDeque<TxnRecord> = VecDeque::with_capacity(HISTORY + 1);
    let mut out = Outcome {
        variant: cfg.variant,
        seed: cfg.seed,
        cycles: 0,
        frames: 0,
        pin_changes: 0,
        mismatch: None,
        coverage: Coverage::default(),
        vcd_files: Vec::new(),
    };
    let mut ro = rtl.outputs();

    // the reset states must agree before the first edge
    let (mo, mp0, rp0) = (side.mo, side.model.probes(), rtl.probes());
    if !agree(cfg.compare, &mo, &mp0, &ro, &rp0) {
        out.mismatch = Some(Mismatch { cycle: 0, diffs: diff(cfg.compare, &flatten(&mo, &mp0), &flatten(&ro, &rp0)), history: Vec::new() });
        out.coverage = side.cov;
        return Ok(out);
    }

    let mut writer: Option<TraceWriter> = None;
    // cycles, frames and pin changes up to the first mismatch (the trace may run on)
    let mut counted = (0u64, 0u64, 0u64);
    let t_to = trace.map(|(_, _, b)| b).unwrap_or(0);

    for n in 0..cfg.cycles {
        if let Some((path, from, _)) = trace {
            if n == from {
                let title = format!("tmc429 cosim {} seed {}: model and RTL", cfg.variant, cfg.seed);
                writer = Some(TraceWriter::create(path, cfg.fclk, &title).map_err(|e| format!("{}: {e}", path.display()))?);
                rtl.trace_open(&rtl_trace_path(path), cfg.fclk)?;
            }
        }
        let (inp, mp, ended) = side.step(n, Some(&ro));
        if let Some(c) = ended {
            if history.len() == HISTORY {
                history.pop_front();
            }
            history.push_back(c);
        }
        let mo = side.mo;
        ro = rtl.tick(&inp);
        let rp = rtl.probes();
        let ok = agree(cfg.compare, &mo, &mp, &ro, &rp);
        if let Some(w) = writer.as_mut() {
            let txt = ended.map(|c| c.short(chip));
            w.tick(n, &inp, &mo, &mp, &ro, &rp, !ok, txt.as_deref()).map_err(|e| format!("writing VCD: {e}"))?;
            if n + 1 >= t_to {
                if let Some(w) = writer.take() {
                    w.finish().map_err(|e| format!("writing VCD: {e}"))?;
                }
                rtl.trace_close();
            }
        }
        out.cycles = n + 1;
        if !ok && out.mismatch.is_none() {
            let mut h: Vec<TxnRecord> = history.iter().copied().collect();
            if let Some(c) = side.current {
                h.push(c);
                if h.len() > HISTORY {
                    h.remove(0);
                }
            }
            out.mismatch = Some(Mismatch { cycle: n + 1, diffs: diff(cfg.compare, &flatten(&mo, &mp), &flatten(&ro, &rp)), history: h });
            counted = (n + 1, side.frames, side.pin_changes);
            if trace.is_none() || n + 1 >= t_to {
                break;
            }
        }
        if out.mismatch.is_some() && n + 1 >= t_to {
            break;
        }
    }
    if let Some(w) = writer.take() {
        w.finish().map_err(|e| format!("writing VCD: {e}"))?;
        rtl.trace_close();
    }
    (out.frames, out.pin_changes) = (side.frames, side.pin_changes);
    if out.mismatch.is_some() {
        (out.cycles, out.frames, out.pin_changes) = counted;
    }
    out.coverage = side.cov;
    Ok(out)
}

/// Runs model and RTL in lock-step on two threads ([`crate::pair::run_pair`]): the model side
/// on this thread, the RTL and the comparison on a second one. Without a mismatch the outcome
/// is the model side's (cycles, transactions, coverage), which does not depend on the RTL; on a
/// mismatch the run is made again by the single-thread loop [`simulate`] (the stimulus is
/// seeded), which stops at the same first mismatch and gives the report: the outcome is the
/// same as [`simulate`]'s either way.
fn simulate_pair(cfg: &Config) -> Result<Outcome, String> {
    let mut side = ModelSide::new(cfg);
    let reset = (side.mo, side.model.probes());
    let mut n = 0u64;
    let first = run_pair(cfg.variant, cfg.compare, reset, |buf| {
        let end = (n + BATCH as u64).min(cfg.cycles);
        while n < end {
            let (inp, probes, _) = side.step(n, None);
            buf.push(Expected::new(&inp, &side.mo, &probes));
            n += 1;
        }
        n < cfg.cycles
    })?;
    if first.is_some() {
        return simulate(cfg, None);
    }
    Ok(Outcome {
        variant: cfg.variant,
        seed: cfg.seed,
        cycles: cfg.cycles,
        frames: side.frames,
        pin_changes: side.pin_changes,
        mismatch: None,
        coverage: side.cov,
        vcd_files: Vec::new(),
    })
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
