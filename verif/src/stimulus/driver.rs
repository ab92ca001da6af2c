//! The virtual µC's pin driver: a transaction becomes SPI pin levels, edge by edge (frame
//! setup, SCK_C low and high halves, the gap with nSCS_C high), or idle cycles.

use tmc429_model::Inputs;

use super::{Frame, Txn};

/// Where the driver is inside a transaction.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Phase {
    /// Between transactions or in a pin change or idle time.
    Idle,
    /// nSCS_C low before the first SCK_C edge.
    Setup,
    /// SCK_C low for bit `n`.
    Low(u8),
    /// SCK_C high for bit `n` (the µC samples SDO_C when entering this phase).
    High(u8),
    Hold,
    Gap,
}

/// Turns transactions into pin levels, one [`Inputs`] per CLK cycle.
pub struct Driver {
    pub inputs: Inputs,
    phase: Phase,
    left: u32,
    frame: Option<Frame>,
}

/// What happened in the cycle just driven.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Event {
    None,
    /// SCK_C rises now for bit `n`: sample SDO_C (the level before this edge).
    Sample(u8),
    /// The frame's nSCS_C rises now.
    FrameEnd(Frame),
}

impl Default for Driver {
    fn default() -> Self {
        Driver { inputs: Inputs::default(), phase: Phase::Idle, left: 0, frame: None }
    }
}

impl Driver {
    /// True when the current transaction is finished and a new one can start.
    pub fn ready(&self) -> bool {
        self.left == 0 && matches!(self.phase, Phase::Idle | Phase::Gap)
    }

    pub fn phase(&self) -> Phase {
        self.phase
    }

    pub fn frame(&self) -> Option<&Frame> {
        self.frame.as_ref()
    }

    /// Starts a transaction (call only when [`Driver::ready`]).
    pub fn start(&mut self, t: Txn) {
        match t {
            Txn::Frame(f) => {
                self.frame = Some(f);
                self.phase = Phase::Setup;
                self.left = f.setup.max(1);
                self.inputs.nscs_c = false;
                self.inputs.sck_c = true;
            }
            Txn::Pins { levels, hold } => {
                self.phase = Phase::Idle;
                self.left = hold.max(1);
                let i = &mut self.inputs;
                i.ref1 = levels.ref_[0];
                i.ref2 = levels.ref_[1];
                i.ref3 = levels.ref_[2];
                i.refr1 = levels.refr[0];
                i.refr2 = levels.refr[1];
                i.refr3 = levels.refr[2];
                i.sdi_s = levels.sdi_s;
            }
            Txn::Idle(n) => {
                self.phase = Phase::Idle;
                self.left = n.max(1);
            }
        }
    }

    /// Advances one cycle; returns the inputs for this cycle and what happened.
    #[inline]
    pub fn step(&mut self) -> (Inputs, Event) {
        let mut ev = Event::None;
        if self.left == 0 {
            // phase over: move on
            if let Some(f) = self.frame {
                match self.phase {
                    Phase::Setup => self.enter_low(&f, 0),
                    Phase::Low(n) => {
                        self.phase = Phase::High(n);
                        self.left = f.half;
                        self.inputs.sck_c = true;
                        ev = Event::Sample(n);
                    }
                    Phase::High(n) => {
                        if (n as u32 + 1) < f.nbits as u32 {
                            self.enter_low(&f, n + 1);
                        } else {
                            self.phase = Phase::Hold;
                            self.left = f.hold.max(1);
                        }
                    }
                    Phase::Hold => {
                        self.phase = Phase::Gap;
                        self.left = f.gap.max(1);
                        self.inputs.nscs_c = true;
                        ev = Event::FrameEnd(f);
                    }
                    Phase::Gap | Phase::Idle => {
                        self.frame = None;
                        self.phase = Phase::Idle;
                    }
                }
            } else {
                self.phase = Phase::Idle;
            }
        }
        self.left = self.left.saturating_sub(1);
        (self.inputs, ev)
    }

    fn enter_low(&mut self, f: &Frame, n: u8) {
        self.phase = Phase::Low(n);
        self.left = f.half;
        self.inputs.sck_c = false;
        self.inputs.sdi_c = f.bit(n as u32);
    }
}
