//! Datagram scripts of `tmc429 spi`: parsing (with line numbers) and running on a [`Host`].
//!
//! ```text
//! # comment to the end of a line
//! 0x1A000123        a 32-bit datagram: 8 hex digits, optional 0x or $ prefix
//! bits 8 0x01       a short frame of N bits (1..31)
//! wait 100000       advance this many CLK cycles
//! pin REF1=1 REF3=0 set input pins from now on (REF1..REF3, REFR1..REFR3, SDI_S)
//! ```

use std::fmt;
use std::io::{self, Write};

use std::sync::{Arc, Mutex};

use crate::events::{Event, EventDecoder};
use crate::host::Host;
use crate::regmap::{self, Addr};
use crate::text::shown;
use crate::{Chip, Inputs};

/// Input pins a script may set.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Pin {
    Ref1,
    Ref2,
    Ref3,
    Refr1,
    Refr2,
    Refr3,
    SdiS,
}

impl Pin {
    pub const NAMES: [(&'static str, Pin); 7] = [
        ("REF1", Pin::Ref1),
        ("REF2", Pin::Ref2),
        ("REF3", Pin::Ref3),
        ("REFR1", Pin::Refr1),
        ("REFR2", Pin::Refr2),
        ("REFR3", Pin::Refr3),
        ("SDI_S", Pin::SdiS),
    ];

    pub fn parse(name: &str) -> Option<Pin> {
        Pin::NAMES.iter().find(|(n, _)| n.eq_ignore_ascii_case(name)).map(|(_, p)| *p)
    }

    pub fn set(self, pins: &mut Inputs, level: bool) {
        match self {
            Pin::Ref1 => pins.ref1 = level,
            Pin::Ref2 => pins.ref2 = level,
            Pin::Ref3 => pins.ref3 = level,
            Pin::Refr1 => pins.refr1 = level,
            Pin::Refr2 => pins.refr2 = level,
            Pin::Refr3 => pins.refr3 = level,
            Pin::SdiS => pins.sdi_s = level,
        }
    }
}

/// One command of a script.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Command {
    Datagram(u32),
    Bits { n: u32, value: u32 },
    Wait(u64),
    Pins(Vec<(Pin, bool)>),
}

/// A command with the line it came from (1-based).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Line {
    pub line: usize,
    pub command: Command,
}

/// A parse error: where and what was expected.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ParseError {
    pub file: String,
    pub line: usize,
    pub message: String,
}

impl fmt::Display for ParseError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}: {}", self.file, self.line, self.message)
    }
}

fn parse_hex(tok: &str) -> Option<(u64, usize)> {
    let digits = tok.strip_prefix("0x").or_else(|| tok.strip_prefix("0X")).or_else(|| tok.strip_prefix('$')).unwrap_or(tok);
    if digits.is_empty() || digits.len() > 16 || !digits.chars().all(|c| c.is_ascii_hexdigit()) {
        return None;
    }
    u64::from_str_radix(digits, 16).ok().map(|v| (v, digits.len()))
}

fn parse_line(text: &str) -> Result<Option<Command>, String> {
    let body = text.split('#').next().unwrap_or("").trim();
    if body.is_empty() {
        return Ok(None);
    }
    let toks: Vec<&str> = body.split_whitespace().collect();
    match toks[0].to_ascii_lowercase().as_str() {
        "bits" => {
            if toks.len() != 3 {
                return Err("expected 'bits N VALUE' (N 1..31, VALUE in hex)".into());
            }
            let n: u32 = toks[1]
                .parse()
                .ok()
                .filter(|n| (1..=31).contains(n))
                .ok_or_else(|| format!("expected a bit count 1..31, found '{}'", shown(toks[1])))?;
            let (v, _) = parse_hex(toks[2]).ok_or_else(|| format!("expected a hex value, found '{}'", shown(toks[2])))?;
            if v >> n != 0 {
                return Err(format!("value {} does not fit in {} bits", shown(toks[2]), n));
            }
            Ok(Some(Command::Bits { n, value: v as u32 }))
        }
        "wait" => {
            if toks.len() != 2 {
                return Err("expected 'wait CYCLES'".into());
            }
            let c: u64 =
                toks[1].replace('_', "").parse().map_err(|_| format!("expected a decimal cycle count, found '{}'", shown(toks[1])))?;
            Ok(Some(Command::Wait(c)))
        }
        "pin" => {
            if toks.len() < 2 {
                return Err("expected 'pin NAME=0|1 ...'".into());
            }
            let mut set = Vec::new();
            for t in &toks[1..] {
                let (name, val) = t.split_once('=').ok_or_else(|| format!("expected NAME=0 or NAME=1, found '{}'", shown(t)))?;
                let pin = Pin::parse(name)
                    .ok_or_else(|| format!("unknown pin '{}': expected REF1, REF2, REF3, REFR1, REFR2, REFR3 or SDI_S", shown(name)))?;
                let level = match val {
                    "0" => false,
                    "1" => true,
                    _ => return Err(format!("pin {}: expected 0 or 1, found '{}'", shown(name), shown(val))),
                };
                set.push((pin, level));
            }
            Ok(Some(Command::Pins(set)))
        }
        _ => {
            if toks.len() != 1 {
                return Err(format!("unexpected '{}' after the datagram", shown(&toks[1..].join(" "))));
            }
            match parse_hex(toks[0]) {
                Some((v, 8)) => Ok(Some(Command::Datagram(v as u32))),
                Some(_) => Err(format!("a datagram has exactly 8 hex digits, found '{}'", shown(toks[0]))),
                None => Err(format!("expected a datagram (8 hex digits), 'bits', 'wait' or 'pin', found '{}'", shown(toks[0]))),
            }
        }
    }
}

/// Parses a whole script. All errors are returned, each with its line.
pub fn parse(src: &str, file: &str) -> Result<Vec<Line>, Vec<ParseError>> {
    let mut lines = Vec::new();
    let mut errors = Vec::new();
    for (i, text) in src.lines().enumerate() {
        match parse_line(text) {
            Ok(Some(command)) => lines.push(Line { line: i + 1, command }),
            Ok(None) => {}
            Err(message) => errors.push(ParseError { file: file.to_string(), line: i + 1, message }),
        }
    }
    if errors.is_empty() {
        Ok(lines)
    } else {
        Err(errors)
    }
}

/// Output options of [`run`].
#[derive(Clone, Copy, Debug, Default)]
pub struct RunOptions {
    /// Prefix each line with the CLK cycle at which nSCS_C rose.
    pub timestamps: bool,
    /// Append the register name and decoded fields.
    pub decode: bool,
    /// Interleave `chain`, `step` and `int` event lines (pin-level, [`crate::events`]) in
    /// cycle order; a frame line's cycle is the edge at which nSCS_C rose.
    pub events: bool,
}

/// The decoding of a datagram and its reply for humans.
pub fn decode(chip: Chip, datagram: u32, reply: u32) -> String {
    let a7 = ((datagram >> 25) & 0x7F) as u8;
    let read = (datagram >> 24) & 1 == 1;
    let name = regmap::display_name(chip, a7);
    let data = if read { reply & 0xFF_FFFF } else { datagram & 0xFF_FFFF };
    let fields = match regmap::lookup(chip, a7) {
        Some((reg, _)) => match Addr::from_a7(a7) {
            Addr::Ram(a) => format!("cell{}={} cell{}={}", 2 * a as u32 + 1, (data >> 8) & 63, 2 * a as u32, data & 63),
            _ => regmap::decode_fields(reg, data),
        },
        None => String::new(),
    };
    let st = (reply >> 24) as u8;
    let sep = if fields.is_empty() { "" } else { " " };
    format!("{} {}{}{} | {}", if read { "R" } else { "W" }, name, sep, fields, decode_status(st))
}

/// The status byte's bits, bit 0 first (TMC428 Table 6-4).
pub const STATUS_BITS: [&str; 8] = ["xEQt1", "RS1", "xEQt2", "RS2", "xEQt3", "RS3", "CDGW", "INT"];

/// `status $15: xEQt1 xEQt2 xEQt3` (TMC428 Table 6-4).
pub fn decode_status(st: u8) -> String {
    let set: Vec<&str> = (0..8).rev().filter(|b| st >> b & 1 == 1).map(|b| STATUS_BITS[b]).collect();
    format!("status ${:02X}: {}", st, if set.is_empty() { "-".to_string() } else { set.join(" ") })
}

/// Writes the queued events with a cycle ≤ `upto` (all with `None`).
fn flush_events(queue: &Arc<Mutex<Vec<Event>>>, upto: Option<u64>, out: &mut dyn Write) -> io::Result<()> {
    let mut q = queue.lock().unwrap();
    let n = match upto {
        Some(c) => q.iter().take_while(|e| e.cycle() <= c).count(),
        None => q.len(),
    };
    for e in q.drain(..n) {
        writeln!(out, "{e}")?;
    }
    Ok(())
}

/// Runs a parsed script, writing one line per frame (and, with `events`, one per event).
pub fn run(host: &mut Host, script: &[Line], opts: RunOptions, out: &mut dyn Write) -> io::Result<()> {
    let queue: Arc<Mutex<Vec<Event>>> = Arc::new(Mutex::new(Vec::new()));
    let saved = if opts.events {
        let q = queue.clone();
        let mut dec = EventDecoder::new();
        let prev = host.take_observer();
        host.set_change_observer(Box::new(move |c, _i, o| {
            dec.observe(c, o, c.cycle(), &mut |e| q.lock().unwrap().push(e));
        }));
        Some(prev)
    } else {
        None
    };
    let r = run_lines(host, script, opts, &queue, out);
    if let Some(prev) = saved {
        host.take_observer();
        if let Some(p) = prev {
            host.set_observer(p);
        }
    }
    r?;
    flush_events(&queue, None, out)
}

fn run_lines(host: &mut Host, script: &[Line], opts: RunOptions, queue: &Arc<Mutex<Vec<Event>>>, out: &mut dyn Write) -> io::Result<()> {
    for l in script {
        match &l.command {
            Command::Datagram(d) => {
                let r = host.datagram(*d);
                flush_events(queue, Some(host.last_frame_end()), out)?;
                let mut s = String::new();
                if opts.timestamps {
                    s += &format!("{} ", host.last_frame_end());
                }
                s += &format!("{r:08X}");
                if opts.decode {
                    s += "  # ";
                    s += &decode(host.chip().chip(), *d, r);
                }
                writeln!(out, "{s}")?;
            }
            Command::Bits { n, value } => {
                let r = host.frame(*value, *n);
                flush_events(queue, Some(host.last_frame_end()), out)?;
                let digits = n.div_ceil(4) as usize;
                let mut s = String::new();
                if opts.timestamps {
                    s += &format!("{} ", host.last_frame_end());
                }
                s += &format!("{r:0digits$X}");
                if opts.decode && *n >= 8 {
                    s += "  # short frame, nothing executed | ";
                    s += &decode_status((r >> (n - 8)) as u8);
                } else if opts.decode {
                    s += "  # short frame, nothing executed";
                }
                writeln!(out, "{s}")?;
            }
            Command::Wait(c) => {
                host.wait(*c);
                flush_events(queue, Some(host.cycle()), out)?;
            }
            Command::Pins(set) => {
                for (p, v) in set {
                    p.set(host.pins_mut(), *v);
                }
            }
        }
    }
    Ok(())
}
