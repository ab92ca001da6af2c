//! The TMCL firmware manual's commands and parameters ([TMCL] §5.7, §6, §7, §8, §9, §10) and
//! how each module type covers them: as the manual, different on this module (how), or not
//! available (why). The parameter cells come from the module types' parameter tables
//! (`crate::personality`); docs/tmcl.md shows [`coverage_markdown`] and
//! [`parameters_markdown`], and a test keeps them equal.

use crate::personality::{ModuleType, Param};
use std::fmt::Write as _;

/// How a module type covers one item of the manual.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Coverage {
    AsManual,
    Different(&'static str),
    NotAvailable(&'static str),
}

impl Coverage {
    pub fn cell(self) -> String {
        match self {
            Coverage::AsManual => "as the manual".into(),
            Coverage::Different(how) => format!("different: {how}"),
            Coverage::NotAvailable(why) => format!("not available: {why}"),
        }
    }
}

/// The axis parameters of the manual's tables ([TMCL] §6, §7, §8, §9).
pub const AXIS_PARAMS: &[(u8, &str)] = &[
    (0, "target position"),
    (1, "actual position"),
    (2, "target speed"),
    (3, "actual speed"),
    (4, "maximum positioning speed"),
    (5, "maximum acceleration"),
    (6, "absolute max. current"),
    (7, "standby current"),
    (8, "target pos. reached"),
    (9, "ref. switch status"),
    (10, "right limit switch status"),
    (11, "left limit switch status"),
    (12, "right limit switch disable"),
    (13, "left limit switch disable"),
    (14, "CL torque mode target current"),
    (15, "maximum possible current"),
    (16, "CL velocity reached"),
    (17, "CL velocity reached window"),
    (18, "status word"),
    (19, "CL torque mode actual current"),
    (20, "CL torque mode slope"),
    (25, "thermal winding time constant"),
    (26, "I²t limit"),
    (27, "I²t sum"),
    (28, "I²t exceed counter"),
    (29, "clear I²t exceeded flag"),
    (108, "CL field weakening minimum velocity"),
    (109, "CL field weakening maximum velocity"),
    (112, "CL encoder offset"),
    (113, "CL current scale minimum"),
    (114, "CL current scale maximum"),
    (115, "CL current scale input select"),
    (116, "CL current scale lower error limit"),
    (117, "CL current scale upper error limit"),
    (118, "CL current scale increment value"),
    (119, "CL current scale decrement value"),
    (120, "CL current scale increment timeout"),
    (121, "CL current scale decrement timeout"),
    (122, "CL current scale enable"),
    (123, "CL actual current scale factor"),
    (124, "CL correction velocity proportional factor"),
    (125, "CL max. following error"),
    (126, "CL max. correction velocity"),
    (127, "relative positioning option"),
    (128, "ramp mode"),
    (129, "closed loop operation"),
    (130, "start/stop velocity"),
    (131, "measured speed"),
    (132, "encoder initialization"),
    (133, "CL init flag"),
    (134, "CL position reached window"),
    (135, "CL position reached time"),
    (136, "CL standstill position error gain"),
    (137, "CL standstill position error dampening factor"),
    (138, "CL standstill position error limit"),
    (140, "microstep resolution"),
    (141, "CL torque mode start/stop current"),
    (150, "motor current"),
    (151, "current phase A"),
    (152, "current phase B"),
    (153, "supply voltage"),
    (154, "DC current"),
    (155, "module temperature"),
    (162, "chopper blank time"),
    (163, "chopper mode"),
    (164, "chopper hysteresis decrement"),
    (165, "chopper hysteresis end"),
    (166, "chopper hysteresis start"),
    (167, "chopper off time"),
    (168, "smartEnergy current minimum (SEIMIN)"),
    (169, "smartEnergy current down step"),
    (170, "smartEnergy hysteresis"),
    (171, "smartEnergy current up step"),
    (172, "smartEnergy hysteresis start"),
    (173, "stallGuard2 filter enable"),
    (174, "stallGuard2 threshold"),
    (175, "slope control high side"),
    (176, "slope control low side"),
    (177, "short protection disable"),
    (178, "short detection timer"),
    (179, "Vsense"),
    (180, "smartEnergy actual current"),
    (181, "stop on stall"),
    (182, "smartEnergy threshold speed"),
    (183, "smartEnergy slow run current"),
    (193, "ref. search mode"),
    (194, "referencing search speed"),
    (195, "referencing switch speed"),
    (196, "end switch distance"),
    (198, "clear on null"),
    (200, "boost current"),
    (201, "encoder mode"),
    (202, "motor resolution"),
    (204, "freewheeling"),
    (206, "actual load value"),
    (207, "max encoder deviation error flag"),
    (208, "driver error flags"),
    (209, "encoder counter"),
    (210, "encoder resolution"),
    (212, "max. encoder deviation"),
    (214, "power down delay"),
    (230, "gamma"),
    (233, "virtual actual position"),
    (236, "CL actual target current scale factor"),
    (237, "position error"),
    (254, "Step/Dir mode"),
];

/// The bank-0 global parameters of the manual ([TMCL] §10.1).
pub const GLOBAL_PARAMS: &[(u8, &str)] = &[
    (64, "EEPROM magic"),
    (65, "RS485 baud rate"),
    (66, "serial address"),
    (67, "ASCII mode"),
    (68, "serial heartbeat"),
    (69, "CAN bit rate"),
    (70, "CAN reply ID"),
    (71, "CAN ID"),
    (73, "configuration EEPROM lock flag"),
    (75, "telegram pause time"),
    (76, "serial host address"),
    (77, "auto start mode"),
    (79, "end switch polarity"),
    (81, "TMCL code protection"),
    (83, "CAN secondary address"),
    (84, "coordinate storage"),
    (85, "do not restore user variables"),
    (88, "interface selection"),
    (128, "TMCL application status"),
    (129, "download mode"),
    (130, "TMCL program counter"),
    (132, "tick timer"),
    (133, "random number"),
];

use Coverage::*;

const TMC429_VELOCITY: Coverage = Different("velocity in TMC429 units −2047..2047, not pps");
const PPS_VELOCITY: Coverage = Different("velocity quantised to the TMC429's step; at most fCLK·2047/2^16 pps");
const RFS: Coverage = Different(
    "STATUS answers 0 when no search is active (the manual's table has the sense reversed); the modes of §9 on the world's switches",
);
const GIO: Coverage = Different("GIO 9..12, 1 (temperature, coil and input currents) answer 3: not modelled");
const UF: Coverage = NotAvailable("no customer-specific functions (status 6)");

/// The manual's commands ([TMCL] §5.7): number (`None`: ASCII only), mnemonic, section, and
/// the coverage of the TMCM-3110 and the TMCM-1311.
pub const COMMANDS: &[(Option<u8>, &str, &str, Coverage, Coverage)] = &[
    (Some(1), "ROR", "5.7.1", TMC429_VELOCITY, PPS_VELOCITY),
    (Some(2), "ROL", "5.7.2", TMC429_VELOCITY, PPS_VELOCITY),
    (Some(3), "MST", "5.7.3", AsManual, AsManual),
    (
        Some(4),
        "MVP ABS, REL, COORD",
        "5.7.4",
        Different("24-bit positions; REL from the actual position"),
        Different("one move covers at most ±8 388 607 µsteps; REL per axis parameter 127"),
    ),
    (Some(5), "SAP", "5.7.5", AsManual, AsManual),
    (Some(6), "GAP", "5.7.6", AsManual, AsManual),
    (Some(7), "STAP", "5.7.7", AsManual, AsManual),
    (Some(8), "RSAP", "5.7.8", AsManual, AsManual),
    (Some(9), "SGP", "5.7.9", AsManual, AsManual),
    (Some(10), "GGP", "5.7.10", AsManual, AsManual),
    (Some(11), "STGP", "5.7.11", AsManual, AsManual),
    (Some(12), "RSGP", "5.7.12", AsManual, AsManual),
    (Some(13), "RFS START, STOP, STATUS", "5.7.13", RFS, RFS),
    (Some(14), "SIO", "5.7.14", Different("bank 0 also: the pull-ups of IN0..IN7"), AsManual),
    (Some(15), "GIO", "5.7.15", GIO, GIO),
    (Some(19), "CALC", "5.7.16", AsManual, AsManual),
    (Some(20), "COMP", "5.7.17", AsManual, AsManual),
    (Some(21), "JC", "5.7.18", AsManual, AsManual),
    (Some(22), "JA", "5.7.19", AsManual, AsManual),
    (Some(23), "CSUB", "5.7.20", AsManual, AsManual),
    (Some(24), "RSUB", "5.7.21", AsManual, AsManual),
    (Some(27), "WAIT TICKS, POS, REFSW, LIMSW, RFS", "5.7.22", AsManual, AsManual),
    (Some(28), "STOP", "5.7.23", AsManual, AsManual),
    (Some(30), "SCO", "5.7.24", AsManual, AsManual),
    (Some(31), "GCO", "5.7.25", AsManual, AsManual),
    (Some(32), "CCO", "5.7.26", AsManual, AsManual),
    (Some(39), "ACO", "5.7.27", AsManual, AsManual),
    (Some(33), "CALCX", "5.7.28", AsManual, AsManual),
    (Some(34), "AAP", "5.7.29", AsManual, AsManual),
    (Some(35), "AGP", "5.7.30", AsManual, AsManual),
    (Some(36), "CLE", "5.7.31", AsManual, AsManual),
    (
        Some(37),
        "VECT",
        "5.7.32",
        Different("vectors of three axes: target reached 3..5, stop switches 27..32; no 15, 21"),
        Different("15 (stallGuard2) is never raised"),
    ),
    (Some(25), "EI", "5.7.33", AsManual, AsManual),
    (Some(26), "DI", "5.7.34", AsManual, AsManual),
    (Some(38), "RETI", "5.7.35", AsManual, AsManual),
    (Some(64), "UF0..UF7 (64..71)", "5.7.36", UF, UF),
    (Some(138), "request target position reached event", "5.7.37", AsManual, AsManual),
    (None, "BIN", "5.7.38", AsManual, AsManual),
    (Some(136), "firmware version", "5.7.39", Different("`3110V100`, $0C260100"), Different("`1311V100`, $051F0100")),
    (Some(137), "reset to factory defaults", "5.7.39", AsManual, AsManual),
    (Some(139), "enter ASCII mode", "4.4", AsManual, AsManual),
    (None, "RUN, STOP (ASCII)", "4.4.3", AsManual, AsManual),
];

/// How module type `kind` covers axis parameter `no` of the manual.
pub fn axis_coverage(kind: ModuleType, no: u8) -> Coverage {
    param_coverage(kind.axis_param(no), || kind.axis_absent(no))
}

/// How module type `kind` covers bank-0 parameter `no` of the manual.
pub fn global_coverage(kind: ModuleType, no: u8) -> Coverage {
    param_coverage(kind.global_param(no), || kind.global_absent(no))
}

fn param_coverage(p: Option<&'static Param>, absent: impl Fn() -> &'static str) -> Coverage {
    match p {
        Some(p) => p.note.map_or(AsManual, Different),
        None => NotAvailable(absent()),
    }
}

/// The seed-coverage tables of docs/tmcl.md.
pub fn coverage_markdown() -> String {
    let mut s = String::new();
    let [a, b] = ModuleType::ALL.map(|k| k.name());
    let _ = writeln!(s, "Commands ([TMCL] §5.7):\n\n| No. | Command | § | {a} | {b} |\n|---|---|---|---|---|");
    for (no, name, sec, c3110, c1311) in COMMANDS {
        let no = no.map_or("—".to_string(), |n| n.to_string());
        let _ = writeln!(s, "| {no} | {name} | {sec} | {} | {} |", c3110.cell(), c1311.cell());
    }
    let _ = writeln!(s, "\nAxis parameters ([TMCL] §6–§9):\n\n| No. | Parameter | {a} | {b} |\n|---|---|---|---|");
    for (no, name) in AXIS_PARAMS {
        let [x, y] = ModuleType::ALL.map(|k| axis_coverage(k, *no).cell());
        let _ = writeln!(s, "| {no} | {name} | {x} | {y} |");
    }
    let _ = writeln!(s, "\nGlobal parameters, bank 0 ([TMCL] §10.1):\n\n| No. | Parameter | {a} | {b} |\n|---|---|---|---|");
    for (no, name) in GLOBAL_PARAMS {
        let [x, y] = ModuleType::ALL.map(|k| global_coverage(k, *no).cell());
        let _ = writeln!(s, "| {no} | {name} | {x} | {y} |");
    }
    let _ = writeln!(s, "\nBanks 1, 2, 3 ([TMCL] §10.2–§10.4):\n\n| Bank | {a} | {b} |\n|---|---|---|");
    let bank1 = NotAvailable("no customer-specific C variables (status 4)").cell();
    let _ = writeln!(s, "| 1 | {bank1} | {bank1} |");
    let _ = writeln!(s, "| 2 | as the manual | as the manual |");
    let _ = writeln!(s, "| 3 | {} | as the manual |", Different("stop switch transitions 27..32 of three axes").cell());
    s
}

/// A module type's parameter tables: number, name, access, range, factory default, notes.
pub fn parameters_markdown(kind: ModuleType) -> String {
    let mut s = String::new();
    for (title, table) in [("Axis parameters", kind.axis_params()), ("Global parameters, bank 0", kind.global_params())] {
        let _ =
            writeln!(s, "{title} of the {}:\n\n| No. | Name | Access | Range | Default | Notes |\n|---|---|---|---|---|---|", kind.name());
        for p in table {
            let range = if p.access.writable() { format!("{} .. {}", p.min, p.max) } else { "—".into() };
            let default = if p.live { "—".into() } else { p.default.to_string() };
            let _ = writeln!(s, "| {} | {} | {} | {range} | {default} | {} |", p.no, p.name, p.access.letters(), p.note.unwrap_or(""));
        }
        s.push('\n');
    }
    s
}
