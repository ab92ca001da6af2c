//! The state of a run between edges, and one edge of it.

use std::collections::VecDeque;

use tmc429_model::events::EventDecoder;
use tmc429_model::motor_regs::sext24;
use tmc429_model::{Chip, Outputs, Probes};
use tmc429_testbench::cosim::{Mismatch, TxnRecord, HISTORY};
use tmc429_testbench::signals::{agree, diff, flatten};
use tmc429_testbench::stimulus::{Driver, Event, Frame, Phase, Txn};
use tmc429_testbench::vectors::scenario::PinRuns;

use super::{
    count, data_pin, mismatch_report, motor_stats, next_check, sample, Engine, ExpectResult, Idle, MotorStats, Options, Queued, Report,
    Sample, Shadow, Sim,
};
use crate::scenario::{fmt_time, Action, Check, Expect, Scenario, PINS};
use crate::vcdout::VcdWriter;

/// The state of a run between edges: the virtual µC (driver, queue, transactions), the
/// scenario's events and expectations, the statistics and the outputs being written.
pub(super) struct Run<'a> {
    pub(super) sc: &'a Scenario,
    pub(super) opt: &'a Options,
    pub(super) cosim: bool,
    pub(super) shadow: Shadow,
    pub(super) drv: Driver,
    pub(super) queue: VecDeque<Queued>,
    pub(super) current: Option<(TxnRecord, Option<usize>)>,
    pub(super) history: VecDeque<TxnRecord>,
    pub(super) results: Vec<Option<ExpectResult>>,
    pub(super) fired: Vec<bool>,
    pub(super) stats: Vec<MotorStats>,
    pub(super) decoder: EventDecoder,
    pub(super) datagrams: u64,
    pub(super) step_pulses: [u64; 3],
    pub(super) samples: Vec<Sample>,
    pub(super) every: u64,
    pub(super) next_sample: u64,
    pub(super) mismatch: Option<String>,
    pub(super) pins: Option<PinRuns>,
    pub(super) vcd: Option<VcdWriter>,
    /// The model's (or the RTL alone's) pins and probes after the last edge.
    pub(super) mo: Outputs,
    pub(super) mp: Probes,
    /// The RTL's, when it runs.
    pub(super) ro_rp: Option<(Outputs, Probes)>,
    pub(super) cycles: u64,
    pub(super) due: Option<u64>,
}

impl<'a> Run<'a> {
    pub(super) fn new(sc: &'a Scenario, opt: &'a Options, sim: &Sim) -> Result<Run<'a>, String> {
        let chip = sc.chip;
        let cosim = opt.engine == Engine::Cosim;
        let n_motors = if chip == Chip::Tmc4210 { 1 } else { 3 };
        let every = (sc.duration / opt.samples.max(1) as u64).max(1);
        let vcd = match &opt.vcd {
            Some(p) => Some(
                VcdWriter::create(p, sc.fclk, &format!("tmc429 run {}: {} on {}", sc.name, chip, opt.engine.name()), cosim)
                    .map_err(|e| format!("{}: cannot write: {e}", p.display()))?,
            ),
            None => None,
        };
        let (mo, mp) = sim.state();
        Ok(Run {
            sc,
            opt,
            cosim,
            shadow: Shadow::new(chip),
            drv: Driver::default(),
            queue: VecDeque::new(),
            current: None,
            history: VecDeque::new(),
            results: vec![None; sc.expects.len()],
            fired: vec![false; sc.events.len()],
            stats: vec![MotorStats::default(); n_motors],
            decoder: EventDecoder::new(),
            datagrams: 0,
            step_pulses: [0; 3],
            samples: Vec::new(),
            every,
            next_sample: every,
            mismatch: None,
            pins: opt.record_pins.then(PinRuns::new),
            vcd,
            mo,
            mp,
            ro_rp: sim.rtl.as_ref().map(|r| (r.outputs(), r.probes())),
            cycles: 0,
            due: None,
        })
    }

    /// A scenario action: a write becomes a frame in the µC's queue, a pin change applies to
    /// the driver's inputs at once.
    pub(super) fn enqueue(&mut self, a: &Action) {
        match a {
            Action::Write(w) => {
                let data = self.shadow.resolve(w);
                let mut frame = Frame::write(w.a7, data);
                frame.half = self.sc.sck_half;
                self.queue.push_back(Queued { frame, read_for: None });
            }
            Action::Pins(ps) => {
                for &(i, level) in ps {
                    let inp = &mut self.drv.inputs;
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
        }
    }

    /// The co-simulation's comparison of the reset states (before the first edge).
    pub(super) fn first_compare(&mut self) {
        if let (true, Some((ro, rp))) = (self.cosim, self.ro_rp) {
            if !agree(self.opt.compare, &self.mo, &self.mp, &ro, &rp) {
                let m = Mismatch {
                    cycle: 0,
                    diffs: diff(self.opt.compare, &flatten(&self.mo, &self.mp), &flatten(&ro, &rp)),
                    history: Vec::new(),
                };
                self.mismatch = Some(mismatch_report(self.sc.chip, m));
            }
        }
    }

    /// The µC has nothing to send and no frame in flight.
    pub(super) fn driver_idle(&self) -> bool {
        self.queue.is_empty() && self.drv.phase() == Phase::Idle && self.drv.ready() && self.drv.frame().is_none()
    }

    /// The model alone up to the next edge with work ([`Idle::edges`]).
    pub(super) fn idle_stretch(&mut self, sim: &mut Sim, progress: &mut dyn FnMut(u64, u64)) {
        if let (Some(m), Some(c)) = (sim.model.as_mut(), self.due) {
            let limit = c.min(self.next_sample).min(self.sc.duration);
            let run = Idle { inputs: self.drv.inputs, limit, duration: self.sc.duration };
            let (stats, decoder) = (&mut self.stats, &mut self.decoder);
            let (datagrams, step_pulses) = (&mut self.datagrams, &mut self.step_pulses);
            self.mo = run.edges(m, &mut self.cycles, stats, decoder, datagrams, step_pulses, progress).unwrap_or(self.mo);
        }
    }

    /// One edge of the run: the µC driver's pins, the engines, the co-simulation's comparison,
    /// the VCD, a read's result, the scenario's checks and the samples.
    pub(super) fn edge(&mut self, sim: &mut Sim) -> Result<(), String> {
        let n = self.cycles;
        let (inp, ended) = self.driver_edge(n);
        // The probes are read only in the edges that use them: the VCD, the co-simulation, a
        // condition or check of the scenario, a sample; the statistics read the motors directly.
        let checks = self.due.is_none_or(|c| n + 1 >= c);
        let want_probes = self.vcd.is_some() || self.cosim || checks || n + 1 == self.next_sample || n + 1 == self.sc.duration;
        self.engines(sim, &inp, want_probes);
        self.cycles = n + 1;
        let bad = self.compare();
        if let Some(w) = self.vcd.as_mut() {
            let txt = ended.map(|(c, _)| c.short(self.sc.chip));
            let b = self.ro_rp.as_ref().filter(|_| self.cosim).map(|(o, p)| (o, p));
            w.tick(n, &inp, &self.mo, &self.mp, b, bad, txt.as_deref())
                .map_err(|e| format!("{}: cannot write: {e}", w.path().display()))?;
        }
        if let Some((c, Some(i))) = ended {
            self.read_result(&c, i);
        }
        if checks {
            self.after_edge(self.cycles);
            self.due = next_check(self.sc, &self.fired, &self.results, self.cycles);
        }
        if self.cycles == self.next_sample || self.cycles == self.sc.duration {
            self.next_sample += self.every;
            self.samples.push(sample(self.sc, &self.shadow, &self.mp, self.cycles));
        }
        Ok(())
    }

    /// The µC driver's part of edge `n + 1`: the next queued frame starts when the driver is
    /// ready; the pins it drives, and the transaction that ended in this edge.
    pub(super) fn driver_edge(&mut self, n: u64) -> (tmc429_model::Inputs, Option<(TxnRecord, Option<usize>)>) {
        if self.drv.ready() {
            if let Some(q) = self.queue.pop_front() {
                self.current =
                    Some((TxnRecord { start: n + 1, end: 0, frame: q.frame, reply_model: 0, reply_rtl: 0, bits: 0 }, q.read_for));
                self.drv.start(Txn::Frame(q.frame));
            }
        }
        let (inp, ev) = self.drv.step();
        if let Some(p) = self.pins.as_mut() {
            p.push(inp);
        }
        let mut ended = None;
        match ev {
            Event::Sample(_) => {
                if let Some((c, _)) = self.current.as_mut() {
                    c.reply_model = c.reply_model << 1 | data_pin(&self.mo);
                    c.reply_rtl = c.reply_rtl << 1 | self.ro_rp.map(|(ro, _)| data_pin(&ro)).unwrap_or(data_pin(&self.mo));
                    c.bits += 1;
                }
            }
            Event::FrameEnd(_) => {
                if let Some((mut c, r)) = self.current.take() {
                    c.end = n + 1;
                    if self.history.len() == HISTORY {
                        self.history.pop_front();
                    }
                    self.history.push_back(c);
                    ended = Some((c, r));
                }
            }
            Event::None => {}
        }
        (inp, ended)
    }

    /// Both engines' edge with the pins `inp`, and the statistics of the motors.
    pub(super) fn engines(&mut self, sim: &mut Sim, inp: &tmc429_model::Inputs, want_probes: bool) {
        let n = self.cycles;
        if let Some(m) = sim.model.as_mut() {
            self.mo = m.tick(inp);
            if want_probes {
                self.mp = m.probes();
            }
            motor_stats(m, &mut self.stats);
            let (datagrams, step_pulses) = (&mut self.datagrams, &mut self.step_pulses);
            self.decoder.observe(m, &self.mo, n + 1, &mut |e| count(e, datagrams, step_pulses));
        }
        if let Some(r) = sim.rtl.as_mut() {
            let (ro, rp) = (r.tick(inp), r.probes());
            self.ro_rp = Some((ro, rp));
            if sim.model.is_none() {
                (self.mo, self.mp) = (ro, rp);
                for (m, st) in self.stats.iter_mut().enumerate() {
                    let p = &rp.motor[m];
                    st.steps += p.step as u64;
                    st.peak_v = st.peak_v.max(p.v_internal.abs());
                    st.peak_a = st.peak_a.max(p.a_actual.abs());
                }
            }
        }
    }

    /// The co-simulation's comparison after an edge; true on a mismatch (which ends the run).
    pub(super) fn compare(&mut self) -> bool {
        let Some((ro, rp)) = self.ro_rp.filter(|_| self.cosim) else {
            return false;
        };
        if agree(self.opt.compare, &self.mo, &self.mp, &ro, &rp) {
            return false;
        }
        let mut h: Vec<TxnRecord> = self.history.iter().copied().collect();
        if let Some((c, _)) = self.current {
            h.push(c);
            if h.len() > HISTORY {
                h.remove(0);
            }
        }
        let m =
            Mismatch { cycle: self.cycles, diffs: diff(self.opt.compare, &flatten(&self.mo, &self.mp), &flatten(&ro, &rp)), history: h };
        self.mismatch = Some(mismatch_report(self.sc.chip, m));
        true
    }

    /// The report of the finished run.
    pub(super) fn report(mut self, sim: &Sim) -> Result<Report, String> {
        if let Some(w) = self.vcd.take() {
            w.finish()?;
        }
        for (m, st) in self.stats.iter_mut().enumerate() {
            let (pd, rd, us) = self.shadow.clk_config(m);
            (st.pulse_div, st.ramp_div, st.usrs) = (pd, rd, us);
            st.x_actual = sext24(self.mp.motor[m].x_actual);
        }
        let sc = self.sc;
        let stopped = self.mismatch.is_some();
        let expects =
            sc.expects.iter().zip(self.results).map(|(e, r)| r.unwrap_or_else(|| unchecked(sc, e, stopped, self.cycles))).collect();
        Ok(Report {
            name: sc.name.clone(),
            file: sc.file.clone(),
            chip: sc.chip,
            fclk: sc.fclk,
            engine: self.opt.engine,
            cycles: self.cycles,
            motors: self.stats,
            datagrams: sim.model.is_some().then_some(self.datagrams),
            step_pulses: sim.model.is_some().then_some(self.step_pulses),
            expects,
            mismatch: self.mismatch,
            samples: self.samples,
            vcd: self.opt.vcd.clone(),
            pins: self.pins,
        })
    }
}

/// The result of an expectation the run did not decide: failed, with why.
fn unchecked(sc: &Scenario, e: &Expect, stopped: bool, cycles: u64) -> ExpectResult {
    let detail = if stopped {
        "not checked: the co-simulation stopped at a mismatch".into()
    } else if matches!(e.check, Check::Reached { .. }) {
        format!("not reached by the end of the run at {}", fmt_time(sc.seconds(cycles)))
    } else {
        "not checked: the run ended first".into()
    };
    ExpectResult { name: e.name.clone(), line: e.line, passed: false, detail }
}
