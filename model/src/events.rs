//! Events decoded from the chip's pins, as `tmc429 spi --events` prints them and the C library
//! queues them: driver-chain datagrams (sniffed on nSCS_S/nSCS2/nSCS3, SCK_S, SDO_S), Step/Dir
//! steps (from the STEP and DIR pins) and changes of INT.
//!
//! The decoder looks only at pins and at the configuration registers that give the pins their
//! meaning (polarities, en_sd, step_half, inv_stp, inv_dir), so what it reports is what a
//! logic analyser on the board would see.

use std::fmt;

use crate::regmap::f;
use crate::{Chip, Global, Outputs, Tmc429};

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Event {
    /// A datagram sent to the driver chain: `nbits` bits, first bit sent in bit `nbits − 1`.
    Chain { cycle: u64, nbits: u32, bits: u64 },
    /// A step pulse on the Step/Dir interface of motor 0..2; `negative` from DIR.
    Step { cycle: u64, motor: u8, negative: bool },
    /// INT changed to `level`.
    Int { cycle: u64, level: bool },
}

impl Event {
    pub fn cycle(&self) -> u64 {
        match *self {
            Event::Chain { cycle, .. } | Event::Step { cycle, .. } | Event::Int { cycle, .. } => cycle,
        }
    }
}

impl fmt::Display for Event {
    fn fmt(&self, fm: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Event::Chain { cycle, nbits, bits } => {
                let digits = nbits.div_ceil(4).max(1) as usize;
                write!(fm, "chain {cycle} {nbits} {bits:0digits$X}")
            }
            Event::Step { cycle, motor, negative } => {
                write!(fm, "step {cycle} {motor} {}", if negative { '-' } else { '+' })
            }
            Event::Int { cycle, level } => write!(fm, "int {cycle} {}", level as u8),
        }
    }
}

/// Pin-level decoder. Feed it after every edge with [`EventDecoder::observe`].
#[derive(Clone, Debug)]
pub struct EventDecoder {
    prev: Option<Outputs>,
    int: bool,
    /// Chain frame in progress: bits so far (beyond 64 only the last 64 are kept) and count.
    frame: Option<(u64, u32)>,
    /// Last STEP level per motor (as on the pin).
    step_level: [bool; 3],
    /// Step/Dir mode of the previous edge (a mode change resynchronizes the levels).
    step_dir_prev: bool,
}

impl Default for EventDecoder {
    fn default() -> Self {
        Self::new()
    }
}

impl EventDecoder {
    pub fn new() -> Self {
        EventDecoder { prev: None, int: false, frame: None, step_level: [false; 3], step_dir_prev: false }
    }

    /// Decodes the edge just made (`cycle` = index of that edge) from the chip and its outputs.
    #[inline]
    pub fn observe(&mut self, chip: &Tmc429, out: &Outputs, cycle: u64, sink: &mut impl FnMut(Event)) {
        let int = chip.int();
        if int != self.int {
            self.int = int;
            sink(Event::Int { cycle, level: int });
        }
        let step_dir = chip.chip() != Chip::Tmc428 && chip.global().ifc(f::EN_SD);
        let mode_changed = step_dir != self.step_dir_prev;
        if !mode_changed && self.prev.as_ref() == Some(out) {
            // No pin changed: no step, no chain bit, no chip-select edge.
            return;
        }
        self.pins_changed(chip, out, cycle, step_dir, mode_changed, sink);
    }

    /// The part of [`EventDecoder::observe`] for an edge that changed a pin or the mode: out of
    /// line, so that the per-edge check in `observe` stays small where it is inlined.
    #[inline(never)]
    fn pins_changed(&mut self, chip: &Tmc429, out: &Outputs, cycle: u64, step_dir: bool, mode_changed: bool, sink: &mut impl FnMut(Event)) {
        let g = chip.global();
        self.step_dir_prev = step_dir;
        let prev = match self.prev.replace(*out) {
            Some(p) => p,
            None => {
                self.step_level = step_pins(out);
                return;
            }
        };
        if step_dir && mode_changed {
            self.frame = None;
            self.step_level = step_pins(out);
            return;
        }
        if step_dir {
            self.step_pulses(chip, out, cycle, sink);
            return;
        }
        self.step_level = step_pins(out);
        if chip.chip() == Chip::Tmc4210 {
            return;
        }
        self.chain_frames(g, out, &prev, cycle, sink);
    }

    /// Step/Dir mode: a Step event for each motor whose STEP pin made an active edge (both
    /// edges with step_half, C93), with its DIR level.
    fn step_pulses(&mut self, chip: &Tmc429, out: &Outputs, cycle: u64, sink: &mut impl FnMut(Event)) {
        let g = chip.global();
        self.frame = None;
        let lv = step_pins(out);
        let dirs = dir_pins(out);
        let half = g.ifc(f::STEP_HALF);
        let active = !g.ifc(f::INV_STP);
        let inv_dir = g.ifc(f::INV_DIR);
        let n = if chip.chip() == Chip::Tmc4210 { 1 } else { 3 };
        for m in 0..n {
            let was = self.step_level[m];
            let now = lv[m];
            let stepped = if half { was != now } else { !was && now == active };
            if stepped {
                sink(Event::Step { cycle, motor: m as u8, negative: dirs[m] ^ inv_dir });
            }
        }
        self.step_level = lv;
    }

    /// SPI mode: the bits of a datagram on SDO_S at the rising SCK_S edges while a chip select
    /// is active (C81, C84), one Chain event when the select ends.
    fn chain_frames(&mut self, g: &Global, out: &Outputs, prev: &Outputs, cycle: u64, sink: &mut impl FnMut(Event)) {
        // SPI chain: chip select active when any of nSCS_S, nSCS2, nSCS3 is active.
        let cs_high_active = g.g(f::POL_NSCS_S) != 0 && g.g(f::CS_COM_IND) == 0;
        let cs = |o: &Outputs| {
            if cs_high_active {
                o.nscs_s
            } else {
                !o.nscs_s || !o.nscs2 || !o.nscs3
            }
        };
        let sck_inv = g.g(f::POL_SCK_S) != 0;
        let (cs_now, cs_was) = (cs(out), cs(prev));
        if cs_now && !cs_was {
            self.frame = Some((0, 0));
        }
        if let Some((bits, n)) = self.frame.as_mut() {
            let sck_rose = (out.sck_s ^ sck_inv) && !(prev.sck_s ^ sck_inv);
            if sck_rose && cs_was {
                *bits = (*bits << 1) | prev.sdo_s as u64;
                *n += 1;
            }
        }
        if !cs_now && cs_was {
            if let Some((bits, n)) = self.frame.take() {
                if n > 0 {
                    sink(Event::Chain { cycle, nbits: n, bits });
                }
            }
        }
    }
}

/// STEP1..3 levels as on the pins (TMC429 §10: S1 = SDO_S, S2 = nSCS_S, S3 = nSCS2).
fn step_pins(o: &Outputs) -> [bool; 3] {
    [o.sdo_s, o.nscs_s, o.nscs2]
}

/// DIR1..3 levels as on the pins (D1 = SCK_S, D2 = SDI_S, D3 = nSCS3).
fn dir_pins(o: &Outputs) -> [bool; 3] {
    [o.sck_s, o.sdi_s_o, o.nscs3]
}
