//! Logic-analyzer captures of the chip's pins (docs/bench.md): reading and writing sigrok
//! session files and VCD, the pin map, captures made from a simulation of the chip
//! (`tmc429 capture export`), and the comparison of a real chip's capture with the golden model
//! (`tmc429 capture compare`).
//!
//! A [`Capture`] is what a logic analyzer records: channels sampled at one sample rate, kept as
//! the sample indices at which each channel changes. Its sample rate has no relation to the
//! chip's CLK.

pub mod compare;
pub mod export;
pub mod frames;
pub mod pins;
pub mod replay;
pub mod report;
pub mod sr;
pub mod vcdfile;

use std::fmt;
use std::path::Path;

/// One recorded channel: its level at sample 0 and the samples at which it toggles.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Channel {
    pub name: String,
    pub initial: bool,
    /// Sample indices (ascending, each > 0) of the level changes: the first sample that shows
    /// the new level.
    pub edges: Vec<u64>,
}

impl Channel {
    /// The level at sample `s`.
    pub fn level(&self, s: u64) -> bool {
        self.initial ^ (self.edges.partition_point(|&e| e <= s) & 1 == 1)
    }
}

/// A capture: channels sampled at `samplerate` Hz, `length` samples long.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Capture {
    pub samplerate: u64,
    pub length: u64,
    pub channels: Vec<Channel>,
}

impl Capture {
    /// Seconds of sample `s`.
    pub fn seconds(&self, s: u64) -> f64 {
        s as f64 / self.samplerate as f64
    }

    pub fn channel(&self, name: &str) -> Option<usize> {
        self.channels.iter().position(|c| c.name.eq_ignore_ascii_case(name))
    }

    /// Builds a capture from per-channel level runs (what the readers collect sample by
    /// sample): drops repeated levels.
    pub fn from_changes(samplerate: u64, length: u64, names: Vec<String>, changes: Vec<Vec<(u64, bool)>>) -> Capture {
        let channels = names
            .into_iter()
            .zip(changes)
            .map(|(name, ch)| {
                let initial = ch.first().map(|&(s, l)| s == 0 && l).unwrap_or(false);
                let mut level = initial;
                let mut edges = Vec::new();
                for (s, l) in ch {
                    if l != level && s < length {
                        edges.push(s.max(1));
                        level = l;
                    }
                }
                edges.dedup();
                Channel { name, initial, edges }
            })
            .collect();
        Capture { samplerate, length, channels }
    }
}

/// A capture file that cannot be used: what is wrong, for `tmc429: error:` and exit 2.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CaptureError(pub String);

impl fmt::Display for CaptureError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for CaptureError {}

/// File formats of captures.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// sigrok session file (`.sr`, what PulseView and sigrok-cli save).
    Sigrok,
    /// Value change dump (`.vcd`).
    Vcd,
}

impl Format {
    /// The format of a file name: `.sr` or `.vcd`.
    pub fn of(path: &Path) -> Result<Format, CaptureError> {
        match path.extension().and_then(|e| e.to_str()).map(|e| e.to_ascii_lowercase()).as_deref() {
            Some("sr") => Ok(Format::Sigrok),
            Some("vcd") => Ok(Format::Vcd),
            _ => Err(CaptureError(format!(
                "{}: unknown capture format: expected a sigrok session file (.sr) or a VCD (.vcd)",
                path.display()
            ))),
        }
    }
}

/// Reads a capture file (`.sr` or `.vcd`).
pub fn read(path: &Path) -> Result<Capture, CaptureError> {
    match Format::of(path)? {
        Format::Sigrok => sr::read(path),
        Format::Vcd => vcdfile::read(path),
    }
}

/// Writes a capture file (`.sr` or `.vcd`), whole or not at all (a temporary file committed
/// when complete, `Staged`).
pub fn write(path: &Path, cap: &Capture) -> Result<(), CaptureError> {
    let fmt = Format::of(path)?;
    let staged = tmc429_testbench::vectors::files::Staged::new(path);
    match fmt {
        Format::Sigrok => sr::write(staged.tmp(), cap),
        Format::Vcd => vcdfile::write(staged.tmp(), cap),
    }?;
    staged.commit().map(drop).map_err(CaptureError)
}

/// A frequency for messages: `24 MHz`, `32.768 kHz`, `1 GHz`.
pub fn fmt_hz(hz: f64) -> String {
    let (v, unit) = if hz >= 1e9 {
        (hz / 1e9, "GHz")
    } else if hz >= 1e6 {
        (hz / 1e6, "MHz")
    } else if hz >= 1e3 {
        (hz / 1e3, "kHz")
    } else {
        (hz, "Hz")
    };
    let s = format!("{v:.6}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    format!("{s} {unit}")
}

/// A time in seconds for reports: `12.345678 ms`.
pub fn fmt_ms(t: f64) -> String {
    format!("{:.6} ms", t * 1e3)
}
