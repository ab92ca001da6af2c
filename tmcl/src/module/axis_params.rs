//! Axis parameters: SAP, GAP, STAP, RSAP ([TMCL] §5.7.5–§5.7.8, §6) — the TMCM-3110's here,
//! the TMCM-1311's in `axis1311`. The check (`check`) has already refused unknown numbers,
//! read-only parameters and values out of range.

use super::*;

impl<C: Spi429> Module<C> {
    pub(super) fn sap(&mut self, p: u8, m: usize, v: i32) -> (u8, i32) {
        match self.kind {
            ModuleType::Tmcm3110 => self.sap_3110(p, m, v),
            ModuleType::Tmcm1311 => self.sap_1311(p, m, v),
        }
    }

    pub(super) fn gap(&mut self, p: u8, m: usize) -> (u8, i32) {
        let v = match p {
            0 => self.target_position(m),
            1 => self.actual_position(m),
            2 => self.target_speed(m),
            3 => self.actual_speed(m),
            8 => (self.x_actual_reg(m) == self.x_target_reg(m)) as i32,
            9 => self.home_switch(m) as i32,
            10 => self.right_switch(m) as i32,
            11 => self.left_switch(m) as i32,
            196 => self.st[m].rfs.distance,
            _ => match self.kind {
                ModuleType::Tmcm3110 => self.gap_3110(p, m),
                ModuleType::Tmcm1311 => self.gap_1311(p, m),
            },
        };
        ok(v)
    }

    /// STAP: the value in use goes to the EEPROM.
    pub(super) fn stap(&mut self, p: u8, m: usize) -> (u8, i32) {
        let v = self.ap(m, p);
        if self.eeprom_locked() {
            return err(Status::EepromLocked, 0);
        }
        self.eeprom.axes[m].set_raw(p, v);
        self.save_eeprom();
        ok(v)
    }

    /// RSAP: the stored value is set again (as SAP would).
    pub(super) fn rsap(&mut self, p: u8, m: usize) -> (u8, i32) {
        let v = self.eeprom.axes[m].get(p).unwrap_or(0);
        self.sap(p, m, v)
    }

    /// Switches between velocity mode and the positioning mode MVP uses. Into a positioning
    /// mode the target is the actual position and the configured maximum speed returns, so
    /// no move to an older target starts; into velocity mode the target speed is 0.
    pub(super) fn switch_mode(&mut self, m: usize, velocity: bool) {
        let now_velocity = self.rm(m) == reg::RM_VELOCITY;
        if velocity {
            if !now_velocity {
                self.wr_motor(m, reg::V_TARGET, 0);
                self.st[m].target_speed = 0;
                self.set_rm(m, reg::RM_VELOCITY);
            }
            return;
        }
        if now_velocity {
            let x = self.rd_motor(m, reg::X_ACTUAL);
            self.wr_motor(m, reg::X_TARGET, x);
            if self.kind == ModuleType::Tmcm1311 {
                self.st[m].target = self.position32(m);
            }
            self.restore_v_max(m);
        }
        let rm = self.positioning_rm(m);
        self.set_rm(m, rm);
    }

    fn sap_3110(&mut self, p: u8, m: usize, v: i32) -> (u8, i32) {
        match p {
            0 => return self.set_target_position(m, v),
            1 => return self.set_actual_position(m, v),
            2 => return self.set_speed(m, reg::V_TARGET, v),
            3 => return self.set_speed(m, reg::V_ACTUAL, v),
            _ => {}
        }
        let mut a = self.axes[m];
        a.set_raw(p, v);
        if matches!(p, 5 | 153 | 154)
            && crate::calc::pmul_pdiv(a.get(5).unwrap_or(0), a.get(153).unwrap_or(0), a.get(154).unwrap_or(0)).is_none()
        {
            // pmul/pdiv cannot represent this a_max with these dividers (TMC429 §8.7.1 limits).
            return err(Status::InvalidValue, v);
        }
        self.axes[m] = a;
        match p {
            4 | 5 | 130 | 153 | 154 => self.write_ramp(m),
            12 | 13 | 149 => self.write_ref_conf(m),
            138 => {
                self.switch_mode(m, v == 2);
            }
            141 => self.wr_motor(m, reg::DX_REF_TOLERANCE, v as u32),
            _ => {}
        }
        ok(v)
    }

    fn gap_3110(&mut self, p: u8, m: usize) -> i32 {
        match p {
            135 => sext(self.rd_motor(m, reg::A_ACTUAL), 12),
            138 => self.rm(m) as i32,
            197 => self.st[m].rfs.last_switch_pos,
            _ => self.ap(m, p),
        }
    }
}
