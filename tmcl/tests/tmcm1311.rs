//! The TMCM-1311 personality ([TMCL] §6, §8, §9): the manual's units on the TMC429, 32-bit
//! positions, the ideal encoder, the closed-loop, stallGuard2 and coolStep values refused,
//! the home switch on IN1; and the manual's example programs (§3.3.2, §8.11.1, §8.11.2) run
//! as printed or refused at download with the reason, on both module types.

mod common;
use common::*;

use std::path::Path;
use tmcl::asm;
use tmcl::module::AppState;
use tmcl::personality::ModuleType::{Tmcm1311, Tmcm3110};
use tmcl::proto::op;
use tmcl::units;

const FCLK: u64 = 16_000_000;

fn example(name: &str) -> Vec<tmcl::Instruction> {
    let p = Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/tmcl").join(name);
    let text = std::fs::read_to_string(&p).unwrap();
    asm::assemble(&p, &text, &asm::FileSystem).unwrap_or_else(|e| panic!("{e}")).code
}

/// The rate the TMC429 runs for `pps` with the pulse divisor the module picks for it.
fn quantised(pps: i64) -> i32 {
    let pd = units::pulse_div_for(FCLK, pps).unwrap();
    units::pps_of(FCLK, units::v_of(FCLK, pps, pd) as i32, pd).round() as i32
}

/// [TMCL] §3.3.2 as printed: the TMCM-3110 refuses it at download (its velocities are
/// TMC429 units); the TMCM-1311 rotates left, then right at 50 000 pps for 5 s each, then
/// moves between +100 000 and −100 000.
#[test]
fn first_program_3_3_2() {
    let code = example("first-program.tmc");
    let e = module_of(Tmcm3110).load_program(&code).unwrap_err();
    assert_eq!(
        e,
        "instruction 0 (ROL 0, 50000): velocity 50000 is outside −2047..2047 (TMC429 units; --module tmcm-1311 takes pps) (status 4)"
    );
    let mut m = module_of(Tmcm1311);
    m.load_program(&code).unwrap();
    ok(&mut m, op::APP_RUN, 0, 0, 0);
    let v = quantised(50_000);
    m.run_ms(2500);
    assert_eq!((gap(&mut m, 2, 0), gap(&mut m, 3, 0)), (-50_000, -v), "ROL 0, 50000");
    m.run_ms(5000);
    assert_eq!((gap(&mut m, 2, 0), gap(&mut m, 3, 0)), (50_000, v), "ROR 0, 50000");
    assert_eq!((gap(&mut m, 4, 0), gap(&mut m, 5, 0)), (51_200, 51_200), "factory defaults before the SAPs");
    // The program moves on (the target changes) when WAIT POS saw the target reached.
    run_until(&mut m, 5000, |m| gap(m, 0, 0) == 100_000);
    assert_eq!((gap(&mut m, 4, 0), gap(&mut m, 5, 0)), (50_000, 50_000));
    run_until(&mut m, 20_000, |m| gap(m, 0, 0) == -100_000);
    run_until(&mut m, 20_000, |m| gap(m, 0, 0) == 100_000);
    assert_eq!(m.vm.state, AppState::Run);
}

/// [TMCL] §8.11.1 and §8.11.2 as printed switch closed loop on: refused at download on both
/// module types, naming the instruction and the reason; the same over the protocol (status 3
/// or 4, nothing stored).
#[test]
fn closed_loop_programs_8_11_are_refused() {
    for (file, kind, at, why) in [
        ("closed-loop-1.tmc", Tmcm3110, 1, "axis parameter 202: encoder function of the TMCM-1311 (no encoder on this module) (status 3)"),
        (
            "closed-loop-1.tmc",
            Tmcm1311,
            6,
            "axis parameter 129 = 1: closed-loop operation needs a motor model this module does not have (status 4)",
        ),
        (
            "closed-loop-2.tmc",
            Tmcm3110,
            1,
            "axis parameter 132: closed-loop function of the TMCM-1311 (no encoder feedback on this module) (status 3)",
        ),
        (
            "closed-loop-2.tmc",
            Tmcm1311,
            1,
            "axis parameter 132 = 1: encoder initialization prepares closed-loop operation, which this module does not model (status 4)",
        ),
    ] {
        let code = example(file);
        let mut m = module_of(kind);
        let e = m.load_program(&code).unwrap_err();
        assert!(e.starts_with(&format!("instruction {at} (")) && e.ends_with(why), "{file} {kind:?}: {e}");
        ok(&mut m, op::DOWNLOAD_START, 0, 0, 0);
        for (a, ins) in code.iter().enumerate() {
            let (s, _) = direct(&mut m, ins.op, ins.typ, ins.motor, ins.value);
            if a == at {
                assert_eq!(s, if kind == Tmcm3110 { 3 } else { 4 }, "{file} {kind:?}");
                break;
            }
            assert_eq!(s, 101);
        }
        assert_eq!(m.download_address(), Some(at), "the refused instruction is not stored");
    }
}

/// The motion part of §8.11.2 in open loop: the target-reached interrupt sends the axis
/// between 0 and 51 200 µsteps.
#[test]
fn position_reached_interrupts() {
    let mut m = module_of(Tmcm1311);
    m.load_program(&example("position-reached.tmc")).unwrap();
    ok(&mut m, op::APP_RUN, 0, 0, 0);
    for target in [51_200, 0, 51_200, 0] {
        run_until(&mut m, 10_000, |m| gap(m, 1, 0) == target && gap(m, 3, 0) == 0 || gap(m, 0, 0) != target);
        run_until(&mut m, 10_000, |m| gap(m, 0, 0) != target);
    }
}

#[test]
fn speeds_and_accelerations_in_pps() {
    let mut m = module_of(Tmcm1311);
    let max = units::max_pps(FCLK) as i32;
    assert_eq!(max, 499_755);
    assert_eq!(direct(&mut m, op::SAP, 4, 0, max + 1).0, 4, "faster than the TMC429 at 16 MHz");
    assert_eq!(direct(&mut m, op::ROR, 0, 0, max + 1).0, 4);
    ok(&mut m, op::SAP, 4, 0, 12_345);
    assert_eq!(gap(&mut m, 4, 0), 12_345, "read back as written");
    // At the fastest rate 51 200 pps² is below the TMC429's smallest acceleration (TMC429
    // §8.1.7.1.1): refused, nothing changed.
    assert_eq!(direct(&mut m, op::SAP, 4, 0, max).0, 4);
    assert_eq!(gap(&mut m, 4, 0), 12_345);
    ok(&mut m, op::SAP, 5, 0, 400_000);
    ok(&mut m, op::SAP, 4, 0, max);
    assert_eq!(direct(&mut m, op::SAP, 5, 0, 10).0, 4);
    assert_eq!(gap(&mut m, 5, 0), 400_000);
    // A new acceleration while the axis runs may need other dividers: the speed stays. (The
    // search speeds too must pair with an acceleration of 100 pps².)
    ok(&mut m, op::SAP, 4, 0, 1000);
    ok(&mut m, op::SAP, 194, 0, 300);
    ok(&mut m, op::SAP, 195, 0, 100);
    ok(&mut m, op::SAP, 5, 0, 100);
    ok(&mut m, op::ROR, 0, 0, 300);
    run_until(&mut m, 10_000, |m| gap(m, 3, 0) == 300);
    let pd_slow = units::dividers(FCLK, 300, 100).unwrap().0;
    let pd_fast = units::dividers(FCLK, 300, 400_000).unwrap().0;
    assert!(pd_fast < pd_slow, "{pd_fast} {pd_slow}");
    ok(&mut m, op::SAP, 5, 0, 400_000);
    m.run_ms(200);
    let step = units::pps_of(FCLK, 1, pd_fast);
    assert!((gap(&mut m, 3, 0) - 300).abs() as f64 <= step / 2.0 + 1.0, "{} at a step of {step}", gap(&mut m, 3, 0));
    // Velocity mode: the target speed as commanded, the actual speed the TMC429's rate with
    // the dividers for that speed and acceleration.
    for v in [100, -777, 20_000, 400_000] {
        ok(&mut m, op::ROR, 0, 0, v);
        let (pd, _, _) = units::dividers(FCLK, v.abs() as i64, 400_000).unwrap();
        let rate = units::pps_of(FCLK, units::v_of(FCLK, v as i64, pd) as i32, pd).round() as i32;
        assert!((rate - v).abs() as f64 <= units::pps_of(FCLK, 1, pd) / 2.0 + 1.0);
        run_until(&mut m, 10_000, |m| gap(m, 3, 0) == rate);
        assert_eq!((gap(&mut m, 2, 0), gap(&mut m, 131, 0)), (v, rate), "ROR {v}");
    }
    // The velocity-reached flag (16) with its window (17) and the status word (18).
    ok(&mut m, op::SAP, 17, 0, 1000);
    assert_eq!(gap(&mut m, 16, 0), 1);
    let sw = gap(&mut m, 18, 0);
    assert_eq!(sw & 0b1_1111_1111, 0b0_0001_0010, "velocity reached, velocity mode: {sw:b}");
    ok(&mut m, op::MST, 0, 0, 0);
    run_until(&mut m, 10_000, |m| gap(m, 3, 0) == 0);
}

#[test]
fn positions_are_32_bit() {
    let mut m = module_of(Tmcm1311);
    // Beyond the TMC429's 24 bits: 8 388 000 + 1000.
    ok(&mut m, op::SAP, 1, 0, 8_388_000);
    assert_eq!(gap(&mut m, 0, 0), 8_388_000, "at rest the target follows");
    ok(&mut m, op::MVP, 0, 0, 8_389_000);
    run_until(&mut m, 5000, |m| gap(m, 8, 0) == 1 && gap(m, 3, 0) == 0);
    assert_eq!(gap(&mut m, 1, 0), 8_389_000);
    // Across 2^31: MVP ABS takes the shorter way, the counter wraps ([TMCL] §5.7.4); a
    // relative move must not leave the 32-bit range.
    ok(&mut m, op::SAP, 1, 0, i32::MAX - 499);
    assert_eq!(direct(&mut m, op::MVP, 1, 0, 1000).0, 4);
    ok(&mut m, op::MVP, 0, 0, i32::MIN + 500);
    run_until(&mut m, 5000, |m| gap(m, 8, 0) == 1 && gap(m, 3, 0) == 0);
    assert_eq!(gap(&mut m, 1, 0), i32::MIN + 500);
    assert_eq!(m.chip.mechanical_position_of(0), 8_389_000 - 8_388_000 + 1000, "1000 steps up");
    // One move covers at most 2^23 − 1 µsteps.
    assert_eq!(direct(&mut m, op::MVP, 1, 0, 1 << 23).0, 4);
    assert_eq!(direct(&mut m, op::MVP, 1, 0, (1 << 23) - 1).0, 100);
    ok(&mut m, op::MST, 0, 0, 0);
    assert_eq!(direct(&mut module_of(Tmcm1311), op::MVP, 0, 1, 0).0, 4, "one axis");
}

/// Encoder at the configured resolution (209, 210, 202, 140), relative positioning (127),
/// position error (237), the null channel (201, 198).
#[test]
fn the_ideal_encoder() {
    let mut m = module_of(Tmcm1311);
    ok(&mut m, op::SAP, 210, 0, 4000);
    ok(&mut m, op::MVP, 0, 0, 51_200);
    run_until(&mut m, 5000, |m| gap(m, 8, 0) == 1 && gap(m, 3, 0) == 0);
    assert_eq!(gap(&mut m, 209, 0), 4000, "one revolution: 200 full steps × 256");
    assert_eq!((gap(&mut m, 237, 0), gap(&mut m, 233, 0)), (0, 51_200));
    // A written counter: the position error in µsteps (4000 counts = 51 200 µsteps).
    ok(&mut m, op::SAP, 209, 0, 3000);
    assert_eq!(gap(&mut m, 237, 0), 12_800);
    // MVP REL from the last target (127 = 0), the actual position (1) or the encoder (2).
    ok(&mut m, op::SAP, 127, 0, 2);
    ok(&mut m, op::MVP, 1, 0, 100);
    assert_eq!(gap(&mut m, 0, 0), 38_400 + 100);
    ok(&mut m, op::SAP, 127, 0, 0);
    ok(&mut m, op::MVP, 1, 0, 100);
    assert_eq!(gap(&mut m, 0, 0), 38_600);
    ok(&mut m, op::SAP, 127, 0, 1);
    ok(&mut m, op::MVP, 0, 0, 40_000);
    run_until(&mut m, 5000, |m| gap(m, 8, 0) == 1 && gap(m, 3, 0) == 0);
    // Clear on the next null channel (198 sets bit 2 of 201): at the revolution boundary
    // 51 200 the counter is 0; the bit clears itself.
    ok(&mut m, op::SAP, 198, 0, 1);
    assert_eq!((gap(&mut m, 198, 0), gap(&mut m, 201, 0)), (1, 4));
    ok(&mut m, op::MVP, 0, 0, 64_000);
    run_until(&mut m, 5000, |m| gap(m, 8, 0) == 1 && gap(m, 3, 0) == 0);
    assert_eq!(gap(&mut m, 209, 0), 1000, "12 800 µsteps past the null channel");
    assert_eq!((gap(&mut m, 198, 0), gap(&mut m, 201, 0)), (0, 0));
}

/// Values that would enable closed loop, torque mode, stallGuard2 or coolStep answer 4; their
/// other settings are kept.
#[test]
fn closed_loop_stallguard_coolstep_refused() {
    let mut m = module_of(Tmcm1311);
    for (p, v) in [(129, 1), (128, 2), (14, 100), (19, 0), (132, 1), (172, 1), (181, 1000)] {
        assert_eq!(direct(&mut m, op::SAP, p, 0, v).0, 4, "SAP {p}, 0, {v}");
    }
    for (p, v) in [(129, 0), (172, 0), (181, 0), (174, -10), (126, 5000), (163, 1)] {
        assert_eq!(direct(&mut m, op::SAP, p, 0, v), (100, v), "SAP {p}, 0, {v}");
        assert_eq!(gap(&mut m, p, 0), v);
    }
    assert_eq!((gap(&mut m, 129, 0), gap(&mut m, 133, 0), gap(&mut m, 14, 0)), (0, 0, 0));
    // Driver-stage readings do not exist here.
    for p in [150, 151, 152, 154, 155, 206, 208] {
        assert_eq!(direct(&mut m, op::GAP, p, 0, 0).0, 3, "GAP {p}");
    }
    // Maximum possible current from parameters 6 and 179.
    ok(&mut m, op::SAP, 6, 0, 255);
    assert_eq!(gap(&mut m, 15, 0), 3000);
    ok(&mut m, op::SAP, 179, 0, 1);
    assert_eq!(gap(&mut m, 15, 0), 1500);
    assert_eq!(gap(&mut m, 153, 0), 240, "supply voltage [0.1 V]");
}

/// The home switch on IN1 ([TMCL] §6 parameter 9, §9): IN1 itself, or the axis's home switch
/// that drives IN1.
#[test]
fn home_switch_on_in1() {
    let mut m = module_of(Tmcm1311);
    assert_eq!(gap(&mut m, 9, 0), 0, "IN1 open (no pull-up)");
    m.io.driven[1] = Some(true);
    assert_eq!(gap(&mut m, 9, 0), 1);
    m.world.home[0] = Some((100, 200));
    assert_eq!((gap(&mut m, 9, 0), ok(&mut m, op::GIO, 1, 0, 0)), (0, 0));
    ok(&mut m, op::MVP, 0, 0, 150);
    run_until(&mut m, 5000, |m| gap(m, 8, 0) == 1 && gap(m, 3, 0) == 0);
    assert_eq!((gap(&mut m, 9, 0), ok(&mut m, op::GIO, 1, 0, 0)), (1, 1));
    assert_eq!(gap(&mut m, 18, 0) >> 6 & 1, 1, "status word bit 6");
}
