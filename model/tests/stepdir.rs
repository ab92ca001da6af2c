//! Step/Dir output at pin level (TMC429 §10, §8.2.4; TMC4210; contract C90–C96).

mod drv;
use drv::*;
use tmc429_model::regmap::{f, global_a7, motor_a7};
use tmc429_model::{Chip, Outputs};

fn sd_host(chip: Chip, stpdiv: u32, ifc: u32) -> (tmc429_model::host::Host, std::sync::Arc<std::sync::Mutex<Vec<(u64, Outputs)>>>) {
    let (mut h, t) = host_with_trace(chip);
    h.write(GCONF, gconf(0, stpdiv, 0));
    h.write(IF_CONF, f::EN_SD.put(1) | ifc);
    t.lock().unwrap().clear();
    (h, t)
}

fn hold_velocity(h: &mut tmc429_model::host::Host, m: u8, v: i32) {
    h.write(motor_a7(m, 10), 3);
    h.write(motor_a7(m, 5), (v as u32) & 0xFFF);
}

/// TMC429 §10.1: t_STEP = 16·(1 + STPDIV) CLK; the pulse count equals the steps made.
#[test]
fn pulse_length() {
    for s in [0u32, 3, 15] {
        let (mut h, t) = sd_host(Chip::Tmc429, s, 0);
        assert!(!h.outputs().sdo_s, "STEP inactive low");
        hold_velocity(&mut h, 0, 20);
        h.wait(40_000);
        hold_velocity(&mut h, 0, 0);
        h.wait(3_000);
        let x = h.read(motor_a7(0, 1));
        let p = pulses(&t.lock().unwrap(), |o| o.sdo_s);
        assert!(x > 5);
        assert_eq!(p.len() as u32, x, "STPDIV {s}");
        assert!(p.iter().all(|&(_, l)| l == 16 * (1 + s as u64)), "STPDIV {s}: {:?}", &p[..3]);
        assert!(t.lock().unwrap().iter().all(|(_, o)| !o.sck_s), "DIR low for positive steps");
    }
}

/// At v = 2047, pulse_div = 0, STPDIV 0: never more than one step per 32 CLK, none lost.
#[test]
fn max_rate() {
    let (mut h, t) = sd_host(Chip::Tmc429, 0, 0);
    hold_velocity(&mut h, 0, 2047);
    h.wait(100_000);
    hold_velocity(&mut h, 0, 0);
    h.wait(1_000);
    let x = h.read(motor_a7(0, 1));
    let p = pulses(&t.lock().unwrap(), |o| o.sdo_s);
    assert_eq!(p.len() as u32, x);
    assert!(x > 3000);
    for w in p.windows(2) {
        assert!(w[1].0 - w[0].0 >= 32);
    }
    assert!(p.iter().all(|&(_, l)| l == 16));
}

/// step_half: STEP toggles once per step (TMC429 §8.2.4).
#[test]
fn step_half_toggles() {
    let (mut h, t) = sd_host(Chip::Tmc429, 2, f::STEP_HALF.put(1));
    hold_velocity(&mut h, 0, 30);
    h.wait(30_000);
    hold_velocity(&mut h, 0, 0);
    h.wait(1_000);
    let x = h.read(motor_a7(0, 1));
    let tr = t.lock().unwrap();
    let toggles = tr.windows(2).filter(|w| w[0].1.sdo_s != w[1].1.sdo_s).count();
    assert!(x > 5);
    assert_eq!(toggles as u32, x);
}

/// inv_stp / inv_dir invert the pins; DIR = 1 for negative steps (code $12), inverted → 0.
#[test]
fn inverted_polarities() {
    let (mut h, t) = sd_host(Chip::Tmc429, 1, f::INV_STP.put(1) | f::INV_DIR.put(1));
    assert!(h.outputs().sdo_s, "inverted STEP idles high");
    hold_velocity(&mut h, 0, -40);
    h.wait(20_000);
    let tr = t.lock().unwrap();
    let p = pulses(&tr, |o| !o.sdo_s);
    assert!(p.len() > 5);
    assert!(p.iter().all(|&(_, l)| l == 32));
    // DIR (SCK_S) = negative XOR inv_dir = 0 from the first pulse on.
    let first = p[0].0;
    assert!(tr.iter().filter(|(c, _)| *c >= first).all(|(_, o)| !o.sck_s));
}

/// TMC429 §10.1: the first step after a direction change follows the DIR edge by t_DIR2STP = t_STEP.
#[test]
fn direction_to_step_delay() {
    let (mut h, t) = sd_host(Chip::Tmc429, 4, 0);
    hold_velocity(&mut h, 0, 50);
    h.wait(20_000);
    hold_velocity(&mut h, 0, -50);
    h.wait(20_000);
    let tr = t.lock().unwrap();
    let dir_edges: Vec<u64> = tr.windows(2).filter(|w| !w[0].1.sck_s && w[1].1.sck_s).map(|w| w[1].0).collect();
    assert_eq!(dir_edges.len(), 1);
    let d = dir_edges[0];
    let next = pulses(&tr, |o| o.sdo_s).into_iter().find(|&(s, _)| s > d).unwrap();
    assert_eq!(next.0 - d, 16 * 5);
    // STEP was inactive while DIR changed.
    assert!(tr.iter().filter(|(c, _)| *c + 1 >= d && *c <= d).all(|(_, o)| !o.sdo_s));
}

/// TMC429 §10: S1 = SDO_S, D1 = SCK_S, S2 = nSCS_S, D2 = SDI_S, S3 = nSCS2, D3 = nSCS3; the
/// event decoder reports each motor's steps with their signs.
#[test]
fn pin_mapping_three_motors() {
    let (mut h, log) = host_with_events(Chip::Tmc429);
    h.write(GCONF, gconf(0, 0, 0));
    h.write(IF_CONF, f::EN_SD.put(1));
    assert!(h.outputs().sdi_s_oe);
    hold_velocity(&mut h, 0, 40);
    hold_velocity(&mut h, 1, -60);
    hold_velocity(&mut h, 2, 80);
    h.wait(50_000);
    for m in 0..3u8 {
        hold_velocity(&mut h, m, 0);
    }
    h.wait(1_000);
    let st = steps(&log);
    for m in 0..3u8 {
        let x = tmc429_model::motor_regs::sext24(h.read(motor_a7(m, 1)));
        let n = st.iter().filter(|s| s.1 == m).count() as i32;
        let neg = st.iter().filter(|s| s.1 == m && s.2).count() as i32;
        assert!(n > 10);
        assert_eq!(if m == 1 { -n } else { n }, x, "motor {m}");
        assert_eq!(neg, if m == 1 { n } else { 0 });
    }
}

/// TMC4210: STEP = SDO_S, DIR = SCK_S, logic high until en_sd = 1; only its registers answer.
#[test]
fn tmc4210() {
    let (mut h, t) = host_with_trace(Chip::Tmc4210);
    assert!(h.outputs().sdo_s && h.outputs().sck_s && h.outputs().nscs_s);
    hold_velocity(&mut h, 0, -100);
    h.wait(10_000);
    assert!(t.lock().unwrap().iter().all(|(_, o)| o.sdo_s && o.sck_s), "high until configured");
    h.write(GCONF, f::STPDIV.put(0));
    h.write(IF_CONF, f::EN_SD.put(1));
    t.lock().unwrap().clear();
    h.wait(10_000);
    let tr = t.lock().unwrap();
    let p = pulses(&tr, |o| o.sdo_s);
    assert!(p.len() > 10);
    assert!(p.iter().all(|&(_, l)| l == 16));
    assert!(tr.iter().all(|(_, o)| o.nscs_s && o.nscs2 && o.nscs3 && !o.sdi_s_oe));
    drop(tr);
    // Registers it lacks read 0: current scaling, datagram words, cover, motor 2 and 3.
    h.write(motor_a7(0, 8), 0x777777);
    assert_eq!(h.read(motor_a7(0, 8)), 0);
    for j in 0..4 {
        h.write(global_a7(j), 0xFFFFFF);
        assert_eq!(h.read(global_a7(j)), 0);
    }
    h.write(motor_a7(1, 0), 0x123);
    assert_eq!(h.read(motor_a7(1, 0)), 0);
    assert_eq!(h.status() & 0x40, 0, "no CDGW on the TMC4210");
}

/// Switching en_sd back to 0 returns the TMC429 pins to the idle SPI chain.
#[test]
fn leaving_step_dir() {
    let (mut h, _t) = sd_host(Chip::Tmc429, 0, 0);
    hold_velocity(&mut h, 0, 100);
    h.wait(5_000);
    h.write(IF_CONF, 0);
    h.write(motor_a7(0, 5), 0);
    h.wait(2_000);
    let o = h.outputs();
    assert!(o.nscs_s && o.sck_s && o.nscs2 && o.nscs3 && !o.sdi_s_oe);
}

/// C66: power down stops the Step/Dir counters with everything else behind the SPI slave; a
/// pulse in progress keeps STEP active and ends t_STEP running edges after it began.
#[test]
fn power_down_freezes_a_pulse() {
    use tmc429_model::{Inputs, Tmc429};
    let mut c = Tmc429::new(Chip::Tmc429);
    c.write_register(GCONF, gconf(0, 2, 0)); // STPDIV 2: T = 48
    c.write_register(IF_CONF, f::EN_SD.put(1));
    c.write_register(motor_a7(0, 10), 3);
    c.write_register(motor_a7(0, 5), 100);
    let idle = Inputs::default();
    // The pins take the Step/Dir levels at the next edge (SDO_S is high in SPI mode, C2).
    c.tick(&idle);
    assert!(!c.outputs().sdo_s, "S1 inactive");
    let mut n = 0;
    while !c.outputs().sdo_s {
        c.tick(&idle);
        n += 1;
        assert!(n < 100_000, "no step");
    }
    let mut running_edges_high = 0;
    for _ in 0..10 {
        c.tick(&idle);
        running_edges_high += 1;
    }
    c.write_register(global_a7(8), 0);
    assert!(c.is_powered_down());
    for _ in 0..5000 {
        c.tick(&idle);
        assert!(c.outputs().sdo_s, "STEP holds in power down");
    }
    // nSCS_C low wakes the chip (C66); the waking edge itself is still powered down.
    let select = Inputs { nscs_c: false, ..idle };
    while c.is_powered_down() {
        c.tick(&select);
    }
    while c.outputs().sdo_s {
        c.tick(&select);
        running_edges_high += 1;
    }
    assert_eq!(running_edges_high, 48, "t_STEP = 16·(1 + 2) running edges");
}

/// C95: with STPDIV 15 (t_STEP = 256 CLK) the motion core steps faster than 1/(2·t_STEP) (one
/// step per 32 CLK at v = 2047): the backlog grows and every step is still output later, one
/// pulse of 256 CLK with at least 256 CLK between pulses; steps in the opposite direction cancel
/// steps not yet output, so the driver ends exactly at x_actual with fewer pulses than steps.
#[test]
fn backlog_beyond_the_pulse_rate() {
    let (mut h, t) = sd_host(Chip::Tmc429, 15, 0);
    hold_velocity(&mut h, 0, 2047);
    h.wait(20_000);
    let x1 = h.read(motor_a7(0, 1));
    hold_velocity(&mut h, 0, -2047);
    h.wait(8_000);
    hold_velocity(&mut h, 0, 0);
    let x2 = h.read(motor_a7(0, 1));
    // forward steps, then backward ones, all while the output lagged behind
    assert!(x1 > 500 && x2 < x1 && x2 > 0, "x1 {x1}, x2 {x2}");
    let emitted_early = pulses(&t.lock().unwrap(), |o| o.sdo_s).len() as u32;
    assert!(emitted_early < x2, "the backlog is still there: {emitted_early} pulses, x_actual {x2}");
    h.wait(400_000);
    let tr = t.lock().unwrap();
    let p = pulses(&tr, |o| o.sdo_s);
    assert_eq!(p.len() as u32, x2, "pulses = x_actual: the backward steps cancelled forward ones");
    assert!(p.iter().all(|&(_, l)| l == 256));
    for w in p.windows(2) {
        assert!(w[1].0 - (w[0].0 + w[0].1) >= 256);
    }
    assert!(tr.iter().all(|(_, o)| !o.sck_s), "no backward pulse: DIR stays low");
}

/// TMC429 §8.2.4 note: "REFMUX does not work in Step/Dir mode because the SPI signal nSCS_S is
/// not available. The output is signal S2 (step2) in Step/Dir mode." The model (C87): with
/// refmux = 1 the switches are the values the 74HC157 sampling stored while datagrams were
/// sent; in Step/Dir mode nothing is sampled (S2 pulses are no chip select), so they keep the
/// last SPI-mode sample — 0 if there was none — and the REF pins do not reach them.
#[test]
fn refmux_in_step_dir_mode_holds_the_last_sample() {
    let (mut h, _log) = host_with_events(Chip::Tmc429);
    load_tables(&mut h);
    h.write(GCONF, gconf(2, 7, f::REFMUX.put(1)));
    // SPI mode: a datagram samples left = (1, 0, 1) (presented while nSCS_S is high),
    // right = (0, 1, 0) (while low).
    {
        let p = h.pins_mut();
        p.ref1 = true;
        p.ref3 = true;
    }
    h.wait(10);
    request(&mut h);
    run_board(&mut h, 1000, [true, false, true], [false, true, false], 0, 0);
    let sampled = h.read(global_a7(14));
    assert_eq!(sampled, 0b10_0110, "r1 0, l1 1, r2 1, l2 0, r3 0, l3 1");
    // Step/Dir mode, motor 2 stepping negative (S2 = nSCS_S pulses; its sampled right switch
    // r2 is active, its left switch l2 not): the REF pins change, the switches keep the sample.
    h.write(IF_CONF, f::EN_SD.put(1));
    h.write(motor_a7(1, 10), 3);
    h.write(motor_a7(1, 5), (-500i32) as u32 & 0xFFF);
    for levels in [[false; 3], [true; 3], [false, true, false]] {
        let p = h.pins_mut();
        p.ref1 = levels[0];
        p.ref2 = levels[1];
        p.ref3 = levels[2];
        h.wait(5000);
        assert_eq!(h.read(global_a7(14)), sampled, "REF pins {levels:?}");
    }
    assert!((h.chip().motor(1).x_actual as i32) << 8 >> 8 < -100, "motor 2 stepped (S2 pulses)");
    // From power-on straight into Step/Dir with refmux = 1: nothing was ever sampled.
    let (mut h, _log) = host_with_events(Chip::Tmc429);
    h.write(GCONF, gconf(0, 7, f::REFMUX.put(1)));
    h.write(IF_CONF, f::EN_SD.put(1));
    let p = h.pins_mut();
    p.ref1 = true;
    p.ref2 = true;
    p.ref3 = true;
    h.wait(100);
    assert_eq!(h.read(global_a7(14)), 0);
}
