//! Global parameters: SGP, GGP, STGP, RSGP ([TMCL] §5.7.9–§5.7.12, §10): bank 0 (module
//! settings, stored by SGP itself, §10.1), bank 2 (user variables, 0..55 storable, §10.3),
//! bank 3 (interrupt settings, §10.4). The check (`check`) has already refused unknown
//! numbers, read-only parameters and values out of range.

use super::*;

impl<C: Spi429> Module<C> {
    pub(super) fn sgp(&mut self, p: u8, bank: u8, v: i32) -> (u8, i32) {
        match bank {
            0 => self.sgp_bank0(p, v),
            2 => {
                self.user_vars[p as usize] = v;
                ok(v)
            }
            _ => {
                self.irq_cfg[p as usize] = v;
                if p <= 2 {
                    self.vm.timer_next[p as usize] = self.now_ms() + v as u64;
                }
                ok(v)
            }
        }
    }

    fn sgp_bank0(&mut self, p: u8, v: i32) -> (u8, i32) {
        match p {
            73 => {
                // Write 1234 to lock, 4321 to unlock; reads 1 or 0.
                let l = (v == 1234) as i32;
                self.global.set_raw(73, l);
                self.eeprom.global.set_raw(73, l);
                self.save_eeprom();
            }
            132 => self.tick_offset = (self.now_ms() as u32).wrapping_sub(v as u32),
            _ if self.eeprom_locked() => return err(Status::EepromLocked, v),
            _ => {
                let old = self.gp(p);
                self.global.set_raw(p, v);
                self.eeprom.global.set_raw(p, v);
                if p == 79 {
                    let ifc = self.if_configuration();
                    self.wr(reg::IF_CONFIGURATION, ifc);
                }
                if p == 81 && old & 1 != 0 && v & 1 == 0 {
                    // Switching the protection against disassembling off erases the program.
                    self.program = vec![Instruction::default(); PROGRAM_SIZE];
                    self.prog_len = 0;
                    self.reset_vm();
                }
                self.save_eeprom();
            }
        }
        ok(v)
    }

    pub(super) fn ggp(&mut self, p: u8, bank: u8) -> (u8, i32) {
        let v = match (bank, p) {
            (0, 128) => self.vm.state as i32,
            (0, 129) => self.download.is_some() as i32,
            (0, 130) => self.vm.pc as i32,
            (0, 132) => (self.now_ms() as u32).wrapping_sub(self.tick_offset) as i32,
            (0, 133) => {
                // xorshift64*
                self.rng ^= self.rng >> 12;
                self.rng ^= self.rng << 25;
                self.rng ^= self.rng >> 27;
                ((self.rng.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 33) & 0x7fff_ffff) as i32
            }
            (0, _) => self.gp(p),
            (2, _) => self.user_vars[p as usize],
            _ => self.irq_cfg[p as usize],
        };
        ok(v)
    }

    /// STGP: bank-0 settings are in the EEPROM already (SGP stores them); user variables
    /// 0..55 go there now.
    pub(super) fn stgp(&mut self, p: u8, bank: u8) -> (u8, i32) {
        if self.eeprom_locked() && !(bank == 0 && p == 73) {
            return err(Status::EepromLocked, 0);
        }
        if bank == 0 {
            return ok(self.gp(p));
        }
        let v = self.user_vars[p as usize];
        self.eeprom.user_vars[p as usize] = v;
        self.save_eeprom();
        ok(v)
    }

    /// RSGP: the stored value back into RAM.
    pub(super) fn rsgp(&mut self, p: u8, bank: u8) -> (u8, i32) {
        let v = if bank == 0 {
            let v = self.eeprom.global.get(p).unwrap_or(0);
            self.global.set_raw(p, v);
            v
        } else {
            let v = self.eeprom.user_vars[p as usize];
            self.user_vars[p as usize] = v;
            v
        };
        ok(v)
    }
}
