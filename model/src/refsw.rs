//! Reference switch mapping (`rtl/tmc429_refsw.v`, the same unit; TMC428 §9.6, Table 9-3;
//! TMC429 §8.2.4.5; contract C60).

use crate::regmap::f;
use crate::sync::bit;
use crate::{Chip, Global};

/// Left and right switch levels (bit m = motor m, 1 = active) from the synchronized pins
/// `pins` (a [`crate::sync::SyncBank`] word) and the configuration.
#[inline]
pub fn levels(chip: Chip, g: &Global, pins: u16) -> (u8, u8) {
    let inv = chip != Chip::Tmc428 && g.ifc(f::INV_REF);
    let pin = |b: u32| ((pins >> b) & 1 != 0) ^ inv;
    let (ref1, ref2, ref3) = (pin(bit::REF1), pin(bit::REF2), pin(bit::REF3));
    let mot1r = g.g(f::MOT1R) != 0;
    if chip == Chip::Tmc4210 {
        // REF_L = REF1 (l1), GP_IN = REF2 (read as l2), REF_R = REF3 with mot1r (TMC4210 §1.5.4).
        let l = ref1 as u8 | (ref2 as u8) << 1;
        let r = (ref3 && mot1r) as u8;
        return (l, r);
    }
    if g.g(f::REFMUX) != 0 {
        // Sampled through the 74HC157 while datagrams are sent (driver chain).
        let mut l = 0;
        let mut r = 0;
        for m in 0..3 {
            r |= ((g.mux_switches >> (2 * m)) & 1) << m;
            l |= ((g.mux_switches >> (2 * m + 1)) & 1) << m;
        }
        return (l, r);
    }
    let l;
    let mut r = 0u8;
    if mot1r {
        l = ref1 as u8 | (ref2 as u8) << 1;
        r = ref3 as u8;
    } else {
        l = ref1 as u8 | (ref2 as u8) << 1 | (ref3 as u8) << 2;
    }
    if chip == Chip::Tmc429 && !mot1r && g.ifc(f::EN_REFR) {
        r = pin(bit::REFR1) as u8 | (pin(bit::REFR2) as u8) << 1 | (pin(bit::REFR3) as u8) << 2;
    }
    (l, r)
}
