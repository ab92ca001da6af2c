//! The driver side (`rtl/tmc429_chain.v`, `_current.v`, `_stepdir.v`, `_drvpins.v`): the units'
//! edge and the driver-side output pins with the 74HC157 switch sampling (TMC428 §9, §11, §12;
//! TMC429 §8.2, §10, §11; docs/model-contract.md C70–C99).

use crate::regmap::f;
use crate::{chain, current, schedule, stepdir, sync, Chip, Tmc429};

/// Driver side: microstep unit, current scaling, SPI chain and Step/Dir (C70–C99).
impl Tmc429 {
    /// How many coming edges the driver units stay quiet for as long as no ramp tick, step or
    /// write comes: the chain idle without a request or counting down inside a state, the
    /// Step/Dir unit's counters running (0: the coming edge has work; `u64::MAX`: no count ends
    /// the quiet).
    #[inline]
    pub(crate) fn drivers_quiet_edges(&self) -> u64 {
        let chain = if self.chip == Chip::Tmc4210 {
            u64::MAX
        } else {
            let c = &self.chain;
            let spi = self.spi_mode();
            if c.state == chain::IDLE {
                let busy = c.req || c.cs || c.stepped != 0 || (self.global.cw && spi);
                if busy {
                    0
                } else {
                    u64::MAX
                }
            } else if spi {
                // Counting down inside a state: the edge only decrements (Chain::count_down).
                c.counting_edges()
            } else {
                0
            }
        };
        let sd = if self.chip == Chip::Tmc428 { u64::MAX } else { self.sd.quiet_edges(self.step_dir_mode(), self.run_edges + 1) };
        chain.min(sd)
    }

    /// The coming edge is a ramp tick that the chain's continuous update or the current-scale
    /// selector counts (C83, C75).
    #[inline]
    pub(crate) fn ramp_tick_drives(&self) -> bool {
        if self.chip == Chip::Tmc4210 {
            return false;
        }
        match schedule::lane_of(&schedule::PHASE_RAMP, schedule::phase(self.prescaler)) {
            Some(i) => {
                let cont = self.spi_mode() && self.global.g(f::CONT_UPDATE) != 0;
                let (m, cs) = (&self.motors[i], &self.cur[i]);
                schedule::due(self.prescaler, m.ramp_div) && (cont || !cs.tick_changes_nothing(m))
            }
            None => false,
        }
    }

    /// Driver interface mode of the current state (C89, C91).
    #[inline]
    pub(crate) fn spi_mode(&self) -> bool {
        match self.chip {
            Chip::Tmc428 => true,
            Chip::Tmc429 => !self.global.ifc(f::EN_SD),
            Chip::Tmc4210 => false,
        }
    }

    #[inline]
    pub(crate) fn step_dir_mode(&self) -> bool {
        self.chip != Chip::Tmc428 && self.global.ifc(f::EN_SD)
    }

    /// One edge of the driver units, from the old state (C1, C70). Runs before the motion core
    /// mutates the motors, so every unit sees the step flags and indices of the previous edge.
    /// Returns true when a driver-side pin may have changed.
    #[inline]
    pub(crate) fn drivers(&mut self, pins: u16) -> bool {
        let ramp_ticks = schedule::ramp_ticks(self.prescaler, &self.motors);
        let spi = self.spi_mode();
        let mut changed = false;
        if self.chip != Chip::Tmc4210 {
            let sdi = (pins >> sync::bit::SDI_S) & 1 != 0;
            let hs = self.chain.tick(spi, &self.ram, &self.global, &self.motors, &self.cur, ramp_ticks, sdi);
            self.global.handshake(&hs);
            changed = hs.changed;
            if ramp_ticks != 0 {
                for i in 0..3 {
                    if (ramp_ticks >> i) & 1 != 0 {
                        self.cur[i].ramp_tick(&self.motors[i]);
                    }
                }
            }
        }
        if self.chip != Chip::Tmc428 {
            let n = self.motor_count();
            let sd = self.step_dir_mode();
            changed |= self.sd.tick(self.run_edges, sd, n, &self.motors, self.global.g(f::CLK2_DIV), self.global.ifc(f::STEP_HALF));
        }
        changed
    }

    /// Drives the driver-side output pins from the new state and samples the multiplexed
    /// reference switches on nSCS_S edges (C81, C87, C91, C92). `pins`: the synchronized inputs of
    /// the old state.
    pub(crate) fn driver_pins(&mut self, pins: u16) {
        let g = &self.global;
        if self.spi_mode() {
            let (ncs, ncs2, ncs3, sck, sdo) = self.chain.pins(g);
            if g.g(f::REFMUX) != 0 && ncs != self.out.nscs_s {
                // 74HC157 on nSCS_S: left switches while the pin is high, right while low (C87).
                let inv = self.chip != Chip::Tmc428 && g.ifc(f::INV_REF);
                let mut mux = g.mux_switches;
                // The pin was low before this edge → the right switches were presented.
                let right = !self.out.nscs_s;
                for m in 0..3u32 {
                    let lv = ((pins >> (sync::bit::REF1 + m)) & 1 != 0) ^ inv;
                    let b = if right { 2 * m } else { 2 * m + 1 };
                    mux = (mux & !(1 << b)) | ((lv as u8) << b);
                }
                self.global.mux_switches = mux;
            }
            self.out.nscs_s = ncs;
            self.out.nscs2 = ncs2;
            self.out.nscs3 = ncs3;
            self.out.sck_s = sck;
            self.out.sdo_s = sdo;
            self.out.sdi_s_o = false;
            self.out.sdi_s_oe = false;
            return;
        }
        let inv_stp = g.ifc(f::INV_STP);
        let inv_dir = g.ifc(f::INV_DIR);
        let sd = self.step_dir_mode();
        match self.chip {
            Chip::Tmc429 => {
                // S1 = SDO_S, D1 = SCK_S, S2 = nSCS_S, D2 = SDI_S, S3 = nSCS2, D3 = nSCS3.
                let (s1, d1) = self.sd.pins(0, inv_stp, inv_dir);
                let (s2, d2) = self.sd.pins(1, inv_stp, inv_dir);
                let (s3, d3) = self.sd.pins(2, inv_stp, inv_dir);
                self.out.sdo_s = s1;
                self.out.sck_s = d1;
                self.out.nscs_s = s2;
                self.out.sdi_s_o = d2;
                self.out.sdi_s_oe = true;
                self.out.nscs2 = s3;
                self.out.nscs3 = d3;
            }
            _ => {
                // TMC4210: STEP = SDO_S, DIR = SCK_S; logic high until en_sd = 1 (C92).
                let (s, d) = if sd { self.sd.pins(0, inv_stp, inv_dir) } else { (true, true) };
                self.out.sdo_s = s;
                self.out.sck_s = d;
                self.out.nscs_s = true;
                self.out.nscs2 = true;
                self.out.nscs3 = true;
                self.out.sdi_s_o = false;
                self.out.sdi_s_oe = false;
            }
        }
    }

    /// Driver-chain state (read-only).
    pub fn chain(&self) -> &chain::Chain {
        &self.chain
    }

    /// Current-scale selector of motor `m` (read-only).
    pub fn current_scale(&self, m: usize) -> &current::CurrentScale {
        &self.cur[m]
    }

    /// Step/Dir state (read-only).
    pub fn step_dir(&self) -> &stepdir::StepDir {
        &self.sd
    }
}
