//! What the datasheets state without publishing how (contract: known differences and the
//! choices that fill them): the model's documented behaviour, asserted, so that it cannot
//! change unnoticed. C25 (A_ACTUAL smoothing), C54 (the internal microstep of a PULSE_DIV change).

mod common;
use common::*;

use tmc429_model::Chip;

/// C25, known difference: TMC429 §8.1.8 calls A_ACTUAL "smoothed to avoid oscillations of the
/// readout value" and "updated with each clock" without publishing the filter; the model reads
/// the unfiltered velocity change of the last ramp tick (1/256 units): +a_max while
/// accelerating, 0 at the target velocity, −a_max while decelerating. Writes are ignored.
#[test]
fn a_actual_is_the_velocity_change_of_the_last_ramp_tick() {
    let mut h = host(Chip::Tmc429);
    // VELOCITY_MODE, ramp_div 0 (a ramp tick every 32 CLK), a_max 100, v_max 2047.
    motion_setup(&mut h, 0, 0, 0, 0, 2047, 100, 0, 2);
    wr(&mut h, 0, V_TARGET, 100); // T = 25600: 256 ramp ticks of +100
    h.wait(1000);
    assert_eq!(rd(&mut h, 0, A_ACTUAL), 100, "accelerating");
    wr(&mut h, 0, A_ACTUAL, 0x7FF);
    assert_eq!(rd(&mut h, 0, A_ACTUAL), 100, "read-only");
    h.wait(10_000);
    assert_eq!(rd(&mut h, 0, V_ACTUAL), 100);
    assert_eq!(rd(&mut h, 0, A_ACTUAL), 0, "at the target velocity");
    wr(&mut h, 0, V_TARGET, 0);
    h.wait(1000);
    assert_eq!(s12(rd(&mut h, 0, A_ACTUAL)), -100, "decelerating");
}

/// C54, known difference: TMC429 §8.1.13.2 "Changing PULSE_DIV in velocity_mode or in
/// hold_mode might force an internal microstep ... depending on the actual microstep position
/// ... In ramp_mode this does not occur." The condition is not published: in every mode the
/// model makes no step when pulse_div changes (x_actual, the microstep index and the pulse
/// accumulator keep their values).
#[test]
fn pulse_div_change_makes_no_step() {
    for rm in [0u32, 2, 3] {
        for w in [0u32, 17, 64, 131, 255] {
            let mut h = host(Chip::Tmc429);
            wr(&mut h, 0, REF_CONF_RM, rm);
            wr(&mut h, 0, USTEP_COUNT, w);
            for (pd, usrs) in [(5u32, 6u32), (13, 4), (0, 6), (9, 2), (15, 0)] {
                wr(&mut h, 0, CLK_CONFIG, pd << 12 | usrs);
                h.wait(40_000);
                assert_eq!(rd(&mut h, 0, X_ACTUAL), 0, "rm {rm} w {w} pulse_div {pd}");
                assert_eq!(rd(&mut h, 0, USTEP_COUNT), w, "rm {rm} w {w} pulse_div {pd}");
                assert_eq!(h.chip().motor(0).acc, 0);
            }
        }
    }
}
