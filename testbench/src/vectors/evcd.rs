//! Chip-level vectors as value-change dumps of the pins (docs/vectors.md, "EVCD and pin VCD"):
//! extended VCD (`$dumpports`, IEEE 1364-2005 §18.4) with the direction and strength of every
//! pin, and a plain four-state VCD of the same pins (`0 1 z x`) for a waveform viewer.
//!
//! Time unit 1 ps. Line k occupies [k·T, (k+1)·T) with T the CLK period ([`Timing::of`] of
//! `fclk`): at k·T CLK falls and the tester applies the line's inputs; at k·T + ⌊T/2⌋ CLK rises
//! (the line's edge) and the chip's outputs take the line's values. Before the first edge the
//! outputs are unknown (`X`). The dump ends with CLK falling at n·T.
//!
//! EVCD states: tester side `D` `U` (driven low, high) and `Z` (SDI_S released in the cycle
//! the chip starts driving it), chip side `L` `H` (driven), `T` (high impedance) and `X`
//! (unknown). Strengths are 6 (strong) for a driven level, 0 0 for high impedance.

use std::path::Path;

use super::files::AtomicFile;
use super::pinmap::{PinMapper, PinState, PINS};
use super::pins::Meta;
use super::record::PinForm;
use super::stil::{ascii, Timing};

/// Which dump.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Dialect {
    /// Extended VCD (`$dumpports`), `.evcd`.
    Evcd,
    /// Four-state VCD of the pins, `.vcd`.
    Vcd,
}

const N: usize = PINS.len();
/// The clock's place in [`PINS`].
const CLK: usize = 0;
/// Not yet written.
const NONE: u8 = 0;

/// A pin's dump state (EVCD letter) before and after the line's edge.
fn phases(s: PinState) -> (Option<u8>, Option<u8>) {
    let level = |b: bool, lo: u8, hi: u8| if b { hi } else { lo };
    match s {
        PinState::Clock => (Some(b'D'), Some(b'U')),
        PinState::Drive(b) => (Some(level(b, b'D', b'U')), None),
        PinState::Turn(b) => (Some(b'Z'), Some(level(b, b'L', b'H'))),
        PinState::Expect(b) => (None, Some(level(b, b'L', b'H'))),
        PinState::Off => (None, Some(b'T')),
    }
}

/// The value-change text of one pin state.
#[inline]
fn put(buf: &mut Vec<u8>, d: Dialect, id: usize, s: u8) {
    match d {
        Dialect::Evcd => {
            let strength: &[u8] = match s {
                b'D' | b'L' => b" 6 0 <",
                b'U' | b'H' => b" 0 6 <",
                b'X' => b" 6 6 <",
                _ => b" 0 0 <",
            };
            buf.push(b'p');
            buf.push(s);
            buf.extend_from_slice(strength);
            push_u64(buf, id as u64);
        }
        Dialect::Vcd => {
            buf.push(match s {
                b'D' | b'L' => b'0',
                b'U' | b'H' => b'1',
                b'X' => b'x',
                _ => b'z',
            });
            buf.push(b'!' + id as u8);
        }
    }
    buf.push(b'\n');
}

/// Appends the decimal digits of `n`, two at a time.
fn push_u64(buf: &mut Vec<u8>, mut n: u64) {
    const PAIRS: &[u8; 200] = b"0001020304050607080910111213141516171819202122232425262728293031323334353637383940414243444546474849\
                                5051525354555657585960616263646566676869707172737475767778798081828384858687888990919293949596979899";
    let mut tmp = [0u8; 20];
    let mut i = tmp.len();
    while n >= 100 {
        let d = (n % 100) as usize * 2;
        n /= 100;
        i -= 2;
        tmp[i..i + 2].copy_from_slice(&PAIRS[d..d + 2]);
    }
    if n >= 10 {
        i -= 2;
        tmp[i..i + 2].copy_from_slice(&PAIRS[n as usize * 2..n as usize * 2 + 2]);
    } else {
        i -= 1;
        tmp[i] = b'0' + n as u8;
    }
    buf.extend_from_slice(&tmp[i..]);
}

/// The dump states, in the order of [`Changes`]' table.
const LETTERS: [u8; 7] = *b"DUZLHTX";

/// The value-change line of every pin in every state, formatted once.
struct Changes {
    text: Vec<u8>,
    at: [[(u32, u32); LETTERS.len()]; N],
}

impl Changes {
    fn new(d: Dialect) -> Changes {
        let mut c = Changes { text: Vec::new(), at: [[(0, 0); LETTERS.len()]; N] };
        for k in 0..N {
            for (j, s) in LETTERS.iter().enumerate() {
                let start = c.text.len();
                put(&mut c.text, d, k, *s);
                c.at[k][j] = (start as u32, (c.text.len() - start) as u32);
            }
        }
        c
    }

    #[inline]
    fn line(&self, k: usize, s: u8) -> &[u8] {
        let j = LETTERS.iter().position(|l| *l == s).expect("a dump state");
        let (a, n) = self.at[k][j];
        &self.text[a as usize..(a + n) as usize]
    }
}

/// Everything before the first value change (the timescale on lines of its own, as GTKWave's
/// evcd2vcd reads it).
pub fn header(d: Dialect, meta: &Meta) -> String {
    let mut s = format!(
        "$comment tmc429 chip-level vectors: {} ({}, CHIP = {}), {} Hz; line k = CLK edge k, line 0 the reset edge (docs/vectors.md) $end\n\
         $timescale\n    1ps\n$end\n$scope module tmc429_chip $end\n",
        ascii(&meta.scenario),
        meta.chip,
        meta.chip.rtl_param(),
        meta.fclk
    );
    for (k, p) in PINS.iter().enumerate() {
        match d {
            Dialect::Evcd => s.push_str(&format!("$var port 1 <{k} {} $end\n", p.name)),
            Dialect::Vcd => s.push_str(&format!("$var wire 1 {} {} $end\n", (b'!' + k as u8) as char, p.name)),
        }
    }
    s.push_str("$upscope $end\n$enddefinitions $end\n");
    s
}

/// Chip pins as EVCD or pin VCD, written line by line.
pub struct ChipDump {
    d: Dialect,
    file: AtomicFile,
    map: PinMapper,
    timing: Timing,
    states: [PinState; N],
    changes: Changes,
    /// The values of the last line (a line equal to it, without a bus turnaround, changes only
    /// CLK).
    last: Option<[u64; 22]>,
    /// Each pin's last written state (EVCD letter), [`NONE`] before the first.
    cur: [u8; N],
    line: u64,
    buf: Vec<u8>,
}

impl ChipDump {
    pub fn create(path: &Path, d: Dialect, meta: &Meta) -> Result<ChipDump, String> {
        let mut file = AtomicFile::create(path)?;
        file.write_all(header(d, meta).as_bytes())?;
        Ok(ChipDump {
            d,
            file,
            map: PinMapper::new(),
            timing: Timing::of(meta.fclk),
            states: [PinState::Clock; N],
            changes: Changes::new(d),
            last: None,
            cur: [NONE; N],
            line: 0,
            buf: Vec::with_capacity(1 << 17),
        })
    }

    fn time(&mut self, t: u64) {
        self.buf.push(b'#');
        push_u64(&mut self.buf, t);
        self.buf.push(b'\n');
    }

    #[inline]
    fn set(&mut self, k: usize, s: u8) {
        if self.cur[k] != s {
            self.cur[k] = s;
            self.buf.extend_from_slice(self.changes.line(k, s));
        }
    }

    fn line(&mut self, v: &[u64; 22]) -> Result<(), String> {
        let t0 = self.line * self.timing.period;
        if self.last.as_ref() == Some(v) && self.map.steady() {
            self.time(t0);
            self.set(CLK, b'D');
            self.time(t0 + self.timing.rise);
            self.set(CLK, b'U');
            return self.next();
        }
        self.last = Some(*v);
        self.map.states(v, &mut self.states);
        let first = self.line == 0;
        // before the edge: CLK low, the tester's levels; the chip's outputs unknown at first
        self.time(t0);
        if first {
            self.buf.extend_from_slice(if self.d == Dialect::Evcd { b"$dumpports\n" } else { b"$dumpvars\n" });
        }
        let ph = self.states.map(phases);
        for (k, p) in ph.iter().enumerate() {
            match p.0 {
                Some(s) => self.set(k, s),
                None if first => self.set(k, b'X'),
                None => {}
            }
        }
        if first {
            self.buf.extend_from_slice(b"$end\n");
        }
        // the edge: CLK high, the chip's levels after it
        self.time(t0 + self.timing.rise);
        for (k, p) in ph.iter().enumerate() {
            if let Some(s) = p.1 {
                self.set(k, s);
            }
        }
        self.next()
    }

    fn next(&mut self) -> Result<(), String> {
        self.line += 1;
        self.file.drain(&mut self.buf, 1 << 16)
    }
}

impl PinForm for ChipDump {
    #[inline]
    fn line(&mut self, v: &[u64; 22]) -> Result<(), String> {
        ChipDump::line(self, v)
    }
    fn close(mut self) -> Result<AtomicFile, String> {
        // the end of the last cycle
        let t = self.line * self.timing.period;
        self.time(t);
        self.set(CLK, b'D');
        self.file.drain(&mut self.buf, 0)?;
        Ok(self.file)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn value_changes() {
        let mut b = Vec::new();
        put(&mut b, Dialect::Evcd, 12, b'H');
        put(&mut b, Dialect::Evcd, 0, b'D');
        put(&mut b, Dialect::Evcd, 13, b'T');
        put(&mut b, Dialect::Vcd, 13, b'T');
        put(&mut b, Dialect::Vcd, 1, b'U');
        put(&mut b, Dialect::Vcd, 2, b'X');
        assert_eq!(String::from_utf8(b).unwrap(), "pH 0 6 <12\npD 6 0 <0\npT 0 0 <13\nz.\n1\"\nx#\n");
    }

    #[test]
    fn clk_is_the_first_pin() {
        assert_eq!(crate::vectors::pinmap::PINS[CLK].kind, crate::vectors::pinmap::Kind::Clock);
    }

    #[test]
    fn decimal_times() {
        let mut b = Vec::new();
        for n in [0u64, 7, 10, 99, 100, 15_625, 31_250, 312_499_984_375, u64::MAX] {
            push_u64(&mut b, n);
            b.push(b' ');
        }
        assert_eq!(String::from_utf8(b).unwrap(), format!("0 7 10 99 100 15625 31250 312499984375 {} ", u64::MAX));
    }

    #[test]
    fn clock_and_turnaround_phases() {
        assert_eq!(phases(PinState::Clock), (Some(b'D'), Some(b'U')));
        assert_eq!(phases(PinState::Drive(true)), (Some(b'U'), None));
        assert_eq!(phases(PinState::Expect(false)), (None, Some(b'L')));
        assert_eq!(phases(PinState::Off), (None, Some(b'T')));
        assert_eq!(phases(PinState::Turn(true)), (Some(b'Z'), Some(b'H')));
    }
}
