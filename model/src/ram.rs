//! The 128 × 6 bit RAM: driver-chain configuration (cells 0..63) and the quarter-wave
//! microstep table (cells 64..127) (TMC428 §10, Table 10-1; contract C30).

use crate::Chip;

/// Table 12-2 of the TMC428 datasheet: y(i) = int(½ + 64·sin(π·i/128)), 63 where that is 64
/// (all 64 values as TMC429 §11.5 prints them; the 62-value list printed in TMC428 §12 is
/// erratum E5).
pub const SINE_LUT: [u8; 64] = [
    0, 2, 3, 5, 6, 8, 9, 11, 12, 14, 16, 17, 19, 20, 22, 23, 24, 26, 27, 29, 30, 32, 33, 34, 36, 37, 38, 39, 41, 42, 43, 44, 45, 46, 47,
    48, 49, 50, 51, 52, 53, 54, 55, 56, 56, 57, 58, 59, 59, 60, 60, 61, 61, 62, 62, 62, 63, 63, 63, 63, 63, 63, 63, 63,
];

/// Table 11-2 of the TMC428 datasheet: three TMC23x/24x drivers (cells 0..35, LSMD = 2).
pub const TABLE_11_2: [u8; 36] = [
    0x10, 0x05, 0x04, 0x03, 0x02, 0x06, 0x10, 0x0D, 0x0C, 0x0B, 0x0A, 0x2E, //
    0x10, 0x05, 0x04, 0x03, 0x02, 0x06, 0x10, 0x0D, 0x0C, 0x0B, 0x0A, 0x2E, //
    0x07, 0x05, 0x04, 0x03, 0x02, 0x06, 0x0F, 0x0D, 0x0C, 0x0B, 0x0A, 0x2E,
];

/// The TMC429's power-on driver configuration (TMC429 §11.4.2): Table 11-2 with One ($11) at the
/// mixed-decay positions 0, 6, 12, 18, 24, 30.
pub const TMC429_POR_CONFIG: [u8; 36] = [
    0x11, 0x05, 0x04, 0x03, 0x02, 0x06, 0x11, 0x0D, 0x0C, 0x0B, 0x0A, 0x2E, //
    0x11, 0x05, 0x04, 0x03, 0x02, 0x06, 0x11, 0x0D, 0x0C, 0x0B, 0x0A, 0x2E, //
    0x11, 0x05, 0x04, 0x03, 0x02, 0x06, 0x11, 0x0D, 0x0C, 0x0B, 0x0A, 0x2E,
];

/// Power-on RAM contents of a variant (contract C30): TMC428 all 0 (not initialized, TMC428
/// §7.3); TMC429 its default configuration and sine table (TMC429 §11.4.2, §11.5); TMC4210
/// "initialized internally" (TMC4210 §5.3) with values it does not publish: the TMC429's.
pub fn power_on(chip: Chip) -> [u8; 128] {
    let mut ram = [0u8; 128];
    if chip != Chip::Tmc428 {
        ram[..36].copy_from_slice(&TMC429_POR_CONFIG);
        ram[64..].copy_from_slice(&SINE_LUT);
    }
    ram
}

/// Data word of RAM word `addr` (0..63): odd cell in bits 13..8, even cell in bits 5..0.
#[inline]
pub fn read_word(ram: &[u8; 128], addr: u8) -> u32 {
    let a = (addr as usize & 63) * 2;
    ((ram[a + 1] as u32) << 8) | ram[a] as u32
}

/// Writes RAM word `addr` from a datagram's data.
#[inline]
pub fn write_word(ram: &mut [u8; 128], addr: u8, data: u32) {
    let a = (addr as usize & 63) * 2;
    ram[a] = (data & 0x3F) as u8;
    ram[a + 1] = ((data >> 8) & 0x3F) as u8;
}
