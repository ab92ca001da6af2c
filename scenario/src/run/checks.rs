//! The scenario's events and expectations after an edge of a run: triggers that fire their
//! actions, probe and register checks, conditions to be reached.

use tmc429_testbench::cosim::TxnRecord;
use tmc429_testbench::signals::{flatten, SIGNALS};
use tmc429_testbench::stimulus::Frame;

use super::state::Run;
use super::{holds, ExpectResult, Queued};
use crate::scenario::{fmt_time, Check, Expect, Trigger};

impl Run<'_> {
    /// The checks after edge `cycle` (0 = before the first edge), on the state after it.
    pub(super) fn after_edge(&mut self, cycle: u64) {
        let sc = self.sc;
        for (i, ev) in sc.events.iter().enumerate() {
            if self.fired[i] {
                continue;
            }
            let go = match &ev.trigger {
                Trigger::Cycle(c) => *c == cycle,
                Trigger::When(c) => holds(c, &self.mp),
            };
            if go {
                self.fired[i] = true;
                for a in &ev.actions {
                    self.enqueue(a);
                }
            }
        }
        for (i, e) in sc.expects.iter().enumerate() {
            if self.results[i].is_none() {
                self.check(i, e, cycle);
            }
        }
    }

    /// Expectation `i`, `e`, after edge `cycle`: decided here (probes, a condition reached or
    /// not in its window), or a register read queued whose reply decides it ([`Run::read_result`]).
    fn check(&mut self, i: usize, e: &Expect, cycle: u64) {
        let result = |passed: bool, detail: String| Some(ExpectResult { name: e.name.clone(), line: e.line, passed, detail });
        match &e.check {
            Check::Probes { at, values } if *at == cycle => {
                let bad = probe_mismatches(&flatten(&self.mo, &self.mp), values);
                self.results[i] = result(bad.is_empty(), bad.join(", "));
            }
            Check::Register { at, a7, .. } if *at == cycle => {
                let mut frame = Frame::read(*a7);
                frame.half = self.sc.sck_half;
                self.queue.push_back(Queued { frame, read_for: Some(i) });
            }
            Check::Reached { cond, after, within } => {
                if cycle >= *after && holds(cond, &self.mp) {
                    self.results[i] = result(true, format!("at {}", fmt_time(self.sc.seconds(cycle))));
                } else if cycle > after.saturating_add(*within) {
                    self.results[i] = result(false, "not reached".into());
                }
            }
            _ => {}
        }
    }

    /// The reply of the read that answers expectation `i`: its data word (or field) against
    /// the expected value.
    pub(super) fn read_result(&mut self, c: &TxnRecord, i: usize) {
        let e = &self.sc.expects[i];
        if let Check::Register { field, expected, .. } = &e.check {
            let data = (c.reply_model & 0xFF_FFFF) as u32;
            let got = match field {
                Some(f) => f.value(data),
                None => data as i64,
            };
            let ok = got == *expected;
            let detail = if ok { String::new() } else { format!("read {got}") };
            self.results[i] = Some(ExpectResult { name: e.name.clone(), line: e.line, passed: ok, detail });
        }
    }
}

/// The probes of `flat` (pins and probes, [`SIGNALS`] order) that differ from the expected
/// `values`, each as `scope.name is VALUE` (signed, or 24-bit positions, in decimal with sign).
fn probe_mismatches(flat: &[u64], values: &[(usize, i64)]) -> Vec<String> {
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
    bad
}
