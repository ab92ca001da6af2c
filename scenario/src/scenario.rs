//! Scenario files (docs/scenarios.md): TOML that names a chip, its clock, a driver
//! configuration, register writes by register and field name (from the one register table,
//! [`tmc429_model::regmap`]), timed and conditional events, switch changes and expectations.
//!
//! Parsing checks everything before anything runs: unknown names and impossible values are
//! reported with file, line and what was expected ([`ParseError`]).

use std::fmt;

use toml::de::DeTable;

use tmc429_model::regmap::{self, Access, Field, Register, Space};
use tmc429_model::text::shown;
use tmc429_model::Chip;

mod ctx;
mod sections;
use ctx::{Ctx, Named, Sp};
use sections::{driver_setup, lut_setup};

/// One problem in a scenario file.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ParseError {
    pub file: String,
    pub line: usize,
    pub msg: String,
}

impl fmt::Display for ParseError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}: {}", self.file, self.line, self.msg)
    }
}

/// Driver configurations by name (`driver = "…"`).
pub const DRIVERS: [&str; 4] = ["table-11-2", "step-dir", "power-on", "none"];

/// Input pins a scenario may switch (`switch = { ref1 = true }`).
pub const PINS: [&str; 7] = ["ref1", "ref2", "ref3", "refr1", "refr2", "refr3", "sdi_s"];

/// How a register write gets its data.
#[derive(Clone, Debug)]
pub enum WriteData {
    /// The whole 24-bit data word.
    Whole(u32),
    /// These fields (raw values), the others as last written (power-on values at first).
    Fields(Vec<(Field, u32)>),
    /// pmul_pdiv from the motor's a_max, ramp_div and pulse_div as last written, by the
    /// datasheet's method with this p reduction (TMC429 §8.1.10.2.3).
    AutoPmul(f32),
}

/// One register write (one SPI datagram).
#[derive(Clone, Debug)]
pub struct Write {
    pub a7: u8,
    pub reg: &'static Register,
    pub motor: Option<u8>,
    pub data: WriteData,
    pub line: usize,
}

/// Something the scenario does: a register write over SPI or a change of input pins.
#[derive(Clone, Debug)]
pub enum Action {
    Write(Write),
    /// Pin index into [`PINS`] and its new level.
    Pins(Vec<(usize, bool)>),
}

/// A condition on the chip's probes and pins, checked after every CLK edge.
#[derive(Clone, Debug)]
pub enum Condition {
    /// x_actual of a motor equals the value (24-bit, compared modulo 2^24).
    Position { motor: u8, x: i32 },
    /// v_actual (sign and 11 MSBs of the internal velocity) equals the value.
    Velocity { motor: u8, v: i32 },
    /// x_actual = x_target.
    AtTarget { motor: u8, yes: bool },
    /// internal velocity 0.
    Stopped { motor: u8, yes: bool },
    /// The INT output (status bit 7: any unmasked interrupt flag, TMC428 §8.13).
    Int(bool),
}

/// What starts an event.
#[derive(Clone, Debug)]
pub enum Trigger {
    /// After this many CLK edges.
    Cycle(u64),
    /// The first edge after which the condition holds.
    When(Condition),
}

#[derive(Clone, Debug)]
pub struct EventSpec {
    pub line: usize,
    pub trigger: Trigger,
    pub actions: Vec<Action>,
}

/// What an expectation checks.
#[derive(Clone, Debug)]
pub enum Check {
    /// Probe or pin values (index into [`tmc429_testbench::signals::SIGNALS`], expected value) after edge `at`.
    Probes { at: u64, values: Vec<(usize, i64)> },
    /// A register (or one field of it) read over SPI, the read frame starting after edge `at`.
    Register { at: u64, a7: u8, reg: &'static Register, field: Option<Field>, expected: i64 },
    /// The condition holds at some edge in `after..=after + within`.
    Reached { cond: Condition, after: u64, within: u64 },
}

#[derive(Clone, Debug)]
pub struct Expect {
    pub name: String,
    pub line: usize,
    pub check: Check,
}

/// A parsed scenario.
#[derive(Clone, Debug)]
pub struct Scenario {
    pub file: String,
    pub name: String,
    pub chip: Chip,
    pub fclk: u64,
    /// CLK edges to run.
    pub duration: u64,
    /// SCK_C half period of the µC's frames [CLK].
    pub sck_half: u32,
    pub driver: &'static str,
    pub lut: bool,
    /// Writes at the start: driver configuration, LUT, then `[[write]]` in file order.
    pub setup: Vec<Action>,
    pub events: Vec<EventSpec>,
    pub expects: Vec<Expect>,
}

impl Scenario {
    /// Seconds of `cycles` CLK edges.
    pub fn seconds(&self, cycles: u64) -> f64 {
        cycles as f64 / self.fclk as f64
    }
}

/// Time as a human reads it: `12.5 ms`, `3 s`.
pub fn fmt_time(seconds: f64) -> String {
    let (v, unit) = if seconds >= 1.0 {
        (seconds, "s")
    } else if seconds >= 1e-3 {
        (seconds * 1e3, "ms")
    } else if seconds >= 1e-6 {
        (seconds * 1e6, "µs")
    } else {
        (seconds * 1e9, "ns")
    };
    let s = format!("{v:.3}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    format!("{s} {unit}")
}

/// A time string to CLK cycles at `fclk`.
pub fn parse_time(s: &str, fclk: u64) -> Result<u64, String> {
    let t = s.trim();
    let split = t.find(|c: char| !(c.is_ascii_digit() || c == '.' || c == '_' || c == 'e' || c == '-' || c == '+')).unwrap_or(t.len());
    let (num, unit) = t.split_at(split);
    let num: String = num.chars().filter(|&c| c != '_').collect();
    let x: f64 = num
        .parse()
        .map_err(|_| format!("expected a time such as \"10 ms\", \"2.5 s\", \"500 us\" or \"1000 cycles\", found \"{}\"", shown(s)))?;
    if !(x >= 0.0 && x.is_finite()) {
        return Err(format!("expected a time ≥ 0, found \"{}\"", shown(s)));
    }
    let scale = match unit.trim() {
        "cycles" | "cycle" | "clk" => None,
        "s" => Some(1.0),
        "ms" => Some(1e-3),
        "us" | "µs" => Some(1e-6),
        "ns" => Some(1e-9),
        u => return Err(format!("unknown time unit \"{}\" in \"{}\": expected s, ms, us, ns or cycles", shown(u), shown(s))),
    };
    let cycles = match scale {
        Some(scale) => (x * scale * fclk as f64).round(),
        None => x.round(),
    };
    // 2^64 and above would be cut to u64::MAX by the conversion: a time that long is rejected
    if cycles >= u64::MAX as f64 {
        return Err(format!("time \"{}\" is {cycles:e} CLK cycles, more than a 64-bit cycle count holds", shown(s)));
    }
    Ok(cycles as u64)
}

/// Byte offset of the line that opens the most levels (dots of dotted keys, `[`, `{`), outside
/// strings and comments: where a nesting error without a place of its own is reported.
fn deepest_line(text: &str) -> usize {
    let (mut best, mut best_at, mut at) = (0, 0, 0);
    for line in text.split_inclusive('\n') {
        let (mut n, mut quote) = (0, None);
        for c in line.chars() {
            match (quote, c) {
                (None, '"' | '\'') => quote = Some(c),
                (Some(q), c) if c == q => quote = None,
                (None, '#') => break,
                (None, '.' | '[' | '{') => n += 1,
                _ => {}
            }
        }
        if n > best {
            (best, best_at) = (n, at);
        }
        at += line.len();
    }
    best_at
}

/// A frequency: integer Hz or a string with Hz, kHz, MHz.
fn parse_freq(s: &str) -> Result<u64, String> {
    let t = s.trim();
    let (n, mult) = if let Some(n) = t.strip_suffix("MHz") {
        (n, 1e6)
    } else if let Some(n) = t.strip_suffix("kHz") {
        (n, 1e3)
    } else {
        (t.strip_suffix("Hz").unwrap_or(t), 1.0)
    };
    let v: f64 = n.trim().parse().map_err(|_| format!("expected a frequency such as 32000000 or \"32 MHz\", found \"{}\"", shown(s)))?;
    let hz = (v * mult).round();
    if !(1e3..=1e9).contains(&hz) {
        return Err(format!("frequency \"{}\" out of range 1 kHz .. 1 GHz", shown(s)));
    }
    Ok(hz as u64)
}

/// The values a field takes in a write: signed fields as signed numbers.
pub fn field_range(f: &Field) -> (i64, i64) {
    if f.signed {
        (-(1i64 << (f.width - 1)), (1i64 << (f.width - 1)) - 1)
    } else {
        (0, (1i64 << f.width) - 1)
    }
}

/// Whether the µC may write the register at all (R-only registers without a write effect
/// may not).
pub fn writable(r: &Register) -> bool {
    r.fields.iter().any(|f| f.access != Access::R) || r.effect.contains("write")
}

fn registers_of(chip: Chip, space: Space) -> impl Iterator<Item = &'static Register> {
    regmap::REGISTERS.iter().filter(move |r| r.space == space && r.chips.contains(chip))
}

/// Parses a scenario file's text; every error with its line (`file` names it in the errors).
pub fn parse(text: &str, file: &str) -> Result<Scenario, Vec<ParseError>> {
    let doc = match DeTable::parse(text) {
        Ok(d) => d,
        Err(e) => {
            let mut c = Ctx { file, text, errors: Vec::new(), chip: Chip::Tmc429, fclk: 32_000_000 };
            match e.span() {
                Some(sp) => c.err(sp.start, format!("TOML: {}", e.message().trim())),
                // the parser's recursion limit has no place: the line that nests deepest
                None => {
                    c.err(deepest_line(text), format!("TOML: {} (keys, arrays or inline tables nested too deeply)", e.message().trim()))
                }
            }
            return Err(c.errors);
        }
    };
    let root = doc.get_ref();
    let mut c = Ctx { file, text, errors: Vec::new(), chip: Chip::Tmc429, fclk: 0 };
    const TOP: [&str; 10] = ["name", "chip", "fclk", "duration", "driver", "lut", "sck_half", "write", "event", "expect"];
    c.check_keys(root, &TOP, "scenario");
    c.chip_and_fclk(root);
    let name = match root.get("name") {
        Some(v) => c.string(v, "name").unwrap_or("").to_string(),
        None => file.rsplit('/').next().unwrap_or(file).trim_end_matches(".toml").to_string(),
    };
    let duration = c.duration(root);
    let sck_half = c.sck_half(root);
    let (driver, lut) = (c.driver(root), c.lut(root));
    let line_of = |c: &Ctx, k: &str| root.get_key_value(k).map(|(k, _)| c.line(k.span().start)).unwrap_or(1);
    let mut setup = driver_setup(driver, line_of(&c, "driver"));
    if lut {
        setup.extend(lut_setup(line_of(&c, "lut")));
    }
    if let Some(v) = root.get("write") {
        for (at, t) in c.tables(v, "write") {
            let w = c.writes(t, at);
            setup.extend(w);
        }
    }
    let mut events = Vec::new();
    if let Some(v) = root.get("event") {
        for (at, t) in c.tables(v, "event") {
            events.extend(c.event(at, t, duration));
        }
    }
    let mut expects = Vec::new();
    if let Some(v) = root.get("expect") {
        for (at, t) in c.tables(v, "expect") {
            expects.extend(c.expect(at, t, duration, sck_half));
        }
    }
    if !c.errors.is_empty() {
        c.errors.sort_by_key(|e| e.line);
        return Err(c.errors);
    }
    Ok(Scenario { file: file.to_string(), name, chip: c.chip, fclk: c.fclk, duration, sck_half, driver, lut, setup, events, expects })
}

/// A condition in words.
pub fn describe(c: &Condition) -> String {
    match c {
        Condition::Position { motor, x } => format!("motor {motor} x_actual = {x}"),
        Condition::Velocity { motor, v } => format!("motor {motor} v_actual = {v}"),
        Condition::AtTarget { motor, yes } => format!("motor {motor} {}at target", if *yes { "" } else { "not " }),
        Condition::Stopped { motor, yes } => format!("motor {motor} {}", if *yes { "stopped" } else { "moving" }),
        Condition::Int(b) => format!("INT = {}", *b as u8),
    }
}
