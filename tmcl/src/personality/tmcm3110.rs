//! The TMCM-3110 personality: three axes on one TMC429, parameters in the chip's own units
//! (velocities −2047..2047, accelerations 1..2047, 24-bit positions; TMC429 §8.1.13).

use super::Access::*;
use super::{live, setting, Param, KEPT_DRIVER};

const P24: (i64, i64) = (-(1 << 23), (1 << 23) - 1);
const UNITS: Option<&str> = Some("TMC429 units −2047..2047, not pps (R = fCLK·v/2^(pulse_div+16) steps/s)");

/// Axis parameters.
pub const AXIS: &[Param] = &[
    live(0, "target position", RW, P24.0, P24.1, Some("24 bits (TMC429 x_target), not 32")),
    live(1, "actual position", RW, P24.0, P24.1, Some("24 bits (TMC429 x_actual); at rest in a positioning mode the target follows")),
    live(2, "target speed", RW, -2047, 2047, UNITS),
    live(3, "actual speed", RW, -2047, 2047, UNITS),
    setting(4, "maximum positioning speed", RWE, 0, 2047, 1000, Some("TMC429 v_max 0..2047, not pps")),
    setting(5, "maximum acceleration", RWE, 1, 2047, 1000, Some("TMC429 a_max 1..2047, not pps²; pmul/pdiv recomputed")),
    setting(6, "absolute max. current", RWE, 0, 255, 128, KEPT_DRIVER),
    setting(7, "standby current", RWE, 0, 255, 8, KEPT_DRIVER),
    live(8, "target position reached", R, 0, 1, None),
    live(9, "reference (home) switch", R, 0, 1, Some("the axis's home switch (--home-switch), not IN1")),
    live(10, "right limit switch", R, 0, 1, None),
    live(11, "left limit switch", R, 0, 1, None),
    setting(12, "right limit switch disable", RWE, 0, 1, 0, None),
    setting(13, "left limit switch disable", RWE, 0, 1, 0, None),
    setting(130, "minimum speed", RWE, 0, 2047, 1, Some("TMC429 v_min 0..2047, not pps")),
    live(135, "actual acceleration", R, 0, 0, Some("another meaning: actual acceleration (TMC429 a_actual)")),
    setting(138, "ramp mode", RWE, 0, 2, 0, Some("another meaning: ramp mode (0 position, 1 soft, 2 velocity); the manual has it at 128")),
    setting(140, "microstep resolution", RWE, 0, 8, 8, KEPT_DRIVER),
    setting(141, "reference switch tolerance", RWE, 0, 4095, 0, Some("another meaning: TMC429 dx_ref_tolerance")),
    setting(149, "soft stop flag", RWE, 0, 1, 0, Some("not in the manual: TMC429 SOFT_STOP")),
    setting(153, "ramp divisor", RWE, 0, 13, 7, Some("another meaning: TMC429 ramp_div (pmul/pdiv recomputed)")),
    setting(154, "pulse divisor", RWE, 0, 13, 3, Some("another meaning: TMC429 pulse_div (pmul/pdiv recomputed)")),
    setting(193, "reference search mode", RWE, 1, 136, 1, None),
    setting(194, "reference search speed", RWE, 0, 2047, 500, Some("TMC429 units 0..2047, not pps")),
    setting(195, "reference switch speed", RWE, 0, 2047, 100, Some("TMC429 units 0..2047, not pps")),
    live(196, "distance between end switches", R, 0, 0, None),
    live(197, "last reference switch position", R, 0, 0, Some("not in the manual: where the search last met the switch")),
    setting(200, "boost current", RWE, 0, 255, 0, KEPT_DRIVER),
    setting(204, "freewheeling delay [ms]", RWE, 0, 65535, 0, KEPT_DRIVER),
    setting(214, "power down delay [10 ms]", RWE, 1, 65535, 200, KEPT_DRIVER),
];

/// Why a manual axis parameter is not available on this module.
pub fn axis_absent(no: u8) -> &'static str {
    match no {
        25..=29 => "I²t monitoring of the TMCM-1311 (no motor current model)",
        128 => "the TMCM-3110 has its ramp mode at 138",
        150..=152 | 155 | 206 | 208 => "driver-stage reading (no driver stage modelled)",
        162..=183 => "TMC262 driver setting (chopper, stallGuard2, coolStep): no driver stage modelled",
        198 | 201 | 202 | 207 | 209 | 210 | 212 => "encoder function of the TMCM-1311 (no encoder on this module)",
        254 => "Step/Dir input mode of the TMCM-1311 (no Step/Dir input)",
        14..=20 | 108 | 109 | 112..=134 | 136 | 137 | 230 | 233 | 236 | 237 => {
            "closed-loop function of the TMCM-1311 (no encoder feedback on this module)"
        }
        _ => "not an axis parameter of the TMCM-3110",
    }
}

/// Bank-0 global parameters.
pub const GLOBAL: &[Param] = &[
    setting(64, "EEPROM magic", RWE, 0, 255, crate::config::EEPROM_MAGIC, None),
    setting(65, "RS485 baud rate", RWE, 0, 11, 0, Some("kept, no effect on TCP or a pseudo-terminal")),
    setting(66, "serial address", RWE, 0, 255, 1, None),
    setting(67, "ASCII mode", RWE, 0, 0x31, 0, None),
    setting(68, "serial heartbeat [ms]", RWE, 0, i32::MAX as i64, 0, None),
    setting(73, "configuration EEPROM lock flag", RWE, 0, 1, 0, None),
    setting(75, "telegram pause time", RWE, 0, 255, 0, Some("kept, no effect on TCP or a pseudo-terminal")),
    setting(76, "serial host address", RWE, 0, 255, 2, None),
    setting(77, "auto start mode", RWE, 0, 1, 0, None),
    setting(79, "end switch polarity", RWE, 0, 1, 0, Some("inverts all end switches (TMC429 inv_ref)")),
    setting(81, "TMCL code protection", RWE, 0, 3, 0, None),
    setting(84, "coordinate storage", RWE, 0, 1, 0, None),
    setting(85, "do not restore user variables", RWE, 0, 1, 0, None),
    live(128, "TMCL application status", R, 0, 3, None),
    live(129, "download mode", R, 0, 1, None),
    live(130, "TMCL program counter", R, 0, 0, None),
    live(132, "tick timer [ms]", RW, i32::MIN as i64, i32::MAX as i64, None),
    live(133, "random number", R, 0, 0, None),
];

/// Why a manual bank-0 parameter is not available on this module.
pub fn global_absent(no: u8) -> &'static str {
    match no {
        88 => "interface selection of the TMCM-1311 (host links are TCP and a pseudo-terminal)",
        _ => "no CAN interface modelled",
    }
}

/// Interrupt numbers: timers 0..2, target reached 3..5 (axes 0..2), stop switches 27..32
/// (left, right of axes 0..2), input changes 39..46, global 255.
pub const INTERRUPTS: &[u8] = &[0, 1, 2, 3, 4, 5, 27, 28, 29, 30, 31, 32, 39, 40, 41, 42, 43, 44, 45, 46, 255];
