//! Scenario files (docs/scenarios.md): TOML that names a chip, its clock, a driver
//! configuration, register writes by register and field name (from the one register table,
//! [`tmc429_model::regmap`]), timed and conditional events, switch changes and expectations.
//!
//! Parsing checks everything before anything runs: unknown names and impossible values are
//! reported with file, line and what was expected ([`ParseError`]).

use std::fmt;

use toml::de::{DeTable, DeValue};
use toml::Spanned;

use tmc429_model::regmap::{self, Access, Field, Register, Space};
use tmc429_model::text::shown;
use tmc429_model::Chip;
use tmc429_testbench::signals::{self, SIGNALS};

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
    /// Probe or pin values (index into [`SIGNALS`], expected value) after edge `at`.
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

struct Ctx<'a> {
    file: &'a str,
    text: &'a str,
    errors: Vec<ParseError>,
    chip: Chip,
    fclk: u64,
}

type Sp<'i> = Spanned<DeValue<'i>>;

impl Ctx<'_> {
    fn line(&self, offset: usize) -> usize {
        self.text[..offset.min(self.text.len())].bytes().filter(|&b| b == b'\n').count() + 1
    }
    fn err(&mut self, offset: usize, msg: impl Into<String>) {
        let line = self.line(offset);
        self.errors.push(ParseError { file: self.file.to_string(), line, msg: msg.into() });
    }

    fn int(&mut self, v: &Sp, what: &str) -> Option<i64> {
        match v.get_ref() {
            DeValue::Integer(i) => match i64::from_str_radix(i.as_str(), i.radix()) {
                Ok(x) => Some(x),
                Err(_) => {
                    self.err(v.span().start, format!("{what}: integer out of range"));
                    None
                }
            },
            DeValue::Boolean(b) => Some(*b as i64),
            other => {
                self.err(v.span().start, format!("{what}: expected an integer, found {}", other.type_str()));
                None
            }
        }
    }

    fn string<'v>(&mut self, v: &'v Sp, what: &str) -> Option<&'v str> {
        match v.get_ref() {
            DeValue::String(s) => Some(s.as_ref()),
            other => {
                self.err(v.span().start, format!("{what}: expected a string, found {}", other.type_str()));
                None
            }
        }
    }

    fn boolean(&mut self, v: &Sp, what: &str) -> Option<bool> {
        match v.get_ref() {
            DeValue::Boolean(b) => Some(*b),
            DeValue::Integer(_) => match self.int(v, what)? {
                0 => Some(false),
                1 => Some(true),
                x => {
                    self.err(v.span().start, format!("{what}: expected true/false or 0/1, found {x}"));
                    None
                }
            },
            other => {
                self.err(v.span().start, format!("{what}: expected true or false, found {}", other.type_str()));
                None
            }
        }
    }

    /// A time: an integer counts CLK cycles; a string is `N cycles` or a number with s, ms,
    /// us (µs) or ns.
    fn time(&mut self, v: &Sp, what: &str) -> Option<u64> {
        if let DeValue::Integer(_) = v.get_ref() {
            let x = self.int(v, what)?;
            if x < 0 {
                self.err(v.span().start, format!("{what}: expected a cycle count ≥ 0, found {x}"));
                return None;
            }
            return Some(x as u64);
        }
        let s = self.string(v, what)?.trim().to_string();
        match parse_time(&s, self.fclk) {
            Ok(c) => Some(c),
            Err(e) => {
                self.err(v.span().start, format!("{what}: {e}"));
                None
            }
        }
    }

    fn table<'v, 'i>(&mut self, v: &'v Sp<'i>, what: &str) -> Option<&'v DeTable<'i>> {
        match v.get_ref() {
            DeValue::Table(t) => Some(t),
            other => {
                self.err(v.span().start, format!("{what}: expected a table, found {}", other.type_str()));
                None
            }
        }
    }

    /// A table or an array of tables.
    fn tables<'v, 'i>(&mut self, v: &'v Sp<'i>, what: &str) -> Vec<(usize, &'v DeTable<'i>)> {
        match v.get_ref() {
            DeValue::Table(t) => vec![(v.span().start, t)],
            DeValue::Array(a) => {
                let mut out = Vec::new();
                for item in a.iter() {
                    if let Some(t) = self.table(item, what) {
                        out.push((item.span().start, t));
                    }
                }
                out
            }
            other => {
                self.err(v.span().start, format!("{what}: expected a table or an array of tables, found {}", other.type_str()));
                Vec::new()
            }
        }
    }

    fn motor(&mut self, v: &Sp) -> Option<u8> {
        let m = self.int(v, "motor")?;
        let n = if self.chip == Chip::Tmc4210 { 1 } else { 3 };
        if !(0..n).contains(&m) {
            let range = if n == 1 { "0 (the TMC4210 has one motor)".to_string() } else { "0..2".to_string() };
            self.err(v.span().start, format!("motor {m} out of range: expected {range}"));
            return None;
        }
        Some(m as u8)
    }

    /// `motor = N` of a table, if present.
    fn motor_key(&mut self, t: &DeTable) -> Result<Option<u8>, ()> {
        match t.get("motor") {
            Some(v) => self.motor(v).map(Some).ok_or(()),
            None => Ok(None),
        }
    }
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

/// What a key of a write or register table names.
enum Named {
    Reg(&'static Register),
    Field(&'static Register, &'static Field),
}

impl Ctx<'_> {
    /// Resolves a register or field name for a motor (`motor` given) or a global register.
    fn name(&mut self, key: &Spanned<std::borrow::Cow<str>>, motor: Option<u8>) -> Option<Named> {
        let k = key.get_ref().as_ref();
        let ks = shown(k);
        let space = if motor.is_some() { Space::Motor } else { Space::Global };
        if let Some(r) = registers_of(self.chip, space).find(|r| r.name.eq_ignore_ascii_case(k)) {
            return Some(Named::Reg(r));
        }
        for r in registers_of(self.chip, space) {
            if let Some(f) = r.field(k) {
                return Some(Named::Field(r, f));
            }
        }
        // the other space?
        let other = if motor.is_some() { Space::Global } else { Space::Motor };
        let in_other = registers_of(self.chip, other).any(|r| r.name.eq_ignore_ascii_case(k) || r.field(k).is_some());
        let msg = if in_other && motor.is_some() {
            format!("'{ks}' is a global register or field: remove `motor`")
        } else if in_other {
            format!("'{ks}' is a motor register or field: add `motor = 0..2`")
        } else if regmap::REGISTERS.iter().any(|r| r.name.eq_ignore_ascii_case(k) || r.field(k).is_some()) {
            format!("'{ks}' does not exist on the {}", self.chip)
        } else {
            let names: Vec<&str> = registers_of(self.chip, space).map(|r| r.name).collect();
            format!(
                "unknown {} register or field '{ks}': expected one of {} or one of their fields (tmc429 regmap)",
                if motor.is_some() { "motor" } else { "global" },
                names.join(", ")
            )
        };
        self.err(key.span().start, msg);
        None
    }

    fn field_value(&mut self, v: &Sp, reg: &Register, f: &Field) -> Option<u32> {
        let what = format!("{}.{}", reg.name, f.name);
        if f.access == Access::R {
            self.err(v.span().start, format!("{what} is read-only"));
            return None;
        }
        let x = self.int(v, &what)?;
        let (lo, hi) = field_range(f);
        if !(lo..=hi).contains(&x) {
            self.err(
                v.span().start,
                format!("{what} = {x} out of range: expected {lo}..{hi} ({} bits{})", f.width, if f.signed { ", signed" } else { "" }),
            );
            return None;
        }
        Some((x as u32) & (((1u64 << f.width) - 1) as u32))
    }

    /// One table of register writes: `{ motor = 0, clk_config = { pulse_div = 5 }, v_max = 2047 }`.
    /// Consecutive fields of the same register become one datagram.
    fn writes(&mut self, t: &DeTable, at: usize) -> Vec<Action> {
        let Ok(motor) = self.motor_key(t) else { return Vec::new() };
        let mut out: Vec<Write> = Vec::new();
        for (k, v) in t.iter() {
            if k.get_ref() == "motor" {
                continue;
            }
            let line = self.line(k.span().start);
            let Some(named) = self.name(k, motor) else { continue };
            match named {
                Named::Reg(reg) => {
                    if !writable(reg) {
                        self.err(k.span().start, format!("{} is read-only", reg.name));
                        continue;
                    }
                    let a7 = reg.a7(motor.unwrap_or(0));
                    let data = match v.get_ref() {
                        DeValue::Table(ft) => {
                            let mut fields = Vec::new();
                            for (fk, fv) in ft.iter() {
                                match reg.field(fk.get_ref()) {
                                    Some(f) => {
                                        if let Some(x) = self.field_value(fv, reg, f) {
                                            fields.push((*f, x));
                                        }
                                    }
                                    None => {
                                        let names: Vec<&str> = reg.fields.iter().map(|f| f.name).collect();
                                        self.err(
                                            fk.span().start,
                                            format!(
                                                "{} has no field '{}': expected one of {}",
                                                reg.name,
                                                shown(fk.get_ref()),
                                                names.join(", ")
                                            ),
                                        );
                                    }
                                }
                            }
                            WriteData::Fields(fields)
                        }
                        DeValue::String(s) if reg.name == "pmul_pdiv" && s.as_ref() == "auto" => WriteData::AutoPmul(0.01),
                        DeValue::String(s) => {
                            self.err(
                                v.span().start,
                                format!(
                                    "{}: expected an integer or a table of fields{}, found \"{}\"",
                                    reg.name,
                                    if reg.name == "pmul_pdiv" { " or \"auto\"" } else { "" },
                                    shown(s)
                                ),
                            );
                            continue;
                        }
                        _ => {
                            let Some(x) = self.int(v, reg.name) else { continue };
                            let (lo, hi) = if reg.fields.len() == 1 { field_range(&reg.fields[0]) } else { (0, 0xFF_FFFF) };
                            // a single-field register takes the field's range; x_latched and
                            // friends take any 24-bit word
                            let (lo, hi) =
                                if reg.fields.len() == 1 && reg.fields[0].access == Access::R { (-(1 << 23), 0xFF_FFFF) } else { (lo, hi) };
                            if !(lo..=hi).contains(&x) {
                                self.err(v.span().start, format!("{} = {x} out of range: expected {lo}..{hi}", reg.name));
                                continue;
                            }
                            let word = if reg.fields.len() == 1 { (x as u32) << reg.fields[0].lsb } else { x as u32 };
                            WriteData::Whole(word & 0xFF_FFFF)
                        }
                    };
                    out.push(Write { a7, reg, motor, data, line });
                }
                Named::Field(reg, f) => {
                    let Some(x) = self.field_value(v, reg, f) else { continue };
                    let a7 = reg.a7(motor.unwrap_or(0));
                    if let Some(Write { a7: la, data: WriteData::Fields(fs), .. }) = out.last_mut() {
                        if *la == a7 {
                            fs.push((*f, x));
                            continue;
                        }
                    }
                    out.push(Write { a7, reg, motor, data: WriteData::Fields(vec![(*f, x)]), line });
                }
            }
        }
        if out.is_empty() && t.iter().all(|(k, _)| k.get_ref() == "motor") {
            self.err(at, "a write names no register");
        }
        out.into_iter().map(Action::Write).collect()
    }

    fn switches(&mut self, t: &DeTable) -> Vec<(usize, bool)> {
        let mut out = Vec::new();
        for (k, v) in t.iter() {
            let name = k.get_ref().to_ascii_lowercase();
            match PINS.iter().position(|p| *p == name) {
                Some(i) => {
                    if let Some(b) = self.boolean(v, &name) {
                        out.push((i, b));
                    }
                }
                None => self.err(k.span().start, format!("unknown pin '{}': expected one of {}", shown(k.get_ref()), PINS.join(", "))),
            }
        }
        out
    }

    fn condition(&mut self, v: &Sp, what: &str) -> Option<Condition> {
        let t = self.table(v, what)?;
        let motor = self.motor_key(t).ok()?;
        let keys: Vec<_> = t.iter().filter(|(k, _)| k.get_ref() != "motor").collect();
        if keys.len() != 1 {
            self.err(
                v.span().start,
                format!("{what}: expected exactly one of x_actual, v_actual, at_target, stopped (with `motor`) or int"),
            );
            return None;
        }
        let (k, val) = keys[0];
        let name = k.get_ref().as_ref();
        let need_motor = |c: &mut Self| -> Option<u8> {
            if motor.is_none() {
                c.err(k.span().start, format!("{what}: '{}' needs `motor = 0..2`", shown(name)));
            }
            motor
        };
        match name {
            "x_actual" => {
                let m = need_motor(self)?;
                let x = self.int(val, name)?;
                if !(-(1 << 23)..(1 << 23)).contains(&x) {
                    self.err(val.span().start, format!("x_actual = {x} out of range: expected -8388608..8388607"));
                    return None;
                }
                Some(Condition::Position { motor: m, x: x as i32 })
            }
            "v_actual" => {
                let m = need_motor(self)?;
                let x = self.int(val, name)?;
                if !(-2047..=2047).contains(&x) {
                    self.err(val.span().start, format!("v_actual = {x} out of range: expected -2047..2047"));
                    return None;
                }
                Some(Condition::Velocity { motor: m, v: x as i32 })
            }
            "at_target" => {
                let m = need_motor(self)?;
                Some(Condition::AtTarget { motor: m, yes: self.boolean(val, name)? })
            }
            "stopped" => {
                let m = need_motor(self)?;
                Some(Condition::Stopped { motor: m, yes: self.boolean(val, name)? })
            }
            "int" => Some(Condition::Int(self.boolean(val, name)?)),
            _ => {
                self.err(
                    k.span().start,
                    format!("{what}: unknown condition '{}': expected x_actual, v_actual, at_target, stopped or int", shown(name)),
                );
                None
            }
        }
    }

    fn check_keys(&mut self, t: &DeTable, allowed: &[&str], what: &str) {
        for (k, _) in t.iter() {
            if !allowed.contains(&k.get_ref().as_ref()) {
                self.err(k.span().start, format!("{what}: unknown key '{}': expected {}", shown(k.get_ref()), allowed.join(", ")));
            }
        }
    }

    fn probe_values(&mut self, v: &Sp) -> Vec<(usize, i64)> {
        let Some(t) = self.table(v, "probe") else { return Vec::new() };
        let Ok(motor) = self.motor_key(t) else { return Vec::new() };
        let mut out = Vec::new();
        for (k, val) in t.iter() {
            let name = k.get_ref().as_ref();
            if name == "motor" {
                continue;
            }
            let idx = match motor {
                Some(m) => signals::index_of(&format!("motor{m}.{name}")),
                None => signals::index_of(&format!("top.{name}")).or_else(|| signals::index_of(&format!("chain.{name}"))),
            };
            let Some(i) = idx else {
                let list: Vec<String> = SIGNALS
                    .iter()
                    .filter(|s| if motor.is_some() { s.scope == "motor0" } else { s.scope == "top" || s.scope == "chain" })
                    .map(|s| s.name.to_string())
                    .collect();
                self.err(
                    k.span().start,
                    format!(
                        "unknown {}probe '{}': expected one of {}",
                        if motor.is_some() { "motor " } else { "" },
                        shown(name),
                        list.join(", ")
                    ),
                );
                continue;
            };
            if let Some(x) = self.int(val, name) {
                let w = SIGNALS[i].width;
                let lo = if w >= 24 || SIGNALS[i].signed { -(1i64 << (w - 1)) } else { 0 };
                let hi = if w >= 63 { i64::MAX } else { (1i64 << w) - 1 };
                if !(lo..=hi).contains(&x) {
                    self.err(val.span().start, format!("probe {name} = {x} out of range: expected {lo}..{hi}"));
                    continue;
                }
                out.push((i, x));
            }
        }
        out
    }
}

/// Parses a scenario. `file` names it in messages.
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
    if let Some(v) = root.get("chip") {
        if let Some(s) = c.string(v, "chip") {
            match s.parse::<Chip>() {
                Ok(ch) => c.chip = ch,
                Err(e) => c.err(v.span().start, e),
            }
        }
    }
    c.fclk = c.chip.default_fclk();
    if let Some(v) = root.get("fclk") {
        let r = match v.get_ref() {
            DeValue::Integer(_) => c.int(v, "fclk").map(|x| parse_freq(&x.to_string())),
            _ => c.string(v, "fclk").map(parse_freq),
        };
        match r {
            Some(Ok(f)) => c.fclk = f,
            Some(Err(e)) => c.err(v.span().start, format!("fclk: {e}")),
            None => {}
        }
    }
    let name = match root.get("name") {
        Some(v) => c.string(v, "name").unwrap_or("").to_string(),
        None => file.rsplit('/').next().unwrap_or(file).trim_end_matches(".toml").to_string(),
    };
    let duration = match root.get("duration") {
        Some(v) => {
            let d = c.time(v, "duration");
            if d == Some(0) {
                c.err(v.span().start, "duration: expected more than 0 cycles");
            }
            d.unwrap_or(0)
        }
        None => {
            c.err(0, "missing `duration` (how long to run, e.g. duration = \"50 ms\")");
            0
        }
    };
    let sck_half = match root.get("sck_half") {
        Some(v) => match c.int(v, "sck_half") {
            Some(x) if (tmc429_model::host::MIN_SCK_HALF as i64..=1000).contains(&x) => x as u32,
            Some(x) => {
                c.err(v.span().start, format!("sck_half = {x}: expected 3..1000 CLK (TMC428 Table 6-1: at least 3)"));
                4
            }
            None => 4,
        },
        None => 4,
    };
    let mut setup = Vec::new();
    let mut driver = "none";
    if let Some(v) = root.get("driver") {
        if let Some(s) = c.string(v, "driver") {
            match DRIVERS.iter().find(|d| **d == s) {
                Some(d) => driver = d,
                None => c.err(v.span().start, format!("unknown driver '{}': expected one of {}", shown(s), DRIVERS.join(", "))),
            }
            match (driver, c.chip) {
                ("table-11-2", Chip::Tmc4210) => {
                    c.err(v.span().start, "driver 'table-11-2': the TMC4210 has no driver chain (use 'step-dir')")
                }
                ("step-dir", Chip::Tmc428) => c.err(v.span().start, "driver 'step-dir': the TMC428 has no Step/Dir interface"),
                _ => {}
            }
        }
    }
    let mut lut = false;
    if let Some(v) = root.get("lut") {
        if let Some(s) = c.string(v, "lut") {
            match s {
                "sine" => lut = true,
                "none" => {}
                _ => c.err(v.span().start, format!("unknown lut '{}': expected sine or none", shown(s))),
            }
            if lut && c.chip == Chip::Tmc4210 {
                c.err(v.span().start, "lut: the TMC4210 has no microstep table");
                lut = false;
            }
        }
    }
    let line_of = |c: &Ctx, k: &str| root.get_key_value(k).map(|(k, _)| c.line(k.span().start)).unwrap_or(1);
    setup.extend(driver_setup(c.chip, driver, line_of(&c, "driver")));
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
            c.check_keys(t, &["at", "when", "write", "switch"], "event");
            let line = c.line(at);
            let trigger = match (t.get("at"), t.get("when")) {
                (Some(a), None) => c.time(a, "at").map(Trigger::Cycle),
                (None, Some(w)) => c.condition(w, "when").map(Trigger::When),
                _ => {
                    c.err(at, "event: expected exactly one of `at` (a time) or `when` (a condition)");
                    None
                }
            };
            let mut actions = Vec::new();
            if let Some(w) = t.get("write") {
                for (wat, wt) in c.tables(w, "write") {
                    actions.extend(c.writes(wt, wat));
                }
            }
            if let Some(s) = t.get("switch") {
                if let Some(st) = c.table(s, "switch") {
                    let p = c.switches(st);
                    if !p.is_empty() {
                        actions.push(Action::Pins(p));
                    }
                }
            }
            if t.get("write").is_none() && t.get("switch").is_none() {
                c.err(at, "event: expected `write` and/or `switch`");
            }
            if let (Some(Trigger::Cycle(x)), true) = (&trigger, duration > 0) {
                if *x >= duration {
                    c.err(
                        at,
                        format!(
                            "event at {} is not before the end of the scenario (duration {})",
                            fmt_time(*x as f64 / c.fclk as f64),
                            fmt_time(duration as f64 / c.fclk as f64)
                        ),
                    );
                }
            }
            if let Some(trigger) = trigger {
                events.push(EventSpec { line, trigger, actions });
            }
        }
    }
    let mut expects = Vec::new();
    if let Some(v) = root.get("expect") {
        for (at, t) in c.tables(v, "expect") {
            c.check_keys(t, &["name", "at", "probe", "register", "reached", "within", "after"], "expect");
            let line = c.line(at);
            let given_name = t.get("name").and_then(|n| c.string(n, "name").map(str::to_string));
            let mut checks: Vec<(Check, String)> = Vec::new();
            let tname = |c: &Ctx, x: u64| fmt_time(x as f64 / c.fclk as f64);
            if let Some(r) = t.get("reached") {
                if t.get("at").is_some() || t.get("probe").is_some() || t.get("register").is_some() {
                    c.err(at, "expect: `reached` goes with `within` (and `after`), not with `at`, `probe` or `register`");
                }
                let cond = c.condition(r, "reached");
                let within = match t.get("within") {
                    Some(w) => c.time(w, "within"),
                    None => {
                        c.err(at, "expect: `reached` needs `within` (a time)");
                        None
                    }
                };
                let after = match t.get("after") {
                    Some(a) => c.time(a, "after"),
                    None => Some(0),
                };
                if let (Some(cond), Some(within), Some(after)) = (cond, within, after) {
                    let n = format!("{} within {} after {}", describe(&cond), tname(&c, within), tname(&c, after));
                    checks.push((Check::Reached { cond, after, within }, n));
                }
            } else {
                let Some(atv) = t.get("at") else {
                    c.err(at, "expect: expected `at` with `probe` and/or `register`, or `reached` with `within`");
                    continue;
                };
                let Some(when) = c.time(atv, "at") else { continue };
                if duration > 0 && when > duration {
                    c.err(
                        atv.span().start,
                        format!("at {} is after the end of the scenario (duration {})", tname(&c, when), tname(&c, duration)),
                    );
                }
                if let Some(p) = t.get("probe") {
                    let values = c.probe_values(p);
                    let n = values
                        .iter()
                        .map(|(i, x)| format!("{}.{} = {x}", SIGNALS[*i].scope, SIGNALS[*i].name))
                        .collect::<Vec<_>>()
                        .join(", ");
                    if !values.is_empty() {
                        checks.push((Check::Probes { at: when, values }, format!("{n} at {}", tname(&c, when))));
                    }
                }
                if let Some(r) = t.get("register") {
                    if let Some(rt) = c.table(r, "register") {
                        let Ok(motor) = c.motor_key(rt) else { continue };
                        for (k, val) in rt.iter() {
                            if k.get_ref() == "motor" {
                                continue;
                            }
                            let Some(named) = c.name(k, motor) else { continue };
                            let Some(x) = c.int(val, k.get_ref()) else { continue };
                            let (reg, field) = match named {
                                Named::Reg(r) if r.fields.len() == 1 => (r, Some(r.fields[0])),
                                Named::Reg(r) => (r, None),
                                Named::Field(r, f) => (r, Some(*f)),
                            };
                            if field.is_none() && !(0..=0xFF_FFFF).contains(&x) {
                                c.err(val.span().start, format!("{} = {x} out of range: expected 0..16777215", reg.name));
                                continue;
                            }
                            if let Some(f) = field {
                                let (lo, hi) = field_range(&f);
                                if !(lo..=hi).contains(&x) {
                                    c.err(val.span().start, format!("{} = {x} out of range: expected {lo}..{hi}", f.name));
                                    continue;
                                }
                            }
                            // the read frame must end before the scenario does
                            let frame = 64 * sck_half as u64 + 16;
                            if duration > 0 && when + frame > duration {
                                c.err(
                                    atv.span().start,
                                    format!(
                                        "register read at {} ends after the scenario (duration {}): a read takes {frame} CLK",
                                        tname(&c, when),
                                        tname(&c, duration)
                                    ),
                                );
                                continue;
                            }
                            let a7 = reg.a7(motor.unwrap_or(0));
                            let who = match (motor, field) {
                                (Some(m), Some(f)) => format!("motor {m} {} = {x}", f.name),
                                (Some(m), None) => format!("motor {m} {} = {x}", reg.name),
                                (None, Some(f)) => format!("{} = {x}", f.name),
                                (None, None) => format!("{} = {x}", reg.name),
                            };
                            checks.push((
                                Check::Register { at: when, a7, reg, field, expected: x },
                                format!("{who} (read) at {}", tname(&c, when)),
                            ));
                        }
                    }
                }
                if t.get("probe").is_none() && t.get("register").is_none() {
                    c.err(at, "expect: `at` needs `probe` and/or `register`");
                }
            }
            let k = checks.len();
            for (check, auto) in checks {
                let name = match &given_name {
                    Some(n) if k > 1 => format!("{n}: {auto}"),
                    Some(n) => n.clone(),
                    None => auto,
                };
                expects.push(Expect { name, line, check });
            }
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

fn global_write(name: &str, fields: Vec<(&'static str, u32)>, line: usize) -> Action {
    let reg = regmap::REGISTERS.iter().find(|r| r.name == name && r.chips.contains(Chip::Tmc429)).expect("register in the map");
    let fs = fields.into_iter().map(|(n, v)| (*reg.field(n).expect("field in the map"), v)).collect();
    Action::Write(Write { a7: reg.a7(0), reg, motor: None, data: WriteData::Fields(fs), line })
}

fn ram_writes(words: impl Iterator<Item = (u8, u32)>, half: u8, line: usize) -> Vec<Action> {
    let reg = regmap::REGISTERS.iter().find(|r| r.space == Space::Ram && r.index == half).expect("RAM register");
    words
        .map(|(addr, data)| Action::Write(Write { a7: regmap::ram_a7(addr), reg, motor: None, data: WriteData::Whole(data), line }))
        .collect()
}

/// The writes of a named driver configuration (TMC428 §11.2 Table 11-2 with LSMD = 2; Step/Dir:
/// en_sd, TMC429 §10).
fn driver_setup(chip: Chip, driver: &str, line: usize) -> Vec<Action> {
    match driver {
        "table-11-2" => {
            let cells = &tmc429_model::ram::TABLE_11_2;
            let mut v = ram_writes((0..18u8).map(|a| (a, (cells[2 * a as usize + 1] as u32) << 8 | cells[2 * a as usize] as u32)), 0, line);
            v.push(global_write("global_parameters", vec![("lsmd", 2)], line));
            v
        }
        "step-dir" => {
            let _ = chip;
            vec![global_write("if_configuration", vec![("en_sd", 1)], line)]
        }
        _ => Vec::new(),
    }
}

/// The 32 words of the Table 12-2 sine LUT (TMC428 §12).
fn lut_setup(line: usize) -> Vec<Action> {
    let y = &tmc429_model::ram::SINE_LUT;
    ram_writes((0..32u8).map(|k| (32 + k, (y[2 * k as usize + 1] as u32) << 8 | y[2 * k as usize] as u32)), 1, line)
}
