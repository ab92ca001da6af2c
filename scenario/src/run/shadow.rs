//! The register values the scenario last wrote, the base of its field writes.

use tmc429_model::regmap::{self, Access, Space};
use tmc429_model::Chip;

use crate::scenario::WriteData;

/// Register values as the scenario last wrote them (power-on values at first): the base of
/// field writes, and the dividers for physical units. The Python package's virtual µC writes
/// fields the same way.
pub struct Shadow {
    words: [u32; 128],
}

impl Shadow {
    pub fn new(chip: Chip) -> Shadow {
        let mut words = [0u32; 128];
        for (a7, w) in words.iter_mut().enumerate() {
            if let Some((r, _)) = regmap::lookup(chip, a7 as u8) {
                if r.space != Space::Ram && r.name != "cover_pos_len" {
                    *w = r.reset & r.writable_mask();
                }
            }
        }
        Shadow { words }
    }
    pub(super) fn clk_config(&self, m: usize) -> (u32, u32, u32) {
        let w = self.words[regmap::motor_a7(m as u8, regmap::idx::CLK_CONFIG) as usize];
        (regmap::f::PULSE_DIV.get(w), regmap::f::RAMP_DIV.get(w), regmap::f::USRS.get(w))
    }
    /// The data word of a write, from the shadow; updates the shadow.
    pub fn resolve(&mut self, w: &crate::scenario::Write) -> u32 {
        let old = self.words[w.a7 as usize];
        // W1C fields write 0 (keep the flag) unless named
        let w1c = w.reg.fields.iter().filter(|f| f.access == Access::W1c).fold(0, |m, f| m | f.mask());
        let data = match &w.data {
            WriteData::Whole(d) => *d,
            WriteData::Fields(fs) => fs.iter().fold(old & !w1c, |d, (f, v)| (d & !f.mask()) | f.put(*v)),
            WriteData::AutoPmul(red) => {
                let m = w.motor.unwrap_or(0);
                let a_max = regmap::f::A_MAX.get(self.words[regmap::motor_a7(m, regmap::idx::A_MAX) as usize]);
                let (pd, rd, _) = self.clk_config(m as usize);
                let r = tmc429_model::pmulpdiv::calc(a_max as i32, rd as i32, pd as i32, *red);
                r.register_value().unwrap_or(old)
            }
        };
        self.words[w.a7 as usize] = data & !w1c & 0xFF_FFFF;
        data & 0xFF_FFFF
    }
}
