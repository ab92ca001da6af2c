//! Current scaling: selection of is_agtat / is_aleat / is_v0 (TMC428 §8.9 Table 8-2,
//! TMC429 §8.1.9) with the is_v0 delay of 255 ramp ticks at rest (contract C75–C77).
//! The DAC values are scaled by [`crate::microstep::scale`] (Table 8-1).

use crate::motor_regs::Motor;

/// Which scale factor is selected.
pub const SEL_ALEAT: u8 = 0;
pub const SEL_AGTAT: u8 = 1;
pub const SEL_V0: u8 = 2;

/// Ramp ticks at rest before is_v0 is selected (TMC428 §8.9: t = 255·32·2^ramp_div / fCLK).
pub const V0_DELAY_TICKS: u8 = 255;

/// Per-motor state of the current-scale selector.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CurrentScale {
    /// Ramp ticks counted with V = 0 (saturates at 255; cleared in every cycle with V ≠ 0).
    pub v0_count: u8,
    /// Selected factor: [`SEL_ALEAT`], [`SEL_AGTAT`] or [`SEL_V0`].
    pub sel: u8,
}

impl CurrentScale {
    /// The motor's ramp tick (contract C40), from the motor's old state (C75, C77): moving
    /// (V ≠ 0) selects is_agtat or is_aleat by |a_actual| against a_threshold and clears the
    /// counter; at rest the counter counts ramp ticks and from the 255th on selects is_v0 if
    /// is_agtat and is_aleat are both > 0 (TMC429 §8.1.9 footnote *2), else is_aleat. Between
    /// ramp ticks the selection holds (the current scale is a function of the ramp clock).
    #[inline]
    pub fn ramp_tick(&mut self, m: &Motor) {
        if m.v != 0 {
            self.v0_count = 0;
            // Table 8-2: a_threshold > 1023 always selects is_aleat.
            let agt = m.a_threshold <= 1023 && m.a_actual.unsigned_abs() > m.a_threshold as u32;
            self.sel = if agt { SEL_AGTAT } else { SEL_ALEAT };
        } else {
            if self.v0_count < V0_DELAY_TICKS {
                self.v0_count += 1;
            }
            if self.v0_count == V0_DELAY_TICKS {
                // "For selection of current scaling IS_V0 (at rest) IS_AGTAT and IS_ALEAT must
                // be larger than 0" (TMC429 §8.1.9 *2): otherwise the nominal current is_aleat.
                self.sel = Self::rest_selection(m);
            }
            // During the delay the previous selection is kept (C75).
        }
    }

    /// The selection at rest once the delay is over: is_v0 if is_agtat and is_aleat are both
    /// > 0 (TMC429 §8.1.9 footnote *2), else is_aleat (C75).
    #[inline]
    pub fn rest_selection(m: &Motor) -> u8 {
        if m.is_agtat != 0 && m.is_aleat != 0 {
            SEL_V0
        } else {
            SEL_ALEAT
        }
    }

    /// A ramp tick of the motor would change nothing: at rest, the delay over and the rest
    /// selection in place (the fast path of `Tmc429::tick` skips such ticks).
    #[inline]
    pub fn tick_changes_nothing(&self, m: &Motor) -> bool {
        m.v == 0 && self.v0_count == V0_DELAY_TICKS && self.sel == Self::rest_selection(m)
    }

    /// i_scale of the motor's registers for the current selection.
    #[inline]
    pub fn i_scale(&self, m: &Motor) -> u8 {
        match self.sel {
            SEL_AGTAT => m.is_agtat,
            SEL_V0 => m.is_v0,
            _ => m.is_aleat,
        }
    }
}
