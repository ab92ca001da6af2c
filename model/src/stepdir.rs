//! Step/Dir output (TMC429 §10, §8.2.4 with en_sd = 1; TMC4210; contract C91–C96).
//!
//! Per motor a small state machine with one down-counter:
//! ```text
//! READY ──backlog ≠ 0, same direction──► PULSE (STEP active or toggled, T edges)
//!   ► SPACE (STEP inactive, T edges; skipped with step_half) ► READY
//! READY ──backlog ≠ 0, other direction──► DIRSET (DIR changed, T edges) ► READY
//! ```
//! with T = t_STEP = 16·(1 + STPDIV) CLK. Steps of the motion core add ±1 to a signed backlog
//! (24-bit, the difference between x_actual and the position given to the driver); READY
//! takes the step of the same edge into account, so a pulse starts one CLK after the step.

use crate::motor_regs::Motor;

pub const READY: u8 = 0;
pub const PULSE: u8 = 1;
pub const SPACE: u8 = 2;
pub const DIRSET: u8 = 3;

const MASK24: i32 = 0xFF_FFFF;

#[inline]
fn wrap24(v: i32) -> i32 {
    ((v & MASK24) << 8) >> 8
}

/// t_STEP in CLK edges (TMC429 §10.1): 16·(1 + STPDIV), STPDIV = clk2_div[3:0].
#[inline]
pub fn t_step(clk2_div: u32) -> u16 {
    16 * (1 + (clk2_div & 0xF) as u16)
}

/// Step/Dir state of the three motors.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct StepDir {
    pub state: [u8; 3],
    pub cnt: [u16; 3],
    /// Steps made by the motion core and not yet output (24-bit two's complement).
    pub backlog: [i32; 3],
    /// STEP flop before inv_stp: active level (normal) or toggle state (step_half).
    pub step: [bool; 3],
    /// DIR flop before inv_dir: 1 = negative (as code $12).
    pub dir: [bool; 3],
    /// Bit m: motor m is not READY with an empty backlog (a model shortcut, derived state).
    busy: u8,
    /// Last edge at which [`StepDir::tick`] did its full work.
    last: u64,
    /// First edge at which some motor has something to do (model shortcut, derived state:
    /// the minimum over busy motors of the edge at which their counter reaches 1).
    next: u64,
}

impl StepDir {
    pub fn reset() -> Self {
        StepDir::default()
    }

    /// How many edges from edge `now` on change nothing as long as no step comes (`enabled` =
    /// Step/Dir mode): 0 when edge `now` has work, `u64::MAX` when only a step or a change of
    /// mode ends the quiet.
    #[inline]
    pub fn quiet_edges(&self, enabled: bool, now: u64) -> u64 {
        if self.busy == 0 && (enabled || (self.step == [false; 3] && self.dir == [false; 3])) {
            u64::MAX
        } else if enabled {
            self.next.saturating_sub(now)
        } else {
            0
        }
    }

    /// One CLK edge for `n` motors. `enabled`: Step/Dir mode (C91); while disabled the unit is
    /// held in its reset state and steps are not output. Returns true when a pin level changed.
    /// `now`: index of this edge (any monotonic edge count).
    #[inline]
    pub fn tick(&mut self, now: u64, enabled: bool, n: usize, motors: &[Motor; 3], clk2_div: u32, step_half: bool) -> bool {
        if !enabled {
            if self.busy != 0 || self.step != [false; 3] || self.dir != [false; 3] {
                *self = StepDir::default();
                return true;
            }
            return false;
        }
        let steps = motors[0].step as u8 | (motors[1].step as u8) << 1 | (motors[2].step as u8) << 2;
        if steps == 0 && (self.busy == 0 || now < self.next) {
            // Only counters run: cnt[i] is implicit until `next` (the RTL counts the motor's
            // Step/Dir slots, 16 edges apart).
            return false;
        }
        self.catch_up(now, n);
        let t = t_step(clk2_div);
        let (step_old, dir_old) = (self.step, self.dir);
        for (i, mo) in motors.iter().enumerate().take(n) {
            if (self.busy | steps) >> i & 1 != 0 {
                self.motor_edge(i, mo, t, step_half);
            }
        }
        // Earliest edge with work: READY with a backlog → next edge; else when cnt reaches 1.
        let mut next = u64::MAX;
        for i in 0..n {
            if (self.busy >> i) & 1 != 0 {
                let due = if self.state[i] == READY { now + 1 } else { now + self.cnt[i] as u64 };
                next = next.min(due);
            }
        }
        self.next = next;
        self.step != step_old || self.dir != dir_old
    }

    /// Brings the implicit counters up to date before edge `now`: cnt[i] −= (now − 1 − last)
    /// for the busy motors (the RTL counts the 16-edge slots they span).
    #[inline]
    fn catch_up(&mut self, now: u64, n: usize) {
        let elapsed = now.wrapping_sub(self.last).wrapping_sub(1);
        if elapsed != 0 {
            for i in 0..n {
                if self.state[i] != READY {
                    self.cnt[i] = (self.cnt[i] as u64).saturating_sub(elapsed).max(1) as u16;
                }
            }
        }
        self.last = now;
    }

    /// One edge of motor `i`'s unit with the motion core's step of the old state `mo` (C95):
    /// the backlog takes the step; in READY (or at the end of a SPACE or DIRSET phase) a
    /// nonzero backlog starts a DIR change (C94) or a STEP pulse of T = `t` edges (C93).
    #[inline]
    fn motor_edge(&mut self, i: usize, mo: &Motor, t: u16, step_half: bool) {
        if self.state[i] != READY && self.cnt[i] > 1 && !mo.step {
            self.cnt[i] -= 1;
            return;
        }
        let inc = match (mo.step, mo.dir) {
            (false, _) => 0,
            (true, false) => 1,
            (true, true) => -1,
        };
        let backlog = wrap24(self.backlog[i] + inc);
        let ready = match self.state[i] {
            READY => true,
            _ if self.cnt[i] > 1 => {
                self.cnt[i] -= 1;
                false
            }
            PULSE if !step_half => {
                self.step[i] = false;
                self.state[i] = SPACE;
                self.cnt[i] = t;
                false
            }
            _ => true,
        };
        self.backlog[i] = backlog;
        if ready {
            self.state[i] = READY;
            if backlog != 0 {
                let neg = backlog < 0;
                if neg != self.dir[i] {
                    // C94: DIR changes, the step follows t_DIR2STP = t_STEP later.
                    self.dir[i] = neg;
                    self.state[i] = DIRSET;
                } else {
                    self.step[i] = if step_half { !self.step[i] } else { true };
                    self.backlog[i] = wrap24(backlog - if neg { -1 } else { 1 });
                    self.state[i] = PULSE;
                }
                self.cnt[i] = t;
            }
        }
        let idle = self.state[i] == READY && self.backlog[i] == 0;
        self.busy = (self.busy & !(1 << i)) | ((!idle as u8) << i);
    }

    /// (STEP, DIR) pin levels of motor `m` with inv_stp / inv_dir (C93).
    #[inline]
    pub fn pins(&self, m: usize, inv_stp: bool, inv_dir: bool) -> (bool, bool) {
        (self.step[m] ^ inv_stp, self.dir[m] ^ inv_dir)
    }
}
