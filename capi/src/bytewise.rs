//! Byte-wise SPI with chip select under the caller's control, and the register peek
//! (`tmc429.h`, section "Byte-wise SPI and register peek").
//!
//! Vendor drivers (Trinamic's TMC-API `ReadWriteSPI(byte, last)`, janelia-arduino, the stepRocker
//! firmware) send one byte per SPI call with nSCS_C held low across calls and need each reply byte
//! at once. These calls give them exactly that: [`tmc429_spi_select`] pulls nSCS_C low,
//! [`tmc429_spi_transfer_byte`] clocks 8 bits and returns the byte the chip sent in them,
//! [`tmc429_spi_deselect`] raises nSCS_C — the chip executes a datagram at that rising edge if 32
//! bits were shifted (TMC429 §6.2; contract C12: fewer or more execute nothing).
//! [`tmc429_peek_register`] reads a register as a read datagram would, without SPI traffic and
//! without CLK time, for assertions in tests.

use std::ffi::c_int;

use crate::{guard, out_ref, with_sim, TMC429_ERR_ARG, TMC429_ERR_STATE, TMC429_OK};

/// Pulls nSCS_C low (one SCK_C half period passes). `TMC429_ERR_STATE` if it is low already.
#[no_mangle]
pub extern "C" fn tmc429_spi_select(h: u64) -> c_int {
    guard(|| {
        with_sim(h, |s| {
            if s.host.selected() {
                return Err(TMC429_ERR_STATE);
            }
            s.host.select();
            Ok(TMC429_OK)
        })
    })
}

/// Eight SCK_C periods with nSCS_C low, MSB first (SPI mode 3); `*rx` receives the byte the chip
/// sent meanwhile. `TMC429_ERR_STATE` unless selected.
///
/// # Safety
/// `rx` must be NULL (reported as `TMC429_ERR_NULL`) or valid and aligned for one byte.
#[no_mangle]
pub unsafe extern "C" fn tmc429_spi_transfer_byte(h: u64, tx: u8, rx: *mut u8) -> c_int {
    guard(|| {
        let rx = out_ref(rx)?;
        with_sim(h, |s| {
            if !s.host.selected() {
                return Err(TMC429_ERR_STATE);
            }
            *rx = s.host.shift(tx as u32, 8) as u8;
            Ok(TMC429_OK)
        })
    })
}

/// Raises nSCS_C: the chip executes the frame if exactly 32 bits were shifted since the select;
/// then one SCK_C half period passes. `TMC429_ERR_STATE` unless selected.
#[no_mangle]
pub extern "C" fn tmc429_spi_deselect(h: u64) -> c_int {
    guard(|| {
        with_sim(h, |s| {
            if !s.host.selected() {
                return Err(TMC429_ERR_STATE);
            }
            s.host.deselect();
            Ok(TMC429_OK)
        })
    })
}

/// The 24 data bits a read datagram of `address` (RRS and the 6 address bits, datagram bits
/// 31..25: `SMDA << 4 | IDX`, `$30 | JDX`, `$40 | RAM address`) would return now, without SPI
/// traffic and without CLK time; unused addresses read 0 (contract C21). `address` above 127 is
/// `TMC429_ERR_ARG`.
///
/// # Safety
/// `data` must be NULL (reported as `TMC429_ERR_NULL`) or valid and aligned for one `u32`.
#[no_mangle]
pub unsafe extern "C" fn tmc429_peek_register(h: u64, address: u32, data: *mut u32) -> c_int {
    guard(|| {
        let data = out_ref(data)?;
        let a7 = u8::try_from(address).ok().filter(|a| *a < 0x80).ok_or(TMC429_ERR_ARG)?;
        with_sim(h, |s| {
            *data = s.host.chip().read_register(a7);
            Ok(TMC429_OK)
        })
    })
}
