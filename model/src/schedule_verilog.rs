//! The frame schedule's time slots as a Verilog header (`rtl/tmc429_schedule.vh`), rendered
//! from the lanes of [`crate::schedule`] by `tmc429 regmap --format verilog-schedule`; the RTL
//! decodes its slots through these names, and a test keeps the file in the repository equal to
//! this rendering (docs/model-contract.md C41).
//!
//! Per slot, `TMC429_PH_<SLOT>(m)`: the phase of motor m's slot in the 32-cycle frame, a 5-bit
//! constant for a constant m (a genvar or a localparam).

use crate::regmap_verilog::define;
use crate::schedule::{PHASE_COMMIT, PHASE_PULSE, PHASE_RAMP, PHASE_SNAPSHOT, PHASE_STEPDIR};

/// The command that writes the header.
pub const REGENERATE: &str = "tmc429 regmap --format verilog-schedule > rtl/tmc429_schedule.vh";

/// The edges from a motor's target snapshot to its commit that the target-velocity unit's stages
/// take (`rtl/tmc429_vtarget.v`: snapshot, c, five multiply cycles; seven square-root cycles; the
/// clamp in the commit edge). Its stages are decoded from the snapshot phase, so every lane must
/// commit this many edges after its snapshot.
pub const VT_CYCLES: u32 = 14;

/// `((m) == 0 ? 5'dP0 : (m) == 1 ? 5'dP1 : 5'dP2)`.
fn per_motor(p: &[u32; 3]) -> String {
    format!("((m) == 0 ? 5'd{} : (m) == 1 ? 5'd{} : 5'd{})", p[0], p[1], p[2])
}

/// The header `rtl/tmc429_schedule.vh`.
pub fn header() -> String {
    let mut s = format!(
        "// TMC428/TMC429/TMC4210 frame schedule for the RTL: the phase (prescaler[4:0]) of each motor's\n\
         // slots in the 32-cycle frame (TMC428 §8.7, §8.13; TMC429 §8.1.7; docs/model-contract.md C41).\n\
         // Generated from model/src/schedule.rs; do not edit. Regenerate with\n\
         //   {REGENERATE}\n\
         `ifndef TMC429_SCHEDULE_VH\n`define TMC429_SCHEDULE_VH\n\n"
    );
    define(&mut s, "TMC429_PH_SNAPSHOT(m)", &per_motor(&PHASE_SNAPSHOT), "motor m's registers into the target-velocity unit");
    define(&mut s, "TMC429_PH_COMMIT(m)", &per_motor(&PHASE_COMMIT), "motor m's target velocity committed in this edge");
    define(&mut s, "TMC429_PH_RAMP(m)", &per_motor(&PHASE_RAMP), "motor m's ramp tick in a ramp frame");
    define(&mut s, "TMC429_PH_PULSE(m)", &per_motor(&PHASE_PULSE), "motor m's pulse tick in a pulse frame");
    define(&mut s, "TMC429_PH_STEPDIR(m)", &per_motor(&PHASE_STEPDIR), "motor m's Step/Dir slot (and 16 after it)");
    s += "\n`endif // TMC429_SCHEDULE_VH\n";
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::regmap_verilog::define_value as value;

    /// C41: motor m's target snapshot, commit, ramp tick and pulse tick at phases 7m, 7m + 14,
    /// 7m + 16, 7m + 17.
    #[test]
    fn names_carry_the_contract_phases() {
        let h = header();
        assert_eq!(value(&h, "TMC429_PH_SNAPSHOT(m)"), Some("((m) == 0 ? 5'd0 : (m) == 1 ? 5'd7 : 5'd14)"));
        assert_eq!(value(&h, "TMC429_PH_COMMIT(m)"), Some("((m) == 0 ? 5'd14 : (m) == 1 ? 5'd21 : 5'd28)"));
        assert_eq!(value(&h, "TMC429_PH_RAMP(m)"), Some("((m) == 0 ? 5'd16 : (m) == 1 ? 5'd23 : 5'd30)"));
        assert_eq!(value(&h, "TMC429_PH_PULSE(m)"), Some("((m) == 0 ? 5'd17 : (m) == 1 ? 5'd24 : 5'd31)"));
        assert_eq!(value(&h, "TMC429_PH_STEPDIR(m)"), Some("((m) == 0 ? 5'd19 : (m) == 1 ? 5'd26 : 5'd1)"));
    }

    /// The RTL's pipelines rest on the lanes' shape: every lane VT_CYCLES from its snapshot to
    /// its commit (the target-velocity unit's stages), and the ramp tick's operands,
    /// registered in the edge before the tick (`rtl/tmc429_accel.v`), take a target committed
    /// in an earlier edge; the ticks, formed in the edge before them from the frame's count of
    /// trailing ones registered one edge earlier (`rtl/tmc429_schedule.v`), fall at phase 2 or
    /// later, so that the count is the frame's.
    #[test]
    fn every_lane_has_the_same_shape() {
        for m in 0..3 {
            assert_eq!(PHASE_COMMIT[m] - PHASE_SNAPSHOT[m], VT_CYCLES, "motor {m}");
            assert!(PHASE_RAMP[m] >= PHASE_COMMIT[m] + 2, "motor {m}");
            assert!(PHASE_PULSE[m] < 32, "motor {m}");
            assert!(PHASE_RAMP[m] >= 2 && PHASE_PULSE[m] >= 2, "motor {m}");
        }
    }

    /// The Step/Dir unit's slots (the phase PHASE_STEPDIR[m] and 16 after it) are motor m's
    /// alone, and neither the edge before each, which reads the motor's backlog word, nor the
    /// edge after it, which adds the slot's change to the word, is a motor's slot: one backlog
    /// adder and one RAM port serve the three motors (`rtl/tmc429_stepdir.v`).
    #[test]
    fn the_step_dir_slots_are_apart() {
        assert_eq!(PHASE_STEPDIR, [19, 26, 1]);
        let half = |p: u32| p % 16;
        for m in 0..3 {
            for n in 0..3 {
                assert!(m == n || half(PHASE_STEPDIR[m]) != half(PHASE_STEPDIR[n]), "motors {m}, {n}");
                assert_ne!(half(PHASE_STEPDIR[m] + 15), half(PHASE_STEPDIR[n]), "motors {m}, {n}");
                assert_ne!(half(PHASE_STEPDIR[m] + 1), half(PHASE_STEPDIR[n]), "motors {m}, {n}");
                assert!(m == n || half(PHASE_STEPDIR[m] + 1) != half(PHASE_STEPDIR[n] + 1), "motors {m}, {n}");
            }
        }
    }
}
