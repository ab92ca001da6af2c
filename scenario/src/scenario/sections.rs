//! The sections of a scenario file: its header (chip, fclk, duration, sck_half, driver, lut),
//! one `[[event]]` and one `[[expect]]` table, and the writes a named driver or LUT stands for.

use toml::de::{DeTable, DeValue};

use tmc429_model::regmap::{self, Space};
use tmc429_model::text::shown;
use tmc429_model::Chip;
use tmc429_testbench::signals::SIGNALS;

use super::{
    describe, field_range, fmt_time, parse_freq, Action, Check, Ctx, EventSpec, Expect, Named, Sp, Trigger, Write, WriteData, DRIVERS,
};

impl Ctx<'_> {
    /// `chip` and `fclk` (the chip's own CLK when not given).
    pub(super) fn chip_and_fclk(&mut self, root: &DeTable) {
        if let Some(v) = root.get("chip") {
            if let Some(s) = self.string(v, "chip") {
                match s.parse::<Chip>() {
                    Ok(ch) => self.chip = ch,
                    Err(e) => self.err(v.span().start, e),
                }
            }
        }
        self.fclk = self.chip.default_fclk();
        if let Some(v) = root.get("fclk") {
            let r = match v.get_ref() {
                DeValue::Integer(_) => self.int(v, "fclk").map(|x| parse_freq(&x.to_string())),
                _ => self.string(v, "fclk").map(parse_freq),
            };
            match r {
                Some(Ok(f)) => self.fclk = f,
                Some(Err(e)) => self.err(v.span().start, format!("fclk: {e}")),
                None => {}
            }
        }
    }

    /// `duration` in CLK cycles (required, more than 0; 0 after an error).
    pub(super) fn duration(&mut self, root: &DeTable) -> u64 {
        match root.get("duration") {
            Some(v) => {
                let d = self.time(v, "duration");
                if d == Some(0) {
                    self.err(v.span().start, "duration: expected more than 0 cycles");
                }
                d.unwrap_or(0)
            }
            None => {
                self.err(0, "missing `duration` (how long to run, e.g. duration = \"50 ms\")");
                0
            }
        }
    }

    /// `sck_half`, the µC's SCK half period in CLK (default 4).
    pub(super) fn sck_half(&mut self, root: &DeTable) -> u32 {
        let Some(v) = root.get("sck_half") else { return 4 };
        match self.int(v, "sck_half") {
            Some(x) if (tmc429_model::host::MIN_SCK_HALF as i64..=1000).contains(&x) => x as u32,
            Some(x) => {
                self.err(v.span().start, format!("sck_half = {x}: expected 3..1000 CLK (TMC428 Table 6-1: at least 3)"));
                4
            }
            None => 4,
        }
    }

    /// `driver`: one of [`DRIVERS`] the chip has ("none" when not given).
    pub(super) fn driver(&mut self, root: &DeTable) -> &'static str {
        let mut driver = "none";
        let Some(v) = root.get("driver") else { return driver };
        let Some(s) = self.string(v, "driver") else { return driver };
        match DRIVERS.iter().find(|d| **d == s) {
            Some(d) => driver = d,
            None => self.err(v.span().start, format!("unknown driver '{}': expected one of {}", shown(s), DRIVERS.join(", "))),
        }
        match (driver, self.chip) {
            ("table-11-2", Chip::Tmc4210) => {
                self.err(v.span().start, "driver 'table-11-2': the TMC4210 has no driver chain (use 'step-dir')")
            }
            ("step-dir", Chip::Tmc428) => self.err(v.span().start, "driver 'step-dir': the TMC428 has no Step/Dir interface"),
            _ => {}
        }
        driver
    }

    /// `lut`: whether the sine table is written ("sine"; "none" or not given: no).
    pub(super) fn lut(&mut self, root: &DeTable) -> bool {
        let Some(v) = root.get("lut") else { return false };
        let Some(s) = self.string(v, "lut") else { return false };
        let lut = match s {
            "sine" => true,
            "none" => false,
            _ => {
                self.err(v.span().start, format!("unknown lut '{}': expected sine or none", shown(s)));
                false
            }
        };
        if lut && self.chip == Chip::Tmc4210 {
            self.err(v.span().start, "lut: the TMC4210 has no microstep table");
            return false;
        }
        lut
    }

    /// One `[[event]]` table at offset `at`: its trigger (`at` a time before the end of the
    /// scenario, or `when` a condition) and its writes and switch changes.
    pub(super) fn event(&mut self, at: usize, t: &DeTable, duration: u64) -> Option<EventSpec> {
        self.check_keys(t, &["at", "when", "write", "switch"], "event");
        let line = self.line(at);
        let trigger = match (t.get("at"), t.get("when")) {
            (Some(a), None) => self.time(a, "at").map(Trigger::Cycle),
            (None, Some(w)) => self.condition(w, "when").map(Trigger::When),
            _ => {
                self.err(at, "event: expected exactly one of `at` (a time) or `when` (a condition)");
                None
            }
        };
        let mut actions = Vec::new();
        if let Some(w) = t.get("write") {
            for (wat, wt) in self.tables(w, "write") {
                actions.extend(self.writes(wt, wat));
            }
        }
        if let Some(st) = t.get("switch").and_then(|s| self.table(s, "switch")) {
            let p = self.switches(st);
            if !p.is_empty() {
                actions.push(Action::Pins(p));
            }
        }
        if t.get("write").is_none() && t.get("switch").is_none() {
            self.err(at, "event: expected `write` and/or `switch`");
        }
        if let (Some(Trigger::Cycle(x)), true) = (&trigger, duration > 0) {
            if *x >= duration {
                let msg = format!(
                    "event at {} is not before the end of the scenario (duration {})",
                    self.time_text(*x),
                    self.time_text(duration)
                );
                self.err(at, msg);
            }
        }
        Some(EventSpec { line, trigger: trigger?, actions })
    }

    /// One `[[expect]]` table at offset `at`: its checks, each named by the table's `name` or
    /// by what it checks.
    pub(super) fn expect(&mut self, at: usize, t: &DeTable, duration: u64, sck_half: u32) -> Vec<Expect> {
        self.check_keys(t, &["name", "at", "probe", "register", "reached", "within", "after"], "expect");
        let line = self.line(at);
        let given_name = t.get("name").and_then(|n| self.string(n, "name").map(str::to_string));
        let checks = match t.get("reached") {
            Some(r) => self.reached(at, t, r).into_iter().collect(),
            None => self.at_checks(at, t, duration, sck_half),
        };
        let k = checks.len();
        checks
            .into_iter()
            .map(|(check, auto)| {
                let name = match &given_name {
                    Some(n) if k > 1 => format!("{n}: {auto}"),
                    Some(n) => n.clone(),
                    None => auto,
                };
                Expect { name, line, check }
            })
            .collect()
    }

    /// A time in CLK cycles as the messages show it.
    fn time_text(&self, x: u64) -> String {
        fmt_time(x as f64 / self.fclk as f64)
    }

    /// `reached = { condition }` with `within` (and `after`).
    fn reached(&mut self, at: usize, t: &DeTable, r: &Sp) -> Option<(Check, String)> {
        if t.get("at").is_some() || t.get("probe").is_some() || t.get("register").is_some() {
            self.err(at, "expect: `reached` goes with `within` (and `after`), not with `at`, `probe` or `register`");
        }
        let cond = self.condition(r, "reached");
        let within = match t.get("within") {
            Some(w) => self.time(w, "within"),
            None => {
                self.err(at, "expect: `reached` needs `within` (a time)");
                None
            }
        };
        let after = match t.get("after") {
            Some(a) => self.time(a, "after"),
            None => Some(0),
        };
        let (cond, within, after) = (cond?, within?, after?);
        let n = format!("{} within {} after {}", describe(&cond), self.time_text(within), self.time_text(after));
        Some((Check::Reached { cond, after, within }, n))
    }

    /// `at` with `probe` and/or `register`: the probe values and register reads at that time.
    fn at_checks(&mut self, at: usize, t: &DeTable, duration: u64, sck_half: u32) -> Vec<(Check, String)> {
        let Some(atv) = t.get("at") else {
            self.err(at, "expect: expected `at` with `probe` and/or `register`, or `reached` with `within`");
            return Vec::new();
        };
        let Some(when) = self.time(atv, "at") else { return Vec::new() };
        if duration > 0 && when > duration {
            let msg = format!("at {} is after the end of the scenario (duration {})", self.time_text(when), self.time_text(duration));
            self.err(atv.span().start, msg);
        }
        let mut checks = Vec::new();
        if let Some(p) = t.get("probe") {
            let values = self.probe_values(p);
            let n = values.iter().map(|(i, x)| format!("{}.{} = {x}", SIGNALS[*i].scope, SIGNALS[*i].name)).collect::<Vec<_>>().join(", ");
            if !values.is_empty() {
                checks.push((Check::Probes { at: when, values }, format!("{n} at {}", self.time_text(when))));
            }
        }
        if let Some(rt) = t.get("register").and_then(|r| self.table(r, "register")) {
            // the read frame must end before the scenario does
            let frame = 64 * sck_half as u64 + 16;
            let late = (duration > 0 && when + frame > duration).then(|| {
                let msg = format!(
                    "register read at {} ends after the scenario (duration {}): a read takes {frame} CLK",
                    self.time_text(when),
                    self.time_text(duration)
                );
                (atv.span().start, msg)
            });
            checks.extend(self.register_checks(rt, when, late));
        }
        if t.get("probe").is_none() && t.get("register").is_none() {
            self.err(at, "expect: `at` needs `probe` and/or `register`");
        }
        checks
    }

    /// `register = { motor = m, name = value, ... }`: one read check per register or field.
    /// `late`: the read would end after the scenario, the error each valid entry reports.
    fn register_checks(&mut self, rt: &DeTable, when: u64, late: Option<(usize, String)>) -> Vec<(Check, String)> {
        let mut checks = Vec::new();
        let Ok(motor) = self.motor_key(rt) else { return checks };
        for (k, val) in rt.iter() {
            if k.get_ref() == "motor" {
                continue;
            }
            let Some(named) = self.name(k, motor) else { continue };
            let Some(x) = self.int(val, k.get_ref()) else { continue };
            let (reg, field) = match named {
                Named::Reg(r) if r.fields.len() == 1 => (r, Some(r.fields[0])),
                Named::Reg(r) => (r, None),
                Named::Field(r, f) => (r, Some(*f)),
            };
            let (name, (lo, hi)) = match field {
                Some(f) => (f.name, field_range(&f)),
                None => (reg.name, (0, 0xFF_FFFF)),
            };
            if !(lo..=hi).contains(&x) {
                self.err(val.span().start, format!("{name} = {x} out of range: expected {lo}..{hi}"));
                continue;
            }
            if let Some((at, msg)) = &late {
                self.err(*at, msg.clone());
                continue;
            }
            let who = match motor {
                Some(m) => format!("motor {m} {name} = {x}"),
                None => format!("{name} = {x}"),
            };
            let a7 = reg.a7(motor.unwrap_or(0));
            checks.push((Check::Register { at: when, a7, reg, field, expected: x }, format!("{who} (read) at {}", self.time_text(when))));
        }
        checks
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
pub(super) fn driver_setup(driver: &str, line: usize) -> Vec<Action> {
    match driver {
        "table-11-2" => {
            let cells = &tmc429_model::ram::TABLE_11_2;
            let mut v = ram_writes((0..18u8).map(|a| (a, (cells[2 * a as usize + 1] as u32) << 8 | cells[2 * a as usize] as u32)), 0, line);
            v.push(global_write("global_parameters", vec![("lsmd", 2)], line));
            v
        }
        "step-dir" => vec![global_write("if_configuration", vec![("en_sd", 1)], line)],
        _ => Vec::new(),
    }
}

/// The 32 words of the Table 12-2 sine LUT (TMC428 §12).
pub(super) fn lut_setup(line: usize) -> Vec<Action> {
    let y = &tmc429_model::ram::SINE_LUT;
    ram_writes((0..32u8).map(|k| (32 + k, (y[2 * k as usize + 1] as u32) << 8 | y[2 * k as usize] as u32)), 1, line)
}
