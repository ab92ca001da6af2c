//! Pin-level vectors: `.hex` (one `$readmemh` word per CLK cycle), `.cols` (the columns of the
//! word, `name width in|out` per line) and `.meta` (`key value` lines). docs/vectors.md.
//!
//! A line is the word `{_sentinel, inputs…, outputs…, _check}`, most significant first, written
//! as exactly `width / 4` hex digits:
//! - `_sentinel` (4 bits, always `A`): a line with missing digits loses it (`$readmemh` fills
//!   the top with zeros), so a truncated line is detected, not replayed;
//! - `_check` (4 bits plus up to 3 zero pad bits that round the word up to whole hex digits):
//!   the XOR of all hex digits of the line is 0, so a changed or shifted digit is detected.
//!
//! Columns whose name begins with `_` are framing, not ports.

use std::fmt::Write as _;

use super::files::AtomicFile;

/// Direction of a column, seen from the unit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Dir {
    In,
    Out,
}

/// One column of the vector word.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Column {
    pub name: &'static str,
    pub width: u32,
    pub dir: Dir,
    /// Compared by the replay (outputs only): the reference RTL drives it today.
    pub compared: bool,
}

pub const fn input(name: &'static str, width: u32) -> Column {
    Column { name, width, dir: Dir::In, compared: false }
}

pub const fn output(name: &'static str, width: u32) -> Column {
    Column { name, width, dir: Dir::Out, compared: true }
}

/// The sentinel digit that opens every line.
pub const SENTINEL: u64 = 0xA;

/// The port columns of a unit and the framing around them.
#[derive(Clone, Debug)]
pub struct Layout {
    pub ports: Vec<Column>,
}

impl Layout {
    pub fn new(ports: Vec<Column>) -> Layout {
        debug_assert!(ports.iter().all(|c| c.width >= 1 && c.width <= 64));
        debug_assert!(ports.windows(2).all(|w| !(w[0].dir == Dir::Out && w[1].dir == Dir::In)));
        Layout { ports }
    }

    pub fn in_width(&self) -> u32 {
        self.ports.iter().filter(|c| c.dir == Dir::In).map(|c| c.width).sum()
    }

    pub fn out_width(&self) -> u32 {
        self.ports.iter().filter(|c| c.dir == Dir::Out).map(|c| c.width).sum()
    }

    /// Width of the `_check` column: 4 bits plus the pad to whole hex digits.
    pub fn check_width(&self) -> u32 {
        4 + (4 - (self.in_width() + self.out_width()) % 4) % 4
    }

    /// Bits per line, framing included (a multiple of 4).
    pub fn width(&self) -> u32 {
        4 + self.in_width() + self.out_width() + self.check_width()
    }

    /// The compare mask over the output field (bit positions as in the word, LSB = last bit of
    /// the last output column), as hex digits.
    pub fn mask_hex(&self) -> String {
        let mut bits = Vec::new();
        for c in self.ports.iter().filter(|c| c.dir == Dir::Out) {
            bits.resize(bits.len() + c.width as usize, c.compared);
        }
        bits_to_hex(&bits)
    }

    /// Output columns that the replay does not compare.
    pub fn not_compared(&self) -> Vec<&'static str> {
        self.ports.iter().filter(|c| c.dir == Dir::Out && !c.compared).map(|c| c.name).collect()
    }

    /// Marks output columns as not compared (unknown names are an error of the caller).
    pub fn without(mut self, names: &[&str]) -> Layout {
        for c in self.ports.iter_mut() {
            if names.contains(&c.name) {
                c.compared = false;
            }
        }
        self
    }

    /// The `.cols` text.
    pub fn cols_text(&self) -> String {
        let mut s = String::from("_sentinel 4 in\n");
        for c in &self.ports {
            let _ = writeln!(s, "{} {} {}", c.name, c.width, if c.dir == Dir::In { "in" } else { "out" });
        }
        let _ = writeln!(s, "_check {} out", self.check_width());
        s
    }
}

/// Hex digits of a bit string (MSB first), left-padded with zero bits to whole digits.
fn bits_to_hex(bits: &[bool]) -> String {
    let pad = (4 - bits.len() % 4) % 4;
    let mut s = String::new();
    let mut nib = 0u8;
    let mut n = 0;
    let mut all = vec![false; pad];
    all.extend_from_slice(bits);
    for b in all {
        nib = nib << 1 | b as u8;
        n += 1;
        if n == 4 {
            s.push(char::from_digit(nib as u32, 16).unwrap().to_ascii_uppercase());
            nib = 0;
            n = 0;
        }
    }
    if s.is_empty() {
        s.push('0');
    }
    s
}

/// Encodes one line: `values` holds one value per port column, in layout order.
pub struct LineEncoder {
    widths: Vec<u32>,
    check_width: u32,
    /// Scratch: the word as hex digit values.
    digits: Vec<u8>,
}

impl LineEncoder {
    pub fn new(layout: &Layout) -> LineEncoder {
        LineEncoder {
            widths: layout.ports.iter().map(|c| c.width).collect(),
            check_width: layout.check_width(),
            digits: Vec::with_capacity(layout.width() as usize / 4),
        }
    }

    /// Appends the line (with its newline) to `out`.
    #[inline]
    pub fn encode(&mut self, values: &[u64], out: &mut Vec<u8>) {
        debug_assert_eq!(values.len(), self.widths.len());
        self.digits.clear();
        // Shift the bits MSB first into a nibble accumulator.
        let mut acc: u8 = SENTINEL as u8;
        let mut n: u32 = 0;
        self.digits.push(acc);
        acc = 0;
        let mut push = |v: u64, w: u32, digits: &mut Vec<u8>| {
            for i in (0..w).rev() {
                acc = acc << 1 | ((v >> i) & 1) as u8;
                n += 1;
                if n == 4 {
                    digits.push(acc);
                    acc = 0;
                    n = 0;
                }
            }
        };
        for (v, w) in values.iter().zip(self.widths.iter()) {
            let v = if *w < 64 { v & ((1u64 << w) - 1) } else { *v };
            push(v, *w, &mut self.digits);
        }
        // pad bits of the check column (zero), then a placeholder for the check digit
        push(0, self.check_width - 4, &mut self.digits);
        debug_assert_eq!(n, 0);
        let x = self.digits.iter().fold(0u8, |a, d| a ^ d);
        self.digits.push(x);
        for d in &self.digits {
            out.push(b"0123456789ABCDEF"[*d as usize]);
        }
        out.push(b'\n');
    }
}

/// What a `.meta` file records.
#[derive(Clone, Debug)]
pub struct Meta {
    pub unit: &'static str,
    pub chip: tmc429_model::Chip,
    /// The package (`package` and its pin count `pins`: the `PINS` parameter of tmc429_chip).
    pub package: tmc429_model::Package,
    pub fclk: u64,
    pub scenario: String,
    pub seed: u64,
    pub cycles: u64,
    /// `ready`: the reference RTL replays these vectors today; otherwise what it lacks.
    pub replay: &'static str,
    /// Free-text notes, one per line (`note …`).
    pub notes: Vec<String>,
}

impl Meta {
    pub fn text(&self, layout: &Layout) -> String {
        let mut s = String::new();
        let nc = layout.not_compared();
        let _ = write!(
            s,
            "# tmc429 test vectors: docs/vectors.md\nformat 1\nunit {}\nchip {}\nchip_code {}\npackage {}\npins {}\nfclk {}\n\
             scenario {}\nseed {}\ncycles {}\nwidth {}\nin_width {}\nout_width {}\nmask {}\nnot_compared {}\nreplay {}\n",
            self.unit,
            self.chip,
            self.chip.rtl_param(),
            self.package,
            self.package.pins(),
            self.fclk,
            self.scenario,
            self.seed,
            self.cycles,
            layout.width(),
            layout.in_width(),
            layout.out_width(),
            layout.mask_hex(),
            if nc.is_empty() { "-".to_string() } else { nc.join(",") },
            self.replay,
        );
        for n in &self.notes {
            let _ = writeln!(s, "note {n}");
        }
        s
    }
}

/// Writes one pin-level vector set: `.hex` line by line, `.cols` and `.meta` at the end; all three
/// go to temporary files first and appear together in [`PinWriter::finish`].
pub struct PinWriter {
    layout: Layout,
    enc: LineEncoder,
    buf: Vec<u8>,
    hex: AtomicFile,
    lines: u64,
}

impl PinWriter {
    pub fn create(stem: &std::path::Path, layout: Layout) -> Result<PinWriter, String> {
        let hex = AtomicFile::create(&stem.with_extension("hex"))?;
        Ok(PinWriter { enc: LineEncoder::new(&layout), layout, buf: Vec::with_capacity(1 << 16), hex, lines: 0 })
    }

    pub fn layout(&self) -> &Layout {
        &self.layout
    }

    #[inline]
    pub fn line(&mut self, values: &[u64]) -> Result<(), String> {
        self.enc.encode(values, &mut self.buf);
        self.lines += 1;
        self.hex.drain(&mut self.buf, 1 << 16)
    }

    /// Appends `n` lines already encoded with a [`LineEncoder`] of the same layout.
    pub fn encoded_lines(&mut self, bytes: &[u8], n: u64) -> Result<(), String> {
        self.hex.drain(&mut self.buf, 0)?;
        self.lines += n;
        self.hex.write_all(bytes)
    }

    pub fn lines(&self) -> u64 {
        self.lines
    }

    /// Writes `.cols` and `.meta` (with the line count) and returns the three files, still
    /// temporary; the caller commits them.
    pub fn finish(mut self, mut meta: Meta) -> Result<Vec<AtomicFile>, String> {
        self.hex.drain(&mut self.buf, 0)?;
        meta.cycles = self.lines;
        let stem = self.hex.path().with_extension("");
        let mut cols = AtomicFile::create(&stem.with_extension("cols"))?;
        cols.write_all(self.layout.cols_text().as_bytes())?;
        let mut m = AtomicFile::create(&stem.with_extension("meta"))?;
        m.write_all(meta.text(&self.layout).as_bytes())?;
        Ok(vec![self.hex, cols, m])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn chip_like() -> Layout {
        Layout::new(vec![input("rst", 1), input("a", 3), output("q", 8), output("p", 1)])
    }

    #[test]
    fn widths_and_framing() {
        let l = chip_like();
        assert_eq!((l.in_width(), l.out_width()), (4, 9));
        // 13 port bits: pad 3 → check column 7 bits, line 24 bits = 6 digits
        assert_eq!(l.check_width(), 7);
        assert_eq!(l.width(), 24);
        assert_eq!(l.cols_text(), "_sentinel 4 in\nrst 1 in\na 3 in\nq 8 out\np 1 out\n_check 7 out\n");
        assert_eq!(l.mask_hex(), "1FF");
        assert_eq!(l.clone().without(&["p"]).mask_hex(), "1FE");
    }

    #[test]
    fn line_encoding() {
        let l = chip_like();
        let mut e = LineEncoder::new(&l);
        let mut out = Vec::new();
        // word: A | 1 101 | 10110011 1 | 000 c  → bits after A: 1101 1011 0011 1000 → D B 3 8
        e.encode(&[1, 5, 0xB3, 1], &mut out);
        let s = String::from_utf8(out).unwrap();
        let x = 0xA ^ 0xD ^ 0xB ^ 0x3 ^ 0x8;
        assert_eq!(s, format!("ADB38{:X}\n", x));
        // the XOR of all digits is 0
        let all = s.trim().chars().fold(0, |a, c| a ^ c.to_digit(16).unwrap());
        assert_eq!(all, 0);
        // values wider than their column are cut to it
        let mut out2 = Vec::new();
        e.encode(&[3, 0xD, 0x1B3, 3], &mut out2);
        assert_eq!(out2, s.as_bytes());
    }
}
