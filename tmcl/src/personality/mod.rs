//! The module types the firmware can be (its personality): the TMCM-3110 (three axes, the
//! TMC429's own units) and the TMCM-1311 of the TMCL firmware manual (one axis, pps, pps²,
//! 32-bit positions). Each has its axis- and global-parameter table: number, name, access,
//! range, factory default and how it differs from the manual ([TMCL] §6, §10). The firmware
//! takes ranges and defaults from these tables, the seed-coverage table of docs/tmcl.md is
//! made from them (`crate::seed`).

pub mod tmcm1311;
pub mod tmcm3110;

/// A module type.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ModuleType {
    Tmcm3110,
    Tmcm1311,
}

/// Access letters of the manual's parameter tables ([TMCL] §6, §10.1): R read, W write, E
/// restored from and storable in the EEPROM.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Access {
    R,
    W,
    RW,
    RWE,
}

impl Access {
    pub fn letters(self) -> &'static str {
        match self {
            Access::R => "R",
            Access::W => "W",
            Access::RW => "RW",
            Access::RWE => "RWE",
        }
    }
    pub fn writable(self) -> bool {
        self != Access::R
    }
    pub fn readable(self) -> bool {
        self != Access::W
    }
}

/// One parameter of a module.
#[derive(Clone, Copy, Debug)]
pub struct Param {
    pub no: u8,
    pub name: &'static str,
    pub access: Access,
    /// The value lives in the chip or in firmware state (positions, speeds, flags); otherwise
    /// the firmware keeps it as a setting (`config::AxisConfig`, `config::GlobalConfig`).
    pub live: bool,
    /// Range a write accepts (the manual's, where it has one).
    pub min: i64,
    pub max: i64,
    /// Factory default of a setting.
    pub default: i32,
    /// How this module differs from the manual; `None`: as the manual.
    pub note: Option<&'static str>,
}

/// A live parameter (its value lives in the chip or the firmware's state).
pub const fn live(no: u8, name: &'static str, access: Access, min: i64, max: i64, note: Option<&'static str>) -> Param {
    Param { no, name, access, live: true, min, max, default: 0, note }
}

/// A setting the firmware keeps (RAM, or RAM and EEPROM for access E).
pub const fn setting(no: u8, name: &'static str, access: Access, min: i64, max: i64, default: i32, note: Option<&'static str>) -> Param {
    Param { no, name, access, live: false, min, max, default, note }
}

/// The note of a setting that is stored and read back but has no effect.
pub const KEPT_DRIVER: Option<&str> = Some("kept, no effect: no driver stage is modelled");

pub const I32: (i64, i64) = (i32::MIN as i64, i32::MAX as i64);

impl ModuleType {
    pub const ALL: [ModuleType; 2] = [ModuleType::Tmcm3110, ModuleType::Tmcm1311];

    /// From the command-line name (`tmcm-3110`, `tmcm-1311`; case and the `tmcm-` prefix optional).
    pub fn parse(s: &str) -> Option<ModuleType> {
        let t = s.trim().to_ascii_lowercase();
        let t = t.strip_prefix("tmcm-").or_else(|| t.strip_prefix("tmcm")).unwrap_or(&t);
        match t {
            "3110" => Some(ModuleType::Tmcm3110),
            "1311" => Some(ModuleType::Tmcm1311),
            _ => None,
        }
    }
    /// The command-line name.
    pub fn cli_name(self) -> &'static str {
        match self {
            ModuleType::Tmcm3110 => "tmcm-3110",
            ModuleType::Tmcm1311 => "tmcm-1311",
        }
    }
    pub fn name(self) -> &'static str {
        match self {
            ModuleType::Tmcm3110 => "TMCM-3110",
            ModuleType::Tmcm1311 => "TMCM-1311",
        }
    }
    /// Module number of the version reply (command 136, [TMCL] §5.7.39).
    pub fn number(self) -> u16 {
        match self {
            ModuleType::Tmcm3110 => 3110,
            ModuleType::Tmcm1311 => 1311,
        }
    }
    /// The byte that marks an EEPROM image of this module type.
    pub fn code(self) -> u8 {
        match self {
            ModuleType::Tmcm3110 => 0,
            ModuleType::Tmcm1311 => 1,
        }
    }
    pub fn from_code(c: u8) -> Option<ModuleType> {
        ModuleType::ALL.into_iter().find(|k| k.code() == c)
    }
    /// Number of axes (motor numbers 0 .. axes−1).
    pub fn axes(self) -> usize {
        match self {
            ModuleType::Tmcm3110 => 3,
            ModuleType::Tmcm1311 => 1,
        }
    }
    pub fn axis_params(self) -> &'static [Param] {
        match self {
            ModuleType::Tmcm3110 => tmcm3110::AXIS,
            ModuleType::Tmcm1311 => tmcm1311::AXIS,
        }
    }
    /// Bank 0 ([TMCL] §10.1).
    pub fn global_params(self) -> &'static [Param] {
        match self {
            ModuleType::Tmcm3110 => tmcm3110::GLOBAL,
            ModuleType::Tmcm1311 => tmcm1311::GLOBAL,
        }
    }
    pub fn axis_param(self, no: u8) -> Option<&'static Param> {
        self.axis_params().iter().find(|p| p.no == no)
    }
    pub fn global_param(self, no: u8) -> Option<&'static Param> {
        self.global_params().iter().find(|p| p.no == no)
    }
    /// Why a parameter number of the manual's axis-parameter table is not available here.
    pub fn axis_absent(self, no: u8) -> &'static str {
        match self {
            ModuleType::Tmcm3110 => tmcm3110::axis_absent(no),
            ModuleType::Tmcm1311 => tmcm1311::axis_absent(no),
        }
    }
    /// Why a bank-0 parameter number of the manual is not available here.
    pub fn global_absent(self, no: u8) -> &'static str {
        match self {
            ModuleType::Tmcm3110 => tmcm3110::global_absent(no),
            ModuleType::Tmcm1311 => tmcm1311::global_absent(no),
        }
    }
    /// Interrupt numbers ([TMCL] §5.6.3; three axes: target reached 3..5, stop switches 27..32).
    pub fn interrupts(self) -> &'static [u8] {
        match self {
            ModuleType::Tmcm3110 => tmcm3110::INTERRUPTS,
            ModuleType::Tmcm1311 => tmcm1311::INTERRUPTS,
        }
    }
    pub fn interrupt_exists(self, n: u8) -> bool {
        self.interrupts().contains(&n)
    }
    /// Interrupt number of "target reached" and of the left stop switch of axis `m`.
    pub fn target_irq(self, m: usize) -> u8 {
        3 + m as u8
    }
    pub fn stop_left_irq(self, m: usize) -> u8 {
        27 + 2 * m as u8
    }
}
