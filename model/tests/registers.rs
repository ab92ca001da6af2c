//! Every register's bits, reset values and side effects (TMC428 Table 7-2, §8–§10; TMC429 §8;
//! contract C20–C31), and out-of-range values behaving as the contract says.

mod common;
use common::*;

use tmc429_model::regmap::{self, global_a7, motor_a7, Space, REGISTERS};
use tmc429_model::{Chip, Inputs};

/// Every register reads its reset value after power-on (C2), on every variant and motor.
#[test]
fn reset_values() {
    for chip in Chip::ALL {
        let mut h = host(chip);
        for r in REGISTERS.iter().filter(|r| r.chips.contains(chip) && r.space != Space::Ram) {
            let motors: &[u8] = if r.space == Space::Motor {
                if chip == Chip::Tmc4210 {
                    &[0]
                } else {
                    &[0, 1, 2]
                }
            } else {
                &[0]
            };
            for &m in motors {
                assert_eq!(h.read(r.a7(m)), r.reset, "{chip} {}[{m}]", r.name);
            }
        }
    }
}

/// Writable fields store exactly their bits; other bits read 0 (C21).
#[test]
fn writable_bits_round_trip() {
    let plain =
        ["x_target", "x_actual", "v_min", "v_max", "v_target", "a_max", "current_scaling", "clk_config", "dx_ref_tolerance", "ustep_count"];
    for chip in [Chip::Tmc428, Chip::Tmc429] {
        let mut h = host(chip);
        // HOLD_MODE, so that no ramp tick rewrites v_target (C24).
        for m in 0..3 {
            wr(&mut h, m, REF_CONF_RM, 3);
        }
        for r in REGISTERS.iter().filter(|r| r.chips.contains(chip) && plain.contains(&r.name)) {
            for m in 0..3 {
                for pattern in [0xFF_FFFFu32, 0xA5_5A5A, 0x5A_A5A5, 0] {
                    h.write(r.a7(m), pattern);
                    assert_eq!(h.read(r.a7(m)), pattern & r.writable_mask(), "{chip} {}[{m}] ← {pattern:06X}", r.name);
                }
            }
        }
    }
}

#[test]
fn field_positions() {
    let mut h = host(Chip::Tmc429);
    // Current scaling: is_agtat 22..20, is_aleat 18..16, is_v0 14..12, a_threshold 10..0.
    wr(&mut h, 1, CURRENT, 0x7F_FFFF);
    assert_eq!(rd(&mut h, 1, CURRENT), 0x77_77FF);
    // clk_config: pulse_div 15..12, ramp_div 11..8, usrs 2..0.
    wr(&mut h, 2, CLK_CONFIG, 0xFF_FFFF);
    assert_eq!(rd(&mut h, 2, CLK_CONFIG), 0xFF07);
    // ref_conf/rm: ref_conf 11..8, rm 1..0; lp (16) read-only.
    wr(&mut h, 0, REF_CONF_RM, 0xFF_FFFF);
    assert_eq!(rd(&mut h, 0, REF_CONF_RM), 0x0F03);
    // Global parameters: every documented bit (TMC429 §8.2.5).
    h.write(global_a7(15), 0xFF_FFFF);
    assert_eq!(h.read(global_a7(15)), 0x31_FFFF);
    // if_configuration: bits 8..0.
    h.write(global_a7(4), 0xFF_FFFF);
    assert_eq!(h.read(global_a7(4)), 0x1FF);
}

/// C22: bit 15 of pmul reads 1; pmul written with bit 7 clear is used as 128 + pmul[6:0].
#[test]
fn pmul_bit_15() {
    let mut h = host(Chip::Tmc428);
    wr(&mut h, 0, PMUL_PDIV, 0x0000);
    assert_eq!(rd(&mut h, 0, PMUL_PDIV), 0x8000);
    wr(&mut h, 0, PMUL_PDIV, 0x1705);
    assert_eq!(rd(&mut h, 0, PMUL_PDIV), 0x9705);
    assert_eq!(h.chip().motor(0).pmul, 0x17);
    // pdiv 14 and 15 are kept (C22).
    wr(&mut h, 0, PMUL_PDIV, 0xFF0F);
    assert_eq!(rd(&mut h, 0, PMUL_PDIV), 0xFF0F);
}

/// C23: v_actual writes set V = w·256 (fraction cleared); −2048 acts as −2047.
#[test]
fn v_actual_write() {
    let mut h = host(Chip::Tmc428);
    wr(&mut h, 0, REF_CONF_RM, 3); // HOLD_MODE
    wr(&mut h, 0, V_ACTUAL, 0x123);
    assert_eq!(h.chip().motor(0).v, 0x123 * 256);
    assert_eq!(rd(&mut h, 0, V_ACTUAL), 0x123);
    wr(&mut h, 0, V_ACTUAL, 0x800);
    assert_eq!(h.chip().motor(0).v, -2047 * 256);
    assert_eq!(rd(&mut h, 0, V_ACTUAL), (-2047i32 as u32) & 0xFFF);
    // In VELOCITY mode a mid-ramp write clears the fraction bits and the ramp goes on from it.
    let mut h = host(Chip::Tmc428);
    motion_setup(&mut h, 0, 0, 0, 0, 2047, 100, 0, 2);
    wr(&mut h, 0, V_TARGET, 1000);
    h.wait(32 * 20);
    assert_ne!(h.chip().motor(0).v & 0xFF, 0);
    wr(&mut h, 0, V_ACTUAL, 5);
    let v = h.chip().motor(0).v;
    assert!(v >= 5 * 256 && v & 0xFF == 0 || v % 100 == 5 * 256 % 100, "fraction cleared, then ramps on: {v}");
}

/// C42: v_actual reads sign(V)·(|V| >> 8), rounded toward 0: a negative V with a nonzero low
/// byte reads one more than V >> 8 (the register file hands the SPI slave V >> 8 and the rounding
/// bit apart, docs/rtl.md). V = −100·k after k ramp ticks at a_max 100, frozen in HOLD_MODE.
#[test]
fn v_actual_read_rounds_toward_zero() {
    for (k, expect) in [(1, 0), (2, 0), (3, -1), (5, -1), (6, -2), (13, -5), (41, -16)] {
        let mut h = host(Chip::Tmc429);
        // ramp_div 6: a ramp tick every 64 frames, so none falls in the HOLD_MODE write
        motion_setup(&mut h, 0, 0, 6, 0, 2047, 100, 0, 2);
        wr(&mut h, 0, V_TARGET, (-1000i32 as u32) & 0xFFF);
        while h.chip().motor(0).v > -100 * k {
            h.wait(1);
        }
        wr(&mut h, 0, REF_CONF_RM, 3); // HOLD_MODE: V stays
        let v = h.chip().motor(0).v;
        assert_eq!(v, -100 * k, "k = {k}");
        assert_eq!(s12(rd(&mut h, 0, V_ACTUAL)), expect, "V = {v}");
    }
}

/// C27: writing x_latched (any data) arms the latch; x_latched itself is read-only.
#[test]
fn x_latched_arms_latch() {
    let mut h = host(Chip::Tmc428);
    assert_eq!(rd(&mut h, 0, REF_CONF_RM) >> 16, 0);
    wr(&mut h, 0, X_LATCHED, 0x12_3456);
    assert_eq!(rd(&mut h, 0, REF_CONF_RM), 1 << 16, "lp set");
    assert_eq!(rd(&mut h, 0, X_LATCHED), 0, "data discarded");
    assert_eq!(rd(&mut h, 1, REF_CONF_RM), 0, "other motors untouched");
}

/// C26: interrupt flags clear where 1 is written and are forced to 0 where masked.
#[test]
fn interrupt_flags_w1c_and_mask() {
    let mut h = host(Chip::Tmc428);
    wr(&mut h, 0, INTERRUPT, 0xFF00);
    // POS_END event: leave and return to the target; REF_MISS event: x_actual leaves and returns to 0.
    wr(&mut h, 0, X_ACTUAL, 1);
    wr(&mut h, 0, X_ACTUAL, 0);
    let v = rd(&mut h, 0, INTERRUPT);
    assert_eq!(v, 0xFF00 | 0x01 | 0x04, "POS_END and REF_MISS");
    wr(&mut h, 0, INTERRUPT, 0xFF01);
    assert_eq!(rd(&mut h, 0, INTERRUPT), 0xFF04, "POS_END cleared by writing 1");
    wr(&mut h, 0, INTERRUPT, 0xFB00);
    assert_eq!(rd(&mut h, 0, INTERRUPT), 0xFB00, "REF_MISS forced 0 by its mask");
    assert_eq!(h.status() & 0x80, 0, "INT clear");
    // Masked events never set a flag.
    wr(&mut h, 0, INTERRUPT, 0x0000);
    wr(&mut h, 0, X_ACTUAL, 7);
    wr(&mut h, 0, X_ACTUAL, 0);
    assert_eq!(rd(&mut h, 0, INTERRUPT), 0);
}

/// C64 and C11: INT in the status byte and nINT on SDO_C while nSCS_C is high.
#[test]
fn int_on_status_and_nint() {
    let mut h = host(Chip::Tmc428);
    assert!(h.outputs().nint_sdo_c);
    wr(&mut h, 2, INTERRUPT, 0x0100);
    wr(&mut h, 2, X_TARGET, 3);
    wr(&mut h, 2, X_TARGET, 0);
    // the event is taken in motor 3's condition slot, within one 32-CLK frame (C63)
    h.wait(32 + 4);
    assert!(!h.outputs().nint_sdo_c, "nINT low");
    assert_eq!(h.status(), 0x80 | 0x15);
    wr(&mut h, 2, INTERRUPT, 0x0101);
    h.wait(4);
    assert!(h.outputs().nint_sdo_c);
}

/// TMC429 sdo_int: nINT_SDO_C is a plain nINT output and data goes to SDOZ_C.
#[test]
fn sdo_int_moves_data_to_sdoz() {
    let mut h = host(Chip::Tmc429);
    h.write(global_a7(4), 0x02);
    // Data still arrives (the host reads SDOZ_C while it is enabled).
    assert_eq!(h.read(global_a7(9)), 0x42_9101);
    // nINT_SDO_C stayed high (no interrupt) through the whole frame.
    let mut seen_low = false;
    h.set_observer(Box::new(move |_, _, o| {
        if !o.nint_sdo_c {
            seen_low = true;
        }
        assert!(!seen_low, "nINT_SDO_C carried data");
    }));
    h.read(global_a7(9));
}

/// C11 against the datasheets' own wording: [428]/[429] §6.2 say SDO_C "becomes valid at least
/// four CLK clock cycles after SCK_C becomes low", Table 6-1 gives t_SD = 2.5 … 3.5 CLK and
/// t_SCKCL = t_SCKCH = 3 CLK; the model takes the table. At the table's minimum half period of
/// 3 CLK every changing data bit of a read shows on the 3rd CLK edge after SCK_C was applied low,
/// and a µC sampling just before each rising SCK_C edge reads type_version $429101.
#[test]
fn sdo_c_valid_within_t_sd() {
    use std::sync::{Arc, Mutex};
    let mut h = host(Chip::Tmc429);
    h.set_sck_half(3).unwrap();
    let trace = Arc::new(Mutex::new(Vec::new()));
    let t = trace.clone();
    h.set_observer(Box::new(move |_, i, o| t.lock().unwrap().push((i.nscs_c, i.sck_c, o.nint_sdo_c))));
    assert_eq!(h.read(global_a7(9)), 0x42_9101);
    let tr = trace.lock().unwrap();
    let mut delays = Vec::new();
    for k in 1..tr.len() {
        // SCK_C applied low before edge k; the bit it shifts out is on the pin from edge k + d − 1.
        if tr[k].0 || !tr[k - 1].1 || tr[k].1 {
            continue;
        }
        let before = tr[k - 1].2;
        if let Some(d) = (k..(k + 6).min(tr.len())).position(|j| tr[j].2 != before) {
            delays.push(d + 1);
        }
    }
    assert!(delays.len() > 5, "{delays:?}");
    assert!(delays.iter().all(|&d| d == 3), "SDO_C changes {delays:?} CLK edges after SCK_C low");
}

/// C29: "The TMC429 stores COVER_POS+1 instead of COVER_POS ... one writes COVER_POS but reads
/// back COVER_POS+1" ([429] §8.2.2) and "All register bits are initialized with 0 during power-on
/// reset" (§7.3): after power-on the register reads 0. cover_len 5 bits; cw set by a
/// cover_datagram write.
#[test]
fn cover_registers() {
    for chip in [Chip::Tmc428, Chip::Tmc429] {
        let mut h = host(chip);
        assert_eq!(h.read(global_a7(2)), 0, "{chip}: power-on read of cover_pos/cover_len");
    }
    let mut h = host(Chip::Tmc428);
    h.write(global_a7(2), 0x00_3F1F);
    assert_eq!(h.read(global_a7(2)) & 0x3F1F, 0x00_001F, "cover_pos 63 reads 0 (+1 mod 64)");
    h.write(global_a7(2), 0x00_0C0C);
    assert_eq!(h.read(global_a7(2)) & 0x3F1F, 0x0D0C);
    assert_eq!(h.read(global_a7(2)) >> 23, 0);
    h.write(global_a7(3), 0xABC);
    assert_eq!(h.read(global_a7(3)), 0xABC);
    assert_eq!(h.status() & 0x40, 0x40, "CDGW");
}

/// C29: type_version reads $429101 on TMC429 and TMC4210, 0 on TMC428 (unused there).
#[test]
fn type_version() {
    assert_eq!(host(Chip::Tmc429).read(global_a7(9)), 0x42_9101);
    assert_eq!(host(Chip::Tmc4210).read(global_a7(9)), 0x42_9101);
    assert_eq!(host(Chip::Tmc428).read(global_a7(9)), 0);
}

/// C21: unused addresses read 0 and ignore writes, per variant.
#[test]
fn unused_addresses() {
    for chip in Chip::ALL {
        let mut h = host(chip);
        for a7 in 0..0x80u8 {
            if regmap::lookup(chip, a7).is_some() {
                continue;
            }
            h.write(a7, 0xFF_FFFF);
            assert_eq!(h.read(a7), 0, "{chip} a7 {a7:02X}");
        }
        // Nothing else changed: every register still at its reset value.
        for r in REGISTERS.iter().filter(|r| r.chips.contains(chip) && r.space != Space::Ram) {
            assert_eq!(h.read(r.a7(0)), r.reset, "{chip} {}", r.name);
        }
    }
    // TMC4210: no current scaling, no datagram registers, one motor.
    let mut h = host(Chip::Tmc4210);
    h.write(motor_a7(0, CURRENT), 0x77_77FF);
    assert_eq!(h.read(motor_a7(0, CURRENT)), 0);
    h.write(motor_a7(1, X_TARGET), 0x123);
    assert_eq!(h.read(motor_a7(1, X_TARGET)), 0);
    h.write(global_a7(15), 0xFF_FFFF);
    assert_eq!(h.read(global_a7(15)), 0x20_0F00, "only mot1r and STPDIV (C31)");
}

/// C30: the RAM is 128 × 6 bit, written and read in pairs; bits 7..6 and 15..14 are dropped.
#[test]
fn ram_pairs() {
    let mut h = host(Chip::Tmc428);
    for addr in 0..64u8 {
        h.write(0x40 | addr, 0xFF_FFFF ^ addr as u32);
    }
    for addr in 0..64u8 {
        let d = 0xFF_FFFF ^ addr as u32;
        assert_eq!(h.read(0x40 | addr), d & 0x3F3F);
        assert_eq!(h.chip().ram()[2 * addr as usize], (d & 0x3F) as u8);
    }
}

/// C66: power_down stops the clocks until nSCS_C falls; the waking datagram executes.
#[test]
fn power_down_and_wake() {
    let mut h = host(Chip::Tmc428);
    motion_setup(&mut h, 0, 0, 0, 0, 2047, 2047, 0, 2);
    wr(&mut h, 0, V_TARGET, 2000);
    h.wait(10_000);
    assert_eq!(h.read(global_a7(8)), 0, "power_down reads 0");
    h.write(global_a7(8), 0);
    let x0 = h.chip().motor(0).x_actual;
    let pre = h.chip().probes().prescaler;
    assert!(h.chip().is_powered_down());
    h.wait(100_000);
    assert_eq!(h.chip().motor(0).x_actual, x0, "no steps while powered down");
    assert_eq!(h.chip().probes().prescaler, pre, "pre-divider frozen");
    // A datagram wakes the chip and executes.
    wr(&mut h, 0, V_TARGET, 0);
    assert!(!h.chip().is_powered_down());
    assert_eq!(rd(&mut h, 0, V_TARGET), 0);
    h.wait(10_000);
    assert_ne!(h.chip().motor(0).x_actual, x0);
}

/// C12: a short frame returns the bits shifted so far and executes nothing; a long one neither.
#[test]
fn short_and_long_frames() {
    let mut h = host(Chip::Tmc428);
    assert_eq!(h.frame(0x1A, 8), 0x15, "status byte only");
    assert_eq!(h.frame(0x1A0001, 24), 0x15_0000);
    assert_eq!(rd(&mut h, 0, DX_REF_TOL), 0, "nothing written");
    // A 40-bit frame (two halves of a long transfer): nothing executes.
    let c = h.chip_mut();
    let mut pins = Inputs::default();
    pins.nscs_c = false;
    let word: u64 = 0x1A_0001_2300;
    for _ in 0..4 {
        c.tick(&pins);
    }
    for i in (0..40).rev() {
        pins.sck_c = false;
        pins.sdi_c = (word >> i) & 1 != 0;
        for _ in 0..4 {
            c.tick(&pins);
        }
        pins.sck_c = true;
        for _ in 0..4 {
            c.tick(&pins);
        }
    }
    pins.nscs_c = true;
    for _ in 0..8 {
        c.tick(&pins);
    }
    assert_eq!(rd(&mut h, 0, DX_REF_TOL), 0);
}

/// Out-of-range fields never panic and behave as the contract says: pdiv 14/15 (C22), usrs 7
/// (C53), LSMD 3 and clk2_div < 7 (stored as written, chain behaviour in part 2), pmul bit 7 clear.
#[test]
fn out_of_range_fields() {
    let mut h = host(Chip::Tmc429);
    // usrs = 7: increment 1 as usrs 6.
    wr(&mut h, 0, CLK_CONFIG, 0x0007);
    assert_eq!(h.chip().motor(0).ustep_increment(), 1);
    // pdiv 15 with RAMP_MODE: runs, target velocity from the shift, reaches the target.
    motion_setup(&mut h, 0, 0, 0, 1, 2047, 2047, 0x000F, 0);
    wr(&mut h, 0, CLK_CONFIG, 0x0007);
    wr(&mut h, 0, X_TARGET, 50);
    h.wait(3_000_000);
    assert_eq!(h.chip().motor(0).x_actual, 50);
    assert_eq!(h.chip().motor(0).ustep, 50, "usrs 7 steps the index by 1");
    // LSMD = 3 and clk2_div = 0 are stored as written.
    h.write(global_a7(15), 0x00_0003);
    assert_eq!(h.read(global_a7(15)), 0x00_0003);
    // pulse_div/ramp_div 15: divide by 2^15.
    let mut h = host(Chip::Tmc428);
    motion_setup(&mut h, 0, 15, 15, 0, 2047, 2047, 0, 2);
    wr(&mut h, 0, V_TARGET, 2047);
    // Motor 0's first ramp tick is at phase 16 of frame 2^15 − 1 (C40, C41): the edge with
    // C = 2^20 − 16; its V is stored in the next edge (C51).
    let before = (1u64 << 20) - 15 - h.cycle();
    h.wait(before);
    assert_eq!(h.chip().motor(0).v, 0);
    h.wait(1);
    assert_eq!(h.chip().motor(0).v, 2047, "one ramp tick of a_max after 2^20 − 14 CLK");
    assert_eq!(h.chip().motor(0).x_actual, 0);
}
