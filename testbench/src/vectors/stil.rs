//! Chip-level vectors as STIL (IEEE 1450-1999), for automatic test equipment
//! (docs/vectors.md, "STIL").
//!
//! One `V` statement per line of the pin-level form (line 0 the reset edge), one waveform
//! character per pin of [`PINS`] in the signal group `all`:
//!
//! | Pin kind | Characters | Waveform |
//! |---|---|---|
//! | `clk` | `P` | down at 0, up at the half period: the line's CLK edge |
//! | input | `0` `1` | driven from 0 (half a period of set-up before the edge) |
//! | output | `L` `H` `X` | compared at the strobe, 7/8 of the period; `X` masks |
//! | SDOZ_C | `L` `H` `T` `X` | as an output; `T` compares high impedance (output off) |
//! | SDI_S | `0` `1`, `L` `H` `T` | driven as an input; else the tester's driver is off and the pin compared (en_sd) |
//!
//! The file is written as the model runs (no buffering of the whole set) under a temporary
//! name that becomes the final one when complete.

use std::path::Path;

use super::files::AtomicFile;
use super::pinmap::{Kind, PinMapper, PinState, PINS};
use super::pins::Meta;
use super::record::PinForm;

/// The waveform table's timing in picoseconds: period, CLK rise, output strobe.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Timing {
    pub period: u64,
    pub rise: u64,
    pub strobe: u64,
}

impl Timing {
    /// One CLK period of `fclk`: CLK rises at half the period (rounded down to 1 ps), outputs
    /// are strobed at 7/8 of it, 3/8 of a period after the edge.
    pub fn of(fclk: u64) -> Timing {
        let period = crate::rtl::period_ps(fclk);
        Timing { period, rise: period / 2, strobe: period * 7 / 8 }
    }
}

/// A time in picoseconds as a STIL time expression in ns (`'15.625ns'`).
pub fn ns(ps: u64) -> String {
    let (int, frac) = (ps / 1000, ps % 1000);
    if frac == 0 {
        format!("'{int}ns'")
    } else {
        let f = format!("{frac:03}");
        format!("'{int}.{}ns'", f.trim_end_matches('0'))
    }
}

/// `s` in the ASCII character set STIL and VCD files are written in (IEEE 1450 §6.1): the
/// typographic characters of the notes become their ASCII spellings, any other becomes `?`.
pub fn ascii(s: &str) -> String {
    let mut o = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            ' '..='~' => o.push(c),
            '§' => o.push_str("sec. "),
            '–' | '—' | '−' => o.push('-'),
            '×' | '·' => o.push('x'),
            '≥' => o.push_str(">="),
            '≤' => o.push_str("<="),
            'µ' => o.push('u'),
            _ => o.push('?'),
        }
    }
    o
}

/// The waveform character of a pin state.
#[inline]
pub fn wfc(s: PinState) -> u8 {
    match s {
        PinState::Clock => b'P',
        PinState::Drive(false) => b'0',
        PinState::Drive(true) => b'1',
        PinState::Expect(false) | PinState::Turn(false) => b'L',
        PinState::Expect(true) | PinState::Turn(true) => b'H',
        PinState::Off => b'T',
    }
}

fn names(f: impl Fn(Kind) -> bool) -> Vec<&'static str> {
    PINS.iter().filter(|p| f(p.kind)).map(|p| p.name).collect()
}

/// Everything before the first vector.
pub fn header(meta: &Meta) -> String {
    let t = Timing::of(meta.fclk);
    let dir = |k: Kind| match k {
        Kind::Clock | Kind::In => "In",
        Kind::Out | Kind::TriOut { .. } => "Out",
        Kind::InOut { .. } => "InOut",
    };
    let signals: String = PINS.iter().map(|p| format!("    {} {};\n", p.name, dir(p.kind))).collect();
    let group = |v: Vec<&str>| v.join(" + ");
    let all = group(PINS.iter().map(|p| p.name).collect());
    let inputs = group(names(|k| k == Kind::In));
    let outputs = group(names(|k| k == Kind::Out));
    let tri = group(names(|k| matches!(k, Kind::TriOut { .. })));
    let inout = group(names(|k| matches!(k, Kind::InOut { .. })));
    let mut ann: Vec<String> = vec![
        format!("chip {} (CHIP = {}), scenario {}, seed {}", meta.chip, meta.chip.rtl_param(), meta.scenario, meta.seed),
        "one V per CLK cycle: vector 0 is the reset edge (rst = 1), vector k the k-th CLK edge after it".into(),
        "inputs are driven from the start of the cycle, CLK rises at the half period, outputs are strobed at 7/8".into(),
    ];
    ann.extend(meta.notes.iter().cloned());
    let ann: String = ann.iter().map(|a| format!("    Ann {{* {} *}}\n", ascii(a).replace("*}", "* }"))).collect();
    format!(
        "STIL 1.0;\n\n\
         Header {{\n    Title \"tmc429 chip-level vectors: {scenario} ({chip})\";\n    \
         Source \"tmc429 vectors, golden model (docs/vectors.md)\";\n{ann}}}\n\n\
         Signals {{\n{signals}}}\n\n\
         SignalGroups {{\n    all = '{all}';\n    inputs = '{inputs}';\n    outputs = '{outputs}';\n}}\n\n\
         Timing tmc429 {{\n    WaveformTable cycle {{\n        Period {period};\n        Waveforms {{\n            \
         clk {{ P {{ '0ns' D; {rise} U; }} }}\n            \
         inputs {{ 01 {{ '0ns' D/U; }} }}\n            \
         outputs {{ LHX {{ {strobe} L/H/X; }} }}\n            \
         {tri} {{ LHTX {{ {strobe} L/H/T/X; }} }}\n            \
         {inout} {{ 01 {{ '0ns' D/U; }} LHTX {{ '0ns' Z; {strobe} L/H/T/X; }} }}\n        }}\n    }}\n}}\n\n\
         PatternBurst burst {{\n    PatList {{ vectors; }}\n}}\n\n\
         PatternExec {{\n    Timing tmc429;\n    PatternBurst burst;\n}}\n\n\
         Pattern vectors {{\n    W cycle;\n",
        scenario = meta.scenario,
        chip = meta.chip,
        period = ns(t.period),
        rise = ns(t.rise),
        strobe = ns(t.strobe),
    )
}

const PREFIX: &[u8] = b"    V { all = ";
const SUFFIX: &[u8] = b"; }\n";

/// Chip pins as STIL, written line by line.
pub struct ChipStil {
    file: AtomicFile,
    map: PinMapper,
    states: [PinState; PINS.len()],
    buf: Vec<u8>,
}

impl ChipStil {
    pub fn create(path: &Path, meta: &Meta) -> Result<ChipStil, String> {
        let mut file = AtomicFile::create(path)?;
        file.write_all(header(meta).as_bytes())?;
        Ok(ChipStil { file, map: PinMapper::new(), states: [PinState::Clock; PINS.len()], buf: Vec::with_capacity(1 << 16) })
    }

    fn line(&mut self, v: &[u64; 22]) -> Result<(), String> {
        self.map.states(v, &mut self.states);
        self.buf.extend_from_slice(PREFIX);
        self.buf.extend(self.states.iter().map(|s| wfc(*s)));
        self.buf.extend_from_slice(SUFFIX);
        self.file.drain(&mut self.buf, 1 << 16)
    }
}

impl PinForm for ChipStil {
    #[inline]
    fn line(&mut self, v: &[u64; 22]) -> Result<(), String> {
        ChipStil::line(self, v)
    }
    fn close(mut self) -> Result<AtomicFile, String> {
        self.buf.extend_from_slice(b"}\n");
        self.file.drain(&mut self.buf, 0)?;
        Ok(self.file)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn times() {
        assert_eq!(ns(31_250), "'31.25ns'");
        assert_eq!(ns(15_625), "'15.625ns'");
        assert_eq!(ns(62_000), "'62ns'");
        assert_eq!(ns(7), "'0.007ns'");
        // 32 MHz: period 31.25 ns, CLK up at 15.625 ns, strobe at 27.343 ns
        assert_eq!(Timing::of(32_000_000), Timing { period: 31_250, rise: 15_625, strobe: 27_343 });
    }

    #[test]
    fn ascii_notes() {
        assert_eq!(ascii("[428] §6.5 a–b ≥ 2 µC é"), "[428] sec. 6.5 a-b >= 2 uC ?");
    }

    #[test]
    fn characters() {
        assert_eq!(
            [PinState::Clock, PinState::Drive(false), PinState::Drive(true), PinState::Expect(false), PinState::Turn(true), PinState::Off]
                .map(wfc),
            *b"P01LHT"
        );
    }
}
