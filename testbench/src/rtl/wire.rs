//! The lock-step pair's wire format (crate::pair): each edge's [`Expected`] as the words of
//! the layout below that changed since the edge before, so that the model side hands the RTL
//! side a few bytes per CLK cycle instead of the whole struct (docs/performance.md, "The
//! pair's wire format").
//!
//! An edge is a header word — word 0 of the layout (the inputs, the output pins, the status
//! byte and the power-down flag) with a mask in its low 16 bits of the other words that follow
//! — and then those words, in ascending order. Every field keeps its full width in its word,
//! so decoding gives back exactly the `Expected` that was encoded (tests/wire.rs).

use super::Expected;

/// Words of one edge's [`Expected`]; word 0 is the header.
const WORDS: usize = 14;

/// The header's low bits: bit k set = word k follows (k = 1..WORDS-1).
const MASK: u64 = 0xFFFF;

/// Declares the layout once and derives both directions from it: `(word, bit, kind, field)`,
/// where kind is `b` (bool, 1 bit), `u8`, `u16`, `u32`, `i32` (its 32 bits) or `u64`.
macro_rules! layout {
    ($( ($k:literal, $at:literal, $kind:ident, $($f:ident).+) )*) => {
        /// The words of `e` (the header's mask bits 0).
        #[inline]
        fn words(e: &Expected) -> [u64; WORDS] {
            let mut w = [0u64; WORDS];
            $( w[$k] |= layout!(@to $kind, e.$($f).+) << $at; )*
            w
        }

        /// Sets the fields of `e` that word `k` holds from `w`.
        #[inline]
        fn set_word(e: &mut Expected, k: usize, w: u64) {
            $( if k == $k { e.$($f).+ = layout!(@from $kind, w >> $at); } )*
        }
    };
    (@to b, $v:expr) => { $v as u64 };
    (@to u8, $v:expr) => { $v as u64 };
    (@to u16, $v:expr) => { $v as u64 };
    (@to u32, $v:expr) => { $v as u64 };
    (@to i32, $v:expr) => { $v as u32 as u64 };
    (@to u64, $v:expr) => { $v };
    (@from b, $w:expr) => { $w & 1 != 0 };
    (@from u8, $w:expr) => { $w as u8 };
    (@from u16, $w:expr) => { $w as u16 };
    (@from u32, $w:expr) => { $w as u32 };
    (@from i32, $w:expr) => { $w as u32 as i32 };
    (@from u64, $w:expr) => { $w };
}

// Word 0, the header, holds what changes with the pins; word 1 what changes every cycle; the
// motors' words what changes while they move.
layout! {
    (0, 16, b, inp.nscs_c) (0, 17, b, inp.sck_c) (0, 18, b, inp.sdi_c) (0, 19, b, inp.sdi_s)
    (0, 20, b, inp.ref1) (0, 21, b, inp.ref2) (0, 22, b, inp.ref3)
    (0, 23, b, inp.refr1) (0, 24, b, inp.refr2) (0, 25, b, inp.refr3)
    (0, 26, b, out.nint_sdo_c) (0, 27, b, out.sdoz_c) (0, 28, b, out.sdoz_c_oe)
    (0, 29, b, out.nscs_s) (0, 30, b, out.sck_s) (0, 31, b, out.sdo_s) (0, 32, b, out.sdi_s_o)
    (0, 33, b, out.sdi_s_oe) (0, 34, b, out.nscs2) (0, 35, b, out.nscs3) (0, 36, b, out.poscmp)
    (0, 40, u8, probes.power_down) (0, 48, u8, probes.status)
    (1, 0, u32, probes.prescaler) (1, 32, u8, probes.chain.state) (1, 40, u8, probes.chain.cell)
    (1, 48, u8, probes.chain.motor) (1, 56, u8, probes.chain.bit_count)
    (2, 0, u64, probes.chain.readback)
    (3, 0, u8, probes.chain.pending) (3, 8, u8, probes.chain.cover_waiting)
    (3, 16, u8, probes.m0.step) (3, 24, u8, probes.m0.dir) (3, 32, u16, probes.m0.pulse_acc)
    (4, 0, u32, probes.m0.x_actual) (4, 32, i32, probes.m0.v_internal)
    (5, 0, u32, probes.m0.x_target) (5, 32, i32, probes.m0.v_target)
    (6, 0, i32, probes.m0.a_actual) (6, 32, u32, probes.m0.ustep)
    (7, 0, u8, probes.m1.step) (7, 8, u8, probes.m1.dir) (7, 16, u16, probes.m1.pulse_acc)
    (7, 32, u8, probes.m2.step) (7, 40, u8, probes.m2.dir) (7, 48, u16, probes.m2.pulse_acc)
    (8, 0, u32, probes.m1.x_actual) (8, 32, i32, probes.m1.v_internal)
    (9, 0, u32, probes.m1.x_target) (9, 32, i32, probes.m1.v_target)
    (10, 0, i32, probes.m1.a_actual) (10, 32, u32, probes.m1.ustep)
    (11, 0, u32, probes.m2.x_actual) (11, 32, i32, probes.m2.v_internal)
    (12, 0, u32, probes.m2.x_target) (12, 32, i32, probes.m2.v_target)
    (13, 0, i32, probes.m2.a_actual) (13, 32, u32, probes.m2.ustep)
}

/// The model side: appends each edge's changed words to a batch.
pub struct Encoder {
    last: [u64; WORDS],
}

impl Encoder {
    /// Both sides start from [`Expected::default`]: every input low, every output and probe 0.
    pub fn new() -> Encoder {
        Encoder { last: words(&Expected::default()) }
    }

    /// Appends `e` to `out`: the header, then the words that differ from the edge before.
    #[inline]
    pub fn push(&mut self, e: &Expected, out: &mut Vec<u64>) {
        let w = words(e);
        let mut mask = 0u64;
        for (k, (now, last)) in w.iter().zip(&self.last).enumerate().skip(1) {
            mask |= ((now != last) as u64) << k;
        }
        out.push(w[0] | mask);
        let mut m = mask;
        while m != 0 {
            let k = m.trailing_zeros() as usize;
            out.push(w[k]);
            m &= m - 1;
        }
        self.last = w;
    }
}

impl Default for Encoder {
    fn default() -> Encoder {
        Encoder::new()
    }
}

/// The RTL side: the current edge's [`Expected`], brought up to date one edge at a time.
pub struct Decoder {
    e: Expected,
}

impl Decoder {
    pub fn new() -> Decoder {
        Decoder { e: Expected::default() }
    }

    /// Decodes the edge that starts at `batch[*at]` and moves `at` past it; `None` at the
    /// batch's end.
    #[inline]
    pub fn next(&mut self, batch: &[u64], at: &mut usize) -> Option<&Expected> {
        let head = *batch.get(*at)?;
        set_word(&mut self.e, 0, head);
        let mut i = *at + 1;
        let mut m = head & MASK;
        while m != 0 {
            let k = m.trailing_zeros() as usize;
            set_word(&mut self.e, k, batch[i]);
            i += 1;
            m &= m - 1;
        }
        *at = i;
        Some(&self.e)
    }
}

impl Default for Decoder {
    fn default() -> Decoder {
        Decoder::new()
    }
}
