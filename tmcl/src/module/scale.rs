//! The TMCM-1311's units on the TMC429 ([TMCL] §6): 32-bit positions from the 24-bit x_actual,
//! speeds in pps and accelerations in pps² through dividers picked per motion
//! (`crate::units`), and the ideal encoder (axis parameters 201, 209, 210, 212).

use super::*;
use crate::units;

impl<C: Spi429> Module<C> {
    /// Accumulates the steps issued since the last read of x_actual (every millisecond and
    /// before every use; a millisecond holds far fewer than 2^23 steps).
    pub(super) fn track(&mut self, m: usize) -> i64 {
        let x = self.rd_motor(m, reg::X_ACTUAL);
        let s = &mut self.st[m];
        s.steps += sext(x.wrapping_sub(s.last_x), 24) as i64;
        s.last_x = x;
        s.steps
    }

    /// The 32-bit actual position (wraps as the manual's 32-bit counter does).
    pub(super) fn position32(&mut self, m: usize) -> i32 {
        let s = self.track(m);
        (s + self.st[m].pos_offset) as i32
    }

    /// Sets the 32-bit actual position without moving the axis (the encoder keeps its count).
    pub(super) fn set_position32(&mut self, m: usize, v: i32) {
        let s = self.track(m);
        let old = (s + self.st[m].pos_offset) as i32;
        self.st[m].pos_offset = v as i64 - s;
        self.st[m].target = self.st[m].target.wrapping_add(v.wrapping_sub(old));
    }

    /// The velocity register value of `pps` with the axis's pulse_div.
    pub(super) fn v_reg(&self, m: usize, pps: i64) -> i32 {
        units::v_of(self.chip.fclk(), pps, self.st[m].pulse_div).clamp(-2047, 2047) as i32
    }

    /// The rate [pps] of velocity register value `v` with the axis's pulse_div.
    pub(super) fn pps(&self, m: usize, v: i32) -> i32 {
        units::pps_of(self.chip.fclk(), v, self.st[m].pulse_div).round() as i32
    }

    /// Whether the TMC429 can run `speed` [pps] (with the start/stop velocity) at an
    /// acceleration of `accel` [pps²] (TMC429 §8.1.7.1.1).
    pub(super) fn representable(&self, speed: i64, start: i64, accel: i64) -> bool {
        units::dividers(self.chip.fclk(), speed.abs().max(start), accel).is_some()
    }

    /// Picks pulse_div, ramp_div and a_max so that `speed` [pps], the start/stop velocity and
    /// the axis's present speed fit, with the finest velocity step the acceleration allows
    /// (`units::dividers`); writes them (and the present speed in the new unit) when they
    /// change. Status 4 when the TMC429 cannot.
    pub(super) fn tune(&mut self, m: usize, speed: i64) -> Result<(), Status> {
        let f = self.chip.fclk();
        let v_now = self.v_actual_reg(m);
        let need = speed.abs().max(self.pps(m, v_now).abs() as i64).max(self.ap(m, 130) as i64);
        let (pd, rd, a) = units::dividers(f, need, self.ap(m, 5) as i64).ok_or(Status::InvalidValue)?;
        let s = self.st[m];
        if (pd, rd, a) == (s.pulse_div, s.ramp_div, s.a_max) {
            return Ok(());
        }
        self.st[m].pulse_div = pd;
        self.st[m].ramp_div = rd;
        self.st[m].a_max = a;
        self.write_ramp(m);
        if pd != s.pulse_div {
            if v_now != 0 {
                let v = (v_now as f64 * 2f64.powi(pd as i32 - s.pulse_div as i32)).round().clamp(-2047.0, 2047.0) as i32;
                self.wr_motor(m, reg::V_ACTUAL, v as u32 & 0xfff);
            }
            // The target speed of velocity mode (and of a search leg) in the new unit.
            if self.st[m].rfs.active() {
                self.rfs_drive(m);
            } else if self.rm(m) == reg::RM_VELOCITY {
                let v = self.v_reg(m, self.st[m].target_speed as i64);
                self.wr_motor(m, reg::V_TARGET, v as u32 & 0xfff);
            }
        }
        Ok(())
    }

    /// The speed [pps] the axis's present motion runs at most.
    pub(super) fn motion_speed(&mut self, m: usize) -> i64 {
        if self.st[m].rfs.active() {
            self.ap(m, 194).max(self.ap(m, 195)) as i64
        } else if self.rm(m) == reg::RM_VELOCITY {
            self.st[m].target_speed.unsigned_abs() as i64
        } else {
            self.ap(m, 4) as i64
        }
    }

    // ----- the ideal encoder -----

    /// Microsteps per motor revolution: full steps (202) × 2^microstep resolution (140).
    pub(super) fn usteps_per_rev(&self, m: usize) -> i64 {
        self.ap(m, 202) as i64 * (1i64 << self.ap(m, 140))
    }

    /// Encoder positions since power-on: the steps at the configured resolution (210).
    fn encoder_raw(&mut self, m: usize) -> i64 {
        let steps = self.track(m);
        let upr = self.usteps_per_rev(m);
        if upr == 0 {
            return 0;
        }
        (steps * self.ap(m, 210) as i64).div_euclid(upr)
    }

    /// Encoder counter (axis parameter 209).
    pub(super) fn encoder(&mut self, m: usize) -> i32 {
        (self.encoder_raw(m) + self.st[m].enc_offset) as i32
    }

    pub(super) fn set_encoder(&mut self, m: usize, v: i32) {
        let raw = self.encoder_raw(m);
        self.st[m].enc_offset = v as i64 - raw;
    }

    /// The encoder counter in microsteps.
    fn encoder_usteps(&mut self, m: usize) -> i64 {
        let e = self.encoder_raw(m) + self.st[m].enc_offset;
        let res = self.ap(m, 210) as i64;
        if res == 0 {
            return 0;
        }
        e * self.usteps_per_rev(m) / res
    }

    /// Actual position minus the encoder position, in microsteps (axis parameter 237).
    pub(super) fn position_error(&mut self, m: usize) -> i32 {
        (self.position32(m) as i64 - self.encoder_usteps(m)) as i32
    }

    /// The encoder counter in microsteps (axis parameter 127 = 2).
    pub(super) fn encoder_position(&mut self, m: usize) -> i32 {
        self.encoder_usteps(m) as i32
    }

    /// Sets the encoder counter to the count of position `p` (after a reference search).
    pub(super) fn reference_encoder(&mut self, m: usize, p: i32) {
        let upr = self.usteps_per_rev(m);
        if upr > 0 {
            let e = (p as i64 * self.ap(m, 210) as i64).div_euclid(upr);
            self.set_encoder(m, e as i32);
        }
    }

    /// Once per millisecond: the null channel (once per motor revolution; encoder mode 201
    /// bits 2 and 3 clear the counter on it) and the maximum deviation check (212).
    pub(super) fn encoder_service(&mut self, m: usize) {
        let upr = self.usteps_per_rev(m);
        if upr > 0 {
            let rev = self.track(m).div_euclid(upr);
            let old = self.st[m].enc_rev;
            self.st[m].enc_rev = rev;
            let mode = self.ap(m, 201);
            if rev != old && mode & 0x0c != 0 {
                // The counter is 0 at the revolution boundary crossed.
                let b = rev.max(old);
                self.st[m].enc_offset = -(b * self.ap(m, 210) as i64);
                if mode & 0x04 != 0 {
                    self.axes[m].set_raw(201, mode & !0x04);
                }
            }
        }
        let limit = self.ap(m, 212).unsigned_abs() as i64;
        if limit != 0 && !self.st[m].deviation && (self.position_error(m) as i64).abs() > limit {
            self.st[m].deviation = true;
            self.hard_stop(m);
        }
    }
}
