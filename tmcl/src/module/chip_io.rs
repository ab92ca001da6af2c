//! The TMC429 as the firmware drives it, datagram by datagram: register access, the interface
//! configuration, each axis's ramp registers and ramp mode, positions, switches (TMC429 §8).

use super::*;

impl<C: Spi429> Module<C> {
    pub(super) fn wr(&mut self, a7: u8, data: u32) -> u8 {
        self.chip.write(a7, data & 0x00ff_ffff)
    }
    pub(super) fn rd(&mut self, a7: u8) -> u32 {
        self.chip.read(a7) & 0x00ff_ffff
    }
    pub(super) fn rd_motor(&mut self, m: usize, idx: u8) -> u32 {
        self.rd(reg::motor(m, idx))
    }
    pub(super) fn wr_motor(&mut self, m: usize, idx: u8, data: u32) {
        self.wr(reg::motor(m, idx), data);
    }

    /// Step/Dir outputs for the driver stages, right switches on REFR1..3, end switch polarity
    /// (global parameter 79) as inv_ref (TMC429 §8.2.4).
    pub(super) fn if_configuration(&self) -> u32 {
        reg::IF_EN_SD | reg::IF_EN_REFR | if self.gp(79) != 0 { reg::IF_INV_REF } else { 0 }
    }

    /// ref_conf of an axis: the end switch stops (axis parameters 12, 13; off during a
    /// reference search, [TMCL] §9) and the soft stop (149).
    pub(super) fn ref_conf_bits(&self, m: usize) -> u32 {
        let searching = self.st[m].rfs.active();
        let mut r = 0;
        if searching || self.ap(m, 13) != 0 {
            r |= reg::DISABLE_STOP_L;
        }
        if searching || self.ap(m, 12) != 0 {
            r |= reg::DISABLE_STOP_R;
        }
        if self.ap(m, 149) != 0 {
            r |= reg::SOFT_STOP;
        }
        r
    }

    /// Writes ref_conf, keeping the ramp mode.
    pub(super) fn write_ref_conf(&mut self, m: usize) {
        let rc = self.rd_motor(m, reg::REFCONF_RM);
        let bits = self.ref_conf_bits(m);
        self.wr_motor(m, reg::REFCONF_RM, bits | (rc & 3));
    }

    /// Writes the whole configuration to the chip (power-on, factory reset). The TMC429's
    /// three motors are all set up; the module type uses the first of them.
    pub(super) fn init_chip(&mut self) {
        self.update_pins();
        let ifc = self.if_configuration();
        self.wr(reg::IF_CONFIGURATION, ifc);
        self.wr(reg::GLOBAL_PARAMETERS, 0);
        for m in 0..AXES {
            if self.kind == ModuleType::Tmcm1311 {
                let v = self.ap(m, 4) as i64;
                // The factory settings are representable: tune cannot fail on them.
                let _ = self.tune(m, v);
            }
            self.write_ramp(m);
            // dx_ref_tolerance: TMCM-3110 axis parameter 141 (on the TMCM-1311 141 is another setting).
            let tol = if self.kind == ModuleType::Tmcm3110 { self.ap(m, 141) } else { 0 };
            self.wr_motor(m, reg::DX_REF_TOLERANCE, tol as u32);
            self.write_ref_conf(m);
            self.wr_motor(m, reg::INT_MASK_FLAGS, 0x00ff);
            self.wr_motor(m, reg::V_TARGET, 0);
            self.wr_motor(m, reg::V_ACTUAL, 0);
            self.wr_motor(m, reg::X_TARGET, 0);
            self.wr_motor(m, reg::X_ACTUAL, 0);
            self.st[m].last_x = 0;
            let rm = self.start_rm(m);
            self.set_rm(m, rm);
        }
        self.edges.reached = self.arrived_mask();
        self.edges.switches = self.switch_register();
        self.edges.inputs = self.inputs();
    }

    /// The velocity register value of the configured maximum positioning speed.
    pub(super) fn chip_v_max(&self, m: usize) -> i32 {
        match self.kind {
            ModuleType::Tmcm3110 => self.ap(m, 4),
            ModuleType::Tmcm1311 => self.v_reg(m, self.ap(m, 4) as i64),
        }
    }

    /// Writes an axis's ramp registers: v_min, v_max, the dividers, a_max, pmul/pdiv. The
    /// TMCM-3110 takes them from its axis parameters 130, 4, 154, 153, 5; the TMCM-1311 from
    /// the dividers `scale::tune` picked.
    pub(super) fn write_ramp(&mut self, m: usize) {
        let (v_min, pd, rd, a) = match self.kind {
            ModuleType::Tmcm3110 => (self.ap(m, 130), self.ap(m, 154), self.ap(m, 153), self.ap(m, 5)),
            ModuleType::Tmcm1311 => {
                let s = self.st[m];
                (self.v_reg(m, self.ap(m, 130) as i64).max(1), s.pulse_div as i32, s.ramp_div as i32, s.a_max)
            }
        };
        self.wr_motor(m, reg::V_MIN, v_min as u32);
        if !self.st[m].speed_changed {
            let v = self.chip_v_max(m);
            self.wr_motor(m, reg::V_MAX, v as u32);
        }
        self.wr_motor(m, reg::PULSEDIV_RAMPDIV, ((pd as u32) << 12) | ((rd as u32) << 8));
        self.wr_motor(m, reg::A_MAX, a as u32);
        if let Some((pm, pdiv)) = crate::calc::pmul_pdiv(a, rd, pd) {
            self.wr_motor(m, reg::PMUL_PDIV, ((pm as u32) << 8) | pdiv as u32);
        }
    }

    pub(super) fn set_rm(&mut self, m: usize, rm: u32) {
        let rc = self.rd_motor(m, reg::REFCONF_RM);
        self.wr_motor(m, reg::REFCONF_RM, (rc & 0x0f00) | (rm & 3));
    }

    pub(super) fn rm(&mut self, m: usize) -> u32 {
        self.rd_motor(m, reg::REFCONF_RM) & 3
    }

    /// The ramp mode MVP uses: SOFT_MODE with TMCM-3110 axis parameter 138 = 1, else RAMP_MODE.
    pub(super) fn positioning_rm(&self, m: usize) -> u32 {
        if self.kind == ModuleType::Tmcm3110 && self.ap(m, 138) == 1 {
            reg::RM_SOFT
        } else {
            reg::RM_RAMP
        }
    }

    /// The ramp mode at power-on: TMCM-3110 axis parameter 138 = 2 starts in velocity mode.
    fn start_rm(&self, m: usize) -> u32 {
        if self.kind == ModuleType::Tmcm3110 && self.ap(m, 138) == 2 {
            reg::RM_VELOCITY
        } else {
            self.positioning_rm(m)
        }
    }

    pub(super) fn x_actual_reg(&mut self, m: usize) -> i32 {
        sext(self.rd_motor(m, reg::X_ACTUAL), 24)
    }
    pub(super) fn x_target_reg(&mut self, m: usize) -> i32 {
        sext(self.rd_motor(m, reg::X_TARGET), 24)
    }
    pub(super) fn v_actual_reg(&mut self, m: usize) -> i32 {
        sext(self.rd_motor(m, reg::V_ACTUAL), 12)
    }

    /// Position reached flag of every axis (bit m), from x_actual = x_target.
    fn reached_mask(&mut self) -> u8 {
        let mut mask = 0;
        for m in 0..self.kind.axes() {
            if self.x_actual_reg(m) == self.x_target_reg(m) {
                mask |= 1 << m;
            }
        }
        mask
    }

    /// Axes at rest (bit m), from v_actual = 0.
    fn rest_mask(&mut self) -> u8 {
        (0..self.kind.axes()).fold(0, |mask, m| mask | (((self.v_actual_reg(m) == 0) as u8) << m))
    }

    /// Axes at rest on their target (bit m): what WAIT POS, the "target reached" interrupt and
    /// the event of command 138 wait for (a pass through the target while braking is not it).
    pub fn arrived_mask(&mut self) -> u8 {
        self.reached_mask() & self.rest_mask()
    }

    /// Switch states from the chip's reference switch register: bit 2m right, 2m+1 left.
    pub(super) fn switch_register(&mut self) -> u8 {
        (self.rd(reg::REF_SWITCHES) & 0x3f) as u8
    }
    pub(super) fn left_switch(&mut self, m: usize) -> bool {
        self.switch_register() & (2 << (2 * m)) != 0
    }
    pub(super) fn right_switch(&mut self, m: usize) -> bool {
        self.switch_register() & (1 << (2 * m)) != 0
    }

    /// The home switch of axis `m` as the firmware reads it: mode + 128 reverses its polarity
    /// ([TMCL] §9, axis parameter 193).
    pub(super) fn home_switch(&self, m: usize) -> bool {
        self.home_level(m) ^ (self.ap(m, 193) & 0x80 != 0)
    }

    /// The level of the home switch input: on the TMCM-1311 the home switch is wired to IN1
    /// ([TMCL] §6 parameter 9, §9): without a home switch on the axis IN1 itself is read.
    fn home_level(&self, m: usize) -> bool {
        if self.kind == ModuleType::Tmcm1311 && !self.world.has_home(m) {
            return self.io.input(1);
        }
        let x = self.chip.mechanical_position(m);
        self.world.home(m, x)
    }

    /// Digital inputs IN0..IN7 (bit n); on the TMCM-1311 IN1 carries the home switch.
    pub(super) fn inputs(&self) -> u8 {
        let i = self.io.inputs();
        if self.kind == ModuleType::Tmcm1311 && self.world.has_home(0) {
            (i & !2) | ((self.home_level(0) as u8) << 1)
        } else {
            i
        }
    }

    /// Drives the switch pins from the world model: pin high = switch pressed.
    pub fn update_pins(&mut self) {
        let mut l = [false; 3];
        let mut r = [false; 3];
        for m in 0..AXES {
            let x = self.chip.mechanical_position(m);
            l[m] = self.world.left(m, x);
            r[m] = self.world.right(m, x);
        }
        self.chip.set_ref_pins(l, r);
    }
}
