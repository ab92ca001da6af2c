//! Byte-wise SPI with chip select under the caller's control, and the register peek: the same
//! bytes and the same CLK time as whole-frame transfers, execution at the rising nSCS_C of a
//! 32-bit frame only (TMC429 §6.2, contract C12), and every misuse as an error code.

use tmc429::*;

fn create() -> u64 {
    let mut h = 0u64;
    assert_eq!(unsafe { tmc429_create(TMC429_CHIP_TMC429, 0, &mut h) }, TMC429_OK);
    h
}

fn cycle(h: u64) -> u64 {
    let mut c = 0;
    assert_eq!(unsafe { tmc429_get_cycle(h, &mut c) }, TMC429_OK);
    c
}

/// One frame byte by byte: select, each byte with its reply at once, deselect.
fn bytes(h: u64, tx: &[u8]) -> Vec<u8> {
    assert_eq!(tmc429_spi_select(h), TMC429_OK);
    let rx = tx
        .iter()
        .map(|&b| {
            let mut r = 0u8;
            assert_eq!(unsafe { tmc429_spi_transfer_byte(h, b, &mut r) }, TMC429_OK);
            r
        })
        .collect();
    assert_eq!(tmc429_spi_deselect(h), TMC429_OK);
    rx
}

fn whole(h: u64, tx: &[u8]) -> Vec<u8> {
    let mut rx = vec![0u8; tx.len()];
    assert_eq!(unsafe { tmc429_spi_transfer(h, tx.as_ptr(), rx.as_mut_ptr(), tx.len()) }, TMC429_OK);
    rx
}

fn peek(h: u64, a7: u32) -> u32 {
    let mut d = 0;
    assert_eq!(unsafe { tmc429_peek_register(h, a7, &mut d) }, TMC429_OK);
    d
}

/// [428] §6.5: the datagram examples byte by byte give the replies of whole frames, in the same
/// CLK time ((2 + 16·len) half periods per frame).
#[test]
fn bytes_equal_whole_frames() {
    let (a, b) = (create(), create());
    for d in [0x1A00_0123u32, 0x1B00_0000, 0xFE00_2321, 0xFF00_0000, 0x7300_0000] {
        let tx = d.to_be_bytes();
        assert_eq!(bytes(a, &tx), whole(b, &tx), "{d:08X}");
        assert_eq!(cycle(a), cycle(b));
    }
    assert_eq!(bytes(a, &[0x73, 0, 0, 0]), [0x15, 0x42, 0x91, 0x01]);
    assert_eq!(cycle(a), 6 * (2 + 16 * 4) * 4);
    assert_eq!(bytes(a, &[0]), [0x15]);
    for h in [a, b] {
        assert_eq!(tmc429_destroy(h), TMC429_OK);
    }
}

/// Frames of 2 and 3 bytes return the status byte and the data bytes shifted so far and execute
/// nothing (C12); nor does a frame of 5 bytes.
#[test]
fn short_and_long_byte_frames_execute_nothing() {
    let h = create();
    let a7 = 0x0D; // dx_ref_tolerance of motor 0
    assert_eq!(bytes(h, &[a7 << 1, 0x00, 0x01, 0x23]), [0x15, 0, 0, 0]);
    assert_eq!(peek(h, a7 as u32), 0x123);
    assert_eq!(bytes(h, &[a7 << 1, 0x00, 0x07]), [0x15, 0, 0]);
    assert_eq!(bytes(h, &[a7 << 1, 0x00]), [0x15, 0]);
    assert_eq!(bytes(h, &[a7 << 1, 0x00, 0x04, 0x56, 0x00])[..4], [0x15, 0, 0, 0]);
    assert_eq!(peek(h, a7 as u32), 0x123);
    // a read: the reply bytes come one by one, the status byte first
    assert_eq!(bytes(h, &[a7 << 1 | 1, 0, 0, 0]), [0x15, 0x00, 0x01, 0x23]);
    assert_eq!(tmc429_destroy(h), TMC429_OK);
}

/// The peek returns what a read datagram returns, for every address, without CLK time.
#[test]
fn peek_equals_a_read_and_costs_no_time() {
    let h = create();
    let before = cycle(h);
    let peeks: Vec<u32> = (0..128).map(|a| peek(h, a)).collect();
    assert_eq!(cycle(h), before);
    assert_eq!(peeks[0x39], 0x42_9101);
    for a in 0..128u32 {
        let r = bytes(h, &[(a as u8) << 1 | 1, 0, 0, 0]);
        assert_eq!(u32::from_be_bytes([0, r[1], r[2], r[3]]), peek(h, a), "address ${a:02X}");
    }
    assert_eq!(tmc429_destroy(h), TMC429_OK);
}

/// Misuse: bytes or deselect without select, select twice, a whole frame while selected, NULL, a
/// bad address, a destroyed handle. A failed call changes nothing.
#[test]
fn misuse_is_an_error_code() {
    let h = create();
    let mut r = 0u8;
    let mut d = 0u32;
    unsafe {
        assert_eq!(tmc429_spi_transfer_byte(h, 0, &mut r), TMC429_ERR_STATE);
        assert_eq!(tmc429_spi_deselect(h), TMC429_ERR_STATE);
        assert_eq!(cycle(h), 0);
        assert_eq!(tmc429_spi_select(h), TMC429_OK);
        assert_eq!(tmc429_spi_select(h), TMC429_ERR_STATE);
        let tx = [0u8; 4];
        let mut rx = [0u8; 4];
        assert_eq!(tmc429_spi_transfer(h, tx.as_ptr(), rx.as_mut_ptr(), 4), TMC429_ERR_STATE);
        assert_eq!(tmc429_spi_transfer_byte(h, 0, std::ptr::null_mut()), TMC429_ERR_NULL);
        assert_eq!(tmc429_spi_deselect(h), TMC429_OK);
        assert_eq!(tmc429_peek_register(h, 128, &mut d), TMC429_ERR_ARG);
        assert_eq!(tmc429_peek_register(h, 0, std::ptr::null_mut()), TMC429_ERR_NULL);
        // reset ends a selection
        assert_eq!(tmc429_spi_select(h), TMC429_OK);
        assert_eq!(tmc429_reset(h), TMC429_OK);
        assert_eq!(tmc429_spi_deselect(h), TMC429_ERR_STATE);
        assert_eq!(tmc429_destroy(h), TMC429_OK);
        assert_eq!(tmc429_spi_select(h), TMC429_ERR_HANDLE);
        assert_eq!(tmc429_spi_transfer_byte(h, 0, &mut r), TMC429_ERR_HANDLE);
        assert_eq!(tmc429_spi_deselect(h), TMC429_ERR_HANDLE);
        assert_eq!(tmc429_peek_register(h, 0, &mut d), TMC429_ERR_HANDLE);
    }
    let s = unsafe { std::ffi::CStr::from_ptr(tmc429_strerror(TMC429_ERR_STATE)) };
    assert!(s.to_str().unwrap().starts_with("wrong chip-select state"));
    assert_eq!(tmc429_abi_version(), 3);
}
