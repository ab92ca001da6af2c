//! The chip's pins as a tester or a simulator sees them, for the STIL, EVCD and pin-VCD forms
//! (docs/vectors.md, "Tester forms").
//!
//! The pin-level form has one column per RTL port of `tmc429_chip`: a tri-state pin is two
//! columns, its data and its output enable (`sdoz_c`/`sdoz_c_oe`, `sdi_s_o`/`sdi_s_oe` with
//! the input `sdi_s`). On a board or a tester each is one pin: SDOZ_C ([429] §4.2: high
//! impedance while nSCS_C = 1) and SDI_S (an input; on the TMC429 with en_sd = 1 the output D2,
//! [429] §4.2). [`PINS`] names the pins and the columns each is made of; [`PinState`] is what
//! the pin does in a cycle. The mapping is defined by the column names of
//! [`super::record::chip_layout`], so it follows that layout.

use super::pins::Dir;
use super::record::chip_layout;

/// How a pin is driven.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// The clock: one pulse per line (its rising edge is the line's CLK edge).
    Clock,
    /// Driven by the tester.
    In,
    /// Driven by the chip.
    Out,
    /// Driven by the chip while its enable column is 1, else high impedance.
    TriOut { enable: &'static str },
    /// An input (column `name`) that the chip drives (`out`) while `enable` is 1.
    InOut { out: &'static str, enable: &'static str },
}

/// One pin: its name (the RTL port name) and how its columns make it.
#[derive(Clone, Copy, Debug)]
pub struct Pin {
    pub name: &'static str,
    pub kind: Kind,
}

const fn pin(name: &'static str, kind: Kind) -> Pin {
    Pin { name, kind }
}

/// The pins in file order: the clock, the inputs, the bidirectional SDI_S, the outputs.
pub const PINS: [Pin; 20] = [
    pin("clk", Kind::Clock),
    pin("rst", Kind::In),
    pin("nscs_c", Kind::In),
    pin("sck_c", Kind::In),
    pin("sdi_c", Kind::In),
    pin("ref1", Kind::In),
    pin("ref2", Kind::In),
    pin("ref3", Kind::In),
    pin("refr1", Kind::In),
    pin("refr2", Kind::In),
    pin("refr3", Kind::In),
    pin("sdi_s", Kind::InOut { out: "sdi_s_o", enable: "sdi_s_oe" }),
    pin("nint_sdo_c", Kind::Out),
    pin("sdoz_c", Kind::TriOut { enable: "sdoz_c_oe" }),
    pin("nscs_s", Kind::Out),
    pin("sck_s", Kind::Out),
    pin("sdo_s", Kind::Out),
    pin("nscs2", Kind::Out),
    pin("nscs3", Kind::Out),
    pin("poscmp", Kind::Out),
];

/// What a pin does in one line (one CLK cycle), seen from the tester.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PinState {
    /// The clock pulse (low in the first half of the cycle, high in the second).
    Clock,
    /// The tester drives this level.
    Drive(bool),
    /// The chip drives this level after the line's edge; the tester compares it.
    Expect(bool),
    /// The chip's output is off after the line's edge (high impedance); nobody drives.
    Off,
    /// Bus turnaround of SDI_S: the chip starts driving at this line's edge, so the tester has
    /// stopped; the level after the edge is compared.
    Turn(bool),
}

/// Where a pin's values sit in a line of [`super::record::chip_layout`] values.
#[derive(Clone, Copy, Debug)]
enum Src {
    Clock,
    In(usize),
    Out(usize),
    TriOut { data: usize, enable: usize },
    InOut { data: usize, out: usize, enable: usize },
}

/// Turns the chip's pin-level values, line by line, into pin states.
pub struct PinMapper {
    src: Vec<Src>,
    /// SDI_S enables of the previous line (bus turnaround).
    prev_enable: Vec<bool>,
    /// The last line turned SDI_S around: the same values give other states next time.
    turned: bool,
}

impl Default for PinMapper {
    fn default() -> Self {
        PinMapper::new()
    }
}

impl PinMapper {
    pub fn new() -> PinMapper {
        let layout = chip_layout();
        let col = |name: &str, dir: Dir| {
            layout
                .ports
                .iter()
                .position(|c| c.name == name && c.dir == dir)
                .unwrap_or_else(|| panic!("chip layout has no {dir:?} column {name}"))
        };
        let src: Vec<Src> = PINS
            .iter()
            .map(|p| match p.kind {
                Kind::Clock => Src::Clock,
                Kind::In => Src::In(col(p.name, Dir::In)),
                Kind::Out => Src::Out(col(p.name, Dir::Out)),
                Kind::TriOut { enable } => Src::TriOut { data: col(p.name, Dir::Out), enable: col(enable, Dir::Out) },
                Kind::InOut { out, enable } => {
                    Src::InOut { data: col(p.name, Dir::In), out: col(out, Dir::Out), enable: col(enable, Dir::Out) }
                }
            })
            .collect();
        PinMapper { prev_enable: vec![false; src.len()], src, turned: false }
    }

    /// The states of [`PINS`] for one line of `chip_layout` values (`states.len()` = pins).
    /// Lines must come in order: SDI_S's turnaround depends on the line before.
    #[inline]
    pub fn states(&mut self, v: &[u64], states: &mut [PinState]) {
        self.turned = false;
        for (k, s) in self.src.iter().enumerate() {
            states[k] = match *s {
                Src::Clock => PinState::Clock,
                Src::In(c) => PinState::Drive(v[c] != 0),
                Src::Out(c) => PinState::Expect(v[c] != 0),
                Src::TriOut { data, enable } => {
                    if v[enable] != 0 {
                        PinState::Expect(v[data] != 0)
                    } else {
                        PinState::Off
                    }
                }
                Src::InOut { data, out, enable } => {
                    let (en, was) = (v[enable] != 0, self.prev_enable[k]);
                    self.prev_enable[k] = en;
                    self.turned |= was != en;
                    match (was, en) {
                        (false, false) => PinState::Drive(v[data] != 0),
                        (false, true) => PinState::Turn(v[out] != 0),
                        (true, true) => PinState::Expect(v[out] != 0),
                        (true, false) => PinState::Off,
                    }
                }
            };
        }
    }
}

impl PinMapper {
    /// Whether [`PinMapper::states`] of the same values as the last line gives the same states
    /// (no bus turnaround in the last line).
    pub fn steady(&self) -> bool {
        !self.turned
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn line(f: impl Fn(&str) -> u64) -> Vec<u64> {
        chip_layout().ports.iter().map(|c| f(c.name)).collect()
    }

    #[test]
    fn every_column_is_in_a_pin() {
        let mut used: Vec<&str> = Vec::new();
        for p in PINS {
            match p.kind {
                Kind::Clock => {}
                Kind::In | Kind::Out => used.push(p.name),
                Kind::TriOut { enable } => used.extend([p.name, enable]),
                Kind::InOut { out, enable } => used.extend([p.name, out, enable]),
            }
        }
        let mut cols: Vec<&str> = chip_layout().ports.iter().map(|c| c.name).collect();
        used.sort_unstable();
        cols.sort_unstable();
        assert_eq!(used, cols);
    }

    #[test]
    fn tri_state_and_turnaround() {
        let mut m = PinMapper::new();
        let mut s = [PinState::Clock; PINS.len()];
        let at = |n: &str| PINS.iter().position(|p| p.name == n).unwrap();
        // SDOZ_C off, SDI_S an input at 1
        m.states(&line(|n| (n == "sdoz_c" || n == "sdi_s") as u64), &mut s);
        assert_eq!(s[at("sdoz_c")], PinState::Off);
        assert_eq!(s[at("sdi_s")], PinState::Drive(true));
        assert_eq!(s[at("clk")], PinState::Clock);
        // SDOZ_C drives 1; SDI_S turns to an output driving 1, then stays one, then is released
        let on = line(|n| matches!(n, "sdoz_c" | "sdoz_c_oe" | "sdi_s_o" | "sdi_s_oe") as u64);
        assert!(m.steady());
        m.states(&on, &mut s);
        assert_eq!(s[at("sdoz_c")], PinState::Expect(true));
        assert_eq!(s[at("sdi_s")], PinState::Turn(true));
        assert!(!m.steady());
        m.states(&on, &mut s);
        assert_eq!(s[at("sdi_s")], PinState::Expect(true));
        assert!(m.steady());
        m.states(&line(|_| 0), &mut s);
        assert_eq!(s[at("sdi_s")], PinState::Off);
        assert!(!m.steady());
        m.states(&line(|_| 0), &mut s);
        assert_eq!(s[at("sdi_s")], PinState::Drive(false));
    }
}
