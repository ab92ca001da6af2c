//! The Verilated RTL alone against the datasheet's SPI examples ([428] §6.5 with erratum E1,
//! [4210] §5.2.3 with erratum E2) and the contract's power-on values (C2, C29, C30).
#![cfg(not(tmc429_no_rtl))] // needs Verilator (testbench/build.rs)

use tmc429_model::{Chip, Inputs};
use tmc429_testbench::stimulus::Frame;
use tmc429_testbench::{Rtl, Variant};

/// Sends one 32-bit frame through the pins and returns the bits read on the data pin.
fn frame(rtl: &mut Rtl, f: Frame) -> u32 {
    rtl.spi_frame(f, Inputs::default()) as u32
}

#[test]
fn datasheet_write_and_read_example() {
    for chip in Chip::ALL {
        let mut rtl = Rtl::new(Variant::Chip(chip));
        // write $000123 to dx_ref_tolerance of motor 1: reply status $15 (xEQt1..3 set, INT 0)
        assert_eq!(frame(&mut rtl, Frame::new(0x1A00_0123)), 0x1500_0000, "{chip}");
        assert_eq!(frame(&mut rtl, Frame::new(0x1B00_0000)), 0x1500_0123, "{chip}");
    }
}

#[test]
fn ram_write_example_and_power_on_contents() {
    let mut rtl = Rtl::new(Variant::Chip(Chip::Tmc429));
    // TMC429 power-on RAM: cells 0, 1 = $11 (One), $05 (C30); LUT word 63 = 63, 63
    assert_eq!(frame(&mut rtl, Frame::new(0x8100_0000)), 0x1500_0511);
    assert_eq!(frame(&mut rtl, Frame::new(0xFF00_0000)), 0x1500_3F3F);
    assert_eq!(frame(&mut rtl, Frame::new(0xC100_0000)), 0x1500_0200);
    // [4210] RAM write example (E2: the 32-bit datagram $FE002321), read back
    assert_eq!(frame(&mut rtl, Frame::new(0xFE00_2321)), 0x1500_0000);
    assert_eq!(frame(&mut rtl, Frame::new(0xFF00_0000)), 0x1500_2321);
    // TMC4210 (§5.2.3, §5.3): the same RAM and power-on contents (C30), the example read back
    let mut rtl = Rtl::new(Variant::Chip(Chip::Tmc4210));
    assert_eq!(frame(&mut rtl, Frame::new(0x8100_0000)), 0x1500_0511);
    assert_eq!(frame(&mut rtl, Frame::new(0xFE00_2321)), 0x1500_0000);
    assert_eq!(frame(&mut rtl, Frame::new(0xFF00_0000)), 0x1500_2321);
    // TMC428: RAM all 0 at power-on
    let mut rtl = Rtl::new(Variant::Chip(Chip::Tmc428));
    assert_eq!(frame(&mut rtl, Frame::new(0x8100_0000)), 0x1500_0000);
}

/// A RAM read in the first edges after reset, while the power-on contents are still being
/// copied from the ROM into the RAM array (rtl/tmc429_ram.v, C30): the fastest frame (SCK_C
/// 3 CLK low and high) loads its read data about 55 edges after reset, when words 0..50 are
/// copied and word 63 is not; both read their power-on contents.
#[test]
fn ram_power_on_contents_during_the_copy() {
    let fast = |datagram| Frame { datagram, extra: 0, nbits: 32, half: 3, setup: 3, hold: 3, gap: 3 };
    let mut rtl = Rtl::new(Variant::Chip(Chip::Tmc429));
    assert_eq!(frame(&mut rtl, fast(0xFF00_0000)), 0x1500_3F3F); // LUT word 63: 63, 63
    let mut rtl = Rtl::new(Variant::Chip(Chip::Tmc429));
    assert_eq!(frame(&mut rtl, fast(0x8100_0000)), 0x1500_0511); // cells 0, 1: $11, $05
    let mut rtl = Rtl::new(Variant::Chip(Chip::Tmc428));
    assert_eq!(frame(&mut rtl, fast(0xFF00_0000)), 0x1500_0000); // TMC428: all 0
}

#[test]
fn power_on_registers() {
    let mut rtl = Rtl::new(Variant::Chip(Chip::Tmc429));
    assert_eq!(frame(&mut rtl, Frame::read(0x3F)), 0x1500_0F00); // clk2_div = 15
    assert_eq!(frame(&mut rtl, Frame::read(0x39)), 0x1542_9101); // type_version
    assert_eq!(frame(&mut rtl, Frame::read(0x32)), 0x1500_0000); // stored cover_pos + 1 = 0 (C29)
    assert_eq!(frame(&mut rtl, Frame::read(0x09)), 0x1500_8000); // pmul bit 15 reads 1
    let mut rtl = Rtl::new(Variant::Chip(Chip::Tmc428));
    assert_eq!(frame(&mut rtl, Frame::read(0x39)), 0x1500_0000); // unused on the TMC428
    assert!(!rtl.outputs().poscmp);
    let rtl = Rtl::new(Variant::Chip(Chip::Tmc4210));
    assert!(!rtl.outputs().poscmp); // the TMC4210 has no POSCMP pin ([4210] §3.2, C90)
    let rtl = Rtl::new(Variant::Chip(Chip::Tmc429));
    assert!(rtl.outputs().poscmp); // x_actual 0 matches pos_comp 0 (C2)
}
