//! Driver-chain SPI master at pin level, its timing: the SCK_S period, the datagram length
//! limits, the datagram rate when busy, the continuous-update rate and a datagram without end
//! (TMC428 §6.3, Table 6-2; TMC429 §8.2.5, Table 11.2; contract C81–C84). Datagrams are decoded
//! from nSCS_S / SCK_S / SDO_S by the EventDecoder.

mod drv;
use drv::*;
use tmc429_model::regmap::{f, motor_a7, ram_a7};
use tmc429_model::Chip;

/// TMC428 §9.7 / Table 6-2, C81: SCK_S period 2·(clk2_div+1), low half clk2_div+1; below 7
/// the period stays 16 CLK with the low half clk2_div+1.
#[test]
fn sck_period() {
    for c in [0u32, 3, 6, 7, 8, 15, 100, 255] {
        let (mut h, trace) = host_with_trace(Chip::Tmc429);
        load_tables(&mut h);
        h.write(GCONF, gconf(2, c, 0));
        trace.lock().unwrap().clear();
        request(&mut h);
        h.wait(45 * 2 * 256);
        let t = trace.lock().unwrap();
        let lows = pulses(&t, |o| !o.sck_s);
        assert_eq!(lows.len(), 36, "clk2_div {c}");
        let lo = c as u64 + 1;
        let period = (2 * lo).max(16);
        assert!(lows.iter().all(|&(_, l)| l == lo), "clk2_div {c}: low half");
        // Within a motor's 12 bits the falling edges are one period apart.
        for w in lows[..12].windows(2) {
            assert_eq!(w[1].0 - w[0].0, period, "clk2_div {c}");
        }
        // NxM processing: 1 period (clk2_div ≤ 7) or 1.5 periods (> 7) without a clock.
        let nxm = lows[12].0 - lows[11].0 - period;
        assert_eq!(nxm, if c <= 7 { period } else { 3 * lo }, "clk2_div {c}");
    }
}

/// [429] Table 11.2 ([428] Table 6-2): t_HDSCSdrv, from nSCS_S falling to the first falling
/// SCK_S edge, is 8 / 16 / 256 CLK (min / typ / max: clk2_div 7 / 15 / 255), and so is the hold
/// after the last bit's period; the datagram lasts 8+8+1·16+8+8 = 48 CLK (one bit, clk2_div 7)
/// and 512 + 64·512 + 512 = 33792 CLK (64 bits, clk2_div 255), measured here as the period of
/// back-to-back datagrams (chip select inactive t_SUSCSdrv after one and before the next, C82).
#[test]
fn datagram_length_limits() {
    // (clk2_div, bits, t_HDSCSdrv, datagram length)
    for (c, n, hd, len) in [(7u32, 1u8, 8u64, 48u64), (15, 1, 16, 96), (255, 64, 256, 33792)] {
        let (mut h, trace) = host_with_trace(Chip::Tmc428);
        for a in 0..32u8 {
            // cells 2a, 2a+1: Zero, One; NxM on the cell of the last bit (n - 1)
            let nxm = |cell: u8| if cell == n - 1 { 0x20 } else { 0 };
            h.write(ram_a7(a), (0x11 | nxm(2 * a + 1)) << 8 | (0x10 | nxm(2 * a)));
        }
        h.write(GCONF, gconf(0, c, 0));
        // HOLD mode at v = 2047: a step every 32 CLK keeps a datagram requested.
        h.write(motor_a7(0, 10), 3);
        trace.lock().unwrap().clear();
        h.write(motor_a7(0, 5), 2047);
        h.wait(4 * len + 200);
        let t = trace.lock().unwrap();
        let cs = pulses(&t, |o| !o.nscs_s);
        assert!(cs.len() >= 3, "clk2_div {c}");
        let sck_falls: Vec<u64> = t.windows(2).filter(|w| w[0].1.sck_s && !w[1].1.sck_s).map(|w| w[1].0).collect();
        let sck_rises: Vec<u64> = t.windows(2).filter(|w| !w[0].1.sck_s && w[1].1.sck_s).map(|w| w[1].0).collect();
        for &(start, active) in &cs[..cs.len() - 1] {
            let first_fall = sck_falls.iter().find(|&&f| f > start).unwrap();
            assert_eq!(first_fall - start, hd, "clk2_div {c}: t_HDSCSdrv");
            let end = start + active;
            let last_rise = sck_rises.iter().rev().find(|&&r| r < end).unwrap();
            let hi = c as u64 + 1;
            assert_eq!(end - last_rise, hi + hd, "clk2_div {c}: last bit's high half, then the hold");
            assert_eq!(active, (n as u64 + 1) * 2 * hi, "clk2_div {c}: chip select active");
        }
        for w in cs.windows(2) {
            assert_eq!(w[1].0 - w[0].0, len, "clk2_div {c}: datagram length");
        }
    }
}

/// [429] §8.2.5.3: NxM processing takes 1 SCK_S period at clk2_div 7 and 1.5 above; back-to-back
/// datagrams of the 3×12 chain repeat every 36 + 2 + 2 = 40 periods at clk2_div 7 and every
/// 36 + 2 + 3 = 41 at clk2_div 15: the Table 11.2 frame (C82) with the two NxM gaps between
/// the drivers. (The section's f_SCK/41 at clk2_div 7 counts a period for the last driver's
/// NxM too, one more than the table's one-bit sum leaves room for; the contract takes the table.)
#[test]
fn datagram_rate_when_busy() {
    for (c, periods_x2) in [(7u32, 80u64), (15, 82)] {
        let (mut h, log) = host_with_events(Chip::Tmc429);
        load_tables(&mut h);
        h.write(GCONF, gconf(2, c, 0));
        h.write(motor_a7(0, 10), 3); // HOLD
        h.write(motor_a7(0, 5), 2047); // a step every ~32 CLK keeps a request pending
        h.wait(20_000);
        let cy: Vec<u64> = chains(&log).iter().map(|e| e.0).collect();
        assert!(cy.len() > 10);
        for w in cy[2..].windows(2) {
            assert_eq!(w[1] - w[0], periods_x2 * (c as u64 + 1), "clk2_div {c}");
        }
    }
}

/// TMC428 §9.7: f_cupd = fCLK·Σ 2^−ramp_div / 32768 (C83).
#[test]
fn continuous_update_rate() {
    for (rd, window, want) in [([0u32, 0, 0], 1u64 << 20, 96usize), ([0, 3, 5], 1 << 20, 37), ([7, 7, 7], 1 << 23, 6)] {
        let (mut h, log) = host_with_events(Chip::Tmc429);
        h.write(GCONF, gconf(0, 7, f::CONT_UPDATE.put(1)));
        for m in 0..3u8 {
            h.write(motor_a7(m, 12), rd[m as usize] << 8);
        }
        let t0 = h.cycle() + (1 << 23);
        h.wait(t0 - h.cycle());
        log.lock().unwrap().clear();
        h.wait(window);
        assert_eq!(chains(&log).len(), want, "ramp_div {rd:?}");
    }
}

/// Bad configuration: no NxM bit anywhere — endless transmission (TMC428 §11), never a panic;
/// writing an NxM bit ends it (the RAM is read while sending, C84).
#[test]
fn no_nxm_sends_endlessly() {
    let (mut h, log) = host_with_events(Chip::Tmc428);
    h.write(GCONF, gconf(0, 7, 0));
    request(&mut h);
    h.wait(100_000);
    assert!(chains(&log).is_empty());
    assert!(!h.outputs().nscs_s, "chip select still active");
    assert_ne!(h.status() & 0x40, 0, "cover still being sent");
    h.write(ram_a7(5), 0x20 << 8); // cell 11: NxM
    h.wait(2_000);
    let c = chains(&log);
    assert_eq!(c.len(), 1);
    assert_eq!(h.status() & 0x40, 0);
}
