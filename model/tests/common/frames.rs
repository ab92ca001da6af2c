//! One motor's ramp and pulse generator run frame by frame (C40, C41, C51–C53), skipping the
//! frames without a tick and, where nothing but the position changes, whole runs of ticks at
//! once: moves of 2^22 steps at any pulse_div and ramp_div take milliseconds. The arithmetic is
//! the model's own ([`Motor::target_velocity`], `tmc429_model::accel::approach`); only the schedule is
//! written out here, and `frames_equal_the_chip` (tests/braking_law.rs) holds it to the chip
//! cycle by cycle.
#![allow(dead_code)]

use tmc429_model::motor_regs::{sext24, Motor, HOLD_MODE, SOFT_MODE};

/// What one run observed.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Run {
    /// Frames from the start to the stop (or to the limit).
    pub frames: u64,
    /// The motor came to rest: stop at target (C52), or V = 0 with a target velocity of 0.
    pub stopped: bool,
    /// Largest distance past the target, in steps, in the direction `dir` of the run.
    pub overshoot: u32,
    /// Steps against the direction `dir` of the run.
    pub backward: bool,
    /// Changes of the step direction during the run.
    pub reversals: u32,
    /// Largest |V| >> 8 seen at the start of a frame.
    pub v_peak: u32,
}

/// A motor whose pre-divider frame counter is at `frame` (C40).
#[derive(Clone, Debug)]
pub struct Frames {
    pub m: Motor,
    pub frame: u64,
    /// Direction of the last step (+1, −1; 0 before the first).
    pub last_step: i32,
    /// When set, (frame, x_actual, V) at the start of every frame the run moves on from.
    pub trace: Option<Vec<(u64, u32, i32)>>,
}

fn due(frame: u64, div: u8) -> bool {
    frame & ((1 << div) - 1) == (1 << div) - 1
}

/// |V| >> 8 of a velocity in 1/256 units (what the pulse generator adds, C53).
fn vint(v: i32) -> u32 {
    v.unsigned_abs() >> 8
}

/// V moved toward `t` by at most `step` (C51 over several ramp ticks).
fn approach_by(v: i32, t: i32, step: i64) -> i32 {
    let step = step.min(1 << 21) as i32;
    if v < t {
        (v + step).min(t)
    } else {
        (v - step).max(t)
    }
}

/// x_actual moved by `n` steps in direction `sign` (24-bit wrap-around, C53).
fn moved(x: u32, sign: i32, n: i64) -> u32 {
    ((sext24(x) as i64 + sign as i64 * n) as u32) & 0xFF_FFFF
}

impl Frames {
    pub fn new(m: Motor) -> Self {
        Frames { m, frame: 0, last_step: 0, trace: None }
    }

    /// Stop at target (C52): in RAMP and SOFT mode, dx = 0 and |V|>>8 ≤ v_min.
    fn at_stop(&self) -> bool {
        self.m.rm <= SOFT_MODE && self.m.x_actual == self.m.x_target && vint(self.m.v) <= self.m.v_min as u32
    }

    /// Signed distance to the target (C43).
    fn dx(&self) -> i64 {
        self.m.dx() as i64
    }

    /// Runs the motor toward x_target from the current state until it rests or `limit` frames
    /// have passed; `dir` (+1, −1) is the direction the observations are taken in.
    pub fn run(&mut self, dir: i32, limit: u64) -> Run {
        let start = self.frame;
        let mut r = Run::default();
        let g = self.m.pulse_div.min(self.m.ramp_div);
        // the first frame with a tick
        self.frame |= (1 << g) - 1;
        while self.frame - start < limit {
            r.v_peak = r.v_peak.max(vint(self.m.v));
            if self.at_stop() {
                self.m.v = 0;
                r.stopped = true;
                break;
            }
            if self.m.v == 0 && self.m.target_velocity() == 0 {
                // at rest short of the target (v_min = 0, C50)
                r.stopped = true;
                break;
            }
            if let Some(t) = &mut self.trace {
                t.push((self.frame, self.m.x_actual, self.m.v));
            }
            if !self.skip(dir, limit - (self.frame - start), &mut r) {
                self.ramp_ticks_before_pulse(g);
                self.pulse_ticks_before_ramp(g, dir, &mut r);
                self.tick_frame(dir, &mut r);
                self.frame += 1 << g;
            }
        }
        r.frames = self.frame - start;
        r
    }

    /// Records `n` steps in direction `sign` (the position already moved).
    fn observe(&mut self, r: &mut Run, sign: i32, n: i64, dir: i32) {
        if n == 0 {
            return;
        }
        if sign != dir {
            r.backward = true;
        }
        if self.last_step != 0 && sign != self.last_step {
            r.reversals += 1;
        }
        self.last_step = sign;
        let past = -self.dx() * dir as i64;
        if past > 0 {
            r.overshoot = r.overshoot.max(past as u32);
        }
    }

    /// With ramp_div < pulse_div and the motor off its target: takes the ramp ticks before the
    /// next pulse tick's frame together. d and so vt hold over them, and off the target no
    /// stop at target can occur, so V only approaches vt.
    fn ramp_ticks_before_pulse(&mut self, g: u8) {
        let m = &self.m;
        if m.ramp_div >= m.pulse_div || m.x_actual == m.x_target || m.rm == HOLD_MODE {
            return;
        }
        let next_pulse = self.frame | ((1u64 << m.pulse_div) - 1);
        let n = (next_pulse - self.frame) >> g;
        if n > 0 {
            let vt = m.target_velocity();
            self.m.v = approach_by(m.v, vt * 256, m.a_max as i64 * n as i64);
            self.frame += n << g;
        }
    }

    /// With ramp_div > pulse_div: takes the pulse ticks before the next ramp tick's frame
    /// together when they cannot reach the target: V holds over them, so only x_actual and
    /// the accumulator change.
    fn pulse_ticks_before_ramp(&mut self, g: u8, dir: i32, r: &mut Run) {
        let m = self.m;
        if m.ramp_div <= m.pulse_div || m.rm == HOLD_MODE {
            return;
        }
        let next_ramp = self.frame | ((1u64 << m.ramp_div) - 1);
        let k = (next_ramp - self.frame) >> g;
        let d = self.dx();
        let total = m.acc as u64 + k * vint(m.v) as u64;
        let n = (total / 2048) as i64;
        if k == 0 || (n > 0 && (d.signum() != m.v.signum() as i64 || n >= d.abs())) {
            return;
        }
        self.m.acc = (total % 2048) as u16;
        self.m.x_actual = moved(m.x_actual, m.v.signum(), n);
        self.frame += k << g;
        self.observe(r, m.v.signum(), n, dir);
    }

    /// One frame with a tick: snapshot and commit (C41), ramp tick (C51), pulse tick (C53).
    fn tick_frame(&mut self, dir: i32, r: &mut Run) {
        let vt = self.m.target_velocity();
        let m = &mut self.m;
        if m.rm != HOLD_MODE && due(self.frame, m.ramp_div) {
            let v = tmc429_model::accel::approach(m.v, vt * 256, m.a_max);
            m.a_actual = v - m.v;
            m.v = v;
        }
        if due(self.frame, m.pulse_div) {
            let sum = m.acc + vint(m.v) as u16;
            m.acc = sum & 0x7FF;
            if sum > 0x7FF {
                let sign = if m.v < 0 { -1 } else { 1 };
                m.do_step(m.v < 0);
                self.observe(r, sign, 1, dir);
            }
        }
    }

    /// Skips whole intervals of the larger divider in which V holds (V = 256·vt and vt stays
    /// the same over the steps made) and the target stays at least 2 steps away: only
    /// x_actual and the accumulator change. Returns false when nothing was skipped.
    fn skip(&mut self, dir: i32, room: u64, r: &mut Run) -> bool {
        let m = self.m;
        let vt = m.target_velocity();
        let u = vint(m.v) as u64;
        let sign = m.v.signum();
        if m.v != vt * 256 || u == 0 {
            return false;
        }
        let dist = self.dx() * sign as i64;
        if dist <= 2 {
            return false;
        }
        // the steps allowed: 2 short of the target, and no farther than vt holds (vt is
        // monotonic in |dx|, so the far end decides)
        let mut far = m;
        let mut steps = (dist - 2) as u64;
        loop {
            far.x_actual = moved(m.x_actual, sign, steps as i64);
            if far.target_velocity() == vt || steps < 64 {
                break;
            }
            steps /= 2;
        }
        if far.target_velocity() != vt {
            return false;
        }
        let div = m.pulse_div.max(m.ramp_div);
        let per = 1u64 << (div - m.pulse_div); // pulse ticks per interval
        let intervals = ((steps * 2048).saturating_sub(m.acc as u64) / (u * per)).min(room >> div);
        if intervals < 2 {
            return false;
        }
        let intervals = intervals - 1;
        let total = m.acc as u64 + intervals * per * u;
        let n = (total / 2048) as i64;
        self.m.acc = (total % 2048) as u16;
        self.m.x_actual = moved(m.x_actual, sign, n);
        self.frame += intervals << div;
        self.observe(r, sign, n, dir);
        true
    }
}
