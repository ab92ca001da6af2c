//! The TMCM-1311 personality ([TMCL] §6, §7, §8, §10): one axis in open loop with the manual's
//! units — velocities in microsteps per second (pps), accelerations in pps², 32-bit
//! positions — on top of the TMC429 (`crate::units` picks its dividers). The motor is ideal: it
//! follows the microsteps, and an encoder reads that position at the configured resolution.
//! Closed-loop control, stallGuard2 and coolStep need a motor model this module does not have:
//! the values that would enable them answer status 4, their other settings are kept.

use super::Access::*;
use super::{live, setting, Param, I32, KEPT_DRIVER};

const PPS: (i64, i64) = (0, 327_679_999);
const SPEED: (i64, i64) = (-327_678_000, 327_679_999);
const QUANT: Option<&str> = Some("quantised to the TMC429's velocity step; at most fCLK·2047/2^16 pps (499 755 at 16 MHz)");
const KEPT_CL: Option<&str> = Some("kept, no effect: closed loop is not modelled");

/// Axis parameters of axis 0.
pub const AXIS: &[Param] = &[
    live(0, "target position", RW, I32.0, I32.1, Some("one move covers at most ±8 388 607 µsteps (TMC429 position range)")),
    live(1, "actual position", RW, I32.0, I32.1, None),
    live(2, "target speed", RW, SPEED.0, SPEED.1, QUANT),
    live(3, "actual speed", RW, SPEED.0, SPEED.1, QUANT),
    setting(4, "maximum positioning speed", RWE, PPS.0, PPS.1, 51200, QUANT),
    setting(
        5,
        "maximum acceleration",
        RWE,
        1,
        24_999_998,
        51200,
        Some("quantised to the TMC429's a_max; a value the TMC429 cannot pair with the speeds answers 4"),
    ),
    setting(6, "absolute max. current", RWE, 0, 255, 128, KEPT_DRIVER),
    setting(7, "standby current", RWE, 0, 255, 8, KEPT_DRIVER),
    live(8, "target position reached", R, 0, 1, None),
    live(9, "reference switch status", R, 0, 1, None),
    live(10, "right limit switch status", R, 0, 1, None),
    live(11, "left limit switch status", R, 0, 1, None),
    setting(12, "right limit switch disable", RWE, 0, 1, 0, None),
    setting(13, "left limit switch disable", RWE, 0, 1, 0, None),
    live(
        14,
        "CL torque mode target current",
        RW,
        -3000,
        3000,
        Some("reads 0 (the ideal motor has no advance angle); a write would start torque mode: 4"),
    ),
    live(15, "maximum possible current", R, 0, 3000, None),
    live(16, "CL velocity reached", R, 0, 1, None),
    setting(17, "CL velocity reached window", RW, 0, 268_435_454, 0, None),
    live(18, "status word", R, 0, 0x3fff, Some("bits 2, 5 and 9..13 stay 0 (open loop, no driver stage)")),
    live(19, "CL torque mode actual current", RW, -3000, 3000, Some("reads 0; a write (torque mode) answers 4")),
    setting(20, "CL torque mode slope", RW, I32.0, I32.1, 0, KEPT_CL),
    setting(108, "CL field weakening minimum velocity", RW, PPS.0, PPS.1, 0, KEPT_CL),
    setting(109, "CL field weakening maximum velocity", RW, PPS.0, PPS.1, 0, KEPT_CL),
    setting(112, "CL encoder offset", RWE, I32.0, I32.1, 0, KEPT_CL),
    setting(113, "CL current scale minimum", RW, 0, 255, 15, KEPT_CL),
    setting(114, "CL current scale maximum", RW, 0, 255, 255, KEPT_CL),
    setting(115, "CL current scale input select", RW, 0, 1, 1, KEPT_CL),
    setting(116, "CL current scale lower error limit", RW, 0, I32.1, 0, KEPT_CL),
    setting(117, "CL current scale upper error limit", RW, 0, I32.1, 255, KEPT_CL),
    setting(118, "CL current scale increment value", RW, 0, 255, 1, KEPT_CL),
    setting(119, "CL current scale decrement value", RW, 0, 255, 1, KEPT_CL),
    setting(120, "CL current scale increment timeout", RW, 0, I32.1, 1, KEPT_CL),
    setting(121, "CL current scale decrement timeout", RW, 0, I32.1, 1, KEPT_CL),
    setting(122, "CL current scale enable", RW, 0, 1, 1, KEPT_CL),
    setting(124, "CL correction velocity proportional factor", RW, 0, 65535, 0, KEPT_CL),
    setting(125, "CL max. following error", RW, 0, 268_435_454, 0, KEPT_CL),
    setting(126, "CL max. correction velocity", RW, PPS.0, PPS.1, 0, KEPT_CL),
    setting(127, "relative positioning option", RW, 0, 2, 0, None),
    live(128, "ramp mode", RW, 0, 2, Some("2 (torque mode, closed loop only) answers 4")),
    live(129, "closed loop operation", RW, 0, 1, Some("open loop only: 1 answers 4")),
    setting(130, "start/stop velocity", RWE, PPS.0, PPS.1, 0, Some("TMC429 v_min, at least one velocity step; quantised")),
    live(131, "measured speed", R, 0, 0, None),
    live(132, "encoder initialization", RW, 0, 1, Some("reads 0; 1 (closed-loop set-up) answers 4")),
    live(133, "CL init flag", R, 0, 1, None),
    setting(134, "CL position reached window", RW, 0, 255, 50, KEPT_CL),
    setting(135, "CL position reached time", RW, 0, 131_072, 100, KEPT_CL),
    setting(136, "CL standstill position error gain", RW, 10, 50, 10, KEPT_CL),
    setting(137, "CL standstill position error dampening factor", RW, 0, 65535, 0, KEPT_CL),
    setting(138, "CL standstill position error limit", RW, 0, 268_435_454, 255, KEPT_CL),
    setting(140, "microstep resolution", RWE, 0, 8, 8, Some("sets the encoder's scale (no driver stage)")),
    setting(141, "CL torque mode start/stop current", RW, 0, 3000, 0, KEPT_CL),
    live(153, "supply voltage", R, 0, 0, None),
    setting(162, "chopper blank time", RW, 0, 3, 2, KEPT_DRIVER),
    setting(163, "chopper mode", RW, 0, 1, 0, KEPT_DRIVER),
    setting(164, "chopper hysteresis decrement", RW, 0, 3, 0, KEPT_DRIVER),
    setting(165, "chopper hysteresis end", RW, -3, 12, 0, KEPT_DRIVER),
    setting(166, "chopper hysteresis start", RW, 0, 8, 0, KEPT_DRIVER),
    setting(167, "chopper off time", RW, 0, 15, 5, KEPT_DRIVER),
    setting(168, "smartEnergy current minimum (SEIMIN)", RW, 0, 1, 0, KEPT_DRIVER),
    setting(169, "smartEnergy current down step", RW, 0, 3, 0, KEPT_DRIVER),
    setting(170, "smartEnergy hysteresis", RW, 0, 15, 0, KEPT_DRIVER),
    setting(171, "smartEnergy current up step", RW, 1, 3, 1, KEPT_DRIVER),
    setting(172, "smartEnergy hysteresis start", RW, 0, 15, 0, Some("0 only: another value would enable coolStep (4)")),
    setting(173, "stallGuard2 filter enable", RW, 0, 1, 0, KEPT_DRIVER),
    setting(174, "stallGuard2 threshold", RW, -64, 63, 0, KEPT_DRIVER),
    setting(175, "slope control high side", RW, 0, 3, 2, KEPT_DRIVER),
    setting(176, "slope control low side", RW, 0, 3, 2, KEPT_DRIVER),
    setting(177, "short protection disable", RW, 0, 1, 0, KEPT_DRIVER),
    setting(178, "short detection timer", RW, 0, 3, 0, KEPT_DRIVER),
    setting(179, "Vsense", RW, 0, 1, 0, Some("kept; scales parameter 15")),
    setting(181, "stop on stall", RW, PPS.0, PPS.1, 0, Some("0 only: a speed would enable the stallGuard2 stop (4)")),
    setting(182, "smartEnergy threshold speed", RW, PPS.0, PPS.1, 0, KEPT_DRIVER),
    setting(183, "smartEnergy slow run current", RW, 0, 255, 0, KEPT_DRIVER),
    setting(193, "reference search mode", RWE, 1, 136, 1, None),
    setting(194, "referencing search speed", RWE, PPS.0, PPS.1, 25600, QUANT),
    setting(195, "referencing switch speed", RWE, PPS.0, PPS.1, 5120, QUANT),
    live(196, "end switch distance", R, 0, 0, None),
    live(198, "clear on null", RW, 0, 1, None),
    setting(200, "boost current", RWE, 0, 255, 0, KEPT_DRIVER),
    setting(201, "encoder mode", RWE, 0, 28, 0, Some("null channel once per motor revolution; bit 4 (polarity) has no effect")),
    setting(202, "motor resolution", RW, 0, 400, 200, None),
    setting(204, "freewheeling [ms]", RWE, 0, 65535, 0, KEPT_DRIVER),
    live(207, "max encoder deviation error flag", R, 0, 1, None),
    live(209, "encoder counter", RW, I32.0, I32.1, None),
    setting(210, "encoder resolution", RW, 0, 65535, 51200, None),
    setting(
        212,
        "max. encoder deviation",
        RWE,
        I32.0,
        I32.1,
        0,
        Some("a negative value stops the motor as a positive one does (no driver stage to switch off)"),
    ),
    setting(214, "power down delay [10 ms]", RWE, 1, 65535, 200, KEPT_DRIVER),
    live(233, "virtual actual position", R, 0, 0, None),
    live(237, "position error", R, 0, 0, None),
];

/// Why a manual axis parameter is not available on this module (status 3).
pub fn axis_absent(no: u8) -> &'static str {
    match no {
        25..=29 => "I²t monitoring needs the motor current, which is not modelled",
        123 | 230 | 236 => "closed-loop reading (closed loop is not modelled)",
        150..=152 | 154 | 180 | 208 => "driver-stage reading (no driver stage modelled)",
        155 => "no temperature sensor modelled",
        206 => "stallGuard2 needs a motor load model",
        254 => "no Step/Dir input modelled",
        _ => "not a parameter of this module",
    }
}

const KEPT_LINK: Option<&str> = Some("kept, no effect: the host links are TCP and a pseudo-terminal");

/// Bank-0 global parameters.
pub const GLOBAL: &[Param] = &[
    setting(64, "EEPROM magic", RWE, 0, 255, crate::config::EEPROM_MAGIC, None),
    setting(65, "RS485 baud rate", RWE, 0, 11, 0, KEPT_LINK),
    setting(66, "serial address", RWE, 0, 255, 1, None),
    setting(67, "ASCII mode", RWE, 0, 0x31, 0, None),
    setting(68, "serial heartbeat [ms]", RWE, 0, i32::MAX as i64, 0, None),
    setting(69, "CAN bit rate", RWE, 2, 8, 8, KEPT_LINK),
    setting(70, "CAN reply ID", RWE, 0, 0x7ff, 2, KEPT_LINK),
    setting(71, "CAN ID", RWE, 0, 0x7ff, 1, KEPT_LINK),
    setting(73, "configuration EEPROM lock flag", RWE, 0, 1, 0, None),
    setting(75, "telegram pause time", RWE, 0, 255, 0, KEPT_LINK),
    setting(76, "serial host address", RWE, 0, 255, 2, None),
    setting(77, "auto start mode", RWE, 0, 1, 0, None),
    setting(79, "end switch polarity", RWE, 0, 1, 0, None),
    setting(81, "TMCL code protection", RWE, 0, 3, 0, None),
    setting(83, "CAN secondary address", RWE, 0, 0x7ff, 0, KEPT_LINK),
    setting(84, "coordinate storage", RWE, 0, 1, 0, None),
    setting(85, "do not restore user variables", RWE, 0, 1, 0, None),
    setting(88, "interface selection", RWE, 0, 1, 0, KEPT_LINK),
    live(128, "TMCL application status", R, 0, 3, None),
    live(129, "download mode", R, 0, 1, None),
    live(130, "TMCL program counter", R, 0, 0, None),
    live(132, "tick timer [ms]", RW, i32::MIN as i64, i32::MAX as i64, None),
    live(133, "random number", R, 0, 0, None),
];

/// Every bank-0 parameter of the manual is available.
pub fn global_absent(_no: u8) -> &'static str {
    "not a parameter of this module"
}

/// Interrupt numbers ([TMCL] §5.6.3): timers 0..2, target reached 3, stallGuard2 15 (never
/// raised: stallGuard2 cannot be enabled), deviation 21, stop switches 27 (left) and 28
/// (right), input changes 39..46, global 255.
pub const INTERRUPTS: &[u8] = &[0, 1, 2, 3, 15, 21, 27, 28, 39, 40, 41, 42, 43, 44, 45, 46, 255];
