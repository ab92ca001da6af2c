//! The structs shared with C, in C layout: mirrored in `include/tmc429.h`, where tests/header.rs
//! checks them field by field.

/// One decoded pin event; `kind` says which fields are meaningful.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[allow(non_camel_case_types)]
pub struct tmc429_event_t {
    /// Index of the CLK edge the event was seen at (as `tmc429_get_cycle`).
    pub cycle: u64,
    /// CHAIN: the datagram, first bit sent in bit `nbits - 1` (the last 64 bits when longer).
    pub bits: u64,
    /// `TMC429_EVENT_CHAIN`, `_STEP` or `_INT`.
    pub kind: u32,
    /// CHAIN: number of bits.
    pub nbits: u32,
    /// STEP: motor 0..2.
    pub motor: u8,
    /// STEP: 1 = negative direction (from DIR).
    pub negative: u8,
    /// INT: the new level of INT (1 = interrupt active, nINT low).
    pub level: u8,
    pub reserved: u8,
}

/// The output pins after the last CLK edge, 0 or 1 each.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[allow(non_camel_case_types)]
pub struct tmc429_outputs_t {
    pub nint_sdo_c: u8,
    pub sdoz_c: u8,
    pub sdoz_c_oe: u8,
    pub nscs_s: u8,
    pub sck_s: u8,
    pub sdo_s: u8,
    pub sdi_s_o: u8,
    pub sdi_s_oe: u8,
    pub nscs2: u8,
    pub nscs3: u8,
    pub poscmp: u8,
    pub reserved: u8,
}

/// Internal state of one motor (the model's probe bundle).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[allow(non_camel_case_types)]
pub struct tmc429_motor_probe_t {
    /// x_target, sign-extended from 24 bits.
    pub x_target: i32,
    /// x_actual, sign-extended from 24 bits.
    pub x_actual: i32,
    /// Internal velocity in 1/256 units of v (sign + 11 integer + 8 fraction bits).
    pub v_internal: i32,
    /// v_actual as the register reads (12-bit signed).
    pub v_actual: i32,
    /// v_target register (12-bit signed).
    pub v_target: i32,
    /// a_actual register (12-bit signed).
    pub a_actual: i32,
    /// Microstep index 0..255.
    pub ustep: u32,
    /// 1 in the cycle the motor made a step.
    pub step: u8,
    /// Direction of the last step: 1 = negative.
    pub dir: u8,
    pub reserved: u16,
}
