//! The datasheets' worked examples, reproduced on the running model through its pins.

mod common;
use common::*;

use tmc429_model::pmulpdiv;
use tmc429_model::ram::{SINE_LUT, TABLE_11_2};
use tmc429_model::Chip;

/// TMC428 §6.5 / TMC429 §6.2.3: write $000123 to dx_ref_tolerance of motor 1 and read it back.
/// The printed reply %10010101 contradicts its own "INT=0" (erratum E1): with INT clear the status
/// is $15 (all motors at their targets).
#[test]
fn section_6_5_datagrams() {
    for chip in Chip::ALL {
        let mut h = host(chip);
        assert_eq!(h.datagram(0x1A00_0123), 0x1500_0000, "{chip}");
        assert_eq!(h.datagram(0x1B00_0000), 0x1500_0123, "{chip}");
    }
}

/// With INT set the status byte is the printed $95 (erratum E1).
#[test]
fn section_6_5_reply_with_int_set() {
    let mut h = host(Chip::Tmc429);
    // Unmask POS_END of motor 1 and leave the target: x_actual = 0 ≠ x_target = 5, then back.
    wr(&mut h, 0, INTERRUPT, 0x0100);
    wr(&mut h, 0, X_TARGET, 5);
    wr(&mut h, 0, X_TARGET, 0);
    // the event is taken in motor 1's condition slot, within one 32-CLK frame (C63)
    h.wait(32);
    assert_eq!(h.datagram(0x1A00_0123), 0x9500_0000);
    assert_eq!(h.datagram(0x1B00_0000), 0x9500_0123);
}

/// TMC428 §6.5 and TMC4210 §5.2.3 (whose RAM is "writeable with read-back option", §5.3): RAM
/// write of %100001 to cell 126 and %100011 to cell 127, read back (erratum E2: 32 bits).
#[test]
fn ram_example() {
    for chip in Chip::ALL {
        let mut h = host(chip);
        assert_eq!(h.datagram(0xFE00_2321), 0x1500_0000);
        assert_eq!(h.datagram(0xFF00_0000), 0x1500_2321);
        assert_eq!(h.chip().ram()[126], 0b100001);
        assert_eq!(h.chip().ram()[127], 0b100011);
    }
}

/// TMC428 Table 11-3: the 18 datagrams that load the Table 11-2 configuration (TMC428 §11.2),
/// then `$7E` with LSMD = 2; every word reads back.
#[test]
fn table_11_3_configuration_sequence() {
    const SEQ: [u32; 18] = [
        0x8000_0510,
        0x8200_0304,
        0x8400_0602,
        0x8600_0D10,
        0x8800_0B0C,
        0x8A00_2E0A,
        0x8C00_0510,
        0x8E00_0304,
        0x9000_0602,
        0x9200_0D10,
        0x9400_0B0C,
        0x9600_2E0A,
        0x9800_0507,
        0x9A00_0304,
        0x9C00_0602,
        0x9E00_0D0F,
        0xA000_0B0C,
        0xA200_2E0A,
    ];
    let mut h = host(Chip::Tmc428);
    for d in SEQ {
        assert_eq!(h.datagram(d), 0x1500_0000);
    }
    assert_eq!(&h.chip().ram()[..36], &TABLE_11_2[..]);
    for d in SEQ {
        assert_eq!(h.datagram(d | 0x0100_0000), 0x1500_0000 | (d & 0xFFFF), "read back {d:08X}");
    }
    h.datagram(0x7E00_0F02);
    assert_eq!(h.datagram(0x7F00_0000), 0x1500_0F02);
}

/// TMC428 Table 12-2: the 32 datagrams of the sine table, `word k = $C0000000 | (32+k)<<25 |
/// y(2k+1)<<8 | y(2k)` (y(i) of TMC428 §12), written and read back; first and last as printed.
#[test]
fn table_12_2_lut_sequence() {
    let words: Vec<u32> = (0..32u32)
        .map(|k| 0x8000_0000 | (32 + k) << 25 | (SINE_LUT[2 * k as usize + 1] as u32) << 8 | SINE_LUT[2 * k as usize] as u32)
        .collect();
    assert_eq!(words[0], 0xC000_0200);
    assert_eq!(words[31], 0xFE00_3F3F);
    let mut h = host(Chip::Tmc428);
    for &w in &words {
        h.datagram(w);
    }
    assert_eq!(&h.chip().ram()[64..], &SINE_LUT[..]);
    for &w in &words {
        assert_eq!(h.datagram(w | 0x0100_0000) & 0xFFFF, w & 0xFFFF);
    }
}

/// The TMC429 loads Table 12-2 and its default driver chain at power-on (contract C30).
#[test]
fn tmc429_power_on_ram() {
    let mut h = host(Chip::Tmc429);
    assert_eq!(h.read(0x40), 0x0511, "cells 0/1 = One, DAC_A_5");
    assert_eq!(h.read(0x45), 0x2E0A, "cells 10/11 = DAC_B_2, NxM|PH_B");
    assert_eq!(h.read(0x60), 0x0200, "LUT[0..1] = 0, 2");
    assert_eq!(h.read(0x7F), 0x3F3F);
    assert_eq!(h.read(0x52), 0, "cells 36.. are 0");
    // The LUT is the quarter sine y(i) of TMC429 §11.5 without an offset (C30: the "offset" of
    // the power-on table is not published).
    const Y: [u8; 64] = [
        0, 2, 3, 5, 6, 8, 9, 11, 12, 14, 16, 17, 19, 20, 22, 23, 24, 26, 27, 29, 30, 32, 33, 34, 36, 37, 38, 39, 41, 42, 43, 44, 45, 46,
        47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 56, 57, 58, 59, 59, 60, 60, 61, 61, 62, 62, 62, 63, 63, 63, 63, 63, 63, 63, 63,
    ];
    for w in 0..32u8 {
        let (even, odd) = (Y[2 * w as usize] as u32, Y[2 * w as usize + 1] as u32);
        assert_eq!(h.read(0x60 | w), odd << 8 | even, "LUT word {w}");
    }
    // TMC4210 §5.3: "the on-chip RAM of the TMC4210 is initialized internally", with values it
    // does not publish: the TMC429's (C30).
    let mut h4210 = host(Chip::Tmc4210);
    for a in 0..64u8 {
        assert_eq!(h4210.read(0x40 | a), h.read(0x40 | a), "TMC4210 word {a}");
    }
    let mut h = host(Chip::Tmc428);
    assert_eq!(h.read(0x40), 0);
    assert_eq!(h.read(0x7F), 0);
}

/// The results of the pmulpdiv.c program of TMC429 §8.1.10.2.3 (TMC428 §19), all columns.
#[test]
fn pmulpdiv_results() {
    #[rustfmt::skip]
    let rows: [(i32, i32, i32, f32, i32, i32, f64, f64, i64, i64); 14] = [
        (10, 3, 3, 0.05, 151, 8, 0.078125, 0.073730, 0, 4095),
        (1000, 3, 3, 0.05, 237, 2, 7.812500, 7.406250, 0, 4095),
        (1000, 7, 7, 0.00, 250, 2, 7.812500, 7.812500, 0, 4095),
        (1000, 7, 7, 0.01, 247, 2, 7.812500, 7.718750, 0, 4095),
        (2047, 0, 0, 0.05, 243, 1, 15.992188, 15.187500, 0, 4095),
        (1, 0, 0, 0.05, 243, 12, 0.007812, 0.007416, 0, 4095),
        (100, 7, 7, 0.05, 189, 5, 0.781250, 0.738281, 0, 4095),
        (1000, 6, 3, 0.05, 237, 5, 0.976562, 0.925781, 4, 32767),
        (16, 5, 0, 0.05, 243, 13, 0.003906, 0.003708, 16, 131071),
        (128, 0, 0, 0.00, 128, 4, 1.0, 1.0, 0, 4095),
        (1023, 0, 0, 0.00, 255, 2, 7.992188, 7.968750, 0, 4095),
        (1000, 3, 6, 0.05, -1, -1, 62.5, -0.25, 0, 511),
        (1, 13, 0, 0.05, -1, -1, 9.54e-7, -0.25, 4096, 33554431),
        (0, 0, 0, 0.05, -1, -1, 0.0, -0.25, 0, 4095),
    ];
    for (a, rd, pd, red, pm, pdv, ideal, best, lo, hi) in rows {
        let r = pmulpdiv::calc(a, rd, pd, red);
        assert_eq!((r.p_mul, r.p_div), (pm, pdv), "a_max {a} rd {rd} pd {pd} red {red}");
        // printf("%f") rounds to 6 decimals.
        assert_eq!(format!("{:.6}", r.p_best), format!("{best:.6}"), "p_best a_max {a}");
        if ideal > 1e-3 || ideal == 0.0 {
            assert_eq!(format!("{:.6}", r.p_ideal), format!("{ideal:.6}"), "p_ideal a_max {a}");
        } else {
            assert!((r.p_ideal - ideal).abs() < 1e-8);
        }
        assert_eq!((r.a_max_lower_limit, r.a_max_upper_limit), (lo, hi), "limits a_max {a}");
    }
    assert_eq!(pmulpdiv::calc(10, 3, 3, 0.05).register_value(), Some(151 << 8 | 8));
    assert_eq!(pmulpdiv::calc(0, 0, 0, 0.05).register_value(), None);
}

/// The a_max limits of TMC428 §8.7.1 (errata E3, E10).
#[test]
fn a_max_limits() {
    let lim = |e: i32| {
        let r = pmulpdiv::calc(100, e.max(0), (-e).max(0), 0.0);
        (r.a_max_lower_limit, r.a_max_upper_limit)
    };
    assert_eq!(lim(5), (16, 131071));
    assert_eq!(lim(1), (1, 8191));
    assert_eq!(lim(0).1, 4095);
    assert_eq!(lim(-1).1, 2047, "E10: exactly 2047 at rd − pd = −1");
    assert_eq!(lim(-3).1, 511);
}
