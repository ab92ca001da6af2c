//! The settings the module keeps per axis and globally, with factory defaults and ranges from
//! the module type's parameter tables (`crate::personality`).

use crate::personality::{ModuleType, Param};

/// Axes the TMC429 has; a module type uses the first [`ModuleType::axes`] of them.
pub const AXES: usize = 3;
/// Coordinates per axis: 0 (RAM only) and 1..20 ([TMCL] §5.7.24).
pub const COORDS: usize = 21;
/// User variables kept in EEPROM (bank 2, 0..55; [TMCL] §10.3).
pub const STORED_USER_VARS: usize = 56;
/// Program memory size in instructions ([TMCL] §4).
pub const PROGRAM_SIZE: usize = 2048;
/// The value of global parameter 64 that marks a valid EEPROM ([TMCL] §10.1).
pub const EEPROM_MAGIC: i32 = 0xE4;
/// Settings a parameter table may hold at most.
const MAX_SETTINGS: usize = 96;

/// The settings of one parameter table (the entries that are not live), indexed in table order.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Settings {
    kind: ModuleType,
    global: bool,
    vals: [i32; MAX_SETTINGS],
}

/// Per-axis settings (axis-parameter table).
pub type AxisConfig = Settings;
/// Bank-0 settings (global-parameter table).
pub type GlobalConfig = Settings;

impl Settings {
    /// Factory defaults of the axis settings of a module type.
    pub fn axis(kind: ModuleType) -> Settings {
        Settings::factory(kind, false)
    }
    /// Factory defaults of the bank-0 settings of a module type.
    pub fn global(kind: ModuleType) -> Settings {
        Settings::factory(kind, true)
    }
    fn factory(kind: ModuleType, global: bool) -> Settings {
        let mut s = Settings { kind, global, vals: [0; MAX_SETTINGS] };
        for (i, p) in s.settings().enumerate() {
            s.vals[i] = p.default;
        }
        s
    }
    pub fn kind(&self) -> ModuleType {
        self.kind
    }
    fn table(&self) -> &'static [Param] {
        if self.global {
            self.kind.global_params()
        } else {
            self.kind.axis_params()
        }
    }
    fn settings(&self) -> impl Iterator<Item = &'static Param> {
        let t = self.table();
        t.iter().filter(|p| !p.live)
    }
    fn index(&self, p: u8) -> Option<usize> {
        self.settings().position(|q| q.no == p)
    }
    /// The value of setting `p` (`None`: not a setting of this table).
    pub fn get(&self, p: u8) -> Option<i32> {
        self.index(p).map(|i| self.vals[i])
    }
    /// Sets a setting without checks; false if `p` is not a setting of this table.
    pub fn set_raw(&mut self, p: u8, v: i32) -> bool {
        match self.index(p) {
            Some(i) => {
                self.vals[i] = v;
                true
            }
            None => false,
        }
    }
    /// Whether `v` is a valid value of setting `p`.
    pub fn valid_value(&self, p: u8, v: i32) -> bool {
        self.settings().find(|q| q.no == p).is_some_and(|q| valid(q, v))
    }
    /// The settings the EEPROM holds (access E), in table order.
    pub fn stored_params(&self) -> impl Iterator<Item = u8> {
        let t = self.table();
        t.iter().filter(|p| !p.live && p.access == crate::personality::Access::RWE).map(|p| p.no)
    }
    /// Every stored setting within its range.
    pub fn validate(&self) -> Result<(), String> {
        let what = if self.global { "global" } else { "axis" };
        for p in self.stored_params() {
            let v = self.get(p).unwrap_or(0);
            if !self.valid_value(p, v) {
                return Err(format!("{what} parameter {p} = {v} is out of range for the {}", self.kind.name()));
            }
        }
        Ok(())
    }
}

/// A value within the parameter's range and, for the parameters with a rule of their own,
/// that rule (the numbers are unique across the axis and bank-0 tables): 193 mode 1..8 (+128, [TMCL] §9), 67 bits 0, 4, 5 without 4 and 5 together
/// ([TMCL] §4.4.4), 201 bits 2..4 ([TMCL] §6).
pub fn valid(p: &Param, v: i32) -> bool {
    if (v as i64) < p.min || (v as i64) > p.max {
        return false;
    }
    match p.no {
        193 => matches!(v & 0x7f, 1..=8) && v & !0xff == 0,
        67 => v & !0x31 == 0 && v & 0x30 != 0x30,
        201 => v & !0x1c == 0,
        _ => true,
    }
}
