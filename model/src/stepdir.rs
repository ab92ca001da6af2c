//! Step/Dir output (TMC429 §10, §8.2.4 with en_sd = 1; TMC4210; contract C90–C96).
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

use crate::motor::Motor;

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
}

impl StepDir {
    pub fn reset() -> Self {
        StepDir::default()
    }

    /// True when nothing is in progress (the fast path of [`StepDir::tick`]).
    #[inline]
    pub fn quiet(&self) -> bool {
        self.state == [READY; 3] && self.backlog == [0; 3]
    }

    /// One CLK edge for `n` motors. `enabled`: Step/Dir mode (C90); while disabled the unit is
    /// held in its reset state and steps are not output.
    #[inline]
    pub fn tick(&mut self, enabled: bool, n: usize, motors: &[Motor; 3], clk2_div: u32, step_half: bool) {
        if !enabled {
            if *self != StepDir::default() {
                *self = StepDir::default();
            }
            return;
        }
        if self.quiet() && !motors.iter().take(n).any(|m| m.step) {
            return;
        }
        let t = t_step(clk2_div);
        for i in 0..n {
            let mo = &motors[i];
            let inc = if mo.step {
                if mo.dir {
                    -1
                } else {
                    1
                }
            } else {
                0
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
                        // C93: DIR changes, the step follows t_DIR2STP = t_STEP later.
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
        }
    }

    /// (STEP, DIR) pin levels of motor `m` with inv_stp / inv_dir (C92).
    #[inline]
    pub fn pins(&self, m: usize, inv_stp: bool, inv_dir: bool) -> (bool, bool) {
        (self.step[m] ^ inv_stp, self.dir[m] ^ inv_dir)
    }
}
