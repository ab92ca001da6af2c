//! Runs a [`Scenario`] on an engine: the golden model, the Verilated RTL, or both in
//! lock-step (co-simulation). A virtual µC drives the chip's SPI pins (the co-simulation's
//! pin [`Driver`]); the scenario's writes, reads and switch changes become pin activity, the
//! same on every engine.

use std::collections::VecDeque;
use std::path::PathBuf;

use tmc429_model::events::{Event as PinEvent, EventDecoder};
use tmc429_model::regmap::{self, Access, Space};
use tmc429_model::{Chip, Outputs, Probes, Tmc429};
use tmc429_testbench::cosim::{Mismatch, Outcome, TxnRecord, HISTORY};
use tmc429_testbench::rtl::{Rtl, Variant};
use tmc429_testbench::signals::{agree, diff, flatten, Compare, SIGNALS};
use tmc429_testbench::stimulus::{Driver, Event, Frame, Phase, Txn};
use tmc429_testbench::vectors::scenario::PinRuns;

use crate::scenario::{fmt_time, Action, Check, Condition, Scenario, Trigger, WriteData, PINS};
use crate::units;
use crate::vcdout::VcdWriter;

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

/// Per-motor figures of a run.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct MotorStats {
    /// Step pulses of the pulse generator (microsteps).
    pub steps: u64,
    /// Largest |internal velocity| (1/256 velocity units).
    pub peak_v: i32,
    /// Largest |a_actual| (velocity change of one ramp tick, 1/256 units).
    pub peak_a: i32,
    /// Dividers and microstep resolution as last written.
    pub pulse_div: u32,
    pub ramp_div: u32,
    pub usrs: u32,
    /// Final position.
    pub x_actual: i32,
}

impl MotorStats {
    pub fn peak_hz(&self, fclk: u64) -> f64 {
        units::step_rate_hz(fclk as f64, self.peak_v as f64 / 256.0, self.pulse_div)
    }
    pub fn peak_accel_hz_per_s(&self, fclk: u64) -> f64 {
        units::accel_hz_per_s(fclk as f64, self.peak_a as f64, self.pulse_div, self.ramp_div)
    }
}

/// One point of the motion record.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sample {
    pub seconds: f64,
    pub x: [i32; 3],
    pub v_hz: [f64; 3],
    pub a_hz_per_s: [f64; 3],
}

#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ExpectResult {
    pub name: String,
    pub line: usize,
    pub passed: bool,
    /// What was found (for a failure) or when it held.
    pub detail: String,
}

/// Everything a run produced.
#[derive(Clone, Debug)]
pub struct Report {
    pub name: String,
    pub file: String,
    pub chip: Chip,
    pub fclk: u64,
    pub engine: Engine,
    /// CLK edges simulated.
    pub cycles: u64,
    pub motors: Vec<MotorStats>,
    /// Driver-chain datagrams (decoded from the pins; needs the model side).
    pub datagrams: Option<u64>,
    /// Step/Dir pulses per motor (decoded from the pins; needs the model side).
    pub step_pulses: Option<[u64; 3]>,
    pub expects: Vec<ExpectResult>,
    /// The first co-simulation mismatch and its report.
    pub mismatch: Option<String>,
    pub samples: Vec<Sample>,
    pub vcd: Option<PathBuf>,
    /// The input pins of every cycle run ([`Options::record_pins`]).
    pub pins: Option<PinRuns>,
}

impl Report {
    pub fn failed(&self) -> Vec<&ExpectResult> {
        self.expects.iter().filter(|e| !e.passed).collect()
    }
    pub fn ok(&self) -> bool {
        self.mismatch.is_none() && self.expects.iter().all(|e| e.passed)
    }

    /// The summary `tmc429 run` and `tmc429 demo` print.
    pub fn summary(&self) -> String {
        use std::fmt::Write as _;
        let mut s = String::new();
        let _ = writeln!(s, "scenario {} ({}, {} MHz, engine {})", self.name, self.chip, self.fclk as f64 / 1e6, self.engine.name());
        let _ = writeln!(s, "cycles:       {} ({})", self.cycles, fmt_time(self.cycles as f64 / self.fclk as f64));
        for (m, st) in self.motors.iter().enumerate() {
            let _ = write!(
                s,
                "motor {m}:      {} steps, x_actual {}, peak velocity {:.1} Hz, peak acceleration {:.1} Hz/s",
                st.steps,
                st.x_actual,
                st.peak_hz(self.fclk),
                st.peak_accel_hz_per_s(self.fclk)
            );
            if let Some(p) = self.step_pulses {
                if p[m] > 0 {
                    let _ = write!(s, ", {} STEP pulses", p[m]);
                }
            }
            s.push('\n');
        }
        match self.datagrams {
            Some(d) => {
                let _ = writeln!(s, "datagrams:    {d} (driver chain)");
            }
            None => {
                let _ = writeln!(s, "datagrams:    not counted (needs the model side)");
            }
        }
        if self.engine == Engine::Cosim {
            let _ = writeln!(s, "mismatches:   {}", self.mismatch.is_some() as u32);
        }
        let passed = self.expects.iter().filter(|e| e.passed).count();
        let _ = writeln!(s, "expectations: {passed} of {} passed", self.expects.len());
        for e in &self.expects {
            let _ = writeln!(
                s,
                "  {} {}:{}: {}{}",
                if e.passed { "ok  " } else { "FAIL" },
                self.file,
                e.line,
                e.name,
                if e.detail.is_empty() { String::new() } else { format!(" ({})", e.detail) }
            );
        }
        if let Some(m) = &self.mismatch {
            s.push_str(m);
        }
        if let Some(v) = &self.vcd {
            let _ = writeln!(s, "vcd: {}", v.display());
        }
        s
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

fn sext24(v: u32) -> i32 {
    ((v << 8) as i32) >> 8
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

/// Register values as the scenario last wrote them (power-on values at first): the base of
/// field writes, and the dividers for physical units. The Python package's virtual µC writes
/// fields the same way.
pub struct Shadow {
    words: [u32; 128],
}

impl Shadow {
    pub fn new(chip: Chip) -> Shadow {
        let mut words = [0u32; 128];
        for (a7, w) in words.iter_mut().enumerate() {
            if let Some((r, _)) = regmap::lookup(chip, a7 as u8) {
                if r.space != Space::Ram && r.name != "cover_pos_len" {
                    *w = r.reset & r.writable_mask();
                }
            }
        }
        Shadow { words }
    }
    fn clk_config(&self, m: usize) -> (u32, u32, u32) {
        let w = self.words[regmap::motor_a7(m as u8, regmap::idx::CLK_CONFIG) as usize];
        (regmap::f::PULSE_DIV.get(w), regmap::f::RAMP_DIV.get(w), regmap::f::USRS.get(w))
    }
    /// The data word of a write, from the shadow; updates the shadow.
    pub fn resolve(&mut self, w: &crate::scenario::Write) -> u32 {
        let old = self.words[w.a7 as usize];
        // W1C fields write 0 (keep the flag) unless named
        let w1c = w.reg.fields.iter().filter(|f| f.access == Access::W1c).fold(0, |m, f| m | f.mask());
        let data = match &w.data {
            WriteData::Whole(d) => *d,
            WriteData::Fields(fs) => fs.iter().fold(old & !w1c, |d, (f, v)| (d & !f.mask()) | f.put(*v)),
            WriteData::AutoPmul(red) => {
                let m = w.motor.unwrap_or(0);
                let a_max = regmap::f::A_MAX.get(self.words[regmap::motor_a7(m, regmap::idx::A_MAX) as usize]);
                let (pd, rd, _) = self.clk_config(m as usize);
                let r = tmc429_model::pmulpdiv::calc(a_max as i32, rd as i32, pd as i32, *red);
                r.register_value().unwrap_or(old)
            }
        };
        self.words[w.a7 as usize] = data & !w1c & 0xFF_FFFF;
        data & 0xFF_FFFF
    }
}

/// Runs a scenario. `progress(done, total)` is called every 65 536 cycles.
pub fn run(sc: &Scenario, opt: &Options, progress: &mut dyn FnMut(u64, u64)) -> Result<Report, String> {
    let chip = sc.chip;
    let mut sim = Sim::new(chip, opt.engine)?;
    let cosim = opt.engine == Engine::Cosim;
    let n_motors = if chip == Chip::Tmc4210 { 1 } else { 3 };
    let mut shadow = Shadow::new(chip);
    let mut drv = Driver::default();
    let mut queue: VecDeque<Queued> = VecDeque::new();
    let mut current: Option<(TxnRecord, Option<usize>)> = None;
    let mut history: VecDeque<TxnRecord> = VecDeque::new();
    let mut results: Vec<Option<ExpectResult>> = vec![None; sc.expects.len()];
    let mut fired = vec![false; sc.events.len()];
    let mut stats = vec![MotorStats::default(); n_motors];
    let mut decoder = EventDecoder::new();
    let mut datagrams = 0u64;
    let mut step_pulses = [0u64; 3];
    let mut samples = Vec::new();
    let every = (sc.duration / opt.samples.max(1) as u64).max(1);
    let mut next_sample = every;
    let mut mismatch: Option<String> = None;
    let mut pins = opt.record_pins.then(PinRuns::new);

    let mut vcd = match &opt.vcd {
        Some(p) => Some(
            VcdWriter::create(p, sc.fclk, &format!("tmc429 run {}: {} on {}", sc.name, chip, opt.engine.name()), cosim)
                .map_err(|e| format!("{}: cannot write: {e}", p.display()))?,
        ),
        None => None,
    };

    let enqueue_action = |a: &Action, queue: &mut VecDeque<Queued>, drv: &mut Driver, shadow: &mut Shadow| match a {
        Action::Write(w) => {
            let data = shadow.resolve(w);
            let mut frame = Frame::write(w.a7, data);
            frame.half = sc.sck_half;
            queue.push_back(Queued { frame, read_for: None });
        }
        Action::Pins(ps) => {
            for &(i, level) in ps {
                let inp = &mut drv.inputs;
                match PINS[i] {
                    "ref1" => inp.ref1 = level,
                    "ref2" => inp.ref2 = level,
                    "ref3" => inp.ref3 = level,
                    "refr1" => inp.refr1 = level,
                    "refr2" => inp.refr2 = level,
                    "refr3" => inp.refr3 = level,
                    _ => inp.sdi_s = level,
                }
            }
        }
    };
    for a in &sc.setup {
        enqueue_action(a, &mut queue, &mut drv, &mut shadow);
    }

    let (mut mo, mut mp) = sim.state();
    let mut ro_rp: Option<(Outputs, Probes)> = sim.rtl.as_ref().map(|r| (r.outputs(), r.probes()));
    if cosim {
        let (ro, rp) = ro_rp.unwrap();
        if !agree(opt.compare, &mo, &mp, &ro, &rp) {
            let m = Mismatch { cycle: 0, diffs: diff(opt.compare, &flatten(&mo, &mp), &flatten(&ro, &rp)), history: Vec::new() };
            mismatch = Some(mismatch_report(chip, m));
        }
    }

    // the checks after edge `cycle` (0 = before the first edge)
    let after_edge = |cycle: u64,
                      p: &Probes,
                      o: &Outputs,
                      queue: &mut VecDeque<Queued>,
                      drv: &mut Driver,
                      shadow: &mut Shadow,
                      fired: &mut [bool],
                      results: &mut [Option<ExpectResult>]| {
        for (i, ev) in sc.events.iter().enumerate() {
            if fired[i] {
                continue;
            }
            let go = match &ev.trigger {
                Trigger::Cycle(c) => *c == cycle,
                Trigger::When(c) => holds(c, p),
            };
            if go {
                fired[i] = true;
                for a in &ev.actions {
                    enqueue_action(a, queue, drv, shadow);
                }
            }
        }
        for (i, e) in sc.expects.iter().enumerate() {
            if results[i].is_some() {
                continue;
            }
            match &e.check {
                Check::Probes { at, values } if *at == cycle => {
                    let flat = flatten(o, p);
                    let mut bad = Vec::new();
                    for &(k, want) in values {
                        let s = &SIGNALS[k];
                        let mask = if s.width >= 64 { u64::MAX } else { (1u64 << s.width) - 1 };
                        if flat[k] != (want as u64) & mask {
                            let got = if s.signed || s.width == 24 {
                                let sh = 64 - s.width;
                                (((flat[k] << sh) as i64) >> sh).to_string()
                            } else {
                                flat[k].to_string()
                            };
                            bad.push(format!("{}.{} is {got}", s.scope, s.name));
                        }
                    }
                    results[i] = Some(ExpectResult { name: e.name.clone(), line: e.line, passed: bad.is_empty(), detail: bad.join(", ") });
                }
                Check::Register { at, a7, .. } if *at == cycle => {
                    let mut frame = Frame::read(*a7);
                    frame.half = sc.sck_half;
                    queue.push_back(Queued { frame, read_for: Some(i) });
                }
                Check::Reached { cond, after, within } => {
                    if cycle >= *after && holds(cond, p) {
                        results[i] = Some(ExpectResult {
                            name: e.name.clone(),
                            line: e.line,
                            passed: true,
                            detail: format!("at {}", fmt_time(sc.seconds(cycle))),
                        });
                    } else if cycle > after.saturating_add(*within) {
                        results[i] = Some(ExpectResult { name: e.name.clone(), line: e.line, passed: false, detail: "not reached".into() });
                    }
                }
                _ => {}
            }
        }
    };
    after_edge(0, &mp, &mo, &mut queue, &mut drv, &mut shadow, &mut fired, &mut results);
    // The first edge after which `after_edge` has work (every edge while a condition is watched).
    let mut due = next_check(sc, &fired, &results, 0);

    let mut cycles = 0u64;
    // Edges the model alone can run (no VCD, pins, RTL or frame in flight): see `Idle::edges`.
    let plain = sim.rtl.is_none() && vcd.is_none() && pins.is_none();
    while cycles < sc.duration && mismatch.is_none() {
        if plain && queue.is_empty() && drv.phase() == Phase::Idle && drv.ready() && drv.frame().is_none() {
            if let (Some(m), Some(c)) = (sim.model.as_mut(), due) {
                let limit = c.min(next_sample).min(sc.duration);
                let run = Idle { inputs: drv.inputs, limit, duration: sc.duration };
                mo = run.edges(m, &mut cycles, &mut stats, &mut decoder, &mut datagrams, &mut step_pulses, progress).unwrap_or(mo);
            }
        }
        let n = cycles;
        if drv.ready() {
            if let Some(q) = queue.pop_front() {
                current = Some((TxnRecord { start: n + 1, end: 0, frame: q.frame, reply_model: 0, reply_rtl: 0, bits: 0 }, q.read_for));
                drv.start(Txn::Frame(q.frame));
            }
        }
        let (inp, ev) = drv.step();
        if let Some(p) = pins.as_mut() {
            p.push(inp);
        }
        let mut ended: Option<(TxnRecord, Option<usize>)> = None;
        match ev {
            Event::Sample(_) => {
                if let Some((c, _)) = current.as_mut() {
                    c.reply_model = c.reply_model << 1 | data_pin(&mo);
                    c.reply_rtl = c.reply_rtl << 1 | ro_rp.map(|(ro, _)| data_pin(&ro)).unwrap_or(data_pin(&mo));
                    c.bits += 1;
                }
            }
            Event::FrameEnd(_) => {
                if let Some((mut c, r)) = current.take() {
                    c.end = n + 1;
                    if history.len() == HISTORY {
                        history.pop_front();
                    }
                    history.push_back(c);
                    ended = Some((c, r));
                }
            }
            Event::None => {}
        }
        // one edge
        // The probes are read only in the edges that use them: the VCD, the co-simulation, a
        // condition or check of the scenario, a sample; the statistics read the motors directly.
        let checks = due.is_none_or(|c| n + 1 >= c);
        let want_probes = vcd.is_some() || cosim || checks || n + 1 == next_sample || n + 1 == sc.duration;
        if let Some(m) = sim.model.as_mut() {
            mo = m.tick(&inp);
            if want_probes {
                mp = m.probes();
            }
            motor_stats(m, &mut stats);
            decoder.observe(m, &mo, n + 1, &mut |e| count(e, &mut datagrams, &mut step_pulses));
        }
        if let Some(r) = sim.rtl.as_mut() {
            let ro = r.tick(&inp);
            let rp = r.probes();
            ro_rp = Some((ro, rp));
            if sim.model.is_none() {
                (mo, mp) = (ro, rp);
            }
        }
        cycles = n + 1;
        let mut bad = false;
        if cosim {
            let (ro, rp) = ro_rp.unwrap();
            if !agree(opt.compare, &mo, &mp, &ro, &rp) {
                bad = true;
                let mut h: Vec<TxnRecord> = history.iter().copied().collect();
                if let Some((c, _)) = current {
                    h.push(c);
                    if h.len() > HISTORY {
                        h.remove(0);
                    }
                }
                let m = Mismatch { cycle: cycles, diffs: diff(opt.compare, &flatten(&mo, &mp), &flatten(&ro, &rp)), history: h };
                mismatch = Some(mismatch_report(chip, m));
            }
        }
        if sim.model.is_none() {
            for (m, st) in stats.iter_mut().enumerate() {
                let p = &mp.motor[m];
                st.steps += p.step as u64;
                st.peak_v = st.peak_v.max(p.v_internal.abs());
                st.peak_a = st.peak_a.max(p.a_actual.abs());
            }
        }
        if let Some(w) = vcd.as_mut() {
            let txt = ended.map(|(c, _)| c.short(chip));
            let b = ro_rp.as_ref().filter(|_| cosim).map(|(o, p)| (o, p));
            w.tick(n, &inp, &mo, &mp, b, bad, txt.as_deref()).map_err(|e| format!("{}: cannot write: {e}", w.path().display()))?;
        }
        if let Some((c, Some(i))) = ended {
            if let Check::Register { reg, field, expected, .. } = &sc.expects[i].check {
                let data = (c.reply_model & 0xFF_FFFF) as u32;
                let (got, ok) = match field {
                    Some(f) => (f.value(data), f.value(data) == *expected),
                    None => (data as i64, data as i64 == *expected),
                };
                let e = &sc.expects[i];
                let _ = reg;
                results[i] = Some(ExpectResult {
                    name: e.name.clone(),
                    line: e.line,
                    passed: ok,
                    detail: if ok { String::new() } else { format!("read {got}") },
                });
            }
        }
        if checks {
            after_edge(cycles, &mp, &mo, &mut queue, &mut drv, &mut shadow, &mut fired, &mut results);
            due = next_check(sc, &fired, &results, cycles);
        }
        if cycles == next_sample || cycles == sc.duration {
            next_sample += every;
            samples.push(sample(sc, &shadow, &mp, cycles));
        }
        if cycles & 0xFFFF == 0 {
            progress(cycles, sc.duration);
        }
    }
    progress(cycles, sc.duration);

    if let Some(w) = vcd.take() {
        w.finish()?;
    }
    for (m, st) in stats.iter_mut().enumerate() {
        let (pd, rd, us) = shadow.clk_config(m);
        (st.pulse_div, st.ramp_div, st.usrs) = (pd, rd, us);
        st.x_actual = sext24(mp.motor[m].x_actual);
    }
    let expects = sc
        .expects
        .iter()
        .zip(results)
        .map(|(e, r)| {
            r.unwrap_or_else(|| ExpectResult {
                name: e.name.clone(),
                line: e.line,
                passed: false,
                detail: if mismatch.is_some() {
                    "not checked: the co-simulation stopped at a mismatch".into()
                } else if matches!(e.check, Check::Reached { .. }) {
                    format!("not reached by the end of the run at {}", fmt_time(sc.seconds(cycles)))
                } else {
                    "not checked: the run ended first".into()
                },
            })
        })
        .collect();
    Ok(Report {
        name: sc.name.clone(),
        file: sc.file.clone(),
        chip,
        fclk: sc.fclk,
        engine: opt.engine,
        cycles,
        motors: stats,
        datagrams: sim.model.is_some().then_some(datagrams),
        step_pulses: sim.model.is_some().then_some(step_pulses),
        expects,
        mismatch,
        samples,
        vcd: opt.vcd.clone(),
        pins,
    })
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
    /// full edge handles); the outputs of the last edge run, if any.
    #[allow(clippy::too_many_arguments)]
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
            // An edge of the model's fast path changes no pin and no motor: nothing to count.
            if let Some(o) = m.tick_changes(pins) {
                motor_stats(m, stats);
                decoder.observe(m, &o, *cycles + 1, &mut |e| count(e, datagrams, step_pulses));
            }
            *cycles += 1;
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
