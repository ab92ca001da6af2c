//! Chip variants of the family.

use std::fmt;
use std::str::FromStr;

/// The three members of the family. They share one pin list; what a variant lacks is
/// tied off (see docs/model-contract.md, "Variants").
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Chip {
    /// TMC428: SPI driver chain only, fCLK ≤ 16 MHz, RAM not initialised at power-on.
    Tmc428,
    /// TMC429: SPI driver chain or Step/Dir, position compare, fCLK ≤ 32 MHz.
    Tmc429,
    /// TMC4210: one axis, Step/Dir only, no driver chain registers.
    Tmc4210,
}

impl Chip {
    pub const ALL: [Chip; 3] = [Chip::Tmc428, Chip::Tmc429, Chip::Tmc4210];

    /// The `CHIP` parameter value of the RTL (0, 1, 2).
    pub fn rtl_param(self) -> u32 {
        match self {
            Chip::Tmc428 => 0,
            Chip::Tmc429 => 1,
            Chip::Tmc4210 => 2,
        }
    }

    pub fn from_rtl_param(p: u32) -> Option<Chip> {
        match p {
            0 => Some(Chip::Tmc428),
            1 => Some(Chip::Tmc429),
            2 => Some(Chip::Tmc4210),
            _ => None,
        }
    }

    /// Default clock of the variant: its maximum (TMC428 §6: 16 MHz; TMC429 §1.4: 32 MHz).
    pub fn default_fclk(self) -> u64 {
        match self {
            Chip::Tmc428 => 16_000_000,
            _ => 32_000_000,
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            Chip::Tmc428 => "tmc428",
            Chip::Tmc429 => "tmc429",
            Chip::Tmc4210 => "tmc4210",
        }
    }

    /// Bit of this variant in a [`crate::regmap::ChipSet`].
    pub(crate) fn bit(self) -> u8 {
        1 << self.rtl_param()
    }
}

impl fmt::Display for Chip {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Chip {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        match s.to_ascii_lowercase().as_str() {
            "tmc428" | "428" => Ok(Chip::Tmc428),
            "tmc429" | "429" => Ok(Chip::Tmc429),
            "tmc4210" | "4210" => Ok(Chip::Tmc4210),
            _ => Err(format!("unknown chip '{}': expected tmc428, tmc429 or tmc4210", crate::text::shown(s))),
        }
    }
}

/// Packages of the family ([428] §3, §4; [429] §3, §4.2; [4210] §3): which pins are bonded out.
/// A package lacks pins of its variant; the die behind them is the variant's (C90).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Package {
    /// TMC429-LI: every TMC429 pin.
    Qfn32,
    /// TMC428-PI24 (every TMC428 pin), TMC429-PI24 (no REFR3).
    Sop24,
    /// TMC428-DI20: every TMC428 pin.
    Dil20,
    /// TMC428-I (no nSCS2, nSCS3), TMC429-I (no nSCS2, nSCS3, SDOZ_C, POSCMP, REFR1..3),
    /// TMC4210-I (its only package).
    Ssop16,
}

impl Package {
    /// The packages of a variant; the first has every pin of the variant and is the default.
    pub fn of(chip: Chip) -> &'static [Package] {
        match chip {
            Chip::Tmc428 => &[Package::Sop24, Package::Dil20, Package::Ssop16],
            Chip::Tmc429 => &[Package::Qfn32, Package::Sop24, Package::Ssop16],
            Chip::Tmc4210 => &[Package::Ssop16],
        }
    }

    /// The package with every pin of the variant.
    pub fn full(chip: Chip) -> Package {
        Package::of(chip)[0]
    }

    pub fn name(self) -> &'static str {
        match self {
            Package::Qfn32 => "qfn32",
            Package::Sop24 => "sop24",
            Package::Dil20 => "dil20",
            Package::Ssop16 => "ssop16",
        }
    }

    /// Number of pins (the RTL's `PINS` parameter of `tmc429_chip`).
    pub fn pins(self) -> u32 {
        match self {
            Package::Qfn32 => 32,
            Package::Sop24 => 24,
            Package::Dil20 => 20,
            Package::Ssop16 => 16,
        }
    }

    /// `self` checked against the variant: an error names the packages it has.
    pub fn check(self, chip: Chip) -> Result<Package, String> {
        let of = Package::of(chip);
        if of.contains(&self) {
            return Ok(self);
        }
        let names: Vec<&str> = of.iter().map(|p| p.name()).collect();
        Err(format!("{chip} has no {self} package: expected {}", names.join(" or ")))
    }
}

impl fmt::Display for Package {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Package {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        match s.to_ascii_lowercase().as_str() {
            "qfn32" => Ok(Package::Qfn32),
            "sop24" => Ok(Package::Sop24),
            "dil20" => Ok(Package::Dil20),
            "ssop16" => Ok(Package::Ssop16),
            _ => Err(format!("unknown package '{s}': expected qfn32, sop24, dil20 or ssop16")),
        }
    }
}
