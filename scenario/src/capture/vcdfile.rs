//! Captures as VCD: reading any VCD's one-bit variables as channels (a logic analyzer's export,
//! or the project's own VCDs), and writing the pin-only, flat VCD that sigrok's VCD input reads
//! (one-bit wires under one scope, no vectors or strings; its sample rate is 1/timescale).

use std::fs::File;
use std::io::{BufReader, BufWriter, Read, Seek, SeekFrom, Write};
use std::path::Path;

use vcd::{Command, Value};

use super::{Capture, CaptureError};

/// The VCD timescale whose unit is exactly one sample at `hz`, if there is one
/// (`(k, unit)`, k in 1, 10, 100): `10 ns` for 100 MHz, `1 us` for 1 MHz.
pub fn exact_timescale(hz: u64) -> Option<(u32, &'static str)> {
    const UNITS: [(&str, u128); 6] =
        [("fs", 1), ("ps", 1_000), ("ns", 1_000_000), ("us", 1_000_000_000), ("ms", 1_000_000_000_000), ("s", 1_000_000_000_000_000)];
    let fs_per_sample = 1_000_000_000_000_000u128.checked_div(hz as u128)?;
    if fs_per_sample * hz as u128 != 1_000_000_000_000_000 {
        return None;
    }
    UNITS.iter().rev().find_map(|&(u, f)| {
        let k = fs_per_sample.checked_div(f)?;
        (fs_per_sample % f == 0 && matches!(k, 1 | 10 | 100)).then_some((k as u32, u))
    })
}

/// Reads the one-bit variables of a VCD as channels. Vectors, reals and strings are skipped.
/// A variable's channel name is its reference; names that occur in more than one scope are
/// qualified with the scope path (`motor0.step`).
pub fn read(path: &Path) -> Result<Capture, CaptureError> {
    let file = path.display().to_string();
    let f = open_complete(path, &file)?;
    let mut p = vcd::Parser::new(BufReader::with_capacity(1 << 20, f));
    let mut r = Reader::default();
    loop {
        let line = p.line();
        let cmd = match p.next() {
            None => break,
            Some(Ok(c)) => c,
            Some(Err(e)) => return Err(CaptureError(format!("{file}:{line}: not a valid VCD: {e}"))),
        };
        r.command(cmd).map_err(|m| CaptureError(format!("{file}:{line}: {m}")))?;
    }
    if r.header {
        return Err(CaptureError(format!("{file}: no $enddefinitions: the VCD is truncated or not a VCD")));
    }
    let (k, unit) = r.timescale.ok_or_else(|| CaptureError(format!("{file}: no $timescale: the sample rate is unknown")))?;
    let per_s = unit.divisor();
    if per_s % k as u64 != 0 {
        return Err(CaptureError(format!("{file}: timescale {k} {unit}: unsupported")));
    }
    let names = channel_names(&r.vars);
    Ok(Capture::from_changes(per_s / k as u64, r.time + 1, names, r.changes))
}

/// What [`read`] has taken from the VCD's commands so far.
struct Reader {
    scope: Vec<String>,
    /// (scope path, reference, id) of every one-bit variable
    vars: Vec<(String, String, vcd::IdCode)>,
    timescale: Option<(u32, vcd::TimescaleUnit)>,
    /// before `$enddefinitions`
    header: bool,
    time: u64,
    /// per variable, its value changes (time, level)
    changes: Vec<Vec<(u64, bool)>>,
    by_id: std::collections::HashMap<vcd::IdCode, Vec<usize>>,
}

impl Default for Reader {
    fn default() -> Self {
        Reader {
            scope: Vec::new(),
            vars: Vec::new(),
            timescale: None,
            header: true,
            time: 0,
            changes: Vec::new(),
            by_id: Default::default(),
        }
    }
}

impl Reader {
    /// Takes one command; an error is the message for the command's line.
    fn command(&mut self, cmd: Command) -> Result<(), String> {
        match cmd {
            Command::Timescale(k, u) => self.timescale = Some((k, u)),
            Command::ScopeDef(_, name) => self.scope.push(name),
            Command::Upscope => {
                self.scope.pop();
            }
            Command::VarDef(_, 1, id, reference, _) if self.header => self.vars.push((self.scope.join("."), reference, id)),
            Command::Enddefinitions => {
                self.header = false;
                self.changes = vec![Vec::new(); self.vars.len()];
                for (k, v) in self.vars.iter().enumerate() {
                    self.by_id.entry(v.2).or_default().push(k);
                }
            }
            Command::Timestamp(t) => {
                if t < self.time {
                    return Err(format!("time #{t} goes back (after #{})", self.time));
                }
                self.time = t;
            }
            Command::ChangeScalar(id, v) if !self.header => {
                if let Some(ks) = self.by_id.get(&id) {
                    for &k in ks {
                        self.changes[k].push((self.time, v == Value::V1));
                    }
                }
            }
            _ => {}
        }
        Ok(())
    }
}

/// Opens a VCD file that is not empty and ends with a complete line (a file cut short
/// mid-line is truncated).
fn open_complete(path: &Path, file: &str) -> Result<File, CaptureError> {
    let mut f = File::open(path).map_err(|e| CaptureError(format!("{file}: cannot read: {e}")))?;
    let len = f.metadata().map(|m| m.len()).unwrap_or(0);
    if len == 0 {
        return Err(CaptureError(format!("{file}: empty file")));
    }
    let mut last = [0u8; 1];
    f.seek(SeekFrom::End(-1)).and_then(|_| f.read_exact(&mut last)).map_err(|e| CaptureError(format!("{file}: cannot read: {e}")))?;
    f.seek(SeekFrom::Start(0)).map_err(|e| CaptureError(format!("{file}: cannot read: {e}")))?;
    if last[0] != b'\n' {
        return Err(CaptureError(format!("{file}: the last line is incomplete: the VCD is truncated")));
    }
    Ok(f)
}

fn channel_names(vars: &[(String, String, vcd::IdCode)]) -> Vec<String> {
    vars.iter()
        .map(|(s, r, _)| {
            let dup = vars.iter().filter(|(_, r2, _)| r2.eq_ignore_ascii_case(r)).count() > 1;
            if dup && !s.is_empty() {
                format!("{s}.{r}")
            } else {
                r.clone()
            }
        })
        .collect()
}

/// VCD identifier of channel `k`: printable characters from `!`.
fn id(k: usize) -> String {
    let mut s = String::new();
    let mut n = k;
    loop {
        s.push((b'!' + (n % 94) as u8) as char);
        n /= 94;
        if n == 0 {
            break;
        }
        n -= 1;
    }
    s
}

/// Writes a flat VCD of one-bit wires. The timescale is one sample when the sample rate allows
/// it (1, 10 or 100 of a unit: 1 GHz, 100 MHz, 10 MHz, …), else 1 ps with times rounded.
pub fn write(path: &Path, cap: &Capture) -> Result<(), CaptureError> {
    let file = path.display().to_string();
    let io = |e: std::io::Error| CaptureError(format!("{file}: cannot write: {e}"));
    let mut w = BufWriter::with_capacity(1 << 20, File::create(path).map_err(io)?);
    let (ts, time): (String, Box<dyn Fn(u64) -> u64>) = match exact_timescale(cap.samplerate) {
        Some((k, u)) => (format!("{k} {u}"), Box::new(|s| s)),
        None => {
            let hz = cap.samplerate as u128;
            ("1 ps".to_string(), Box::new(move |s| ((s as u128 * 1_000_000_000_000 + hz / 2) / hz) as u64))
        }
    };
    writeln!(w, "$version tmc429 capture export $end\n$timescale {ts} $end\n$scope module tmc429 $end").map_err(io)?;
    for (k, c) in cap.channels.iter().enumerate() {
        writeln!(w, "$var wire 1 {} {} $end", id(k), c.name).map_err(io)?;
    }
    writeln!(w, "$upscope $end\n$enddefinitions $end\n#0\n$dumpvars").map_err(io)?;
    for (k, c) in cap.channels.iter().enumerate() {
        writeln!(w, "{}{}", c.initial as u8, id(k)).map_err(io)?;
    }
    writeln!(w, "$end").map_err(io)?;
    // all edges in time order
    let mut edges: Vec<(u64, usize)> = cap.channels.iter().enumerate().flat_map(|(k, c)| c.edges.iter().map(move |&s| (s, k))).collect();
    edges.sort_unstable();
    let mut level: Vec<bool> = cap.channels.iter().map(|c| c.initial).collect();
    let mut last_t = 0;
    for (s, k) in edges {
        let t = time(s);
        if t != last_t {
            writeln!(w, "#{t}").map_err(io)?;
            last_t = t;
        }
        level[k] = !level[k];
        writeln!(w, "{}{}", level[k] as u8, id(k)).map_err(io)?;
    }
    let end = time(cap.length.saturating_sub(1));
    if end > last_t {
        writeln!(w, "#{end}").map_err(io)?;
    }
    w.flush().map_err(io)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::capture::Channel;

    #[test]
    fn timescales() {
        assert_eq!(exact_timescale(100_000_000), Some((10, "ns")));
        assert_eq!(exact_timescale(1_000_000_000), Some((1, "ns")));
        assert_eq!(exact_timescale(1_000_000), Some((1, "us")));
        assert_eq!(exact_timescale(10_000_000), Some((100, "ns")));
        assert_eq!(exact_timescale(24_000_000), None);
        assert_eq!(exact_timescale(32_000_000), None);
    }

    #[test]
    fn round_trip() {
        let cap = Capture {
            samplerate: 100_000_000,
            length: 500_000,
            channels: (0..5)
                .map(|k| Channel { name: format!("P{k}"), initial: k == 2, edges: (1..30).map(|i| i * 1001 + k).collect() })
                .collect(),
        };
        let dir = std::env::temp_dir().join(format!("tmc429-vcd-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let p = dir.join("t.vcd");
        write(&p, &cap).unwrap();
        assert_eq!(read(&p).unwrap(), cap);
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
