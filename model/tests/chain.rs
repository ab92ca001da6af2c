//! Driver-chain SPI master at pin level (TMC428 §6.3, §9.1–§9.7, §11, Table 11-2;
//! contract C80–C89). Datagrams are decoded from nSCS_S / SCK_S / SDO_S by the EventDecoder.

mod common;
mod drv;
use common::replay_skip_quiet;
use drv::*;
use tmc429_model::regmap::{f, global_a7, motor_a7, ram_a7};
use tmc429_model::Chip;

fn datagram_at(w: [u8; 3], iscale: Option<u32>) -> (u32, u64) {
    let (mut h, log) = host_with_events(Chip::Tmc429);
    load_tables(&mut h);
    for m in 0..3u8 {
        set_ustep(&mut h, m, w[m as usize]);
        if let Some(s) = iscale {
            h.write(motor_a7(m, 8), s << 20 | s << 16 | s << 12);
        }
    }
    let before = chains(&log).len();
    request(&mut h);
    settle(&mut h, 10_000);
    let c = chains(&log);
    assert_eq!(c.len(), before + 1, "exactly one datagram per request");
    let (_, n, bits) = c[c.len() - 1];
    (n, bits)
}

/// TMC428 Table 11-2 configuration, Table 12-2 LUT, LSMD 2: the datagrams C71–C76 and C84 give.
#[test]
fn table_11_2_datagrams_bit_for_bit() {
    let cases: [([u8; 3], u64); 9] = [
        ([0, 0, 0], 0x05F05F07F),
        ([1, 1, 1], 0x05F05F07F),
        ([16, 16, 16], 0x35D35D37D),
        ([32, 0, 0], 0x5D705F07F),
        ([64, 64, 64], 0x7C07C0FC0),
        ([100, 0, 0], 0x55805F07F),
        ([128, 0, 0], 0x01E05F07F),
        ([200, 0, 0], 0x78705F07F),
        ([255, 0, 0], 0x01F05F07F),
    ];
    for (w, want) in cases {
        assert_eq!(datagram_at(w, None), (36, want), "w = {w:?}");
    }
    // i_scale %100 on every factor (Table 8-1: 50 %).
    assert_eq!(datagram_at([16, 16, 16], Some(4)), (36, 0x1CF1CF1EF));
}

/// TMC429 §11.4.2: the power-on RAM (One at MDA/MDB), LSMD 2, w = 0.
#[test]
fn tmc429_power_on_configuration() {
    let (mut h, log) = host_with_events(Chip::Tmc429);
    h.write(GCONF, gconf(2, 15, 0));
    request(&mut h);
    settle(&mut h, 10_000);
    assert_eq!(chains(&log), vec![(chains(&log)[0].0, 36, 0x87F87F87F)]);
}

fn covered(pos: u32, len: u32, data: u32) -> u64 {
    let (mut h, log) = host_with_events(Chip::Tmc429);
    load_tables(&mut h);
    h.write(COVER_POS_LEN, pos << 8 | len);
    h.write(COVER_DATAGRAM, data);
    settle(&mut h, 10_000);
    let c = chains(&log);
    assert_eq!(c.len(), 1);
    assert_eq!(c[0].1, 36);
    c[0].2
}

/// TMC428 §9.2–§9.3: a cover datagram on the Table 11-2 configuration; C85: cover_len > 24 acts as 24, positions past the end
/// are dropped.
#[test]
fn cover_datagram() {
    assert_eq!(covered(0, 12, 0xABC), 0xABC05F07F);
    // cover_len 0 sends the unchanged datagram (TMC428 §9.3).
    assert_eq!(covered(0, 0, 0xFFFFFF), 0x05F05F07F);
    // cover_len 31 → 24 bits at positions 4..27 (first bit sent = position 0 = bit 35).
    assert_eq!(covered(4, 31, 0xFFFFFF), 0x0FFFFFF7F);
    // positions 30..41 requested, only 30..35 exist: the 6 MSBs of the cover datagram.
    assert_eq!(covered(30, 12, 0xA80), 0x05F05F06A);
}

/// C29 read back; C88: cw set until the covered datagram is sent.
#[test]
fn cover_readback_and_cw() {
    let (mut h, log) = host_with_events(Chip::Tmc429);
    load_tables(&mut h);
    h.write(COVER_POS_LEN, 5 << 8 | 3);
    assert_eq!(h.read(COVER_POS_LEN), 6 << 8 | 3);
    h.write(COVER_DATAGRAM, 5);
    // The datagram starts within a few CLK of the write and takes 656 CLK at clk2_div 7.
    assert_eq!(h.read(COVER_POS_LEN) >> 23, 1);
    assert_ne!(h.status() & 0x40, 0);
    settle(&mut h, 10_000);
    assert_eq!(chains(&log).len(), 1);
    assert_eq!(h.read(COVER_POS_LEN), 6 << 8 | 3);
    assert_eq!(h.status() & 0x40, 0);
}

/// TMC428 §9.1: the 48-bit readback holds what SDI_S returned; C88: CDGW
/// stays set after a datagram_low_word write until a datagram completes.
#[test]
fn readback_and_cdgw() {
    let (mut h, log) = host_with_events(Chip::Tmc429);
    load_tables(&mut h);
    h.write(global_a7(0), 0);
    h.wait(5000);
    assert_eq!(chains(&log).len(), 0);
    assert_ne!(h.status() & 0x40, 0, "CDGW armed by the datagram_low_word write");
    let (s1, s2, s3) = (0xA5Cu64, 0x3C1u64, 0x7E2u64);
    request(&mut h);
    run_board(&mut h, 2000, [false; 3], [false; 3], s1 << 24 | s2 << 12 | s3, 36);
    assert_eq!(chains(&log).len(), 1);
    assert_eq!(h.status() & 0x40, 0, "CDGW clear after the datagram");
    assert_eq!(h.read(global_a7(1)), s1 as u32);
    assert_eq!(h.read(global_a7(0)), (s2 << 12 | s3) as u32);
    // A second datagram shifts 36 more bits: the high word keeps the last 48 bits.
    request(&mut h);
    run_board(&mut h, 2000, [false; 3], [false; 3], 0xFFF_000_FFF, 36);
    assert_eq!(h.read(global_a7(1)), (s3 << 12 | 0xFFF) as u32);
    assert_eq!(h.read(global_a7(0)), 0x000FFF);
    // [429] §8.2.1, [428] §9.1: "A write to one of these read-only registers initializes them,
    // to update their contents with the next datagram received" (C87): both words read 0, and
    // a 36-bit datagram then leaves the 12 bits above it at 0.
    h.write(global_a7(1), 0xFFFFFF);
    assert_eq!((h.read(global_a7(1)), h.read(global_a7(0))), (0, 0));
    assert_ne!(h.status() & 0x40, 0, "CDGW armed");
    request(&mut h);
    run_board(&mut h, 2000, [false; 3], [false; 3], 0xABC_DEF_123, 36);
    assert_eq!(h.status() & 0x40, 0);
    assert_eq!((h.read(global_a7(1)), h.read(global_a7(0))), (0x000ABC, 0xDEF123));
}

/// C88: CDGW is set while a datagram is under way after the write and clears at its end.
#[test]
fn cdgw_during_datagram() {
    let (mut h, log) = host_with_events(Chip::Tmc429);
    load_tables(&mut h);
    h.write(global_a7(1), 0);
    request(&mut h);
    let mut seen = Vec::new();
    for _ in 0..20 {
        let c0 = h.cycle();
        let st = h.status();
        seen.push((c0, st & 0x40 != 0));
    }
    let end = chains(&log)[0].0;
    // The status byte is taken 2–3 edges after nSCS_C is applied low (C4, C10).
    let mut both = [false; 2];
    for (c, cdgw) in seen {
        if c + 3 < end || c > end {
            assert_eq!(cdgw, c < end, "status frame from cycle {c}, datagram ended at {end}");
            both[cdgw as usize] = true;
        }
    }
    assert_eq!(both, [true, true]);
}

/// C86: LSMD 3 acts as 2; C74: codes $14–$1F read 1, $10 = 0, $11 = 1.
#[test]
fn lsmd3_and_unused_codes() {
    assert_eq!(
        {
            let (mut h, log) = host_with_events(Chip::Tmc429);
            load_tables(&mut h);
            h.write(GCONF, gconf(3, 7, 0));
            request(&mut h);
            settle(&mut h, 10_000);
            chains(&log)
        }
        .iter()
        .map(|e| (e.1, e.2))
        .collect::<Vec<_>>(),
        vec![(36, 0x05F05F07F)]
    );
    let (mut h, log) = host_with_events(Chip::Tmc428);
    // Cells 0..13: $10 $11 $14 … $1F, the last with NxM.
    let codes: Vec<u8> = [0x10u8, 0x11].into_iter().chain(0x14..=0x1F).collect();
    for (a, pair) in codes.chunks(2).enumerate() {
        let odd = if a == codes.len() / 2 - 1 { pair[1] | 0x20 } else { pair[1] };
        h.write(ram_a7(a as u8), (odd as u32) << 8 | pair[0] as u32);
    }
    h.write(GCONF, gconf(0, 7, 0));
    request(&mut h);
    settle(&mut h, 10_000);
    assert_eq!(chains(&log).iter().map(|e| (e.1, e.2)).collect::<Vec<_>>(), vec![(14, 0x1FFF)]);
}

/// [429] §8.2.4 note: "After power-on, the TMC429 is in SPI mode. The output signals are logic
/// high until they become configured for step/direction mode"; Fig. 11.1 draws SDO_S high
/// before the first falling SCK_S edge and back high when nSCS_S rises (C2, C81).
#[test]
fn driver_outputs_high_until_configured_and_between_datagrams() {
    for chip in [Chip::Tmc428, Chip::Tmc429] {
        let c = tmc429_model::Tmc429::new(chip);
        let o = c.outputs();
        assert!(o.sdo_s && o.sck_s && o.nscs_s && o.nscs2 && o.nscs3, "{chip}: power-on levels {o:?}");
        let (mut h, trace) = host_with_trace(chip);
        load_tables(&mut h);
        // One driver (LSMD 0): the datagram is cells 0..11 of Table 11-2, the last bit PH_B
        // (cell 11, $2E): 1 at w = 0 (Table 12-3), 0 with polarity_ph_ab.
        h.write(GCONF, gconf(0, 7, f::POL_PH_AB.put(1)));
        trace.lock().unwrap().clear();
        request(&mut h);
        h.wait(400);
        request(&mut h);
        h.wait(400);
        let t = trace.lock().unwrap();
        assert_eq!(pulses(&t, |o| !o.nscs_s).len(), 2, "{chip}: two datagrams");
        let mut lows = 0;
        for w in t.windows(2) {
            if w[0].1.nscs_s {
                assert!(w[0].1.sdo_s, "{chip}: SDO_S high while nSCS_S is inactive (cycle {})", w[0].0);
            }
            if !w[0].1.nscs_s && !w[1].1.nscs_s && w[0].1.sck_s && !w[1].1.sck_s {
                lows += 1;
            }
            // the last bit (PH_B = 0) holds until nSCS_S rises, then SDO_S is high
            if !w[0].1.nscs_s && w[1].1.nscs_s {
                assert!(!w[0].1.sdo_s && w[1].1.sdo_s, "{chip}: SDO_S returns high with nSCS_S");
            }
        }
        assert_eq!(lows, 2 * 12, "{chip}: 12 bits per datagram");
    }
}

/// TMC428 §9.7 polarity bits (C81).
#[test]
fn polarities() {
    let (mut h, trace) = host_with_trace(Chip::Tmc429);
    load_tables(&mut h);
    let pol = f::POL_PH_AB.put(1) | f::POL_FD_AB.put(1) | f::POL_DAC_AB.put(1);
    h.write(GCONF, gconf(2, 7, pol | f::POL_NSCS_S.put(1) | f::POL_SCK_S.put(1)));
    assert!(!h.outputs().nscs_s && !h.outputs().sck_s, "idle: CS low (high active), SCK low");
    trace.lock().unwrap().clear();
    request(&mut h);
    h.wait(1000);
    let t = trace.lock().unwrap();
    let cs = pulses(&t, |o| o.nscs_s);
    assert_eq!(cs.len(), 1);
    // Sample SDO_S at the inverted clock's falling edges (the driver's rising SCK).
    let mut bits = 0u64;
    let mut n = 0;
    for w in t.windows(2) {
        if w[0].1.sck_s && !w[1].1.sck_s && w[0].1.nscs_s {
            bits = bits << 1 | w[0].1.sdo_s as u64;
            n += 1;
        }
    }
    // w = 0: DAC_A 0→63, DAC_B 63→0, PH 1→0, FD_A 0→1, FD_B 1→0.
    assert_eq!((n, bits), (36, 0x780780F80));
}

/// TMC428 §9.7 csCommonIndividual: nSCS_S, nSCS2, nSCS3 select the drivers of motors 1, 2, 3.
#[test]
fn individual_chip_selects() {
    let (mut h, trace) = host_with_trace(Chip::Tmc429);
    load_tables(&mut h);
    h.write(GCONF, gconf(2, 7, f::CS_COM_IND.put(1)));
    trace.lock().unwrap().clear();
    request(&mut h);
    h.wait(1000);
    let t = trace.lock().unwrap();
    let rising_while =
        |sel: &dyn Fn(&tmc429_model::Outputs) -> bool| t.windows(2).filter(|w| !w[0].1.sck_s && w[1].1.sck_s && sel(&w[0].1)).count();
    assert_eq!(rising_while(&|o| !o.nscs_s && o.nscs2 && o.nscs3), 12);
    assert_eq!(rising_while(&|o| o.nscs_s && !o.nscs2 && o.nscs3), 12);
    assert_eq!(rising_while(&|o| o.nscs_s && o.nscs2 && !o.nscs3), 12);
    for sel in [|o: &tmc429_model::Outputs| !o.nscs_s, |o: &tmc429_model::Outputs| !o.nscs2, |o: &tmc429_model::Outputs| !o.nscs3] {
        assert_eq!(pulses(&t, sel).len(), 1);
    }
}

/// TMC428 §9.6–§9.7, Table 9-3 with refmux = 1 and a 74HC157 on nSCS_S (C87): left switches
/// sampled while nSCS_S is high, right while low; updated only by datagrams.
#[test]
fn refmux_sampling() {
    let (mut h, _log) = host_with_events(Chip::Tmc429);
    load_tables(&mut h);
    h.write(GCONF, gconf(2, 7, f::REFMUX.put(1)));
    let left = [true, false, true];
    let right = [false, true, true];
    {
        let p = h.pins_mut();
        p.ref1 = left[0];
        p.ref2 = left[1];
        p.ref3 = left[2];
    }
    h.wait(10);
    assert_eq!(h.read(global_a7(14)), 0, "nothing sampled before a datagram");
    request(&mut h);
    run_board(&mut h, 1000, left, right, 0, 0);
    // r1 0, l1 1, r2 2, l2 3, r3 4, l3 5.
    assert_eq!(h.read(global_a7(14)), 0b11_0100 | 0b00_0010 | 0b01_0000);
    // RS bits of the status follow the left switches (C60).
    assert_eq!(h.status() & 0x2A, 0b10_0010);
}

/// The fast paths of `tick` stay exact with the driver side busy: chain datagrams from steps,
/// continuous update and covers, refmux, then Step/Dir — outputs and probes every cycle.
#[test]
fn fast_path_exact_with_drivers() {
    use std::sync::{Arc, Mutex};
    use tmc429_model::{Inputs, Outputs, Probes, Tmc429};
    for chip in [Chip::Tmc428, Chip::Tmc429, Chip::Tmc4210] {
        let trace: Arc<Mutex<Vec<(Inputs, Outputs, Probes)>>> = Arc::default();
        let mut h = tmc429_model::host::Host::new(chip);
        let t = trace.clone();
        h.set_observer(Box::new(move |c: &Tmc429, i: &Inputs, o: &Outputs| t.lock().unwrap().push((*i, *o, c.probes()))));
        load_tables(&mut h);
        h.write(GCONF, gconf(2, 9, f::CONT_UPDATE.put(1) | f::REFMUX.put(1)));
        for m in 0..3u8 {
            h.write(motor_a7(m, 12), 2 << 12 | (m as u32) << 8 | 5);
            h.write(motor_a7(m, 3), 300);
            h.write(motor_a7(m, 6), 50);
            h.write(motor_a7(m, 8), 3 << 20 | 5 << 16 | 1 << 12 | 20);
            h.write(motor_a7(m, 10), 2);
            h.write(motor_a7(m, 4), (200 - 150 * m as i32) as u32 & 0xFFF);
        }
        run_board(&mut h, 30_000, [true, false, true], [false, true, false], 0x123456789, 36);
        h.write(COVER_POS_LEN, 3 << 8 | 9);
        h.write(COVER_DATAGRAM, 0x1A5);
        h.write(global_a7(0), 0);
        run_board(&mut h, 20_000, [false; 3], [true; 3], 0xFFFF, 36);
        for m in 0..3u8 {
            h.write(motor_a7(m, 4), 0);
        }
        h.wait(300_000);
        h.write(IF_CONF, f::EN_SD.put(1) | f::STEP_HALF.put(1));
        h.write(GCONF, gconf(0, 2, 0));
        h.write(motor_a7(0, 4), 0xF00);
        h.wait(40_000);
        let mut slow = Tmc429::new(chip);
        slow.set_fast_path(false);
        for (n, (i, o, pr)) in trace.lock().unwrap().iter().enumerate() {
            let so = slow.tick(i);
            assert_eq!(so, *o, "{chip}: outputs differ at cycle {n}");
            assert_eq!(slow.probes(), *pr, "{chip}: probes differ at cycle {n}");
        }
        assert_eq!(replay_skip_quiet(chip, &trace.lock().unwrap()), Ok(()));
    }
}

/// An observer of the edges that may change something (`Host::set_change_observer`, the C
/// library's event queue) decodes the same pin events at the same cycles as one called after
/// every edge: the edges `Host::wait` runs at once change no pin and no INT. Three axes moving
/// with the chain sending datagrams (C83; not on the TMC4210), then in Step/Dir mode (C91; not
/// on the TMC428).
#[test]
fn change_observer_decodes_the_events_of_every_edge() {
    use std::sync::{Arc, Mutex};
    use tmc429_model::events::{Event, EventDecoder};
    use tmc429_model::host::Host;
    for chip in [Chip::Tmc428, Chip::Tmc429, Chip::Tmc4210] {
        let logs: [Arc<Mutex<Vec<Event>>>; 2] = Default::default();
        let mut hosts = [Host::new(chip), Host::new(chip)];
        for (k, h) in hosts.iter_mut().enumerate() {
            let (log, mut dec) = (logs[k].clone(), EventDecoder::new());
            let obs = Box::new(move |c: &tmc429_model::Tmc429, _: &tmc429_model::Inputs, o: &tmc429_model::Outputs| {
                dec.observe(c, o, c.cycle(), &mut |e| log.lock().unwrap().push(e))
            });
            if k == 0 {
                h.set_observer(obs);
            } else {
                h.set_change_observer(obs);
            }
            load_tables(h);
            for m in 0..3u8 {
                h.write(motor_a7(m, 12), 2 << 12 | (m as u32) << 8 | 5);
                h.write(motor_a7(m, 3), 300);
                h.write(motor_a7(m, 6), 50);
                h.write(motor_a7(m, 10), 2);
                h.write(motor_a7(m, 4), (200 - 150 * m as i32) as u32 & 0xFFF);
            }
            h.wait(300_000);
            h.write(IF_CONF, f::EN_SD.put(1));
            h.wait(200_000);
        }
        let [every, changes] = logs.map(|l| l.lock().unwrap().clone());
        if chip != Chip::Tmc4210 {
            assert!(every.iter().any(|e| matches!(e, Event::Chain { .. })), "{chip}: no datagram");
        }
        if chip != Chip::Tmc428 {
            assert!(every.iter().any(|e| matches!(e, Event::Step { .. })), "{chip}: no step pulse");
        }
        assert_eq!(changes, every, "{chip}");
        assert_eq!(hosts[0].chip().probes(), hosts[1].chip().probes(), "{chip}");
    }
}

/// A chip with Table 11-2 and the sine LUT, LSMD 2, clk2_div 7, and a datagram requested by a
/// cover write with cover_len 0 (the datagram goes out unchanged).
fn chip_with_request() -> tmc429_model::Tmc429 {
    let mut c = tmc429_model::Tmc429::new(Chip::Tmc429);
    for (w, d) in TABLE_11_3.iter().chain(TABLE_12_2.iter()).enumerate() {
        let a = if w < TABLE_11_3.len() { w } else { 32 + w - TABLE_11_3.len() };
        c.write_register(ram_a7(a as u8), *d);
    }
    c.write_register(GCONF, gconf(2, 7, 0));
    c.write_register(COVER_POS_LEN, 0);
    c.write_register(COVER_DATAGRAM, 0);
    c
}

/// Ticks until the chain is in `state` with `cnt` edges left (before the next edge).
fn run_to(c: &mut tmc429_model::Tmc429, state: u8, cnt: u16, bits: u8) {
    let inp = tmc429_model::Inputs::default();
    for _ in 0..100_000 {
        let ch = c.chain();
        if ch.state == state && ch.cnt == cnt && ch.bits == bits {
            return;
        }
        c.tick(&inp);
    }
    panic!("chain never reached state {state} cnt {cnt} bits {bits}");
}

/// SDO_S of the bit at position `bits` (read when it enters LOW).
fn bit_at(c: &mut tmc429_model::Tmc429, bits: u8) -> bool {
    run_to(c, tmc429_model::chain::LOW, 8, bits); // LO = clk2_div + 1 = 8 edges at entry
    c.outputs().sdo_s
}

/// C80: the configuration cell of a bit is read at the edge with 4 edges left in the state before
/// its LOW entry, the LUT cell at the edge with 3 left; a RAM write before such an edge is seen,
/// one after it is not.
#[test]
fn ram_read_edges_of_a_bit() {
    use tmc429_model::chain::{HIGH, SETUP};
    // Bit 0, cell 0 = Zero ($10). Rewritten as One ($11) before the configuration read: seen.
    let mut c = chip_with_request();
    assert!(!bit_at(&mut c.clone(), 0), "Table 11-2 cell 0 is Zero");
    run_to(&mut c, SETUP, 4, 0);
    c.write_register(ram_a7(0), 0x05 << 8 | 0x11);
    assert!(bit_at(&mut c, 0), "written before the edge with cnt 4: One is sent");
    // ... and after it: the cell read before the write is sent.
    let mut c = chip_with_request();
    run_to(&mut c, SETUP, 3, 0);
    c.write_register(ram_a7(0), 0x05 << 8 | 0x11);
    assert!(!bit_at(&mut c, 0), "written after the configuration read: Zero is sent");
    // Bit 1, cell 1 = DAC_A bit 5 ($05): w = 0 reads LUT[0] = 0. LUT[0] := 63 before the LUT
    // read (edge with 3 left in HIGH of bit 0): seen; after it: not.
    let mut c = chip_with_request();
    run_to(&mut c, HIGH, 3, 1);
    c.write_register(ram_a7(32), 2 << 8 | 63);
    assert!(bit_at(&mut c, 1), "LUT written before its read: DAC_A bit 5 = 1");
    let mut c = chip_with_request();
    run_to(&mut c, HIGH, 2, 1);
    c.write_register(ram_a7(32), 2 << 8 | 63);
    assert!(!bit_at(&mut c, 1), "LUT written after its read: DAC_A bit 5 = 0");
}

/// C89: en_sd = 1 during a datagram aborts it (chain IDLE, chip select inactive, pins Step/Dir);
/// the taken cover returns to waiting and goes out when SPI mode returns.
#[test]
fn en_sd_aborts_a_datagram() {
    use tmc429_model::chain::{IDLE, LOW};
    let mut c = chip_with_request();
    c.write_register(COVER_POS_LEN, 4);
    c.write_register(COVER_DATAGRAM, 0xA);
    run_to(&mut c, LOW, 8, 5);
    assert_eq!(c.probes().chain.cover_waiting, 1, "cw reads 1 while the cover is sent");
    c.write_register(IF_CONF, f::EN_SD.put(1));
    let inp = tmc429_model::Inputs::default();
    c.tick(&inp);
    assert_eq!(c.chain().state, IDLE);
    assert!(c.outputs().sdi_s_oe, "Step/Dir pins: D2 on SDI_S");
    assert_eq!(c.probes().chain.cover_waiting, 1, "the cover waits again");
    assert_ne!(c.status() & 0x40, 0, "CDGW still set");
    c.write_register(IF_CONF, 0);
    c.tick(&inp);
    c.tick(&inp);
    assert_ne!(c.chain().state, IDLE, "the waiting cover starts a datagram in SPI mode");
    assert!(c.chain().cover_busy);
}
