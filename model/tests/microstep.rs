//! Microstep unit and current scaling at pin level (TMC428 §8.9 Tables 8-1/8-2, §12 Tables
//! 12-3/12-4 with erratum E5; contract C70–C77). The sine/cosine DAC values, phase and
//! fast-decay bits are read from driver-chain datagrams on SDO_S.

mod drv;
use drv::*;
use tmc429_model::ram::SINE_LUT;
use tmc429_model::regmap::{motor_a7, ram_a7};
use tmc429_model::Chip;

/// Motor 0 sends DAC_A_5..0, PH_A, FD_A, DAC_B_5..0, PH_B, FD_B, Direction, Step (18 bits).
fn full_config(h: &mut tmc429_model::host::Host) {
    let cells: [u32; 18] = [5, 4, 3, 2, 1, 0, 6, 7, 0xD, 0xC, 0xB, 0xA, 9, 8, 0xE, 0xF, 0x12, 0x33];
    for a in 0..9 {
        h.write(ram_a7(a as u8), cells[2 * a + 1] << 8 | cells[2 * a]);
    }
    h.write(GCONF, gconf(0, 7, 0));
}

#[derive(Debug, PartialEq, Eq, Clone, Copy)]
struct Sig {
    sin: u8,
    cos: u8,
    ph_a: bool,
    fd_a: bool,
    ph_b: bool,
    fd_b: bool,
    dir: bool,
    step: bool,
}

fn decode(bits: u64) -> Sig {
    let b = |i: u32| (bits >> i) & 1 != 0;
    Sig {
        sin: ((bits >> 12) & 63) as u8,
        ph_a: b(11),
        fd_a: b(10),
        cos: ((bits >> 4) & 63) as u8,
        ph_b: b(3),
        fd_b: b(2),
        dir: b(1),
        step: b(0),
    }
}

/// One full period of Table 12-4 for a usrs (LUT indices), with Table 12-3 bits per quadrant.
fn table_12_4(usrs: u32) -> Vec<(u8, u8, [bool; 4])> {
    let inc = 64u32 >> usrs.min(6);
    let n = 64 / inc;
    let rising: Vec<u8> = (0..n).map(|k| (k * inc) as u8).collect();
    // 2nd quadrant sin: 63, then 64 − k·inc (the %101 row as corrected, erratum E5).
    let falling: Vec<u8> = std::iter::once(63u8).chain((1..n).map(|k| (64 - k * inc) as u8)).collect();
    // Table 12-3: PH_A, PH_B, FD_A, FD_B.
    let bits = [[true, true, false, true], [true, false, true, false], [false, false, false, true], [false, true, true, false]];
    let mut v = Vec::new();
    for q in 0..4 {
        let (s, c) = if q % 2 == 0 { (&rising, &falling) } else { (&falling, &rising) };
        for k in 0..n as usize {
            v.push((s[k], c[k], bits[q]));
        }
    }
    v
}

fn walk(usrs: u32, negative: bool) {
    let (mut h, log) = host_with_events(Chip::Tmc429);
    load_tables(&mut h);
    full_config(&mut h);
    h.write(motor_a7(0, 12), usrs); // pulse_div 0, ramp_div 0
    h.write(motor_a7(0, 15), 0);
    h.write(motor_a7(0, 10), 3); // HOLD
    let table = table_12_4(usrs);
    let steps = table.len() + 3;
    log.lock().unwrap().clear();
    h.write(motor_a7(0, 5), if negative { (-64i32 as u32) & 0xFFF } else { 64 });
    // 64 → a step every 1024 CLK; an 18-bit datagram takes 21·16 = 336 CLK.
    h.wait(steps as u64 * 1024 + 600);
    let c = chains(&log);
    assert!(c.len() >= steps, "usrs {usrs}: {} datagrams", c.len());
    let len = table.len() as i64;
    for (i, e) in c.iter().take(steps).enumerate() {
        assert_eq!(e.1, 18);
        let p = if negative { -(i as i64 + 1) } else { i as i64 + 1 };
        let (si, ci, q) = table[p.rem_euclid(len) as usize];
        let want = Sig {
            sin: SINE_LUT[si as usize],
            cos: SINE_LUT[ci as usize],
            ph_a: q[0],
            ph_b: q[1],
            fd_a: q[2],
            fd_b: q[3],
            dir: negative,
            step: true,
        };
        assert_eq!(decode(e.2), want, "usrs {usrs} negative {negative} step {}", i + 1);
    }
}

/// Table 12-4 for every usrs, both directions; usrs 7 acts as 6 (C72).
#[test]
fn table_12_4_walks() {
    for usrs in 0..=7 {
        walk(usrs, false);
        walk(usrs, true);
    }
}

/// The %101 row starts its 2nd quadrant with 63, 62, 60, 58 (Table 12-4 corrected, erratum E5).
#[test]
fn usrs5_second_quadrant() {
    let t = table_12_4(5);
    let sins: Vec<u8> = t[32..36].iter().map(|e| e.0).collect();
    assert_eq!(sins, vec![63, 62, 60, 58]);
}

/// §12.1: a usrs change keeps the index offset: after 1 step at usrs 6 (w = 1), full steps
/// walk 1, 65, 129, … (C73).
#[test]
fn usrs_change_keeps_offset() {
    let (mut h, log) = host_with_events(Chip::Tmc429);
    load_tables(&mut h);
    full_config(&mut h);
    h.write(motor_a7(0, 15), 1);
    h.write(motor_a7(0, 12), 0);
    h.write(motor_a7(0, 10), 3);
    log.lock().unwrap().clear();
    h.write(motor_a7(0, 5), 64);
    h.wait(2 * 1024 + 600);
    let c = chains(&log);
    // w = 65: sin LUT[63], cos LUT[1]; w = 129: sin LUT[1], cos LUT[63].
    assert_eq!((decode(c[0].2).sin, decode(c[0].2).cos), (SINE_LUT[63], SINE_LUT[1]));
    assert_eq!((decode(c[1].2).sin, decode(c[1].2).cos), (SINE_LUT[1], SINE_LUT[63]));
    assert_eq!(h.read(motor_a7(0, 15)), 129);
}

/// The datagram (start cycle, bits) of a request timed to start at edge `target` after
/// power-on, with the current scaling register (IDX 8) written to `is` first. TMC429 power-on
/// RAM, LSMD 0 (One DAC_A5..2 PH_A One DAC_B5..2 PH_B), w = 0: DAC_B = 63, so its bits 5..2
/// show the scale (Table 8-1): %000 → 1111, %111 (7/8: 55) → 1101, %001 (1/8: 7) → 0001.
fn datagram_at_edge(is: u32, target: u64) -> (u64, u64) {
    let (mut h, log) = host_with_events(Chip::Tmc429);
    h.write(GCONF, gconf(0, 7, 0));
    h.write(motor_a7(0, 8), is);
    // Calibrate the delay from a write to the datagram start (start = end − (8 + 12·16 + 8):
    // t_HDSCSdrv, 12 bits, the hold, C82).
    let c0 = h.cycle();
    request(&mut h);
    settle(&mut h, 2000);
    let d = chains(&log)[0].0 - 208 - c0;
    h.wait(target - d - h.cycle());
    request(&mut h);
    settle(&mut h, 2000);
    let e = chains(&log)[1];
    (e.0 - 208, e.2)
}

/// TMC428 §8.9: is_v0 only after 255 ramp ticks at rest (t = 255·32·2^ramp_div CLK). From
/// power-on motor 0's ramp ticks of ramp_div 0 are at phase 16 (C41), edges 32·k + 17 counted
/// from 1: the 255th is edge 8145, so a datagram starting at edge 8146 is the first with is_v0
/// (C75, C77).
#[test]
fn is_v0_after_255_ramp_ticks() {
    // is_agtat = is_aleat = %111 (7/8), is_v0 = %001 (1/8).
    let is = 7 << 20 | 7 << 16 | 1 << 12;
    assert_eq!(datagram_at_edge(is, 8145), (8145, 0x87B));
    assert_eq!(datagram_at_edge(is, 8146), (8146, 0x863));
}

/// TMC429 §8.1.9, footnote *2 of the current scale selection scheme: "For selection of current
/// scaling IS_V0 (at rest) IS_AGTAT and IS_ALEAT must be larger than 0." With either at 0 the
/// motor at rest keeps is_aleat (C75); once both are > 0 the next ramp tick at rest selects is_v0.
#[test]
fn is_v0_needs_is_agtat_and_is_aleat_above_0() {
    // is_agtat 0, is_aleat %111, is_v0 %001: 7/8 (1101) long after the delay.
    assert_eq!(datagram_at_edge(7 << 16 | 1 << 12, 8160), (8160, 0x87B));
    assert_eq!(datagram_at_edge(7 << 16 | 1 << 12, 20_000), (20_000, 0x87B));
    // is_agtat %111, is_aleat 0 (= 100 %, Table 8-1), is_v0 %001: 1111.
    assert_eq!(datagram_at_edge(7 << 20 | 1 << 12, 20_000), (20_000, 0x87F));
    // the power-on values (all 0): is_aleat = %000, full current.
    assert_eq!(datagram_at_edge(0, 20_000), (20_000, 0x87F));
    // is_agtat written > 0 at rest: is_v0 from the next ramp tick (ramp_div 0: 32 CLK); with
    // every motor in HOLD_MODE, where the ramp ticks between µC writes take the model's fast
    // path.
    let (mut h, log) = host_with_events(Chip::Tmc429);
    h.write(GCONF, gconf(0, 7, 0));
    for m in 0..3 {
        h.write(motor_a7(m, 10), 3);
    }
    h.write(motor_a7(0, 8), 7 << 16 | 1 << 12);
    h.wait(10_000);
    h.write(motor_a7(0, 8), 7 << 20 | 7 << 16 | 1 << 12);
    h.wait(64);
    request(&mut h);
    settle(&mut h, 2000);
    assert_eq!(chains(&log).last().unwrap().2, 0x863);
}

/// Table 8-2: |a| > a_threshold → is_agtat, else is_aleat; a_threshold > 1023 → is_aleat.
/// Full steps (usrs 0) put 63 on one coil, so its DAC bits 5..2 show the scale:
/// is_agtat %010 → 15 (0011), is_aleat %110 → 47 (1011).
#[test]
fn agtat_while_accelerating() {
    for (thr, want_agtat) in [(50u32, true), (1024, false)] {
        let (mut h, log) = host_with_events(Chip::Tmc429);
        h.write(motor_a7(0, 8), 2 << 20 | 6 << 16 | thr);
        h.write(motor_a7(0, 12), 0); // usrs 0
        h.write(motor_a7(0, 6), 100); // a_max
        h.write(motor_a7(0, 3), 2047);
        h.write(motor_a7(0, 10), 2); // VELOCITY
        log.lock().unwrap().clear();
        h.write(motor_a7(0, 4), 300); // v_target: 768 ramp ticks of acceleration
        h.wait(40_000);
        assert_eq!(h.read(motor_a7(0, 7)), 0, "cruising");
        let nibbles: Vec<u64> = chains(&log)
            .iter()
            .map(|e| {
                let a = (e.2 >> 7) & 15;
                let b = (e.2 >> 1) & 15;
                a.max(b)
            })
            .collect();
        let first_aleat = nibbles.iter().position(|&n| n == 0b1011).expect("is_aleat at cruise");
        assert!(nibbles[first_aleat..].iter().all(|&n| n == 0b1011));
        if want_agtat {
            assert!(first_aleat > 20, "{nibbles:?}");
            assert!(nibbles[..first_aleat].iter().all(|&n| n == 0b0011), "{nibbles:?}");
        } else {
            assert_eq!(first_aleat, 0);
        }
    }
}
