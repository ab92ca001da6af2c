//! The module's I/O as a TMCM-3110 has them, and the virtual world around the axes
//! (end and home switches along each axis). Both are set from the test side.

use crate::config::AXES;

/// Digital inputs IN0..IN7 (IN0 and IN4 are also the analog inputs AIN0 and AIN4), pull-ups,
/// digital outputs OUT0..OUT7 and the analog channels.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Io {
    /// Level driven onto each input from outside; `None` = open (reads its pull-up).
    pub driven: [Option<bool>; 8],
    /// Pull-up enable per input (SIO n, 0, v). Factory default: all on.
    pub pullups: u8,
    /// Output latches OUT0..OUT7.
    pub outputs: u8,
    /// AIN0 and AIN4 raw values 0..4095.
    pub analog: [u16; 2],
    /// Supply voltage in 1/10 V (GIO 8, 1).
    pub supply_dv: u16,
}

impl Default for Io {
    fn default() -> Self {
        Io { driven: [None; 8], pullups: 0xff, outputs: 0, analog: [0; 2], supply_dv: 240 }
    }
}

impl Io {
    /// Logical level of digital input `n`.
    pub fn input(&self, n: usize) -> bool {
        match self.driven.get(n) {
            Some(Some(l)) => *l,
            Some(None) => self.pullups & (1 << n) != 0,
            None => false,
        }
    }
    pub fn inputs(&self) -> u8 {
        (0..8).fold(0u8, |m, n| m | ((self.input(n) as u8) << n))
    }
    /// Analog reading of a digital input driven high: full scale; low or open without pull-up: 0.
    pub fn analog(&self, ch: usize) -> u16 {
        match ch {
            0 => self.analog[0],
            4 => self.analog[1],
            _ => 0,
        }
    }
}

/// Where the switches sit along each axis, and manual overrides.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct World {
    /// Left end switch is active while position <= this.
    pub left_at: [Option<i32>; AXES],
    /// Right end switch is active while position >= this.
    pub right_at: [Option<i32>; AXES],
    /// Home switch is active while position lies in this window (inclusive).
    pub home_window: [Option<(i32, i32)>; AXES],
    /// Forced switch states (OR-ed with the geometry).
    pub left_forced: [bool; AXES],
    pub right_forced: [bool; AXES],
    pub home_forced: [bool; AXES],
}

impl World {
    pub fn left(&self, m: usize, x: i32) -> bool {
        self.left_forced[m] || self.left_at[m].is_some_and(|l| x <= l)
    }
    pub fn right(&self, m: usize, x: i32) -> bool {
        self.right_forced[m] || self.right_at[m].is_some_and(|r| x >= r)
    }
    pub fn home(&self, m: usize, x: i32) -> bool {
        self.home_forced[m] || self.home_window[m].is_some_and(|(a, b)| x >= a && x <= b)
    }
}
