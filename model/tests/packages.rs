//! Packages (contract C90; TMC428 §3, §4; TMC429 §3, §4.2, §8.2.4.5; TMC4210 §3): the pins a
//! package lacks are tied off and its absent REFR inputs read high through their pull-ups.

mod common;
use common::*;

use tmc429_model::host::Host;
use tmc429_model::regmap::global_a7;
use tmc429_model::{Chip, Inputs, Package, Tmc429};

const REF_SWITCHES: u8 = 14;
const IF_CONF: u8 = 4;
const GCONF: u8 = 15;

fn in_package(chip: Chip, p: Package) -> Host {
    Host::from_chip(Tmc429::with_package(chip, p).unwrap())
}

fn set_refr(h: &mut Host, r: [bool; 3]) {
    let p = h.pins_mut();
    p.refr1 = r[0];
    p.refr2 = r[1];
    p.refr3 = r[2];
}

/// TMC428 Table 3-1, TMC429 §3, TMC4210 §3: the packages of each variant; the default has every
/// pin; an unknown combination is an error naming the packages the variant has.
#[test]
fn packages_of_each_variant() {
    assert_eq!(Package::of(Chip::Tmc428), [Package::Sop24, Package::Dil20, Package::Ssop16]);
    assert_eq!(Package::of(Chip::Tmc429), [Package::Qfn32, Package::Sop24, Package::Ssop16]);
    assert_eq!(Package::of(Chip::Tmc4210), [Package::Ssop16]);
    for chip in Chip::ALL {
        assert_eq!(Tmc429::new(chip).package(), Package::of(chip)[0]);
    }
    let e = Tmc429::with_package(Chip::Tmc429, Package::Dil20).err().unwrap();
    assert_eq!(e, "tmc429 has no dil20 package: expected qfn32 or sop24 or ssop16");
    assert_eq!("SSOP16".parse::<Package>(), Ok(Package::Ssop16));
    assert!("soic8".parse::<Package>().unwrap_err().contains("expected qfn32, sop24, dil20 or ssop16"));
}

/// TMC429 §8.2.4.5, "reasonable settings for different packages": with en_refr = 1 the SOP24's
/// r3 "always reads as high level (internal pull-ups)", whatever is applied for REFR3 (the
/// package has no such pin); the QFN32 reads the pin. inv_ref inverts the high level.
#[test]
fn sop24_r3_always_reads_high() {
    for (p, r3_low) in [(Package::Qfn32, 0u32), (Package::Sop24, 1)] {
        let mut h = in_package(Chip::Tmc429, p);
        set_refr(&mut h, [false, false, false]);
        h.write(global_a7(IF_CONF), 0x100); // en_refr
        assert_eq!(h.read(global_a7(REF_SWITCHES)), r3_low << 4, "{p}: r3 with REFR3 low");
        h.write(global_a7(IF_CONF), 0x101); // en_refr, inv_ref: REF1..3 low = active
        assert_eq!(h.read(global_a7(REF_SWITCHES)) & 0x10, (1 - r3_low) << 4, "{p}: inverted");
    }
    // "Do not enable unused REFR1, REFR2, REFR3 inputs of the TMC429 as STOP switches if these
    // inputs are open" (§8.2.4 note): on the SOP24 motor 3 cannot move right with en_refr = 1.
    let mut h = in_package(Chip::Tmc429, Package::Sop24);
    h.write(global_a7(IF_CONF), 0x100);
    motion_setup(&mut h, 2, 0, 0, 0, 2047, 100, 0, 2);
    wr(&mut h, 2, V_TARGET, 100);
    h.wait(20_000);
    assert_eq!(h.chip().motor(2).x_actual, 0, "stopped by the pulled-up right switch");
    assert_eq!(rd(&mut h, 2, INTERRUPT) & 0x80, 0, "no mask, no flag");
}

/// TMC429 §4 (TMC429-I): the SSOP16 has no REFR1..3 ("the additional reference right side
/// switch inputs ... are not available"), no nSCS2/nSCS3 (Step/Dir "for up to two motors"), no
/// SDOZ_C and no POSCMP: REFR inputs read high, the missing outputs are tied off (C90).
#[test]
fn tmc429_ssop16_pins() {
    let mut h = in_package(Chip::Tmc429, Package::Ssop16);
    let o = h.outputs();
    assert!(!o.poscmp && !o.sdoz_c_oe && o.nscs2 && o.nscs3, "{o:?}");
    set_refr(&mut h, [false, false, false]);
    h.write(global_a7(IF_CONF), 0x100);
    assert_eq!(h.read(global_a7(REF_SWITCHES)), 0b01_0101, "r1 r2 r3 pulled up");
    // position compare: the registers work, the pin stays low; sdo_int: no SDOZ_C
    let trace = std::sync::Arc::new(std::sync::Mutex::new(Vec::new()));
    let t = trace.clone();
    h.set_observer(Box::new(move |_c, _i, o| t.lock().unwrap().push(*o)));
    h.write(global_a7(5), 1); // pos_comp 1: no match at x_actual 0
    h.write(global_a7(6), 0x100); // M
    h.write(global_a7(5), 0); // match: I set, the die's POSCMP rises
    assert_eq!(h.read(global_a7(6)), 0x101, "I set by the match");
    h.write(global_a7(IF_CONF), 0x102); // sdo_int
    h.read(global_a7(5));
    // Step/Dir with three motors moving: S3/D3 absent
    h.write(global_a7(IF_CONF), 0x020); // en_sd (en_refr 0: the pulled-up REFR would stop them)
    for m in 0..3 {
        h.write(tmc429_model::regmap::motor_a7(m, 10), 3);
        h.write(tmc429_model::regmap::motor_a7(m, 5), 1000);
    }
    h.wait(5000);
    assert!(h.chip().motor(2).x_actual > 0, "motor 3 steps on the die");
    assert!(trace.lock().unwrap().iter().all(|o| !o.poscmp && !o.sdoz_c_oe && o.nscs2 && o.nscs3));
}

/// TMC428 §4: the SSOP16 has no nSCS2 / nSCS3 (csCommonIndividual is useful "only for the TMC428
/// within the larger packages"); the SOP24 drives them.
#[test]
fn tmc428_ssop16_has_no_individual_chip_selects() {
    for (p, lows) in [(Package::Sop24, 1usize), (Package::Ssop16, 0)] {
        let mut h = in_package(Chip::Tmc428, p);
        // three drivers: cells 0, 1 | 2, 3 | 4 (One, then DAC_A_0 with NxM; One with NxM)
        for (w, d) in [(0x40u8, 0x2011u32), (0x41, 0x2011), (0x42, 0x0031)] {
            h.write(w, d);
        }
        h.write(global_a7(GCONF), 7 << 8 | 1 << 7 | 2); // clk2_div 7, csCommonIndividual, LSMD 2
        let trace = std::sync::Arc::new(std::sync::Mutex::new(Vec::new()));
        let t = trace.clone();
        h.set_observer(Box::new(move |_c, i: &Inputs, o| t.lock().unwrap().push((*i, *o))));
        h.write(global_a7(3), 0); // a datagram
        h.wait(500);
        let t = trace.lock().unwrap();
        let low2 = t.windows(2).filter(|w| w[0].1.nscs2 && !w[1].1.nscs2).count();
        let low3 = t.windows(2).filter(|w| w[0].1.nscs3 && !w[1].1.nscs3).count();
        assert_eq!((low2, low3), (lows, lows), "{p}");
    }
}
