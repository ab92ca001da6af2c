//! Input synchronizers (contract C4): two flops per asynchronous input plus a history flop
//! for edge detection.

use crate::Inputs;

/// Bit positions of the synchronized inputs in a [`SyncBank`] word.
pub mod bit {
    pub const NSCS_C: u32 = 0;
    pub const SCK_C: u32 = 1;
    pub const SDI_C: u32 = 2;
    pub const SDI_S: u32 = 3;
    pub const REF1: u32 = 4;
    pub const REF2: u32 = 5;
    pub const REF3: u32 = 6;
    pub const REFR1: u32 = 7;
    pub const REFR2: u32 = 8;
    pub const REFR3: u32 = 9;
}

/// Packs the input pins into one word, bit positions as in [`bit`].
#[inline]
pub fn pack(inp: &Inputs) -> u16 {
    (inp.nscs_c as u16)
        | (inp.sck_c as u16) << 1
        | (inp.sdi_c as u16) << 2
        | (inp.sdi_s as u16) << 3
        | (inp.ref1 as u16) << 4
        | (inp.ref2 as u16) << 5
        | (inp.ref3 as u16) << 6
        | (inp.refr1 as u16) << 7
        | (inp.refr2 as u16) << 8
        | (inp.refr3 as u16) << 9
}

/// Three flop stages for all inputs: `s1` first synchronizer flop, `s2` synchronized value,
/// `s3` the previous synchronized value (history).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SyncBank {
    pub s1: u16,
    pub s2: u16,
    pub s3: u16,
}

impl SyncBank {
    /// Reset value: the idle levels of [`Inputs::default`], so reset raises no edge.
    pub fn reset() -> Self {
        let idle = pack(&Inputs::default());
        SyncBank { s1: idle, s2: idle, s3: idle }
    }

    /// One CLK edge.
    #[inline]
    pub fn shift(&mut self, pins: u16) {
        self.s3 = self.s2;
        self.s2 = self.s1;
        self.s1 = pins;
    }

    /// Synchronized level of an input.
    #[inline]
    pub fn level(&self, b: u32) -> bool {
        (self.s2 >> b) & 1 != 0
    }
    #[inline]
    pub fn rose(&self, b: u32) -> bool {
        (self.s2 & !self.s3) >> b & 1 != 0
    }
    #[inline]
    pub fn fell(&self, b: u32) -> bool {
        (!self.s2 & self.s3) >> b & 1 != 0
    }
    /// True when all three stages agree (no edge in flight).
    #[inline]
    pub fn settled(&self) -> bool {
        self.s1 == self.s2 && self.s2 == self.s3
    }
}
