//! The TMCM-1311's axis parameters ([TMCL] §6, §7, §8): positions, speeds and accelerations in
//! the manual's units (`scale`), the ideal encoder, the closed-loop and driver parameters kept
//! or refused (`crate::personality::tmcm1311`).

use super::*;

impl<C: Spi429> Module<C> {
    pub(super) fn sap_1311(&mut self, p: u8, m: usize, v: i32) -> (u8, i32) {
        match p {
            0 => return self.set_target_position(m, v),
            1 => return self.set_actual_position(m, v),
            2 => return self.set_speed(m, reg::V_TARGET, v),
            3 => return self.set_speed(m, reg::V_ACTUAL, v),
            128 => {
                self.switch_mode(m, v == 1);
                return ok(v);
            }
            // Open loop (0) and no encoder initialization (0): nothing to do; 1 is refused.
            129 | 132 => return ok(v),
            198 => {
                let mode = self.ap(m, 201);
                self.axes[m].set_raw(201, if v == 1 { mode | 4 } else { mode & !4 });
                return ok(v);
            }
            209 => {
                self.set_encoder(m, v);
                return ok(v);
            }
            _ => {}
        }
        let mut a = self.axes[m];
        a.set_raw(p, v);
        let get = |q: u8| a.get(q).unwrap_or(0) as i64;
        if matches!(p, 4 | 5 | 130 | 194 | 195) {
            let search = get(194).max(get(195));
            let now = if self.rm(m) == reg::RM_VELOCITY { self.st[m].target_speed.unsigned_abs() as i64 } else { 0 };
            let ok_all = [get(4), search, now].iter().all(|&s| self.representable(s, get(130), get(5)));
            if !ok_all {
                // The TMC429 cannot run these speeds at this acceleration (TMC429 §8.1.7.1.1).
                return err(Status::InvalidValue, v);
            }
        }
        self.axes[m] = a;
        match p {
            4 | 5 | 130 | 194 | 195 => {
                let s = self.motion_speed(m);
                // Representable, checked above.
                let _ = self.tune(m, s);
                self.write_ramp(m);
            }
            12 | 13 => self.write_ref_conf(m),
            140 | 202 | 210 => {
                // Another encoder scale: the null channel counts revolutions of it from here.
                let upr = self.usteps_per_rev(m);
                let steps = self.track(m);
                self.st[m].enc_rev = if upr > 0 { steps.div_euclid(upr) } else { 0 };
            }
            _ => {}
        }
        ok(v)
    }

    pub(super) fn gap_1311(&mut self, p: u8, m: usize) -> i32 {
        match p {
            // The ideal motor has no advance angle; torque mode is never active.
            14 | 19 | 129 | 132 | 133 => 0,
            15 => {
                // RMS current limit of parameter 6: 3 A full scale, 1.5 A with Vsense ([TMCL] §6).
                let full = if self.ap(m, 179) == 1 { 1500 } else { 3000 };
                (self.ap(m, 6) * full + 127) / 255
            }
            16 => self.velocity_reached(m) as i32,
            18 => self.status_word(m),
            128 => (self.rm(m) == reg::RM_VELOCITY) as i32,
            131 => self.actual_speed(m),
            153 => self.io.supply_dv as i32,
            198 => (self.ap(m, 201) >> 2) & 1,
            207 => self.st[m].deviation as i32,
            209 => self.encoder(m),
            233 => self.position32(m),
            237 => self.position_error(m),
            _ => self.ap(m, p),
        }
    }

    /// Actual speed within the velocity reached window (17) of the target speed.
    fn velocity_reached(&mut self, m: usize) -> bool {
        let (a, t) = (self.actual_speed(m) as i64, self.target_speed(m) as i64);
        (a - t).abs() <= self.ap(m, 17) as i64
    }

    /// Axis parameter 18: bit 0 target reached, 1 velocity reached, 3 position mode,
    /// 4 velocity mode, 6 home switch, 7 left and 8 right stop switch; the closed-loop,
    /// torque, supply, temperature and I²t bits stay 0.
    fn status_word(&mut self, m: usize) -> i32 {
        let velocity = self.rm(m) == reg::RM_VELOCITY;
        let bits = [
            (0, self.x_actual_reg(m) == self.x_target_reg(m)),
            (1, self.velocity_reached(m)),
            (3, !velocity),
            (4, velocity),
            (6, self.home_switch(m)),
            (7, self.left_switch(m)),
            (8, self.right_switch(m)),
        ];
        bits.iter().fold(0, |w, (b, on)| w | ((*on as i32) << b))
    }
}
