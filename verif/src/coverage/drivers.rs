//! The bins of the driver side under [`crate::stimulus::Profile::Drivers`]: the driver chain's
//! datagrams, selects and polarities, the switch multiplexer, Step/Dir.

use tmc429_model::{Chip, Global, Outputs, Probes, Tmc429};

use super::Coverage;

impl Coverage {
    /// Called every cycle of [`crate::stimulus::Profile::Drivers`] with the model after the tick.
    #[inline]
    pub fn drivers(&mut self, chip: Chip, o: &Outputs, p: &Probes, model: &Tmc429) {
        let g = model.global();
        if chip != Chip::Tmc4210 {
            self.chain_drivers(chip, o, p, model, g);
        }
        if o.sdi_s_oe {
            self.hit("Step/Dir pins (SDI_S driven)");
        }
        if chip == Chip::Tmc4210 && g.ifconf & 0x20 != 0 {
            self.hit("Step/Dir mode: STEP/DIR pins configured");
        }
    }

    /// The driver chain's datagrams (state changes of the chain probe), selects, polarities,
    /// readback, the switch multiplexer and the current scale.
    fn chain_drivers(&mut self, chip: Chip, o: &Outputs, p: &Probes, model: &Tmc429, g: &Global) {
        let st = p.chain.state;
        let last = self.last_chain_state;
        let c = model.chain();
        if st != last {
            match (last, st) {
                (5, 6) => {
                    self.hit("chain datagram sent");
                    if c.motor == 2 {
                        self.hit("chain datagram of 3 drivers");
                    }
                }
                (6, 1) => self.hit("chain back-to-back datagrams"),
                (_, 4) => self.hit("chain NxM gap"),
                (2, 3) if c.bits == 127 => self.hit("chain endless datagram (127 bits, no NxM)"),
                (l, 0) if l != 6 && chip == Chip::Tmc429 => self.hit("en_sd aborts a datagram"),
                _ => {}
            }
            if st == 1 {
                if !c.cover_busy && !g.cw {
                    self.hit("chain continuous-update datagram");
                }
                if c.snap_i_scale.iter().any(|&k| k != 0) {
                    self.hit("chain DAC scaled (i_scale != 0)");
                }
                if c.snap_pol.dac_ab {
                    self.hit("chain polarity_dac_ab in a datagram");
                }
            }
            if (last, st) == (5, 6) && self.cover_seen {
                self.hit("chain cover datagram sent");
            }
            self.last_chain_state = st;
        }
        self.cover_seen = c.cover_busy;
        if p.chain.readback != 0 {
            self.hit("chain readback nonzero");
        }
        if !o.nscs2 {
            self.hit("chain csCommonIndividual: nSCS2 selects");
        }
        if !o.nscs3 {
            self.hit("chain csCommonIndividual: nSCS3 selects");
        }
        if c.cs && o.nscs_s && g.gconf & 0x84 == 0x04 {
            self.hit("chain polarity_nscs_s: select high");
        }
        if st == 0 && !o.sck_s && !o.sdi_s_oe {
            self.hit("chain polarity_sck_s: SCK_S low while idle");
        }
        if g.mux_switches != self.last_mux {
            self.hit("refmux: switch sampled on nSCS_S");
            self.last_mux = g.mux_switches;
        }
        if (0..3).any(|m| model.current_scale(m).sel == tmc429_model::current::SEL_V0) {
            self.hit("current scale is_v0 selected");
        }
    }
}
