//! µC writes of the motion parameters that the RTL keeps in block RAM (v_min, v_max, a_max,
//! pmul_pdiv, dx_ref_tolerance: parameter RAMs read in the frame's slots, rtl/tmc429_vtarget.v,
//! rtl/tmc429_accel.v and rtl/tmc429_pram.v in rtl/tmc429_regfile.v) and of x_target (which the target-velocity snapshot selects) executed in
//! every phase of the 32-cycle frame (C41) while a motor moves: model and RTL agree on every pin
//! and probe in every cycle. A write takes effect in the edge that executes it (C3), including
//! the edge of a slot's read of that register and the edge before it, where the RAM's read and
//! the write meet.
#![cfg(not(tmc429_no_rtl))] // needs Verilator (testbench/build.rs)

use tmc429_model::{Chip, Tmc429};
use tmc429_testbench::rtl::Expected;
use tmc429_testbench::signals::Compare;
use tmc429_testbench::stimulus::{motors, Driver, Frame, PinLevels, Txn};
use tmc429_testbench::{Rtl, Variant};

const X_TARGET: u8 = 0;
const V_MIN: u8 = 2;
const V_MAX: u8 = 3;
const V_TARGET: u8 = 4;
const V_ACTUAL: u8 = 5;
const A_MAX: u8 = 6;
const PMUL_PDIV: u8 = 9;
const REF_CONF_RM: u8 = 10;
const CLK_CONFIG: u8 = 12;
const DX_REF_TOLERANCE: u8 = 13;

fn w(m: u8, idx: u8, data: u32) -> Txn {
    Txn::Frame(Frame::write(m << 4 | idx, data))
}

/// Runs `txns` on the model and the RTL from reset; the first cycle where they disagree.
fn first_disagreement(chip: Chip, txns: Vec<Txn>) -> Option<u64> {
    let mut model = Tmc429::new(chip);
    let mut rtl = Rtl::new(Variant::Chip(chip));
    let mut drv = Driver::default();
    let mut rest = txns.into_iter();
    let mut cycle = 0u64;
    loop {
        if drv.ready() {
            match rest.next() {
                Some(t) => drv.start(t),
                None => return None,
            }
        }
        let inp = drv.step().0;
        let out = model.tick(&inp);
        cycle += 1;
        if !rtl.tick_agrees(&Expected::new(&inp, &out, &model.probes()), Compare::all()) {
            return Some(cycle);
        }
    }
}

/// Motor `m` moving (ramp and pulse ticks in every frame: pulse_div = ramp_div = 0, so the
/// braking law's h = ⌈a_max/128⌉ applies, C50) `dx` steps toward x_target, `d` idle cycles,
/// then the writes `late`, then long enough for them to act (tens of ramp ticks).
fn scenario(m: u8, rm: u32, dx: u32, d: u32, late: &[(u8, u32)]) -> Vec<Txn> {
    let mut t = vec![
        w(m, CLK_CONFIG, 0),
        w(m, V_MIN, 1),
        w(m, V_MAX, 600),
        w(m, A_MAX, 3),
        w(m, PMUL_PDIV, 0xA207), // a valid pair for a_max 3 at ramp_div = pulse_div = 0
        w(m, REF_CONF_RM, rm),
        w(m, V_TARGET, 600),
        w(m, X_TARGET, dx),
        Txn::Idle(3000),
    ];
    t.push(Txn::Idle(d + 1));
    t.extend(late.iter().map(|&(idx, data)| w(m, idx, data)));
    t.push(Txn::Idle(2000));
    t
}

/// Every delay 0..32 before the late writes puts their executing edges in every phase.
fn sweep(rm: u32, dx: u32, late: &[(u8, u32)]) {
    sweep_with(&format!("rm {rm}"), |m, d| scenario(m, rm, dx, d, late));
}

/// `txns(m, d)` for every motor of every variant and every delay `d` in 0..32.
fn sweep_with(what: &str, txns: impl Fn(u8, u32) -> Vec<Txn>) {
    for chip in Chip::ALL {
        for m in 0..motors(chip) as u8 {
            for d in 0..32 {
                if let Some(c) = first_disagreement(chip, txns(m, d)) {
                    panic!("{chip} motor {m}, {what}, delay {d}: model and RTL disagree at cycle {c}");
                }
            }
        }
    }
}

/// VELOCITY_MODE: a_max (the ramp tick's operand) written while V ramps toward v_target (3 per
/// tick before, 40 and then 7 after).
#[test]
fn a_max_written_in_every_phase_velocity_mode() {
    sweep(2, 2000, &[(A_MAX, 40), (A_MAX, 7)]);
}

/// RAMP_MODE five steps from the target, where the braking law sets the target velocity (about
/// 25, below v_max): a_max (h from 1 to 3), v_max (clamping at 20), v_min, pmul_pdiv and
/// x_target (three steps from the start, then 40) written while the motor creeps toward it.
#[test]
fn parameters_written_in_every_phase_ramp_mode() {
    sweep(0, 5, &[(A_MAX, 300), (V_MAX, 20), (V_MIN, 5), (PMUL_PDIV, 0xC008), (X_TARGET, 3), (X_TARGET, 40)]);
}

/// RAMP_MODE with the ramp and pulse ticks 2^13 frames apart (none in the run): x_target 1
/// (away from the target, so that no stop holds V at 0), V written 5·256, then x_target 0 =
/// x_actual: the stop at the target (x_actual = x_target and |V| >> 8 <= v_min, C52) is
/// decided by v_min alone. v_min 10 written in every phase stops the motor (V := 0) in the
/// first condition slot after the write's edge.
#[test]
fn v_min_written_in_every_phase_stop_at_target() {
    sweep_with("v_min", |m, d| {
        vec![
            w(m, CLK_CONFIG, 13 << 12 | 13 << 8),
            w(m, REF_CONF_RM, 0),
            w(m, X_TARGET, 1),
            Txn::Idle(100),
            w(m, V_ACTUAL, 5),
            w(m, X_TARGET, 0),
            Txn::Idle(200 + d),
            w(m, V_MIN, 10),
            Txn::Idle(400),
        ]
    });
}

/// VELOCITY_MODE toward v_target = -20 with every REF input high (the left switch of every
/// motor active, C60) and dx_ref_tolerance 100: |x_actual| < 100 masks the switch stop (C61).
/// dx_ref_tolerance 0 written in every phase stops the motor (V := 0) in the first condition
/// slot after the write's edge; 100 written again releases it in the first slot after that.
#[test]
fn dx_ref_tolerance_written_in_every_phase_switch_stop() {
    let high = PinLevels { ref_: [true; 3], refr: [false; 3], sdi_s: false };
    sweep_with("dx_ref_tolerance", |m, d| {
        let mut t = vec![
            Txn::Pins { levels: high, hold: 1 },
            w(m, CLK_CONFIG, 0),
            w(m, A_MAX, 200),
            w(m, V_MAX, 600),
            w(m, DX_REF_TOLERANCE, 100),
            w(m, REF_CONF_RM, 2),
            w(m, V_TARGET, 0xFFF & (-20i32 as u32)),
            Txn::Idle(1000 + d),
        ];
        t.extend([(DX_REF_TOLERANCE, 0), (DX_REF_TOLERANCE, 100)].iter().map(|&(idx, data)| w(m, idx, data)));
        t.push(Txn::Idle(400));
        t
    });
}
