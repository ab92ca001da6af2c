//! The bins of the motion profile, from the model's state after each tick: steps, switch
//! stops, latches, the driver chain's datagrams, Step/Dir, and once per frame the ramp modes.

use tmc429_model::regmap;
use tmc429_model::{chain, current, motor_regs, stepdir, Chip, Global, Probes, Tmc429};

use super::bins::USRS_STEP_BINS;
use super::{Coverage, MotionSeen, MODE_NAMES};

impl Coverage {
    /// Motion-profile bins, from the model's state after each tick (a few loads per cycle; the
    /// per-motor mode checks run once per 32-cycle frame, after the pulse phase).
    #[inline]
    pub fn model(&mut self, t: &Tmc429, p: &Probes) {
        let Some(mut seen) = self.motion else { return };
        let chip = t.chip();
        let n = t.motor_count();
        let g = t.global();
        self.motor_events(t, p, n, &mut seen);
        if chip != Chip::Tmc4210 {
            self.chain_events(t, g, &mut seen);
        }
        if chip != Chip::Tmc428 && g.ifconf & regmap::f::EN_SD.put(1) != 0 {
            self.step_dir_events(t, g, n, &mut seen);
        }
        if p.prescaler & 31 == 0 {
            self.frame_modes(t, chip, n, &mut seen);
        }
        self.motion = Some(seen);
    }

    /// Steps (by usrs and direction), switch stops and latches of each motor.
    #[inline]
    fn motor_events(&mut self, t: &Tmc429, p: &Probes, n: usize, seen: &mut MotionSeen) {
        for i in 0..n {
            let m = t.motor(i);
            let pm = &p.motor[i];
            if pm.step != 0 {
                self.hit(USRS_STEP_BINS[(m.usrs & 7) as usize]);
                self.hit(if pm.dir != 0 { "step negative" } else { "step positive" });
            }
            let stop = m.cond_prev & motor_regs::INT_STOP != 0;
            if stop && !seen.stop[i] {
                self.hit(if m.ref_conf & motor_regs::SOFT_STOP != 0 { "switch stop, soft" } else { "switch stop, hard" });
            }
            seen.stop[i] = stop;
            if seen.lp[i] && !m.lp {
                self.hit(if m.ref_prev { "latch on a rising switch edge" } else { "latch on a falling switch edge" });
            }
            seen.lp[i] = m.lp;
        }
    }

    /// The driver chain's datagrams, cover datagrams, individual selects, NxM gaps, continuous
    /// update requests and the switch multiplexer's samples.
    #[inline]
    fn chain_events(&mut self, t: &Tmc429, g: &Global, seen: &mut MotionSeen) {
        let c = t.chain();
        if c.state != seen.chain_state {
            match c.state {
                chain::SETUP => {
                    self.hit("datagram sent");
                    if c.cover_busy {
                        self.hit("cover datagram sent");
                    }
                    if g.gconf & regmap::f::CS_COM_IND.put(1) != 0 {
                        self.hit("datagram with individual chip selects");
                    }
                }
                chain::GAP => self.hit("datagram with an NxM gap"),
                _ => {}
            }
            seen.chain_state = c.state;
        }
        for i in 0..3 {
            let k = c.cupd[i];
            if k == 0 && seen.cupd[i] == chain::CUPD_RAMP_TICKS - 1 {
                self.hit("continuous update request");
            }
            seen.cupd[i] = k;
        }
        if g.mux_switches != seen.mux {
            self.hit("refmux: switches sampled");
            seen.mux = g.mux_switches;
        }
    }

    /// Step/Dir direction changes and step pulses (or step_half toggles).
    #[inline]
    fn step_dir_events(&mut self, t: &Tmc429, g: &Global, n: usize, seen: &mut MotionSeen) {
        let sd = t.step_dir();
        for i in 0..n {
            if sd.dir[i] != seen.sd_dir[i] {
                self.hit("Step/Dir: direction change");
                seen.sd_dir[i] = sd.dir[i];
            }
            if sd.state[i] == stepdir::PULSE && sd.cnt[i] > 0 {
                self.hit(if g.ifconf & regmap::f::STEP_HALF.put(1) != 0 { "Step/Dir: step_half toggle" } else { "Step/Dir: step pulse" });
            }
        }
    }

    /// Once per frame: |v_actual| at its limit, mode and x_target changes during motion, each
    /// mode's end of a move, the current scale selected.
    fn frame_modes(&mut self, t: &Tmc429, chip: Chip, n: usize, seen: &mut MotionSeen) {
        for i in 0..n {
            let m = t.motor(i);
            let v_act = m.v_actual();
            if v_act.unsigned_abs() == 2047 {
                self.hit("|v_actual| = 2047");
            }
            if m.v != 0 && m.rm != seen.rm[i] {
                self.hit("mode change during motion");
            }
            if m.v != 0 && m.rm <= motor_regs::SOFT_MODE && m.x_target != seen.x_target[i] {
                self.hit("x_target change during motion");
            }
            match m.rm {
                motor_regs::RAMP_MODE | motor_regs::SOFT_MODE => {
                    if m.v != 0 {
                        seen.moved[i] = true;
                    } else if seen.moved[i] && m.x_actual == m.x_target {
                        self.hit(&format!("{}: move ends at x_target", MODE_NAMES[m.rm as usize]));
                        seen.moved[i] = false;
                    }
                }
                motor_regs::VELOCITY_MODE => {
                    seen.moved[i] = false;
                    if m.v != 0 && v_act == m.vt {
                        self.hit("VELOCITY_MODE: v_actual reaches v_target");
                    }
                }
                _ => {
                    seen.moved[i] = false;
                    if m.v != 0 {
                        self.hit("HOLD_MODE: moving at a written v_actual");
                    }
                }
            }
            seen.rm[i] = m.rm;
            seen.x_target[i] = m.x_target;
            if chip != Chip::Tmc4210 {
                let name = match t.current_scale(i).sel {
                    current::SEL_AGTAT => "current scale is_agtat selected",
                    current::SEL_V0 => "current scale is_v0 selected",
                    _ => "current scale is_aleat selected",
                };
                self.hit(name);
            }
        }
    }
}
