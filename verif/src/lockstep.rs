//! One side of a lock-step run: the seeded stimulus as pins with the log of its SPI frames
//! ([`PinSource`]), the golden model and the coverage beside it ([`Reference`]), and the
//! first-mismatch report ([`Mismatch::report`]) — what `tmc429 cosim`, the cocotb harness and
//! the DPI-C entry print (docs/cosim.md "Reading a mismatch report").

use std::collections::VecDeque;
use std::fmt::Write as _;

use tmc429_model::{Chip, Inputs, Outputs, Probes, Tmc429};

use crate::coverage::{reg_name, Coverage};
use crate::signals::{diff, flatten, format_value, Compare, Diff};
use crate::stimulus::{Driver, Event, Frame, PinLevels, Profile, Stimulus, Txn};

/// Transactions kept for the mismatch report.
pub const HISTORY: usize = 16;

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
        let w = (self.bits as usize).div_ceil(4).max(1);
        let access = access(chip, &self.frame);
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

/// A frame's access decoded by register name: `W x_target[1] = $0003E8`, `R interrupt[2]`,
/// `8-bit frame $15 (not executed)`.
pub fn access(chip: Chip, f: &Frame) -> String {
    if !f.executes() {
        let sent = if f.nbits <= 32 { (f.datagram as u64) >> (32 - f.nbits as u32) } else { f.datagram as u64 };
        return format!("{}-bit frame ${:0w$X} (not executed)", f.nbits, sent, w = (f.nbits.min(32) as usize).div_ceil(4));
    }
    if f.is_read() {
        format!("R {}", reg_name(chip, f.a7()))
    } else {
        format!("W {} = ${:06X}", reg_name(chip, f.a7()), f.data())
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

impl Mismatch {
    /// The mismatch report: cycle, differing signals, last transactions. `label` names the
    /// design under test (`tmc429+PLANT_BUG_STATUS`, `my_chip`), `chip` the variant whose
    /// register map decodes the transactions.
    pub fn report(&self, label: &str, chip: Chip, seed: u64) -> String {
        let mut s = String::new();
        let _ = writeln!(s, "MISMATCH at cycle {} ({}, seed {}):", self.cycle, label, seed);
        let _ = writeln!(s, "  {:<22} {:<20} rtl", "signal", "model");
        for d in &self.diffs {
            let name = format!("{}.{}", d.signal.scope, d.signal.name);
            let _ = writeln!(s, "  {:<22} {:<20} {}", name, format_value(&d.signal, d.model), format_value(&d.signal, d.rtl));
        }
        let _ = writeln!(s, "last {} SPI transactions (oldest first):", self.history.len());
        for t in &self.history {
            let _ = writeln!(s, "  {}", t.describe(chip));
        }
        s
    }
}

/// The data pin the µC reads: SDOZ_C while enabled, else nINT_SDO_C.
#[inline]
pub fn data_pin(o: &Outputs) -> u64 {
    if o.sdoz_c_oe {
        o.sdoz_c as u64
    } else {
        o.nint_sdo_c as u64
    }
}

/// What one edge of a [`PinSource`] did.
#[derive(Clone, Copy, Debug)]
pub struct Step {
    /// The input pins of this edge.
    pub inputs: Inputs,
    /// The transaction that started with this edge.
    pub started: Option<Txn>,
    /// The SPI frame whose nSCS_C rose with this edge (with both sides' replies).
    pub ended: Option<TxnRecord>,
}

/// The seeded stimulus of `tmc429 cosim` as input pins, one edge at a time, with the log of
/// its SPI frames and the replies both sides put on the data pin.
pub struct PinSource {
    chip: Chip,
    stim: Stimulus,
    drv: Driver,
    /// The SPI frame in progress.
    current: Option<TxnRecord>,
    history: VecDeque<TxnRecord>,
    cycle: u64,
    frames: u64,
    pin_changes: u64,
}

impl PinSource {
    pub fn new(chip: Chip, profile: Profile, seed: u64) -> PinSource {
        PinSource {
            chip,
            stim: Stimulus::new(chip, profile, seed),
            drv: Driver::default(),
            current: None,
            history: VecDeque::with_capacity(HISTORY + 1),
            cycle: 0,
            frames: 0,
            pin_changes: 0,
        }
    }

    pub fn chip(&self) -> Chip {
        self.chip
    }

    /// The input pins before the first edge (idle bus, switches open).
    pub fn idle_inputs(&self) -> Inputs {
        self.drv.inputs
    }

    /// The next edge: the next transaction when the last one is done, the pins of this edge,
    /// and the reply bits the µC samples now — from `model` (the model's outputs after the last
    /// edge) and `dut` (the design's, when it is known).
    #[inline]
    pub fn step(&mut self, model: &Outputs, dut: Option<&Outputs>) -> Step {
        let n = self.cycle;
        self.cycle += 1;
        let mut started = None;
        if self.drv.ready() {
            let t = self.stim.next_txn();
            match &t {
                Txn::Frame(f) => {
                    self.frames += 1;
                    self.current = Some(TxnRecord { start: n + 1, end: 0, frame: *f, reply_model: 0, reply_rtl: 0, bits: 0 });
                }
                Txn::Pins { .. } => self.pin_changes += 1,
                Txn::Idle(_) => {}
            }
            self.drv.start(t);
            started = Some(t);
        }
        let (inputs, ev) = self.drv.step();
        let mut ended = None;
        match ev {
            Event::Sample(_) => {
                if let Some(c) = self.current.as_mut() {
                    c.reply_model = c.reply_model << 1 | data_pin(model);
                    if let Some(d) = dut {
                        c.reply_rtl = c.reply_rtl << 1 | data_pin(d);
                    }
                    c.bits += 1;
                }
            }
            Event::FrameEnd(_) => {
                if let Some(mut c) = self.current.take() {
                    c.end = n + 1;
                    if self.history.len() == HISTORY {
                        self.history.pop_front();
                    }
                    self.history.push_back(c);
                    ended = Some(c);
                }
            }
            Event::None => {}
        }
        Step { inputs, started, ended }
    }

    /// Edges so far.
    pub fn cycle(&self) -> u64 {
        self.cycle
    }

    /// SPI frames started.
    pub fn frames(&self) -> u64 {
        self.frames
    }

    /// Pin-change transactions started.
    pub fn pin_changes(&self) -> u64 {
        self.pin_changes
    }

    /// The first mismatch if the design's outputs `dut` after the last edge differ from the
    /// model's `model` on a pin of `mask` ([`Compare::pins`] or fewer; tri-state data only while
    /// both enable it), with the transaction log; probes are not compared (a design under test
    /// has pins only).
    pub fn check_pins(&self, model: &Outputs, dut: &Outputs, mask: Compare) -> Option<Mismatch> {
        if model == dut {
            return None;
        }
        let p = Probes::default();
        let diffs = diff(mask, &flatten(model, &p), &flatten(dut, &p));
        (!diffs.is_empty()).then(|| Mismatch { cycle: self.cycle, diffs, history: self.history() })
    }

    /// The last [`HISTORY`] frames, oldest first, the one in progress last.
    pub fn history(&self) -> Vec<TxnRecord> {
        let mut h: Vec<TxnRecord> = self.history.iter().copied().collect();
        if let Some(c) = self.current {
            h.push(c);
            if h.len() > HISTORY {
                h.remove(0);
            }
        }
        h
    }
}

/// The golden model driven by a [`PinSource`], with the coverage of `tmc429 cosim`: the
/// reference a design under test is compared against, edge by edge.
pub struct Reference {
    profile: Profile,
    src: PinSource,
    model: Tmc429,
    cov: Coverage,
    /// The model's outputs after the last edge.
    out: Outputs,
}

impl Reference {
    pub fn new(chip: Chip, profile: Profile, seed: u64) -> Reference {
        let src = PinSource::new(chip, profile, seed);
        let model = Tmc429::new(chip);
        let mut cov = Coverage::new(chip, profile);
        let idle = src.idle_inputs();
        cov.set_initial_pins(PinLevels {
            ref_: [idle.ref1, idle.ref2, idle.ref3],
            refr: [idle.refr1, idle.refr2, idle.refr3],
            sdi_s: idle.sdi_s,
        });
        Reference { profile, out: model.outputs(), src, model, cov }
    }

    /// The next edge: the stimulus's pins, the data pin sampled by the µC (from `dut`, the
    /// design's outputs after the last edge, when known), then the model's edge and the
    /// coverage. Returns the inputs, the model's probes after the edge and the frame that ended
    /// with this edge.
    #[inline]
    pub fn step(&mut self, dut: Option<&Outputs>) -> (Inputs, Probes, Option<TxnRecord>) {
        let chip = self.src.chip();
        let s = self.src.step(&self.out, dut);
        if let Some(Txn::Pins { levels, .. }) = &s.started {
            self.cov.pins(levels);
        }
        if let Some(c) = &s.ended {
            self.cov.frame(chip, &c.frame, c.reply_model, &self.model);
        }
        self.out = self.model.tick(&s.inputs);
        let mp = self.model.probes();
        self.cov.cycle(&self.out, &mp);
        self.cov.model(&self.model, &mp);
        if self.profile == Profile::Drivers {
            self.cov.drivers(chip, &self.out, &mp, &self.model);
        }
        (s.inputs, mp, s.ended)
    }

    /// The model's outputs after the last edge.
    pub fn outputs(&self) -> Outputs {
        self.out
    }

    pub fn model(&self) -> &Tmc429 {
        &self.model
    }

    pub fn source(&self) -> &PinSource {
        &self.src
    }

    pub fn coverage(&self) -> &Coverage {
        &self.cov
    }

    pub fn into_coverage(self) -> Coverage {
        self.cov
    }

    /// [`PinSource::check_pins`] of the design's outputs `dut` against the model's.
    pub fn check_pins(&self, dut: &Outputs, mask: Compare) -> Option<Mismatch> {
        self.src.check_pins(&self.out, dut, mask)
    }
}
