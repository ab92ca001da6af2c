//! The module's I/O (inputs, pull-ups, outputs, analog channels, supply) and the world around
//! the axes (end and home switches along each axis). Both are set from the command line or,
//! in tests, directly.

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
    /// Raw value of analog channel `ch` (AIN0: 0, AIN4: 4; 0..4095), 0 for other channels.
    pub fn analog(&self, ch: usize) -> u16 {
        match ch {
            0 => self.analog[0],
            4 => self.analog[1],
            _ => 0,
        }
    }
}

/// A stretch of an axis: positions `from..=to`.
pub type Span = (i32, i32);

/// Where the switches sit along each axis, and manual overrides. A switch is pressed while the
/// axis's mechanical position lies in its span: an end switch given by one position
/// (`--left-switch 0=-3000`) reaches to the end of travel, one given by two
/// (`--left-switch 0=-3500:-3000`) can be driven through (a cam or a light barrier).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct World {
    pub left: [Option<Span>; AXES],
    pub right: [Option<Span>; AXES],
    pub home: [Option<Span>; AXES],
    /// Forced switch states (OR-ed with the geometry).
    pub left_forced: [bool; AXES],
    pub right_forced: [bool; AXES],
    pub home_forced: [bool; AXES],
}

fn inside(s: Option<Span>, x: i32) -> bool {
    s.is_some_and(|(a, b)| x >= a && x <= b)
}

impl World {
    /// A left end switch pressed at and below `pos`.
    pub fn left_end(pos: i32) -> Span {
        (i32::MIN, pos)
    }
    /// A right end switch pressed at and above `pos`.
    pub fn right_end(pos: i32) -> Span {
        (pos, i32::MAX)
    }
    pub fn left(&self, m: usize, x: i32) -> bool {
        self.left_forced[m] || inside(self.left[m], x)
    }
    pub fn right(&self, m: usize, x: i32) -> bool {
        self.right_forced[m] || inside(self.right[m], x)
    }
    pub fn home(&self, m: usize, x: i32) -> bool {
        self.home_forced[m] || inside(self.home[m], x)
    }
    /// Whether axis `m` has a home switch.
    pub fn has_home(&self, m: usize) -> bool {
        self.home_forced[m] || self.home[m].is_some()
    }
}
