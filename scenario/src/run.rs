//! Runs a [`Scenario`] on an engine: the golden model, the Verilated RTL, or both in
//! lock-step (co-simulation). A virtual µC drives the chip's SPI pins (the co-simulation's
//! pin [`Driver`]); the scenario's writes, reads and switch changes become pin activity, the
//! same on every engine.

use std::path::PathBuf;

use tmc429_model::events::{Event as PinEvent, EventDecoder};
use tmc429_model::motor_regs::sext24;
use tmc429_model::{Chip, Outputs, Probes, Tmc429};
use tmc429_testbench::cosim::{Mismatch, Outcome};
use tmc429_testbench::rtl::{Rtl, Variant};
use tmc429_testbench::signals::Compare;
use tmc429_testbench::stimulus::Frame;

use crate::scenario::{Check, Condition, Scenario, Trigger};
use crate::units;

mod checks;
mod report;
mod shadow;
mod state;

pub use report::{ExpectResult, MotorStats, Report, Sample};
pub use shadow::Shadow;
use state::Run;

/// What simulates the chip.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Engine {
    /// The golden model (fast).
    Model,
    /// The Verilated RTL alone.
    Rtl,
    /// Model and RTL in lock-step, compared after every edge.
    Cosim,
}

impl Engine {
    pub fn name(self) -> &'static str {
        match self {
            Engine::Model => "model",
            Engine::Rtl => "rtl",
            Engine::Cosim => "cosim",
        }
    }
}

impl std::str::FromStr for Engine {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s {
            "model" => Ok(Engine::Model),
            "rtl" => Ok(Engine::Rtl),
            "cosim" => Ok(Engine::Cosim),
            _ => Err(format!("unknown engine '{s}': expected model, rtl or cosim")),
        }
    }
}

/// How to run.
#[derive(Clone, Debug)]
pub struct Options {
    pub engine: Engine,
    /// Write a VCD here (through a temporary file, renamed when complete).
    pub vcd: Option<PathBuf>,
    /// Signals compared by the co-simulation.
    pub compare: Compare,
    /// Points per motor kept for plots.
    pub samples: usize,
    /// Keep the input pins of every cycle ([`Report::pins`]: the stimulus of test vectors).
    pub record_pins: bool,
}

impl Options {
    pub fn new(engine: Engine) -> Options {
        Options { engine, vcd: None, compare: Compare::all(), samples: 2000, record_pins: false }
    }
}

/// The chip on one or two engines.
struct Sim {
    model: Option<Tmc429>,
    rtl: Option<Rtl>,
}

impl Sim {
    /// Fails with [`tmc429_testbench::rtl::MISSING`] when the engine needs the RTL and this
    /// build has none.
    fn new(chip: Chip, engine: Engine) -> Result<Sim, String> {
        let model = (engine != Engine::Rtl).then(|| Tmc429::new(chip));
        let rtl = match engine {
            Engine::Model => None,
            _ => Some(Rtl::try_new(Variant::Chip(chip)).map_err(|e| format!("{e}, or use --engine model"))?),
        };
        Ok(Sim { model, rtl })
    }
    fn state(&self) -> (Outputs, Probes) {
        match (&self.model, &self.rtl) {
            (Some(m), _) => (m.outputs(), m.probes()),
            (None, Some(r)) => (r.outputs(), r.probes()),
            _ => unreachable!("a Sim has at least one side"),
        }
    }
}

/// The data pin the µC reads: SDOZ_C while enabled, else nINT_SDO_C.
fn data_pin(o: &Outputs) -> u64 {
    if o.sdoz_c_oe {
        o.sdoz_c as u64
    } else {
        o.nint_sdo_c as u64
    }
}

/// Whether a condition holds in a state.
pub fn holds(c: &Condition, p: &Probes) -> bool {
    match *c {
        Condition::Position { motor, x } => p.motor[motor as usize].x_actual & 0xFF_FFFF == x as u32 & 0xFF_FFFF,
        Condition::Velocity { motor, v } => {
            let vi = p.motor[motor as usize].v_internal;
            vi.signum() * (vi.abs() >> 8) == v
        }
        Condition::AtTarget { motor, yes } => {
            let m = &p.motor[motor as usize];
            (m.x_actual == m.x_target) == yes
        }
        Condition::Stopped { motor, yes } => (p.motor[motor as usize].v_internal == 0) == yes,
        Condition::Int(b) => (p.status >> 7 & 1 == 1) == b,
    }
}

/// A frame waiting for the µC.
struct Queued {
    frame: Frame,
    /// Index of the expectation a read answers.
    read_for: Option<usize>,
}

/// Runs a scenario. `progress(done, total)` is called every 65 536 cycles.
pub fn run(sc: &Scenario, opt: &Options, progress: &mut dyn FnMut(u64, u64)) -> Result<Report, String> {
    let mut sim = Sim::new(sc.chip, opt.engine)?;
    let mut r = Run::new(sc, opt, &sim)?;
    for a in &sc.setup {
        r.enqueue(a);
    }
    r.first_compare();
    r.after_edge(0);
    // The first edge after which `after_edge` has work (every edge while a condition is watched).
    r.due = next_check(sc, &r.fired, &r.results, 0);
    // Edges the model alone can run (no VCD, pins, RTL or frame in flight): see `Idle::edges`.
    let plain = sim.rtl.is_none() && r.vcd.is_none() && r.pins.is_none();
    while r.cycles < sc.duration && r.mismatch.is_none() {
        if plain && r.driver_idle() {
            r.idle_stretch(&mut sim, progress);
        }
        r.edge(&mut sim)?;
        if r.cycles & 0xFFFF == 0 {
            progress(r.cycles, sc.duration);
        }
    }
    progress(r.cycles, sc.duration);
    r.report(&sim)
}

/// A stretch of edges in which nothing but the model acts: the µC driver idle with nothing
/// queued, no VCD, pins or RTL, and no event, check or sample due before edge `limit`. The
/// inputs stay `inputs`; each edge only ticks the model and counts what the run reports.
struct Idle {
    inputs: tmc429_model::Inputs,
    limit: u64,
    /// The run's length, for the progress report.
    duration: u64,
}

impl Idle {
    /// Runs the edges after `cycles` up to, not including, edge `limit` (which the caller's
    /// full edge handles); the outputs of the last edge run, if any. The model's hot loop: kept
    /// a function of its own, so that the compiler's inlining inside it does not depend on
    /// the size of the run loop around it.
    #[allow(clippy::too_many_arguments)]
    #[inline(never)]
    fn edges(
        &self,
        m: &mut Tmc429,
        cycles: &mut u64,
        stats: &mut [MotorStats],
        decoder: &mut EventDecoder,
        datagrams: &mut u64,
        step_pulses: &mut [u64; 3],
        progress: &mut dyn FnMut(u64, u64),
    ) -> Option<Outputs> {
        let mut ran = false;
        let pins = tmc429_model::sync::pack(&self.inputs);
        while *cycles + 1 < self.limit {
            // The edges of the model's fast path change no pin and no motor: nothing to count.
            // They are run at once, up to the next progress report.
            let report = (*cycles | 0xFFFF) + 1;
            let skipped = m.skip_quiet(pins, (self.limit - 1).min(report) - *cycles);
            if skipped == 0 {
                let o = m.tick_full(pins);
                motor_stats(m, stats);
                decoder.observe(m, &o, *cycles + 1, &mut |e| count(e, datagrams, step_pulses));
                *cycles += 1;
            } else {
                *cycles += skipped;
            }
            ran = true;
            if *cycles & 0xFFFF == 0 {
                progress(*cycles, self.duration);
            }
        }
        ran.then(|| m.outputs())
    }
}

/// The run's statistics of the motors after an edge of the model (steps, peak |V|, peak |a|).
#[inline]
fn motor_stats(m: &Tmc429, stats: &mut [MotorStats]) {
    for (k, st) in stats.iter_mut().enumerate() {
        let mm = m.motor(k);
        st.steps += mm.step as u64;
        st.peak_v = st.peak_v.max(mm.v.abs());
        st.peak_a = st.peak_a.max(mm.a_actual.abs());
    }
}

/// Counts a decoded pin event: driver-chain datagrams and Step/Dir pulses.
#[inline]
fn count(e: PinEvent, datagrams: &mut u64, step_pulses: &mut [u64; 3]) {
    match e {
        PinEvent::Chain { .. } => *datagrams += 1,
        PinEvent::Step { motor, .. } => step_pulses[motor as usize] += 1,
        PinEvent::Int { .. } => {}
    }
}

/// The first edge after `cycle` after which the scenario's events and expectations have work:
/// `None` (every edge) while a `when` trigger or a `reached` check waits, else the first pending
/// cycle trigger or `at` of a check after `cycle` (`u64::MAX` if there is none).
fn next_check(sc: &Scenario, fired: &[bool], results: &[Option<ExpectResult>], cycle: u64) -> Option<u64> {
    let mut next = u64::MAX;
    for (ev, _) in sc.events.iter().zip(fired).filter(|(_, f)| !**f) {
        match ev.trigger {
            Trigger::When(_) => return None,
            Trigger::Cycle(c) if c > cycle => next = next.min(c),
            Trigger::Cycle(_) => {}
        }
    }
    for (e, _) in sc.expects.iter().zip(results).filter(|(_, r)| r.is_none()) {
        match e.check {
            Check::Reached { .. } => return None,
            Check::Probes { at, .. } | Check::Register { at, .. } if at > cycle => next = next.min(at),
            _ => {}
        }
    }
    Some(next)
}

fn sample(sc: &Scenario, shadow: &Shadow, p: &Probes, cycle: u64) -> Sample {
    let mut s = Sample { seconds: sc.seconds(cycle), x: [0; 3], v_hz: [0.0; 3], a_hz_per_s: [0.0; 3] };
    for m in 0..3 {
        let (pd, rd, _) = shadow.clk_config(m);
        let mp = &p.motor[m];
        s.x[m] = sext24(mp.x_actual);
        s.v_hz[m] = units::step_rate_hz(sc.fclk as f64, mp.v_internal as f64 / 256.0, pd);
        s.a_hz_per_s[m] = units::accel_hz_per_s(sc.fclk as f64, mp.a_actual as f64, pd, rd);
    }
    s
}

fn mismatch_report(chip: Chip, m: Mismatch) -> String {
    let out = Outcome {
        variant: Variant::Chip(chip),
        seed: 0,
        cycles: m.cycle,
        frames: 0,
        pin_changes: 0,
        mismatch: None,
        coverage: Default::default(),
        vcd_files: Vec::new(),
    };
    out.report(&m).replace(", seed 0)", ")")
}
