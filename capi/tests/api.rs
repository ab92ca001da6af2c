//! The C ABI called as C calls it, asserting the datasheet's values: the TMC428 §6.5 datagram
//! examples (replies with the INT-corrected status $15, contract erratum E1), type_version $429101,
//! the 8-bit status read, frame timing, INT, driver-chain and step events in `tmc429 spi --events`
//! form, and every misuse (null, lengths 0 and 5, bad arguments, destroyed handle) returning its
//! error code.
//! The calls are `unsafe` as every call through raw pointers is; the pointers here are valid.

use std::ptr::{null, null_mut};

use tmc429::*;

fn create(variant: i32, fclk: u32) -> u64 {
    unsafe {
        let mut h = 0u64;
        assert_eq!(tmc429_create(variant, fclk, &mut h), TMC429_OK);
        assert_ne!(h, 0);
        h
    }
}

fn xfer(h: u64, tx: &[u8]) -> Vec<u8> {
    unsafe {
        let mut rx = vec![0u8; tx.len()];
        assert_eq!(tmc429_spi_transfer(h, tx.as_ptr(), rx.as_mut_ptr(), tx.len()), TMC429_OK);
        rx
    }
}

fn dg(h: u64, d: u32) -> u32 {
    u32::from_be_bytes(xfer(h, &d.to_be_bytes()).try_into().unwrap())
}

fn cycle(h: u64) -> u64 {
    unsafe {
        let mut c = 0;
        assert_eq!(tmc429_get_cycle(h, &mut c), TMC429_OK);
        c
    }
}

fn drain(h: u64) -> Vec<String> {
    let mut buf = [tmc429_event_t::default(); 8];
    let n = unsafe { tmc429_events_drain(h, buf.as_mut_ptr(), buf.len()) };
    assert!(n >= 0);
    buf[..n as usize].iter().map(format_event).collect()
}

#[test]
fn datasheet_6_5_datagram_examples() {
    unsafe {
        let h = create(TMC429_CHIP_TMC429, 0);
        // Write $000123 to dx_ref_tolerance of motor 1 (A7 %0001101): reply status + 24 zeros.
        assert_eq!(dg(h, 0x1A00_0123), 0x1500_0000);
        assert_eq!(dg(h, 0x1B00_0000), 0x1500_0123);
        // RAM write %100001, %100011 to ADDR 63, read back.
        assert_eq!(dg(h, 0xFE00_2321), 0x1500_0000);
        assert_eq!(dg(h, 0xFF00_0000), 0x1500_2321);
        // type_version (JDX 9, TMC429 §8.2.4.4).
        assert_eq!(dg(h, 0x7300_0000), 0x1542_9101);
        // Status-only 8-bit read.
        assert_eq!(xfer(h, &[0x00]), vec![0x15]);
        // rx may alias tx.
        let mut b = [0x1Bu8, 0, 0, 0];
        assert_eq!(tmc429_spi_transfer(h, b.as_ptr(), b.as_mut_ptr(), 4), TMC429_OK);
        assert_eq!(b, [0x15, 0x00, 0x01, 0x23]);
        assert_eq!(tmc429_destroy(h), TMC429_OK);
    }
}

#[test]
fn frame_timing_and_sck_rate() {
    unsafe {
        let h = create(TMC429_CHIP_TMC429, 32_000_000);
        let mut half = 0;
        assert_eq!(tmc429_get_sck_half(h, &mut half), TMC429_OK);
        assert_eq!(half, 4);
        // (2 + 16·len) half periods per frame.
        dg(h, 0x7300_0000);
        assert_eq!(cycle(h), 66 * 4);
        xfer(h, &[0]);
        assert_eq!(cycle(h), 66 * 4 + 18 * 4);
        // ceil(32 MHz / (2·hz)).
        for (hz, want) in [(4_000_000, 4), (5_000_000, 4), (5_333_334, 3), (5_333_333, 4), (4_000_001, 4), (1_000_000, 16)] {
            assert_eq!(tmc429_set_sck_hz(h, hz), TMC429_OK);
            assert_eq!(tmc429_get_sck_half(h, &mut half), TMC429_OK);
            assert_eq!(half, want, "{hz} Hz");
        }
        assert_eq!(tmc429_set_sck_hz(h, 5_333_335), TMC429_ERR_ARG, "above fclk/6");
        assert_eq!(tmc429_set_sck_hz(h, 0), TMC429_ERR_ARG);
        assert_eq!(tmc429_set_sck_half(h, 2), TMC429_ERR_ARG);
        assert_eq!(tmc429_set_sck_half(h, 3), TMC429_OK);
        let c0 = cycle(h);
        assert_eq!(dg(h, 0x7300_0000), 0x1542_9101, "works at the fastest SCK");
        assert_eq!(cycle(h) - c0, 66 * 3);
        tmc429_destroy(h);
    }
}

#[test]
fn time_advances_exactly() {
    let h = create(TMC429_CHIP_TMC429, 1_500_001);
    assert_eq!(tmc429_advance_us(h, 1), TMC429_OK);
    assert_eq!(cycle(h), 1);
    assert_eq!(tmc429_advance_us(h, 1), TMC429_OK);
    assert_eq!(cycle(h), 3, "the remainder is carried: floor(2 × 1.500001)");
    assert_eq!(tmc429_advance_cycles(h, 1000), TMC429_OK);
    assert_eq!(cycle(h), 1003);
    assert_eq!(tmc429_reset(h), TMC429_OK);
    assert_eq!(cycle(h), 0);
    tmc429_destroy(h);
    let h = create(TMC429_CHIP_TMC428, 0);
    assert_eq!(tmc429_advance_us(h, 1000), TMC429_OK);
    assert_eq!(cycle(h), 16_000, "TMC428 default fclk 16 MHz");
    tmc429_destroy(h);
}

#[test]
fn int_events_from_a_reference_switch() {
    unsafe {
        let h = create(TMC429_CHIP_TMC429, 0);
        // Motor 1 interrupt mask: INT_STOP_LEFT_HIGH (bit 6 of the mask, TMC428 §8.13).
        dg(h, 0x1600_4000);
        tmc429_advance_cycles(h, 10);
        assert!(drain(h).is_empty());
        let c0 = cycle(h);
        assert_eq!(tmc429_set_pin(h, TMC429_PIN_REF1, 1), TMC429_OK);
        tmc429_advance_cycles(h, 40);
        // Two synchronizer flops, then the switch is in the old state from edge c0 + 3 on; the
        // motion core takes it in motor 1's condition slot, the edge of phase 14 (C52, C63): with
        // no power down the pre-divider before edge k (counted from 1) is k - 1.
        let slot = (c0 + 3..).find(|k| (k - 1) % 32 == 14).unwrap();
        assert_eq!(drain(h), vec![format!("int {slot} 1")]);
        let mut st = 0u8;
        assert_eq!(tmc429_get_status(h, &mut st), TMC429_OK);
        assert_eq!(st, 0x97, "INT, RS1, xEQt1..3");
        assert_eq!(xfer(h, &[0]), vec![0x97]);
        let mut o = tmc429_outputs_t::default();
        assert_eq!(tmc429_get_outputs(h, &mut o), TMC429_OK);
        assert_eq!(o.nint_sdo_c, 0, "nINT low");
        // Driver-chain pins idle as after reset (contract C2, [429] §8.2.4 note: logic high
        // until configured): nSCS_S, SCK_S, SDO_S, nSCS2, nSCS3 high, SDI_S an input (0); as
        // STEP1..3 = SDO_S, nSCS_S, nSCS2 and DIR1..3 = SCK_S, SDI_S, nSCS3.
        let (mut step, mut dir) = (0u8, 0u8);
        assert_eq!(tmc429_get_step_dir(h, &mut step, &mut dir), TMC429_OK);
        assert_eq!((step, dir), (0b111, 0b101));
        // Clear the flag (W1C) with the mask kept: INT falls when the datagram executes.
        dg(h, 0x1600_4040);
        let ev = drain(h);
        assert_eq!(ev.len(), 1);
        assert!(ev[0].starts_with("int ") && ev[0].ends_with(" 0"), "{ev:?}");
        assert_eq!(tmc429_get_status(h, &mut st), TMC429_OK);
        assert_eq!(st, 0x17);
        let mut p = 0usize;
        assert_eq!(tmc429_events_pending(h, &mut p), TMC429_OK);
        assert_eq!(p, 0);
        let mut d = 1u64;
        assert_eq!(tmc429_events_dropped(h, &mut d), TMC429_OK);
        assert_eq!(d, 0);
        // With decoding off nothing is queued (each level held over a condition slot).
        assert_eq!(tmc429_events_enable(h, 0), TMC429_OK);
        tmc429_set_pin(h, TMC429_PIN_REF1, 0);
        tmc429_advance_cycles(h, 40);
        tmc429_set_pin(h, TMC429_PIN_REF1, 1);
        tmc429_advance_cycles(h, 40);
        assert_eq!(tmc429_events_pending(h, &mut p), TMC429_OK);
        assert_eq!(p, 0);
        // On again: the decoder restarts and reports the INT that is high.
        assert_eq!(tmc429_events_enable(h, 1), TMC429_OK);
        tmc429_advance_cycles(h, 1);
        assert_eq!(drain(h), vec![format!("int {} 1", cycle(h))]);
        tmc429_destroy(h);
    }
}

#[test]
fn ramp_move_reaches_target_and_probes_agree() {
    unsafe {
        let h = create(TMC429_CHIP_TMC429, 0);
        // Motor 1: v_min 1, v_max 1000, pulse_div 3 / ramp_div 7, a_max 100 with pmul/pdiv from
        // the datasheet's method (p_mul 189, p_div 9), RAMP_MODE, x_target 2000.
        let pm = tmc429_model::pmulpdiv::calc(100, 7, 3, 0.05);
        assert_eq!(pm.register_value(), Some(0xBD09));
        dg(h, 0x0400_0001);
        dg(h, 0x0600_03E8);
        dg(h, 0x1800_3700);
        dg(h, 0x0C00_0064);
        dg(h, 0x1200_BD09);
        dg(h, 0x1400_0000);
        dg(h, 0x0000_07D0);
        let mut reached = false;
        for _ in 0..1000 {
            tmc429_advance_us(h, 1000);
            if xfer(h, &[0])[0] & 1 == 1 {
                reached = true;
                break;
            }
        }
        assert!(reached);
        let mut p = tmc429_motor_probe_t::default();
        assert_eq!(tmc429_get_motor_probe(h, 0, &mut p), TMC429_OK);
        assert_eq!((p.x_actual, p.x_target, p.v_actual), (2000, 2000, 0));
        assert_eq!(dg(h, 0x0300_0000) & 0xFF_FFFF, 2000);
        assert_eq!(tmc429_get_motor_probe(h, 2, &mut p), TMC429_OK);
        assert_eq!(tmc429_get_motor_probe(h, 3, &mut p), TMC429_ERR_ARG);
        tmc429_destroy(h);
        let h = create(TMC429_CHIP_TMC4210, 0);
        assert_eq!(tmc429_get_motor_probe(h, 0, &mut p), TMC429_OK);
        assert_eq!(tmc429_get_motor_probe(h, 1, &mut p), TMC429_ERR_ARG);
        tmc429_destroy(h);
    }
}

/// Null pointers, lengths 0, 5 and SIZE_MAX and out-of-range arguments return their codes,
/// and no failed call advances the chip's time.
#[test]
fn misuse_returns_errors() {
    unsafe {
        let mut h = 0u64;
        assert_eq!(tmc429_create(1, 0, null_mut()), TMC429_ERR_NULL);
        assert_eq!(tmc429_create(3, 0, &mut h), TMC429_ERR_ARG);
        assert_eq!(tmc429_create(-1, 0, &mut h), TMC429_ERR_ARG);
        assert_eq!(tmc429_create(TMC429_CHIP_TMC428, 16_000_001, &mut h), TMC429_ERR_ARG);
        assert_eq!(tmc429_create(TMC429_CHIP_TMC429, 32_000_001, &mut h), TMC429_ERR_ARG);
        let h = create(TMC429_CHIP_TMC429, 0);
        let tx = [0u8; 5];
        let mut rx = [0u8; 5];
        assert_eq!(tmc429_spi_transfer(h, null(), rx.as_mut_ptr(), 4), TMC429_ERR_NULL);
        assert_eq!(tmc429_spi_transfer(h, tx.as_ptr(), null_mut(), 4), TMC429_ERR_NULL);
        assert_eq!(tmc429_spi_transfer(h, tx.as_ptr(), rx.as_mut_ptr(), 0), TMC429_ERR_LENGTH);
        assert_eq!(tmc429_spi_transfer(h, tx.as_ptr(), rx.as_mut_ptr(), 5), TMC429_ERR_LENGTH);
        assert_eq!(tmc429_spi_transfer(h, tx.as_ptr(), rx.as_mut_ptr(), usize::MAX), TMC429_ERR_LENGTH);
        assert_eq!(tmc429_get_cycle(h, null_mut()), TMC429_ERR_NULL);
        assert_eq!(cycle(h), 0, "no failed call advanced time");
        assert_eq!(tmc429_set_pin(h, 7, 1), TMC429_ERR_ARG);
        assert_eq!(tmc429_set_pin(h, -1, 1), TMC429_ERR_ARG);
        assert_eq!(tmc429_set_pin(h, TMC429_PIN_REF1, 2), TMC429_ERR_ARG);
        assert_eq!(tmc429_events_enable(h, 2), TMC429_ERR_ARG);
        let mut ev = [tmc429_event_t::default(); 1];
        assert_eq!(tmc429_events_drain(h, null_mut(), 1), TMC429_ERR_NULL);
        assert_eq!(tmc429_events_drain(h, ev.as_mut_ptr(), 0), TMC429_ERR_LENGTH);
        assert_eq!(tmc429_destroy(h), TMC429_OK);
    }
}

/// `tmc429_event_format`: the line and its NUL must fit, null pointers, an unknown kind and a
/// chain event longer than 64 bits return their codes; a chain event's line.
#[test]
fn event_format_checks_its_arguments() {
    unsafe {
        let mut s = [0 as std::ffi::c_char; 64];
        let e = tmc429_event_t { kind: TMC429_EVENT_INT, cycle: 7, level: 1, ..Default::default() };
        assert_eq!(tmc429_event_format(&e, s.as_mut_ptr(), 8), 7, "\"int 7 1\" and NUL fit in 8");
        assert_eq!(tmc429_event_format(&e, s.as_mut_ptr(), 7), TMC429_ERR_LENGTH);
        assert_eq!(tmc429_event_format(&e, s.as_mut_ptr(), 0), TMC429_ERR_LENGTH);
        assert_eq!(tmc429_event_format(null(), s.as_mut_ptr(), 64), TMC429_ERR_NULL);
        assert_eq!(tmc429_event_format(&e, null_mut(), 64), TMC429_ERR_NULL);
        let bad = tmc429_event_t { kind: 3, ..Default::default() };
        assert_eq!(tmc429_event_format(&bad, s.as_mut_ptr(), 64), TMC429_ERR_ARG);
        let huge = tmc429_event_t { kind: TMC429_EVENT_CHAIN, nbits: u32::MAX, ..Default::default() };
        assert_eq!(tmc429_event_format(&huge, s.as_mut_ptr(), 64), TMC429_ERR_LENGTH);
        let chain = tmc429_event_t { kind: TMC429_EVENT_CHAIN, cycle: 4567, nbits: 36, bits: 0x8_7F87_F87F, ..Default::default() };
        let n = tmc429_event_format(&chain, s.as_mut_ptr(), 64);
        let line: String = s[..n as usize].iter().map(|&c| c as u8 as char).collect();
        assert_eq!(line, "chain 4567 36 87F87F87F");
    }
}

/// A destroyed handle, a never-created one and 0 return TMC429_ERR_HANDLE from every call
/// that takes one; a new chip never gets the old number.
#[test]
fn stale_and_invalid_handles_are_refused() {
    unsafe {
        let h = create(TMC429_CHIP_TMC429, 0);
        assert_eq!(tmc429_destroy(h), TMC429_OK);
        let tx = [0u8; 5];
        let mut rx = [0u8; 5];
        let mut ev = [tmc429_event_t::default(); 1];
        for bad in [h, 0, u64::MAX] {
            let mut u = 0u8;
            let mut c = 0u64;
            assert_eq!(tmc429_destroy(bad), TMC429_ERR_HANDLE);
            assert_eq!(tmc429_reset(bad), TMC429_ERR_HANDLE);
            assert_eq!(tmc429_spi_transfer(bad, tx.as_ptr(), rx.as_mut_ptr(), 4), TMC429_ERR_HANDLE);
            assert_eq!(tmc429_advance_cycles(bad, 1), TMC429_ERR_HANDLE);
            assert_eq!(tmc429_advance_us(bad, 1), TMC429_ERR_HANDLE);
            assert_eq!(tmc429_get_cycle(bad, &mut c), TMC429_ERR_HANDLE);
            assert_eq!(tmc429_set_pin(bad, 0, 1), TMC429_ERR_HANDLE);
            assert_eq!(tmc429_get_status(bad, &mut u), TMC429_ERR_HANDLE);
            assert_eq!(tmc429_set_sck_half(bad, 4), TMC429_ERR_HANDLE);
            assert_eq!(tmc429_events_drain(bad, ev.as_mut_ptr(), 1), TMC429_ERR_HANDLE);
        }
        let h2 = create(TMC429_CHIP_TMC429, 0);
        assert_ne!(h2, h);
        tmc429_destroy(h2);
        let msg = std::ffi::CStr::from_ptr(tmc429_strerror(TMC429_ERR_HANDLE));
        assert_eq!(msg.to_str().unwrap(), "invalid handle (zero, never created or destroyed)");
        assert_eq!(tmc429_abi_version(), TMC429_ABI_VERSION);
    }
}

#[test]
fn handles_work_from_several_threads() {
    let hs: Vec<u64> = (0..4).map(|_| create(TMC429_CHIP_TMC429, 0)).collect();
    let threads: Vec<_> = hs.iter().map(|&h| std::thread::spawn(move || (0..20).all(|_| dg(h, 0x7300_0000) == 0x1542_9101))).collect();
    for t in threads {
        assert!(t.join().unwrap());
    }
    for h in hs {
        assert_eq!(tmc429_destroy(h), TMC429_OK);
    }
}

/// Every event waiting, drained in chunks of 64 (oldest first).
fn drain_all(h: u64) -> Vec<tmc429_event_t> {
    let mut all = Vec::new();
    loop {
        let mut buf = [tmc429_event_t::default(); 64];
        let n = unsafe { tmc429_events_drain(h, buf.as_mut_ptr(), buf.len()) };
        assert!(n >= 0);
        all.extend_from_slice(&buf[..n as usize]);
        if (n as usize) < buf.len() {
            return all;
        }
    }
}

/// Driver-chain datagrams through the C queue: continuous update with the TMC429's power-on
/// chain configuration sends the 36-bit datagram $87F87F87F (TMC429 §11.4.2 configuration, §11.5 LUT); the requests of
/// the three motors come 341 ramp ticks apart (C83: reset offsets 0, 341, 682 of a 1024-tick
/// counter: motor 2 first, then 1, then 0), each motor's ramp phase 7 before the last one's (C41):
/// 341 · 32 − 7 = 10905 CLK at ramp_div 0.
#[test]
fn chain_events_through_the_queue() {
    let h = create(TMC429_CHIP_TMC429, 0);
    // $7E: cont_update = 1, clk2_div = 15, LSMD = 2 (three motors)
    dg(h, 0x7E01_0F02);
    tmc429_advance_cycles(h, 40_000);
    let ev = drain_all(h);
    assert!(ev.len() >= 3, "{} events", ev.len());
    for e in &ev {
        assert_eq!(e.kind, TMC429_EVENT_CHAIN);
        assert_eq!((e.nbits, e.bits), (36, 0x8_7F87_F87F));
    }
    assert_eq!(ev[1].cycle - ev[0].cycle, 10905);
    assert_eq!(ev[2].cycle - ev[1].cycle, 10905);
    let line = format_event(&ev[0]);
    assert_eq!(line, format!("chain {} 36 87F87F87F", ev[0].cycle));
    tmc429_destroy(h);
}

/// Step events through the C queue: in Step/Dir mode (if_configuration en_sd, TMC429 §8.2.4) a
/// RAMP_MODE move of motor 0 from 0 to 25 and back to 0 gives exactly 25 positive then 25
/// negative step events of motor 0 (one pulse per step, C93–C95), and none of the other motors.
#[test]
fn step_events_through_the_queue() {
    unsafe {
        let h = create(TMC429_CHIP_TMC429, 0);
        dg(h, 0x6800_0020); // en_sd
        dg(h, 0x0400_0001); // v_min 1
        dg(h, 0x0600_0064); // v_max 100
        dg(h, 0x1800_3700); // pulse_div 3, ramp_div 7
        dg(h, 0x0C00_0064); // a_max 100
        dg(h, 0x1200_BD09); // p_mul 189, p_div 9
        dg(h, 0x1400_0000); // RAMP_MODE
        drain_all(h);
        let mut steps = Vec::new();
        for target in [25u32, 0] {
            dg(h, target & 0xFF_FFFF);
            let mut reached = false;
            for _ in 0..2000 {
                tmc429_advance_us(h, 1000);
                let mut p = tmc429_motor_probe_t::default();
                assert_eq!(tmc429_get_motor_probe(h, 0, &mut p), TMC429_OK);
                if p.x_actual == target as i32 && p.v_internal == 0 {
                    reached = true;
                    break;
                }
            }
            assert!(reached, "motor 0 did not reach {target}");
            // the last pulse ends: t_STEP = 16 (1 + STPDIV) = 256 CLK (clk2_div 15, C93)
            tmc429_advance_cycles(h, 1000);
            steps.extend(drain_all(h).into_iter().filter(|e| e.kind == TMC429_EVENT_STEP));
        }
        assert_eq!(steps.len(), 50);
        assert!(steps.iter().all(|e| e.motor == 0));
        assert!(steps[..25].iter().all(|e| e.negative == 0));
        assert!(steps[25..].iter().all(|e| e.negative == 1));
        assert!(steps.windows(2).all(|w| w[0].cycle < w[1].cycle));
        assert_eq!(format_event(&steps[0]), format!("step {} 0 +", steps[0].cycle));
        tmc429_destroy(h);
    }
}

fn format_event(e: &tmc429_event_t) -> String {
    let mut s = [0 as std::ffi::c_char; 64];
    let len = unsafe { tmc429_event_format(e, s.as_mut_ptr(), s.len()) };
    assert!(len > 0);
    s[..len as usize].iter().map(|&c| c as u8 as char).collect()
}
