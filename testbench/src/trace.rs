//! VCD of a co-simulation window with the `vcd` crate: the model's pins and probes (scopes
//! `top`, `motor0..2`, `chain`), the inputs, the decoded SPI transactions as strings (scope
//! `spi`), and the RTL's pins and probes side by side (scope `rtl` with the same sub-scopes).
//! Time unit 1 ps, one CLK period per tick (from fclk); the inputs of tick n change at
//! n·T + T/2, the outputs after it at (n+1)·T, as in Verilator's trace of the RTL.

use std::fs::File;
use std::io::{self, BufWriter, Write};
use std::path::Path;

use vcd::{IdCode, TimescaleUnit, Value, VarType, Writer};

use tmc429_model::{Inputs, Outputs, Probes};

use crate::signals::{flatten, N_SIGNALS, SIGNALS};

/// The input pins in the VCD's `top` scope, and their levels in that order.
pub use tmc429_verif::pinword::{input_bits, INPUT_NAMES};

/// Writes the side-by-side VCD.
pub struct TraceWriter {
    w: Writer<BufWriter<File>>,
    period: u64,
    clk: IdCode,
    inputs: [IdCode; 10],
    model: [IdCode; N_SIGNALS],
    rtl: [IdCode; N_SIGNALS],
    mismatch: IdCode,
    txn: IdCode,
    last_in: Option<[bool; 10]>,
    last_model: Option<[u64; N_SIGNALS]>,
    last_rtl: Option<[u64; N_SIGNALS]>,
}

/// The VCD scopes of the compared signals (docs/cosim.md, "The VCD files").
pub const SCOPES: [&str; 5] = ["top", "motor0", "motor1", "motor2", "chain"];

/// Adds the scopes and wires of the compared signals except those named in `skip`; in scope
/// `top` first the wires `extra` adds.
pub fn add_signals(
    w: &mut Writer<BufWriter<File>>,
    skip: &[&str],
    mut extra: impl FnMut(&mut Writer<BufWriter<File>>) -> io::Result<()>,
) -> io::Result<[Option<IdCode>; N_SIGNALS]> {
    let mut ids = [None; N_SIGNALS];
    for scope in SCOPES {
        w.add_module(scope)?;
        if scope == "top" {
            extra(w)?;
        }
        for (k, s) in SIGNALS.iter().enumerate() {
            if s.scope == scope && !skip.contains(&s.name) {
                ids[k] = Some(w.add_wire(s.width, s.name)?);
            }
        }
        w.upscope()?;
    }
    Ok(ids)
}

/// Writes the value `v` of a `width`-bit variable.
pub fn put(w: &mut Writer<BufWriter<File>>, id: IdCode, width: u32, v: u64) -> io::Result<()> {
    if width == 1 {
        w.change_scalar(id, if v & 1 == 1 { Value::V1 } else { Value::V0 })
    } else {
        w.change_vector(id, (0..width).rev().map(|b| if v >> b & 1 == 1 { Value::V1 } else { Value::V0 }))
    }
}

/// Writes a transaction's text to a string variable (blanks become `_`: VCD strings have none).
pub fn put_text(w: &mut Writer<BufWriter<File>>, id: IdCode, text: &str) -> io::Result<()> {
    let s: String = text.chars().map(|c| if c.is_whitespace() { '_' } else { c }).collect();
    w.change_string(id, &s)
}

/// Every compared signal has a wire (nothing skipped).
fn all(ids: [Option<IdCode>; N_SIGNALS]) -> [IdCode; N_SIGNALS] {
    ids.map(|id| id.unwrap_or(IdCode::FIRST))
}

impl TraceWriter {
    /// Creates the file and writes the header. `first_cycle` is the tick whose inputs come first.
    pub fn create(path: &Path, fclk_hz: u64, title: &str) -> io::Result<TraceWriter> {
        let f = File::create(path)?;
        let mut w = Writer::new(BufWriter::new(f));
        w.comment(title)?;
        w.timescale(1, TimescaleUnit::PS)?;
        // the model: scope `top` holds CLK, the inputs, the output pins and global probes
        let mut clk = IdCode::FIRST;
        let mut inputs = [IdCode::FIRST; 10];
        let model = add_signals(&mut w, &[], |w| {
            clk = w.add_wire(1, "clk")?;
            for (k, n) in INPUT_NAMES.iter().enumerate() {
                inputs[k] = w.add_wire(1, n)?;
            }
            Ok(())
        })
        .map(all)?;
        w.add_module("spi")?;
        let txn = w.add_var(VarType::String, 1, "transaction", None)?;
        w.upscope()?;
        w.add_module("rtl")?;
        let rtl = all(add_signals(&mut w, &[], |_| Ok(()))?);
        w.upscope()?;
        w.add_module("cosim")?;
        let mismatch = w.add_wire(1, "mismatch")?;
        w.upscope()?;
        w.enddefinitions()?;
        Ok(TraceWriter {
            w,
            period: crate::rtl::period_ps(fclk_hz),
            clk,
            inputs,
            model,
            rtl,
            mismatch,
            txn,
            last_in: None,
            last_model: None,
            last_rtl: None,
        })
    }

    /// Records tick `n` (0-based): its inputs, the states of both sides after it, and
    /// whether they disagree; `txn` is a decoded transaction that ended in this tick.
    #[allow(clippy::too_many_arguments)]
    pub fn tick(
        &mut self,
        n: u64,
        inp: &Inputs,
        mo: &Outputs,
        mp: &Probes,
        ro: &Outputs,
        rp: &Probes,
        mismatch: bool,
        txn: Option<&str>,
    ) -> io::Result<()> {
        let t_in = n * self.period + self.period / 2;
        self.w.timestamp(t_in)?;
        self.w.change_scalar(self.clk, Value::V0)?;
        let bits = input_bits(inp);
        for k in 0..10 {
            if self.last_in.is_none_or(|l| l[k] != bits[k]) {
                put(&mut self.w, self.inputs[k], 1, bits[k] as u64)?;
            }
        }
        self.last_in = Some(bits);
        self.w.timestamp((n + 1) * self.period)?;
        self.w.change_scalar(self.clk, Value::V1)?;
        let fm = flatten(mo, mp);
        let fr = flatten(ro, rp);
        for k in 0..N_SIGNALS {
            let wdt = SIGNALS[k].width;
            if self.last_model.is_none_or(|l| l[k] != fm[k]) {
                put(&mut self.w, self.model[k], wdt, fm[k])?;
            }
            if self.last_rtl.is_none_or(|l| l[k] != fr[k]) {
                put(&mut self.w, self.rtl[k], wdt, fr[k])?;
            }
        }
        self.last_model = Some(fm);
        self.last_rtl = Some(fr);
        put(&mut self.w, self.mismatch, 1, mismatch as u64)?;
        if let Some(t) = txn {
            put_text(&mut self.w, self.txn, t)?;
        }
        Ok(())
    }

    pub fn finish(mut self) -> io::Result<()> {
        self.w.writer().flush()
    }
}
