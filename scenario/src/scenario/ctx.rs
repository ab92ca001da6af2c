//! The parser's context: the file's text and errors, the chip and its CLK, and the readers of
//! TOML values a scenario is made of (integers, times, strings, tables, register and field
//! names, writes, conditions, probe values), each reporting what it expected where.

use toml::de::{DeTable, DeValue};
use toml::Spanned;

use tmc429_model::regmap::{self, Access, Field, Register, Space};
use tmc429_model::text::shown;
use tmc429_model::Chip;
use tmc429_testbench::signals::{self, SIGNALS};

use super::{field_range, parse_time, registers_of, writable, Action, Condition, ParseError, Write, WriteData, PINS};

pub(super) struct Ctx<'a> {
    pub(super) file: &'a str,
    pub(super) text: &'a str,
    pub(super) errors: Vec<ParseError>,
    pub(super) chip: Chip,
    pub(super) fclk: u64,
}

pub(super) type Sp<'i> = Spanned<DeValue<'i>>;

impl Ctx<'_> {
    pub(super) fn line(&self, offset: usize) -> usize {
        self.text[..offset.min(self.text.len())].bytes().filter(|&b| b == b'\n').count() + 1
    }
    pub(super) fn err(&mut self, offset: usize, msg: impl Into<String>) {
        let line = self.line(offset);
        self.errors.push(ParseError { file: self.file.to_string(), line, msg: msg.into() });
    }

    pub(super) fn int(&mut self, v: &Sp, what: &str) -> Option<i64> {
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

    pub(super) fn string<'v>(&mut self, v: &'v Sp, what: &str) -> Option<&'v str> {
        match v.get_ref() {
            DeValue::String(s) => Some(s.as_ref()),
            other => {
                self.err(v.span().start, format!("{what}: expected a string, found {}", other.type_str()));
                None
            }
        }
    }

    pub(super) fn boolean(&mut self, v: &Sp, what: &str) -> Option<bool> {
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
    pub(super) fn time(&mut self, v: &Sp, what: &str) -> Option<u64> {
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

    pub(super) fn table<'v, 'i>(&mut self, v: &'v Sp<'i>, what: &str) -> Option<&'v DeTable<'i>> {
        match v.get_ref() {
            DeValue::Table(t) => Some(t),
            other => {
                self.err(v.span().start, format!("{what}: expected a table, found {}", other.type_str()));
                None
            }
        }
    }

    /// A table or an array of tables.
    pub(super) fn tables<'v, 'i>(&mut self, v: &'v Sp<'i>, what: &str) -> Vec<(usize, &'v DeTable<'i>)> {
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

    pub(super) fn motor(&mut self, v: &Sp) -> Option<u8> {
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
    pub(super) fn motor_key(&mut self, t: &DeTable) -> Result<Option<u8>, ()> {
        match t.get("motor") {
            Some(v) => self.motor(v).map(Some).ok_or(()),
            None => Ok(None),
        }
    }
}

/// What a key of a write or register table names.
pub(super) enum Named {
    Reg(&'static Register),
    Field(&'static Register, &'static Field),
}

impl Ctx<'_> {
    /// Resolves a register or field name for a motor (`motor` given) or a global register.
    pub(super) fn name(&mut self, key: &Spanned<std::borrow::Cow<str>>, motor: Option<u8>) -> Option<Named> {
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

    pub(super) fn field_value(&mut self, v: &Sp, reg: &Register, f: &Field) -> Option<u32> {
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
    pub(super) fn writes(&mut self, t: &DeTable, at: usize) -> Vec<Action> {
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
                    let Some(data) = self.register_data(reg, v) else { continue };
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

    /// The data of a whole-register write `reg = v`: a table of its fields, "auto" for
    /// pmul_pdiv, or an integer in the register's range (`None` after an error).
    pub(super) fn register_data(&mut self, reg: &'static Register, v: &Sp) -> Option<WriteData> {
        match v.get_ref() {
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
                                format!("{} has no field '{}': expected one of {}", reg.name, shown(fk.get_ref()), names.join(", ")),
                            );
                        }
                    }
                }
                Some(WriteData::Fields(fields))
            }
            DeValue::String(s) if reg.name == "pmul_pdiv" && s.as_ref() == "auto" => Some(WriteData::AutoPmul(0.01)),
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
                None
            }
            _ => {
                let x = self.int(v, reg.name)?;
                let (lo, hi) = if reg.fields.len() == 1 { field_range(&reg.fields[0]) } else { (0, 0xFF_FFFF) };
                // a single-field register takes the field's range; x_latched and
                // friends take any 24-bit word
                let (lo, hi) = if reg.fields.len() == 1 && reg.fields[0].access == Access::R { (-(1 << 23), 0xFF_FFFF) } else { (lo, hi) };
                if !(lo..=hi).contains(&x) {
                    self.err(v.span().start, format!("{} = {x} out of range: expected {lo}..{hi}", reg.name));
                    return None;
                }
                let word = if reg.fields.len() == 1 { (x as u32) << reg.fields[0].lsb } else { x as u32 };
                Some(WriteData::Whole(word & 0xFF_FFFF))
            }
        }
    }

    pub(super) fn switches(&mut self, t: &DeTable) -> Vec<(usize, bool)> {
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

    pub(super) fn condition(&mut self, v: &Sp, what: &str) -> Option<Condition> {
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

    pub(super) fn check_keys(&mut self, t: &DeTable, allowed: &[&str], what: &str) {
        for (k, _) in t.iter() {
            if !allowed.contains(&k.get_ref().as_ref()) {
                self.err(k.span().start, format!("{what}: unknown key '{}': expected {}", shown(k.get_ref()), allowed.join(", ")));
            }
        }
    }

    pub(super) fn probe_values(&mut self, v: &Sp) -> Vec<(usize, i64)> {
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
