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
            _ => Err(format!("unknown chip '{s}': expected tmc428, tmc429 or tmc4210")),
        }
    }
}
