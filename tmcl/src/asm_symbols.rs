//! The include files the TMCL-IDE ships (`TMCLParam.tmc`, `Interrupts.inc`, [TMCL] §5.6.5,
//! §11.3), built into the assembler as far as this module uses them.

/// `TMCLParam.tmc`: the axis and global parameter numbers by name.
const PARAM: &[(&str, i64)] = &[
    ("APTargetPosition", 0),
    ("APActualPosition", 1),
    ("APTargetSpeed", 2),
    ("APActualSpeed", 3),
    ("APMaxPositioningSpeed", 4),
    ("APMaxAcceleration", 5),
    ("APAbsMaxCurrent", 6),
    ("APStandbyCurrent", 7),
    ("APTargetPosReached", 8),
    ("APRefSwitchStatus", 9),
    ("APRightLimitSwitchStatus", 10),
    ("APLeftLimitSwitchStatus", 11),
    ("APRightLimitSwitchDisable", 12),
    ("APLeftLimitSwitchDisable", 13),
    ("APMinimumSpeed", 130),
    ("APActualAcceleration", 135),
    ("APRampMode", 138),
    ("APMicrostepResolution", 140),
    ("APRefSwitchTolerance", 141),
    ("APSoftStopFlag", 149),
    ("APRampDivisor", 153),
    ("APPulseDivisor", 154),
    ("APReferencingMode", 193),
    ("APReferencingSearchSpeed", 194),
    ("APReferencingSwitchSpeed", 195),
    ("APDistanceEndSwitches", 196),
    ("APBoostCurrent", 200),
    ("APFreewheelingDelay", 204),
    ("APPowerDownDelay", 214),
    ("GPSerialAddress", 66),
    ("GPASCIIMode", 67),
    ("GPSerialHeartbeat", 68),
    ("GPSerialHostAddress", 76),
    ("GPAutoStartMode", 77),
    ("GPEndSwitchPolarity", 79),
    ("GPTickTimer", 132),
    ("GPRandomNumber", 133),
    ("Motor0", 0),
    ("Motor1", 1),
    ("Motor2", 2),
];
/// `Interrupts.inc`: the interrupt vector numbers by name.
const IRQ: &[(&str, i64)] = &[
    ("TI_TIMER0", 0),
    ("TI_TIMER1", 1),
    ("TI_TIMER2", 2),
    ("TI_TARGET0", 3),
    ("TI_TARGET1", 4),
    ("TI_TARGET2", 5),
    ("TI_STOPL0", 27),
    ("TI_STOPR0", 28),
    ("TI_STOPL1", 29),
    ("TI_STOPR1", 30),
    ("TI_STOPL2", 31),
    ("TI_STOPR2", 32),
    ("TI_PIN0", 39),
    ("TI_PIN1", 40),
    ("TI_PIN2", 41),
    ("TI_PIN3", 42),
    ("TI_PIN4", 43),
    ("TI_PIN5", 44),
    ("TI_PIN6", 45),
    ("TI_PIN7", 46),
    ("TI_GLOBAL", 255),
];

/// Symbols of the include files the TMCL-IDE ships, as far as this module uses them.
pub(crate) fn builtin_include(name: &str) -> Option<&'static [(&'static str, i64)]> {
    if name.eq_ignore_ascii_case("TMCLParam.tmc") {
        Some(PARAM)
    } else if name.eq_ignore_ascii_case("Interrupts.inc") {
        Some(IRQ)
    } else {
        None
    }
}
