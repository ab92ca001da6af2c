//! The training input of the Verilated models' profile-guided build (build/pgo.rs): the golden
//! pin-level vectors of a variant as the words cpp/pgo_train.cc replays. Also compiled into
//! tests/pgo_pins.rs.

use std::fs;
use std::path::{Path, PathBuf};

/// The input pins in the order of the bits of pgo_train's 16-bit words (cpp/pgo_train.cc),
/// with the level of a pin a set has no column for (a package without REFR pins: pulled up).
pub const PINS: [(&str, bool); 11] = [
    ("nscs_c", true),
    ("sck_c", true),
    ("sdi_c", false),
    ("sdi_s", false),
    ("ref1", false),
    ("ref2", false),
    ("ref3", false),
    ("refr1", true),
    ("refr2", true),
    ("refr3", true),
    ("rst", false),
];

/// The training run's input words for the variant `chip`: every golden pin-level set of it
/// (a `.meta` with `unit chip` and `chip {chip}`), in the order of their names, one after the
/// other (each begins with its reset edge); and the files read.
pub fn training_pins(golden: &Path, chip: &str) -> Result<(Vec<u8>, Vec<PathBuf>), String> {
    let mut read = Vec::new();
    let mut metas: Vec<PathBuf> = fs::read_dir(golden)
        .map_err(|e| format!("cannot read {}: {e}", golden.display()))?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "meta"))
        .collect();
    metas.sort();
    let mut words = Vec::new();
    for meta in metas {
        let text = fs::read_to_string(&meta).map_err(|e| format!("cannot read {}: {e}", meta.display()))?;
        let is = |line: &str| text.lines().any(|l| l.trim() == line);
        if is("unit chip") && is(&format!("chip {chip}")) {
            let (cols, hex) = (meta.with_extension("cols"), meta.with_extension("hex"));
            words.extend(set_words(&cols, &hex)?);
            read.extend([meta, cols, hex]);
        }
    }
    if words.is_empty() {
        return Err(format!("no pin-level golden vectors of the {chip} in {}", golden.display()));
    }
    Ok((words, read))
}

/// One set's lines (`hex`, its columns in `cols`: `name width in|out` from the most
/// significant bit) as pgo_train's words, little-endian.
pub fn set_words(cols: &Path, hex: &Path) -> Result<Vec<u8>, String> {
    let read = |p: &Path| fs::read_to_string(p).map_err(|e| format!("cannot read {}: {e}", p.display()));
    let mut columns = Vec::new();
    for (n, line) in read(cols)?.lines().enumerate() {
        let f: Vec<&str> = line.split_whitespace().collect();
        let width = f.get(1).and_then(|w| w.parse::<u32>().ok());
        match (f.first(), width) {
            (Some(name), Some(w)) if f.len() == 3 => columns.push((name.to_string(), w)),
            _ => return Err(format!("{}:{}: expected `name width in|out`", cols.display(), n + 1)),
        }
    }
    let total: u32 = columns.iter().map(|c| c.1).sum();
    if total > 64 {
        return Err(format!("{}: {total} bits in a line, at most 64 expected", cols.display()));
    }
    // the bit of each input pin in a line, from the most significant column down
    let mut at = total;
    let mut bit_of = std::collections::HashMap::new();
    for (name, w) in &columns {
        at -= w;
        bit_of.insert(name.as_str(), at);
    }
    let mut words = Vec::new();
    for (n, line) in read(hex)?.lines().enumerate() {
        let v = u64::from_str_radix(line.trim(), 16).map_err(|_| format!("{}:{}: expected a hexadecimal word", hex.display(), n + 1))?;
        let mut w = 0u16;
        for (k, (pin, absent)) in PINS.iter().enumerate() {
            let level = bit_of.get(pin).map_or(*absent, |&b| (v >> b) & 1 == 1);
            w |= u16::from(level) << k;
        }
        words.extend_from_slice(&w.to_le_bytes());
    }
    Ok(words)
}
