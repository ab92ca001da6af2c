//! VCD of a scenario run: the input pins and the engine's output pins and probes under the
//! scope names of the co-simulation (`top`, `motor0..2`, `chain`; docs/cosim.md), the µC's SPI frames decoded as
//! strings (`spi.transaction`), and with `--engine cosim` the RTL's side (`rtl.…`) and
//! `cosim.mismatch`. Time unit 1 ps, one CLK period per edge (from fclk); the inputs of edge n
//! change at (n − ½)·T, the outputs after it at n·T, as in `tmc429 cosim`'s VCD.
//!
//! Long runs: `top.clk` and `top.prescaler` change every cycle and are left out (the time axis
//! is the clock: one period per edge), so that the file grows with activity, not with time.

use std::fs::File;
use std::io::{self, BufWriter, Write};
use std::path::Path;

use vcd::{IdCode, TimescaleUnit, VarType, Writer};

use tmc429_model::{Inputs, Outputs, Probes};
use tmc429_testbench::signals::{flatten, N_SIGNALS, SIGNALS};
use tmc429_testbench::vectors::files::Staged;

pub use tmc429_testbench::trace::INPUT_NAMES;
use tmc429_testbench::trace::{add_signals, input_bits, put, put_text};

/// Signals of [`SIGNALS`] not written (they change every cycle).
pub const SKIPPED: [&str; 1] = ["prescaler"];

/// Full names (`scope.name`) of every variable the writer declares, for a run with or without
/// the RTL side.
pub fn variable_names(cosim: bool) -> Vec<String> {
    let mut v: Vec<String> = INPUT_NAMES.iter().map(|n| format!("top.{n}")).collect();
    let sig = |prefix: &str| {
        SIGNALS.iter().filter(|s| !SKIPPED.contains(&s.name)).map(|s| format!("{prefix}{}.{}", s.scope, s.name)).collect::<Vec<_>>()
    };
    v.extend(sig(""));
    v.push("spi.transaction".into());
    if cosim {
        v.extend(sig("rtl."));
        v.push("cosim.mismatch".into());
    }
    v
}

/// A VCD being written under a temporary name ([`Staged`]): [`VcdWriter::finish`] renames it to
/// its target; dropped unfinished (an error during the run), it leaves no file.
pub struct VcdWriter {
    w: Writer<BufWriter<File>>,
    staged: Staged,
    period: u64,
    inputs: [IdCode; 10],
    a: [Option<IdCode>; N_SIGNALS],
    b: Option<[Option<IdCode>; N_SIGNALS]>,
    mismatch: Option<IdCode>,
    txn: IdCode,
    last_in: Option<[bool; 10]>,
    last_a: Option<[u64; N_SIGNALS]>,
    last_b: Option<[u64; N_SIGNALS]>,
    last_mismatch: bool,
}

impl VcdWriter {
    /// Creates the file (under its temporary name) and writes the header; `cosim` adds the RTL
    /// side and the mismatch flag.
    pub fn create(path: &Path, fclk_hz: u64, title: &str, cosim: bool) -> io::Result<VcdWriter> {
        let staged = Staged::new(path);
        let f = File::create(staged.tmp())?;
        let mut w = Writer::new(BufWriter::with_capacity(1 << 20, f));
        w.comment(title)?;
        w.timescale(1, TimescaleUnit::PS)?;
        let mut inputs = [IdCode::FIRST; 10];
        let a = add_signals(&mut w, &SKIPPED, |w| {
            for (k, n) in INPUT_NAMES.iter().enumerate() {
                inputs[k] = w.add_wire(1, n)?;
            }
            Ok(())
        })?;
        w.add_module("spi")?;
        let txn = w.add_var(VarType::String, 1, "transaction", None)?;
        w.upscope()?;
        let (b, mismatch) = if cosim {
            w.add_module("rtl")?;
            let b = add_signals(&mut w, &SKIPPED, |_| Ok(()))?;
            w.upscope()?;
            w.add_module("cosim")?;
            let m = w.add_wire(1, "mismatch")?;
            w.upscope()?;
            (Some(b), Some(m))
        } else {
            (None, None)
        };
        w.enddefinitions()?;
        Ok(VcdWriter {
            w,
            staged,
            period: tmc429_testbench::rtl::period_ps(fclk_hz),
            inputs,
            a,
            b,
            mismatch,
            txn,
            last_in: None,
            last_a: None,
            last_b: None,
            last_mismatch: false,
        })
    }

    /// Records edge `n` (0-based): its inputs and the state after it; `b` is the RTL's side.
    #[allow(clippy::too_many_arguments)]
    pub fn tick(
        &mut self,
        n: u64,
        inp: &Inputs,
        mo: &Outputs,
        mp: &Probes,
        b: Option<(&Outputs, &Probes)>,
        mismatch: bool,
        txn: Option<&str>,
    ) -> io::Result<()> {
        self.inputs_at(n, inp)?;
        let mut fa = flatten(mo, mp);
        let mut fb = b.map(|(o, p)| flatten(o, p));
        // left-out signals must not count as changes
        for k in 0..N_SIGNALS {
            if self.a[k].is_none() {
                fa[k] = 0;
                if let Some(x) = fb.as_mut() {
                    x[k] = 0;
                }
            }
        }
        let changed = self.last_a != Some(fa) || (fb.is_some() && self.last_b != fb) || mismatch != self.last_mismatch || txn.is_some();
        if !changed {
            return Ok(());
        }
        self.w.timestamp((n + 1) * self.period)?;
        for k in 0..N_SIGNALS {
            let wdt = SIGNALS[k].width;
            if let Some(id) = self.a[k] {
                if self.last_a.is_none_or(|l| l[k] != fa[k]) {
                    put(&mut self.w, id, wdt, fa[k])?;
                }
            }
            if let (Some(ids), Some(fb)) = (&self.b, &fb) {
                if let Some(id) = ids[k] {
                    if self.last_b.is_none_or(|l| l[k] != fb[k]) {
                        put(&mut self.w, id, wdt, fb[k])?;
                    }
                }
            }
        }
        self.last_a = Some(fa);
        self.last_b = fb;
        if let Some(id) = self.mismatch {
            if mismatch != self.last_mismatch || n == 0 {
                put(&mut self.w, id, 1, mismatch as u64)?;
            }
            self.last_mismatch = mismatch;
        }
        if let Some(t) = txn {
            put_text(&mut self.w, self.txn, t)?;
        }
        Ok(())
    }

    /// The input pins of edge `n` that changed, half a period before the edge.
    fn inputs_at(&mut self, n: u64, inp: &Inputs) -> io::Result<()> {
        let bits = input_bits(inp);
        if self.last_in != Some(bits) {
            self.w.timestamp(n * self.period + self.period / 2)?;
            for k in 0..10 {
                if self.last_in.is_none_or(|l| l[k] != bits[k]) {
                    put(&mut self.w, self.inputs[k], 1, bits[k] as u64)?;
                }
            }
            self.last_in = Some(bits);
        }
        Ok(())
    }

    /// The target's name.
    pub fn path(&self) -> &Path {
        self.staged.path()
    }

    /// Flushes the file and renames it to its target (errors name the file).
    pub fn finish(mut self) -> Result<(), String> {
        self.w.writer().flush().map_err(|e| format!("{}: cannot write: {e}", self.path().display()))?;
        self.staged.commit().map(drop)
    }
}
