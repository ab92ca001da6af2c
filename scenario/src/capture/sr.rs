//! sigrok session files (`.sr`, format version 2): a zip archive with `version` ("2"),
//! `metadata` (an INI file: sample rate, channel names, bytes per sample) and the logic data in
//! chunks `logic-1-1`, `logic-1-2`, …: one little-endian word of `unitsize` bytes per sample,
//! channel k in bit k. This is what PulseView saves and `sigrok-cli -o FILE.sr` writes.

use std::fs::File;
use std::io::{BufWriter, Read, Write};
use std::path::Path;

use super::{Capture, CaptureError, Channel};

/// Samples per chunk written (libsigrok reads any chunk size).
const CHUNK_SAMPLES: u64 = 1 << 20;

/// Parses a sigrok sample rate: `24 MHz`, `100000000`, `1 GHz`, `500 kHz`, `200 Hz`.
pub fn parse_rate(s: &str) -> Option<u64> {
    let t = s.trim();
    let (num, mult) = [("GHz", 1e9), ("MHz", 1e6), ("kHz", 1e3), ("Hz", 1.0)]
        .iter()
        .find_map(|(u, m)| t.strip_suffix(u).map(|n| (n.trim(), *m)))
        .unwrap_or((t, 1.0));
    let v: f64 = num.parse().ok()?;
    let hz = (v * mult).round();
    (hz >= 1.0 && hz < 1e15).then_some(hz as u64)
}

/// The metadata of a session file: sample rate, channel names (in bit order), bytes per sample
/// and the name of the logic data's chunks.
struct Metadata {
    samplerate: u64,
    names: Vec<String>,
    unitsize: usize,
    capturefile: String,
}

fn parse_metadata(text: &str, file: &str) -> Result<Metadata, CaptureError> {
    let mut in_device = false;
    let (mut rate, mut unitsize, mut capturefile, mut total) = (None, None, None, None);
    let mut probes: Vec<(usize, String)> = Vec::new();
    for (i, raw) in text.lines().enumerate() {
        let line = raw.trim();
        let err = |m: String| CaptureError(format!("{file}: metadata line {}: {m}", i + 1));
        if line.starts_with('[') {
            // the first device holds the logic data
            in_device = line == "[device 1]";
            continue;
        }
        let Some((k, v)) = line.split_once('=') else { continue };
        if !in_device {
            continue;
        }
        match k.trim() {
            "samplerate" => {
                rate = Some(parse_rate(v).ok_or_else(|| err(format!("samplerate '{v}': expected a frequency such as 24 MHz")))?)
            }
            "unitsize" => {
                unitsize = Some(
                    v.trim()
                        .parse::<usize>()
                        .ok()
                        .filter(|u| (1..=8).contains(u))
                        .ok_or_else(|| err(format!("unitsize '{v}': expected 1..8")))?,
                )
            }
            "capturefile" => capturefile = Some(v.trim().to_string()),
            "total probes" => total = v.trim().parse::<usize>().ok(),
            k if k.starts_with("probe") => {
                let n: usize = k[5..].parse().map_err(|_| err(format!("'{k}': expected probeN")))?;
                probes.push((n, v.trim().to_string()));
            }
            _ => {}
        }
    }
    let samplerate =
        rate.ok_or_else(|| CaptureError(format!("{file}: the metadata has no samplerate (a capture needs its sample rate)")))?;
    let unitsize = unitsize.ok_or_else(|| CaptureError(format!("{file}: the metadata has no unitsize")))?;
    let capturefile = capturefile.ok_or_else(|| CaptureError(format!("{file}: the metadata names no logic data (capturefile)")))?;
    let total = total.unwrap_or(probes.iter().map(|p| p.0).max().unwrap_or(0));
    if total > unitsize * 8 {
        return Err(CaptureError(format!("{file}: {total} channels do not fit in unitsize {unitsize}")));
    }
    let mut names: Vec<String> = (1..=total).map(|n| format!("D{}", n - 1)).collect();
    for (n, name) in probes {
        if n == 0 || n > total {
            return Err(CaptureError(format!("{file}: probe{n} is outside the {total} channels of the capture")));
        }
        names[n - 1] = name;
    }
    Ok(Metadata { samplerate, names, unitsize, capturefile })
}

fn zip_err(file: &str, e: zip::result::ZipError) -> CaptureError {
    CaptureError(format!("{file}: not a readable sigrok session file (a zip archive): {e}; is the file complete?"))
}

/// Reads a session file.
pub fn read(path: &Path) -> Result<Capture, CaptureError> {
    let file = path.display().to_string();
    let f = File::open(path).map_err(|e| CaptureError(format!("{file}: cannot read: {e}")))?;
    let mut zip = zip::ZipArchive::new(std::io::BufReader::new(f)).map_err(|e| zip_err(&file, e))?;
    let mut text = |name: &str| -> Result<String, CaptureError> {
        let mut s = String::new();
        let mut entry =
            zip.by_name(name).map_err(|_| CaptureError(format!("{file}: no '{name}' in the archive: not a sigrok session file")))?;
        entry.read_to_string(&mut s).map_err(|e| CaptureError(format!("{file}: {name}: {e}")))?;
        Ok(s)
    };
    let version = text("version")?;
    if version.trim() != "2" {
        return Err(CaptureError(format!("{file}: sigrok session format version {}: expected 2", version.trim())));
    }
    let meta = parse_metadata(&text("metadata")?, &file)?;
    // chunks logic-1-1, logic-1-2, … in numeric order
    let prefix = format!("{}-", meta.capturefile);
    let mut chunks: Vec<(u64, String)> =
        zip.file_names().filter_map(|n| n.strip_prefix(&prefix).and_then(|k| k.parse::<u64>().ok()).map(|k| (k, n.to_string()))).collect();
    chunks.sort();
    if chunks.is_empty() {
        return Err(CaptureError(format!("{file}: no logic data ({prefix}N) in the archive")));
    }
    let mut acc = Changes { changes: vec![Vec::new(); meta.names.len()], prev: None, samples: 0 };
    let mut buf = Vec::new();
    for (_, name) in &chunks {
        buf.clear();
        let mut entry = zip.by_name(name).map_err(|e| zip_err(&file, e))?;
        entry.read_to_end(&mut buf).map_err(|e| CaptureError(format!("{file}: {name}: {e}; is the file complete?")))?;
        if buf.len() % meta.unitsize != 0 {
            return Err(CaptureError(format!(
                "{file}: {name} holds {} bytes, not a whole number of {}-byte samples: the capture is truncated",
                buf.len(),
                meta.unitsize
            )));
        }
        acc.add(&buf, meta.unitsize);
    }
    if acc.samples == 0 {
        return Err(CaptureError(format!("{file}: the capture holds no samples")));
    }
    Ok(Capture::from_changes(meta.samplerate, acc.samples, meta.names, acc.changes))
}

/// The channels' level changes of a session's logic data, chunk by chunk.
struct Changes {
    /// Per channel: (sample, new level) at each change, the first sample's level first.
    changes: Vec<Vec<(u64, bool)>>,
    /// The last sample's word.
    prev: Option<u64>,
    samples: u64,
}

impl Changes {
    /// The samples of one chunk, `unitsize` little-endian bytes each, bit c = channel c.
    fn add(&mut self, buf: &[u8], unitsize: usize) {
        for w in buf.chunks_exact(unitsize) {
            let mut v = 0u64;
            for (k, b) in w.iter().enumerate() {
                v |= (*b as u64) << (8 * k);
            }
            let diff = self.prev.map_or(u64::MAX, |p| p ^ v);
            if diff != 0 {
                for (c, ch) in self.changes.iter_mut().enumerate() {
                    if (diff >> c) & 1 != 0 {
                        ch.push((self.samples, (v >> c) & 1 != 0));
                    }
                }
                self.prev = Some(v);
            }
            self.samples += 1;
        }
    }
}

fn rate_text(hz: u64) -> String {
    for (m, u) in [(1_000_000_000, "GHz"), (1_000_000, "MHz"), (1_000, "kHz")] {
        if hz % m == 0 {
            return format!("{} {u}", hz / m);
        }
    }
    format!("{hz} Hz")
}

/// Writes a session file that sigrok-cli and PulseView open.
pub fn write(path: &Path, cap: &Capture) -> Result<(), CaptureError> {
    let file = path.display().to_string();
    let io = |e: std::io::Error| CaptureError(format!("{file}: cannot write: {e}"));
    let zerr = |e: zip::result::ZipError| CaptureError(format!("{file}: cannot write: {e}"));
    let unitsize = cap.channels.len().div_ceil(8).max(1);
    let mut zw = zip::ZipWriter::new(BufWriter::new(File::create(path).map_err(io)?));
    let opts = zip::write::SimpleFileOptions::default().compression_method(zip::CompressionMethod::Deflated);
    zw.start_file("version", opts).map_err(zerr)?;
    zw.write_all(b"2").map_err(io)?;
    let mut meta = format!(
        "[global]\nsigrok version=0.5.2\n\n[device 1]\ncapturefile=logic-1\ntotal probes={}\nsamplerate={}\ntotal analog=0\n",
        cap.channels.len(),
        rate_text(cap.samplerate)
    );
    for (k, c) in cap.channels.iter().enumerate() {
        meta += &format!("probe{}={}\n", k + 1, c.name);
    }
    meta += &format!("unitsize={unitsize}\n");
    zw.start_file("metadata", opts).map_err(zerr)?;
    zw.write_all(meta.as_bytes()).map_err(io)?;
    let mut words = Words::new(&cap.channels);
    let mut start = 0u64;
    let mut chunk = 1;
    let mut buf = Vec::with_capacity(CHUNK_SAMPLES as usize * unitsize);
    while start < cap.length {
        let end = (start + CHUNK_SAMPLES).min(cap.length);
        buf.clear();
        for s in start..end {
            let v = words.at(s);
            buf.extend_from_slice(&v.to_le_bytes()[..unitsize]);
        }
        zw.start_file(format!("logic-1-{chunk}"), opts).map_err(zerr)?;
        zw.write_all(&buf).map_err(io)?;
        chunk += 1;
        start = end;
    }
    let mut inner = zw.finish().map_err(zerr)?;
    inner.flush().map_err(io)
}

/// The packed sample words of a capture, read in ascending sample order.
struct Words<'a> {
    channels: &'a [Channel],
    next: Vec<usize>,
    word: u64,
}

impl<'a> Words<'a> {
    fn new(channels: &'a [Channel]) -> Words<'a> {
        let word = channels.iter().enumerate().fold(0u64, |w, (k, c)| w | (c.initial as u64) << k);
        Words { channels, next: vec![0; channels.len()], word }
    }
    fn at(&mut self, s: u64) -> u64 {
        for (k, c) in self.channels.iter().enumerate() {
            while self.next[k] < c.edges.len() && c.edges[self.next[k]] <= s {
                self.word ^= 1 << k;
                self.next[k] += 1;
            }
        }
        self.word
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rates() {
        assert_eq!(parse_rate("24 MHz"), Some(24_000_000));
        assert_eq!(parse_rate("200 kHz"), Some(200_000));
        assert_eq!(parse_rate("1 GHz"), Some(1_000_000_000));
        assert_eq!(parse_rate("12500000"), Some(12_500_000));
        assert_eq!(parse_rate("fast"), None);
        assert_eq!(rate_text(24_000_000), "24 MHz");
        assert_eq!(rate_text(12_345), "12345 Hz");
    }

    #[test]
    fn round_trip() {
        let cap = Capture {
            samplerate: 24_000_000,
            length: 3_000_000,
            channels: (0..11)
                .map(|k| Channel { name: format!("P{k}"), initial: k % 2 == 1, edges: (1..40).map(|i| i * 70_001 + k).collect() })
                .collect(),
        };
        let dir = std::env::temp_dir().join(format!("tmc429-sr-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let p = dir.join("t.sr");
        write(&p, &cap).unwrap();
        assert_eq!(read(&p).unwrap(), cap);
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
