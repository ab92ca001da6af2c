//! What a run produced: per-motor figures, the motion record, the expectations' results.

use std::path::PathBuf;

use tmc429_model::Chip;
use tmc429_testbench::vectors::scenario::PinRuns;

use super::Engine;
use crate::scenario::fmt_time;
use crate::units;

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
    /// The input pins of every cycle run ([`super::Options::record_pins`]).
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
