//! The pin-level entry and the seeded stimulus of the C library (capi/src/pins.rs): one call is
//! one edge of the model, the stimulus is `tmc429 cosim`'s edge for edge, a check finds a
//! differing pin at its cycle and reports it as `tmc429 cosim` does, and misuse returns errors.

use std::ffi::{CStr, CString};
use std::ptr::{null, null_mut};

use tmc429::*;
use tmc429_model::{Chip, Tmc429};
use tmc429_verif::lockstep::PinSource;
use tmc429_verif::pinword::{pack_inputs, pack_outputs, unpack_inputs};
use tmc429_verif::signals::{flatten, N_PINS};
use tmc429_verif::stimulus::Profile;

fn chip(variant: i32) -> u64 {
    let mut h = 0;
    assert_eq!(unsafe { tmc429_create(variant, 0, &mut h) }, TMC429_OK);
    assert_eq!(tmc429_events_enable(h, 0), TMC429_OK);
    h
}

fn stim(variant: i32, profile: i32, seed: u64) -> u64 {
    let mut h = 0;
    assert_eq!(unsafe { tmc429_stim_create(variant, profile, seed, &mut h) }, TMC429_OK);
    h
}

fn text(p: *const std::ffi::c_char) -> String {
    unsafe { CStr::from_ptr(p) }.to_string_lossy().into_owned()
}

/// 100 000 edges of the motion stimulus: tick_pins gives the model's outputs and probes, and the
/// stimulus gives PinSource's inputs for the same seed.
#[test]
fn one_call_is_one_edge_of_the_model_on_the_cosim_stimulus() {
    for variant in [TMC429_CHIP_TMC428, TMC429_CHIP_TMC429, TMC429_CHIP_TMC4210] {
        let c = Chip::from_rtl_param(variant as u32).unwrap();
        let (h, s) = (chip(variant), stim(variant, TMC429_PROFILE_MOTION, 3));
        let mut model = Tmc429::new(c);
        let mut src = PinSource::new(c, Profile::Motion, 3);
        let mut out = 0u32;
        assert_eq!(unsafe { tmc429_output_word(h, &mut out) }, TMC429_OK);
        assert_eq!(out, pack_outputs(&model.outputs()));
        let mut probes = [0u64; TMC429_PROBE_COUNT as usize];
        for _ in 0..100_000 {
            let mut inp = 0u32;
            assert_eq!(unsafe { tmc429_stim_next(s, out, out, &mut inp) }, TMC429_OK);
            let want = src.step(&model.outputs(), Some(&model.outputs())).inputs;
            assert_eq!(inp, pack_inputs(&want));
            assert_eq!(unsafe { tmc429_tick_pins(h, inp, &mut out, probes.as_mut_ptr()) }, TMC429_OK);
            let o = model.tick(&unpack_inputs(inp));
            assert_eq!(out, pack_outputs(&o));
            assert_eq!(probes[..], flatten(&o, &model.probes())[N_PINS..]);
            assert_eq!(tmc429_stim_check(s, out, out), 0);
        }
        let (mut cy, mut f, mut p) = (0, 0, 0);
        assert_eq!(unsafe { tmc429_stim_counts(s, &mut cy, &mut f, &mut p) }, TMC429_OK);
        assert_eq!((cy, f, p), (100_000, src.frames(), src.pin_changes()));
        assert!(f > 0);
        assert_eq!(text(unsafe { tmc429_stim_report(s, null()) }), "");
        assert_eq!(tmc429_stim_destroy(s), TMC429_OK);
        assert_eq!(tmc429_destroy(h), TMC429_OK);
    }
}

#[test]
fn a_differing_pin_is_reported_at_its_cycle() {
    let s = stim(TMC429_CHIP_TMC429, TMC429_PROFILE_REGISTERS, 1);
    let idle = pack_outputs(&Tmc429::new(Chip::Tmc429).outputs());
    let mut inp = 0;
    for _ in 0..500 {
        assert_eq!(tmc429_stim_check(s, idle, idle), 0);
        assert_eq!(unsafe { tmc429_stim_next(s, idle, idle, &mut inp) }, TMC429_OK);
    }
    // SDOZ_C data differs while disabled: not a mismatch; POSCMP (bit 10) is.
    assert_eq!(tmc429_stim_check(s, idle, idle ^ 1 << 1), 0);
    assert_eq!(tmc429_stim_check(s, idle, idle ^ 1 << 10), 1);
    assert_eq!(tmc429_stim_check(s, idle, idle), 1, "every check after the first mismatch fails");
    let label = CString::new("my_chip").unwrap();
    let r = text(unsafe { tmc429_stim_report(s, label.as_ptr()) });
    assert!(r.starts_with("MISMATCH at cycle 500 (my_chip, seed 1):\n"), "{r}");
    assert!(r.contains("top.poscmp") && r.contains("SPI transactions (oldest first):"), "{r}");
    assert_eq!(tmc429_stim_destroy(s), TMC429_OK);
}

#[test]
fn probe_names_are_the_cosim_signals() {
    assert_eq!(text(tmc429_probe_name(0)), "motor0.x_target");
    assert_eq!(text(tmc429_probe_name(TMC429_PROBE_COUNT - 1)), "top.status");
    assert_eq!(text(tmc429_probe_name(TMC429_PROBE_COUNT)), "");
    assert_eq!(TMC429_IDLE_INPUTS, pack_inputs(&tmc429_model::Inputs::default()));
}

#[test]
fn misuse_returns_errors() {
    let h = chip(TMC429_CHIP_TMC429);
    let s = stim(TMC429_CHIP_TMC429, TMC429_PROFILE_FULL, 1);
    let mut w = 0u32;
    assert_eq!(unsafe { tmc429_tick_pins(h, 1 << 10, &mut w, null_mut()) }, TMC429_ERR_ARG);
    assert_eq!(unsafe { tmc429_tick_pins(h, 0x383, null_mut(), null_mut()) }, TMC429_ERR_NULL);
    assert_eq!(unsafe { tmc429_tick_pins(h, 0x383, &mut w, null_mut()) }, TMC429_OK);
    // chip and stimulus handles are told apart
    assert_eq!(unsafe { tmc429_tick_pins(s, 0x383, &mut w, null_mut()) }, TMC429_ERR_HANDLE);
    assert_eq!(unsafe { tmc429_stim_next(h, 0, 0, &mut w) }, TMC429_ERR_HANDLE);
    assert_eq!(unsafe { tmc429_stim_next(s, 1 << 11, 0, &mut w) }, TMC429_ERR_ARG);
    assert_eq!(tmc429_stim_check(s, 0, 1 << 11), TMC429_ERR_ARG);
    let mut x = 0u64;
    assert_eq!(unsafe { tmc429_stim_create(3, TMC429_PROFILE_MOTION, 1, &mut x) }, TMC429_ERR_ARG);
    assert_eq!(unsafe { tmc429_stim_create(1, 5, 1, &mut x) }, TMC429_ERR_ARG);
    assert_eq!(unsafe { tmc429_stim_create(1, 0, 1, null_mut()) }, TMC429_ERR_NULL);
    assert_eq!(tmc429_stim_destroy(s), TMC429_OK);
    assert_eq!(tmc429_stim_destroy(s), TMC429_ERR_HANDLE);
    assert_eq!(text(unsafe { tmc429_stim_report(s, null()) }), "");
    assert_eq!(tmc429_destroy(h), TMC429_OK);
}
