//! Reference search (RFS, [TMCL] §5.7.13, §9): modes 1..8 of axis parameter 193, +128
//! reverses the home switch's polarity. A search is a short list of legs, each driving in one
//! direction at search speed (194) or switch speed (195) until a switch is met or left; it is
//! checked once per millisecond. The end switch stops are off during a search.
//!
//! - 1: left switch, then leave it and re-enter it slowly; position 0 is the centre of the two
//!   switching points.
//! - 2: right switch first (its position gives parameter 196), then as 1.
//! - 4: left switch from both sides: through it and back, entering it slowly from the far side
//!   and from the near side; position 0 is the switch's centre. It needs a switch that can be
//!   driven through (`World`: a span with two ends).
//! - 3: right switch first, then as 4.
//! - 5, 6: home switch in negative / positive direction; an end switch reverses the search
//!   (once; the other end switch ends it without a reference); position 0 is the centre of the
//!   switching points of the home switch's edge met in the search direction.
//! - 7, 8: home switch in positive / negative direction; the end switches are ignored.
//!
//! A switch already pressed at the start counts as met.

use super::*;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Sw {
    Left,
    Right,
    Home,
}

/// What ends a leg.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Until {
    /// The switch is pressed while moving in the leg's direction.
    Met,
    /// The switch was pressed and is released while moving in the leg's direction.
    Left,
}

/// One leg: switch, direction (before any reversal), speed, end condition, and whether its end
/// is one of the two switching points that make position 0.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Leg {
    sw: Sw,
    dir: i32,
    fast: bool,
    until: Until,
    point: bool,
}

const fn find(sw: Sw, dir: i32) -> Leg {
    Leg { sw, dir, fast: true, until: Until::Met, point: false }
}
const fn leave(sw: Sw, dir: i32, point: bool) -> Leg {
    Leg { sw, dir, fast: false, until: Until::Left, point }
}
const fn enter(sw: Sw, dir: i32) -> Leg {
    Leg { sw, dir, fast: false, until: Until::Met, point: true }
}

use Sw::*;

const LEFT: &[Leg] = &[find(Left, -1), leave(Left, 1, true), enter(Left, -1)];
const RIGHT_LEFT: &[Leg] = &[find(Right, 1), find(Left, -1), leave(Left, 1, true), enter(Left, -1)];
const LEFT_BOTH: &[Leg] = &[find(Left, -1), leave(Left, -1, false), enter(Left, 1), leave(Left, 1, false), enter(Left, -1)];
const RIGHT_LEFT_BOTH: &[Leg] =
    &[find(Right, 1), find(Left, -1), leave(Left, -1, false), enter(Left, 1), leave(Left, 1, false), enter(Left, -1)];
const HOME_NEG: &[Leg] = &[find(Home, -1), leave(Home, 1, true), enter(Home, -1)];
const HOME_POS: &[Leg] = &[find(Home, 1), leave(Home, -1, true), enter(Home, 1)];

/// Reference search state of one axis.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct Rfs {
    legs: &'static [Leg],
    /// Index of the leg driven; `legs.len()` = no search.
    leg: usize,
    /// −1 after an end switch reversed the search (modes 5, 6).
    flip: i32,
    /// Reversals so far.
    reversals: u8,
    /// The leg's switch was pressed while moving in its direction.
    armed: bool,
    points: [i32; 2],
    n_points: usize,
    right_pos: Option<i32>,
    /// End switches reverse the search (modes 5, 6).
    reverse: bool,
    pub(super) distance: i32,
    pub(super) last_switch_pos: i32,
}

impl Rfs {
    pub(super) fn active(&self) -> bool {
        self.leg < self.legs.len()
    }
    fn current(&self) -> Leg {
        self.legs[self.leg]
    }
    /// RFS STATUS: 0 when no search is active, else the leg driven (1..).
    pub(super) fn status(&self) -> i32 {
        if self.active() {
            self.leg as i32 + 1
        } else {
            0
        }
    }
}

impl<C: Spi429> Module<C> {
    pub(super) fn cancel_rfs(&mut self, m: usize) {
        if self.st[m].rfs.active() {
            self.st[m].rfs.legs = &[];
            self.st[m].rfs.leg = 0;
            self.write_ref_conf(m);
        }
    }

    /// RFS START.
    pub(super) fn rfs_start(&mut self, m: usize) -> (u8, i32) {
        if self.kind == ModuleType::Tmcm1311 {
            let s = self.ap(m, 194).max(self.ap(m, 195)) as i64;
            if self.tune(m, s).is_err() {
                return err(Status::InvalidValue, 0);
            }
        }
        let mode = self.ap(m, 193) & 0x7f;
        let legs = match mode {
            2 => RIGHT_LEFT,
            3 => RIGHT_LEFT_BOTH,
            4 => LEFT_BOTH,
            5 | 8 => HOME_NEG,
            6 | 7 => HOME_POS,
            _ => LEFT,
        };
        let (distance, last) = (self.st[m].rfs.distance, self.st[m].rfs.last_switch_pos);
        self.st[m].rfs = Rfs { legs, flip: 1, reverse: matches!(mode, 5 | 6), distance, last_switch_pos: last, ..Rfs::default() };
        self.write_ref_conf(m);
        self.rfs_drive(m);
        ok(0)
    }

    /// Drives the current leg.
    pub(super) fn rfs_drive(&mut self, m: usize) {
        let r = self.st[m].rfs;
        let leg = r.current();
        let s = if leg.fast { self.ap(m, 194) } else { self.ap(m, 195) };
        let v = leg.dir
            * r.flip
            * match self.kind {
                ModuleType::Tmcm3110 => s,
                ModuleType::Tmcm1311 => self.v_reg(m, s as i64),
            };
        self.set_rm(m, reg::RM_VELOCITY);
        self.wr_motor(m, reg::V_MAX, 2047);
        self.st[m].speed_changed = true;
        self.wr_motor(m, reg::V_TARGET, v as u32 & 0xfff);
    }

    fn sw_active(&mut self, m: usize, sw: Sw) -> bool {
        match sw {
            Left => self.left_switch(m),
            Right => self.right_switch(m),
            Home => self.home_switch(m),
        }
    }

    /// Once per millisecond: checks the leg driven.
    pub(super) fn rfs_service(&mut self, m: usize) {
        if !self.st[m].rfs.active() {
            return;
        }
        let r = self.st[m].rfs;
        let leg = r.current();
        let dir = leg.dir * r.flip;
        let moving = self.v_actual_reg(m).signum() == dir;
        if r.reverse && moving && self.end_switch_ahead(m, dir) {
            if r.reversals > 0 {
                // Both ends met without the home switch: the search ends without a reference.
                self.stop_motor(m);
                return;
            }
            self.st[m].rfs.flip = -r.flip;
            self.st[m].rfs.reversals += 1;
            self.st[m].rfs.armed = false;
            self.rfs_drive(m);
            return;
        }
        let active = self.sw_active(m, leg.sw);
        let done = match leg.until {
            Until::Met => moving && active,
            Until::Left => {
                if moving && active {
                    self.st[m].rfs.armed = true;
                }
                moving && r.armed && !active
            }
        };
        if done {
            self.rfs_leg_done(m, leg);
        }
    }

    /// The end switch in the direction of travel is pressed.
    fn end_switch_ahead(&mut self, m: usize, dir: i32) -> bool {
        if dir < 0 {
            self.left_switch(m)
        } else {
            self.right_switch(m)
        }
    }

    fn rfs_leg_done(&mut self, m: usize, leg: Leg) {
        let x = self.x_actual_reg(m);
        let r = &mut self.st[m].rfs;
        if leg.until == Until::Met {
            r.last_switch_pos = x;
        }
        if leg.sw == Right && r.right_pos.is_none() {
            r.right_pos = Some(x);
        }
        if leg.point {
            r.points[r.n_points] = x;
            r.n_points += 1;
        }
        r.leg += 1;
        r.armed = false;
        if r.active() {
            self.rfs_drive(m);
            return;
        }
        // Stop at once; the centre of the two switching points becomes position 0.
        let zero = ((r.points[0] as i64 + r.points[1] as i64) / 2) as i32;
        if let Some(rp) = r.right_pos {
            r.distance = rp - zero;
        }
        self.wr_motor(m, reg::V_TARGET, 0);
        self.wr_motor(m, reg::V_ACTUAL, 0);
        self.set_reference(m, zero);
        self.write_ref_conf(m);
        let rm = self.positioning_rm(m);
        self.set_rm(m, rm);
        self.restore_v_max(m);
    }

    /// Makes chip position `zero` position 0, the axis at rest on its target.
    fn set_reference(&mut self, m: usize, zero: i32) {
        let x = self.x_actual_reg(m);
        let nx = (x - zero) as u32 & 0xff_ffff;
        match self.kind {
            ModuleType::Tmcm3110 => {
                self.wr_motor(m, reg::X_TARGET, nx);
                self.wr_motor(m, reg::X_ACTUAL, nx);
            }
            ModuleType::Tmcm1311 => {
                let raw = self.rd_motor(m, reg::X_ACTUAL);
                self.wr_motor(m, reg::X_TARGET, raw);
                self.set_position32(m, sext(nx, 24));
                self.st[m].target = sext(nx, 24);
                // The encoder is referenced with the position.
                self.reference_encoder(m, sext(nx, 24));
            }
        }
    }
}
