//! Motion commands ROR, ROL, MST, MVP ([TMCL] §5.7.1–§5.7.4) and the positions and speeds
//! behind them, in the module type's units: the TMC429's own on the TMCM-3110; pps and 32-bit
//! positions on the TMCM-1311 (`scale`).

use super::*;

const P24: std::ops::RangeInclusive<i64> = -(1 << 23)..=(1 << 23) - 1;

impl<C: Spi429> Module<C> {
    /// ROR (positive `v`) and ROL (negative): velocity mode at `v` ([TMCL] §5.7.1, §5.7.2).
    pub(super) fn rotate(&mut self, m: usize, v: i32) -> (u8, i32) {
        let vr = match self.module_speed(m, v) {
            Ok(vr) => vr,
            Err(s) => return err(s, v),
        };
        self.st[m].target_speed = v;
        self.cancel_rfs(m);
        self.set_rm(m, reg::RM_VELOCITY);
        // In velocity mode v_max limits the target; the configured maximum returns with MVP.
        self.wr_motor(m, reg::V_MAX, 2047);
        self.st[m].speed_changed = true;
        self.wr_motor(m, reg::V_TARGET, vr as u32 & 0xfff);
        ok(v)
    }

    /// MST: velocity mode, target speed 0, ramped ([TMCL] §5.7.3).
    pub(super) fn stop_motor(&mut self, m: usize) {
        self.cancel_rfs(m);
        self.set_rm(m, reg::RM_VELOCITY);
        self.wr_motor(m, reg::V_TARGET, 0);
        self.st[m].target_speed = 0;
    }

    /// Stops at once (encoder deviation): velocity mode, target and actual speed 0.
    pub(super) fn hard_stop(&mut self, m: usize) {
        self.stop_motor(m);
        self.wr_motor(m, reg::V_ACTUAL, 0);
    }

    /// MVP to `target` in the module's position units ([TMCL] §5.7.4).
    pub(super) fn move_to(&mut self, m: usize, target: i64) -> (u8, i32) {
        let chip_target = match self.kind {
            ModuleType::Tmcm3110 if P24.contains(&target) => target as u32,
            ModuleType::Tmcm1311 if i32::try_from(target).is_ok() => {
                // One move covers at most the TMC429's position range.
                let d = (target as i32).wrapping_sub(self.position32(m)) as i64;
                if !P24.contains(&d) || self.tune(m, self.ap(m, 4) as i64).is_err() {
                    return err(Status::InvalidValue, target as i32);
                }
                self.st[m].target = target as i32;
                (self.st[m].last_x as i64 + d) as u32
            }
            _ => return err(Status::InvalidValue, target as i32),
        };
        self.cancel_rfs(m);
        self.restore_v_max(m);
        if chip_target & 0xff_ffff != self.rd_motor(m, reg::X_TARGET) {
            // A new target: "target reached" is new when it is reached, even within one
            // millisecond of service.
            self.edges.reached &= !(1 << m);
        }
        self.wr_motor(m, reg::X_TARGET, chip_target & 0xff_ffff);
        let rm = self.positioning_rm(m);
        self.set_rm(m, rm);
        ok(target as i32)
    }

    /// Puts the configured maximum speed back after velocity mode.
    pub(super) fn restore_v_max(&mut self, m: usize) {
        if self.st[m].speed_changed {
            let v = self.chip_v_max(m);
            self.wr_motor(m, reg::V_MAX, v as u32);
            self.st[m].speed_changed = false;
        }
    }

    /// MVP ABS, REL, COORD.
    pub(super) fn mvp(&mut self, typ: u8, m: usize, v: i32) -> (u8, i32) {
        let target = match typ {
            0 => return self.move_to(m, v as i64),
            1 => self.relative_base(m) as i64 + v as i64,
            2 if (0..COORDS as i32).contains(&v) => self.coords[m][v as usize] as i64,
            2 => return err(Status::InvalidValue, v),
            _ => return err(Status::WrongType, v),
        };
        (self.move_to(m, target).0, v)
    }

    /// What MVP REL adds to: the actual position (TMCM-3110); per axis parameter 127 the last
    /// target, the actual position or the encoder position (TMCM-1311, [TMCL] §6).
    fn relative_base(&mut self, m: usize) -> i32 {
        match (self.kind, self.ap(m, 127)) {
            (ModuleType::Tmcm3110, _) | (_, 1) => self.actual_position(m),
            (_, 2) => self.encoder_position(m),
            _ => self.st[m].target,
        }
    }

    /// Axis parameter 1.
    pub(super) fn actual_position(&mut self, m: usize) -> i32 {
        match self.kind {
            ModuleType::Tmcm3110 => self.x_actual_reg(m),
            ModuleType::Tmcm1311 => self.position32(m),
        }
    }

    /// Axis parameter 0.
    pub(super) fn target_position(&mut self, m: usize) -> i32 {
        match self.kind {
            ModuleType::Tmcm3110 => self.x_target_reg(m),
            ModuleType::Tmcm1311 => self.st[m].target,
        }
    }

    /// SAP 1: the axis does not move; at rest in a positioning mode the target follows, so
    /// no move starts.
    pub(super) fn set_actual_position(&mut self, m: usize, v: i32) -> (u8, i32) {
        let at_rest = self.rm(m) != reg::RM_VELOCITY && self.v_actual_reg(m) == 0;
        if self.kind == ModuleType::Tmcm3110 {
            self.wr_motor(m, reg::X_ACTUAL, v as u32 & 0xff_ffff);
            if at_rest {
                self.wr_motor(m, reg::X_TARGET, v as u32 & 0xff_ffff);
            }
        } else {
            self.set_position32(m, v);
            if at_rest {
                let x = self.st[m].last_x;
                self.wr_motor(m, reg::X_TARGET, x);
                self.st[m].target = v;
            }
        }
        ok(v)
    }

    /// SAP 0: the target of the positioning modes (a move starts in one of them).
    pub(super) fn set_target_position(&mut self, m: usize, v: i32) -> (u8, i32) {
        if self.kind == ModuleType::Tmcm3110 {
            self.wr_motor(m, reg::X_TARGET, v as u32 & 0xff_ffff);
            ok(v)
        } else if self.rm(m) != reg::RM_VELOCITY {
            self.move_to(m, v as i64)
        } else {
            self.st[m].target = v;
            ok(v)
        }
    }

    /// Axis parameter 2.
    pub(super) fn target_speed(&mut self, m: usize) -> i32 {
        let v = sext(self.rd_motor(m, reg::V_TARGET), 12);
        if self.kind == ModuleType::Tmcm3110 {
            v
        } else if self.rm(m) == reg::RM_VELOCITY {
            self.st[m].target_speed
        } else {
            self.pps(m, v)
        }
    }

    /// Axis parameter 3.
    pub(super) fn actual_speed(&mut self, m: usize) -> i32 {
        let v = self.v_actual_reg(m);
        match self.kind {
            ModuleType::Tmcm3110 => v,
            ModuleType::Tmcm1311 => self.pps(m, v),
        }
    }

    /// SAP 2 (target speed, `idx` V_TARGET) and SAP 3 (actual speed, V_ACTUAL).
    pub(super) fn set_speed(&mut self, m: usize, idx: u8, v: i32) -> (u8, i32) {
        let vr = match self.module_speed(m, v) {
            Ok(vr) => vr,
            Err(s) => return err(s, v),
        };
        if idx == reg::V_TARGET {
            self.st[m].target_speed = v;
        }
        self.wr_motor(m, idx, vr as u32 & 0xfff);
        ok(v)
    }

    /// The velocity register value of speed `v` in the module's units (the check has
    /// limited it to the register's range); the TMCM-1311 first picks dividers for it.
    fn module_speed(&mut self, m: usize, v: i32) -> Result<i32, Status> {
        match self.kind {
            ModuleType::Tmcm3110 => Ok(v),
            ModuleType::Tmcm1311 => {
                self.tune(m, v as i64)?;
                Ok(self.v_reg(m, v as i64))
            }
        }
    }
}
