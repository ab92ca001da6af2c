//! Functional coverage of the co-simulation: named bins, counted while the regression runs
//! (docs/cosim.md lists them).

use std::collections::BTreeMap;
use std::fmt::Write as _;

use tmc429_model::regmap::{self, Addr};
use tmc429_model::{Chip, Outputs, Probes};

use crate::stimulus::{PinLevels, Profile};

mod bins;
mod drivers;
mod frame;
mod motion;

pub use bins::{motion_bins, CHAIN_BINS, MODE_NAMES};

/// Interrupt flag names, bit 0 first ([428] Table 8-7).
pub const FLAG_NAMES: [&str; 8] =
    ["POS_END", "REF_WRONG", "REF_MISS", "STOP", "STOP_LEFT_LOW", "STOP_RIGHT_LOW", "STOP_LEFT_HIGH", "STOP_RIGHT_HIGH"];

/// Name of a register address for reports: `x_target[1]` (motor 1..3 as in the datasheet),
/// `ram_microstep_table[word 40]`, `unused $37`.
pub fn reg_name(chip: Chip, a7: u8) -> String {
    let a7 = a7 & 0x7F;
    match regmap::lookup(chip, a7) {
        Some((r, Some(m))) => format!("{}[{}]", r.name, m + 1),
        Some((r, None)) => match Addr::from_a7(a7) {
            Addr::Ram(a) => format!("{}[word {}]", r.name, a),
            _ => r.name.to_string(),
        },
        None => format!("unused ${a7:02X}"),
    }
}

/// Counted bins; only registered bins count.
#[derive(Clone, Debug, Default)]
pub struct Coverage {
    bins: BTreeMap<String, u64>,
    last_flags: [u8; 3],
    last_cover_pos: u8,
    last_power_down: bool,
    last_poscmp: Option<bool>,
    last_pins: Option<PinLevels>,
    last_chain_state: u8,
    last_mux: u8,
    /// The datagram under way carries the cover datagram.
    cover_seen: bool,
    /// Motion-profile observations of the previous cycle (see [`Coverage::model`]).
    motion: Option<MotionSeen>,
}

/// What [`Coverage::model`] remembers from the previous cycle.
#[derive(Clone, Copy, Debug, Default)]
struct MotionSeen {
    rm: [u8; 3],
    x_target: [u32; 3],
    /// V ≠ 0 seen since the last stop in RAMP or SOFT mode.
    moved: [bool; 3],
    stop: [bool; 3],
    lp: [bool; 3],
    chain_state: u8,
    mux: u8,
    sd_dir: [bool; 3],
    cupd: [u16; 3],
}

impl Coverage {
    /// The bins of this blocks for a chip under a stimulus profile.
    pub fn new(chip: Chip, profile: Profile) -> Coverage {
        let motion = matches!(profile, Profile::Motion | Profile::MotionCore);
        Coverage {
            bins: bins::bin_names(chip, profile).into_iter().map(|n| (n, 0)).collect(),
            last_power_down: false,
            motion: motion.then(MotionSeen::default),
            ..Coverage::default()
        }
    }

    #[inline]
    pub fn hit(&mut self, bin: &str) {
        if let Some(c) = self.bins.get_mut(bin) {
            *c += 1;
        }
    }

    pub fn bins(&self) -> &BTreeMap<String, u64> {
        &self.bins
    }

    /// Bins never hit.
    pub fn missed(&self) -> Vec<&str> {
        self.bins.iter().filter(|(_, c)| **c == 0).map(|(n, _)| n.as_str()).collect()
    }

    /// Called every cycle with the model's state after the tick.
    #[inline]
    pub fn cycle(&mut self, o: &Outputs, p: &Probes) {
        let pd = p.power_down != 0;
        if pd != self.last_power_down {
            self.hit(if pd { "power down" } else { "wake-up by nSCS_C" });
            self.last_power_down = pd;
        }
        if self.last_poscmp != Some(o.poscmp) {
            if let Some(prev) = self.last_poscmp {
                self.hit(if prev { "POSCMP pin falls" } else { "POSCMP pin rises" });
            }
            self.last_poscmp = Some(o.poscmp);
        }
    }

    /// A pin-change transaction.
    pub fn pins(&mut self, l: &PinLevels) {
        if let Some(p) = self.last_pins {
            if p.ref_ != l.ref_ {
                self.hit("REF pin change");
            }
            if p.refr != l.refr {
                self.hit("REFR pin change");
            }
            if p.sdi_s != l.sdi_s {
                self.hit("SDI_S pin change");
            }
        }
        self.last_pins = Some(*l);
    }

    /// Starting pin levels (the driver's idle levels).
    pub fn set_initial_pins(&mut self, l: PinLevels) {
        self.last_pins = Some(l);
    }

    /// The coverage table: every bin with its count, then the bins never hit.
    pub fn table(&self) -> String {
        let mut s = String::new();
        let width = self.bins.keys().map(|k| k.len()).max().unwrap_or(0);
        let _ = writeln!(s, "coverage: {} bins, {} hit", self.bins.len(), self.bins.len() - self.missed().len());
        for (n, c) in &self.bins {
            let _ = writeln!(s, "  {n:<width$}  {c}");
        }
        let missed = self.missed();
        if missed.is_empty() {
            let _ = writeln!(s, "bins never hit: none");
        } else {
            let _ = writeln!(s, "bins never hit ({}):", missed.len());
            for n in missed {
                let _ = writeln!(s, "  {n}");
            }
        }
        s
    }
}
