//! Every interrupt vector of both module types ([TMCL] §5.6, §5.7.32–§5.7.35, §10.4): enabled
//! while its source is already active it does not fire; it fires once per edge of its source
//! after that. Timers fire a period after EI; the global switch 255 holds requests back.

mod common;
use common::*;

use std::path::Path;
use tmcl::asm;
use tmcl::chip::ModelChip;
use tmcl::personality::ModuleType;
use tmcl::proto::op;
use tmcl::Module;

/// A program whose handler of interrupt `n` counts in user variable 20; bank-3 setting `cfg`.
fn counting(m: &mut Module<ModelChip>, n: u8, cfg: i32) {
    let src = format!("VECT {n}, H\nSGP {n}, 3, {cfg}\nEI {n}\nEI 255\nLoop: JA Loop\nH: GGP 20, 2\nCALC ADD, 1\nAGP 20, 2\nRETI\n");
    let code = asm::assemble(Path::new("irq.tmc"), &src, &asm::FileSystem).unwrap().code;
    m.load_program(&code).unwrap();
    ok(m, op::APP_RUN, 0, 0, 0);
}

/// Same, for an interrupt without bank-3 setting (target reached, deviation, stallGuard2).
fn counting_plain(m: &mut Module<ModelChip>, n: u8) {
    let src = format!("VECT {n}, H\nEI {n}\nEI 255\nLoop: JA Loop\nH: GGP 20, 2\nCALC ADD, 1\nAGP 20, 2\nRETI\n");
    let code = asm::assemble(Path::new("irq.tmc"), &src, &asm::FileSystem).unwrap().code;
    m.load_program(&code).unwrap();
    ok(m, op::APP_RUN, 0, 0, 0);
}

fn count(m: &Module<ModelChip>) -> i32 {
    m.user_var(20)
}

#[test]
fn timers_fire_a_period_after_ei() {
    for kind in ModuleType::ALL {
        for t in 0..3u8 {
            let mut m = module_of(kind);
            counting(&mut m, t, 100);
            m.run_ms(50);
            assert_eq!(count(&m), 0, "{kind:?} timer {t}: not at EI");
            m.run_ms(300);
            assert_eq!(count(&m), 3, "{kind:?} timer {t}: every 100 ms");
        }
    }
}

#[test]
fn target_reached_fires_on_arrival_only() {
    for kind in ModuleType::ALL {
        for ax in 0..kind.axes() as u8 {
            let mut m = module_of(kind);
            // At rest on its target when the interrupt is enabled: no request.
            counting_plain(&mut m, 3 + ax);
            m.run_ms(200);
            assert_eq!(count(&m), 0, "{kind:?} axis {ax}: no move, no interrupt");
            ok(&mut m, op::MVP, 0, ax, 300);
            run_until(&mut m, 5000, |m| gap(m, 8, ax) == 1);
            m.run_ms(20);
            assert_eq!(count(&m), 1, "{kind:?} axis {ax}: once on arrival");
            // A move to where it stands reaches nothing new.
            ok(&mut m, op::MVP, 0, ax, 300);
            m.run_ms(100);
            assert_eq!(count(&m), 1);
            // A short move (within a millisecond of service) is seen.
            ok(&mut m, op::MVP, 1, ax, 2);
            m.run_ms(50);
            assert_eq!(count(&m), 2, "{kind:?} axis {ax}: a two-step move");
        }
    }
}

#[test]
fn stop_switches_fire_on_their_edge_only() {
    for kind in ModuleType::ALL {
        for ax in 0..kind.axes() {
            for left in [true, false] {
                let n = 27 + 2 * ax as u8 + (!left) as u8;
                let mut m = module_of(kind);
                let press = |m: &mut Module<ModelChip>, on: bool| {
                    if left {
                        m.world.left_forced[ax] = on
                    } else {
                        m.world.right_forced[ax] = on
                    }
                };
                // Pressed before EI: enabling does not fire.
                press(&mut m, true);
                m.run_ms(10);
                counting(&mut m, n, 1);
                m.run_ms(20);
                assert_eq!(count(&m), 0, "{kind:?} interrupt {n}: pressed before EI");
                press(&mut m, false);
                m.run_ms(20);
                assert_eq!(count(&m), 0, "{kind:?} interrupt {n}: release (falling) not asked for");
                press(&mut m, true);
                m.run_ms(20);
                assert_eq!(count(&m), 1, "{kind:?} interrupt {n}: pressed");
            }
        }
    }
}

#[test]
fn inputs_fire_on_their_edge_only() {
    for kind in ModuleType::ALL {
        for i in 0..8usize {
            let n = 39 + i as u8;
            let mut m = module_of(kind);
            m.io.driven[i] = Some(true);
            m.run_ms(10);
            counting(&mut m, n, 3);
            m.run_ms(20);
            assert_eq!(count(&m), 0, "{kind:?} IN{i} high before EI");
            m.io.driven[i] = Some(false);
            m.run_ms(20);
            m.io.driven[i] = Some(true);
            m.run_ms(20);
            assert_eq!(count(&m), 2, "{kind:?} IN{i}: both edges (3)");
        }
    }
}

/// TMCM-1311 interrupt 21: the encoder deviation (axis parameter 212) stops the motor and
/// raises it once; 15 (stallGuard2) exists but never fires (stallGuard2 cannot be enabled).
#[test]
fn deviation_and_stallguard_of_the_tmcm1311() {
    let mut m = module_of(ModuleType::Tmcm1311);
    counting_plain(&mut m, 21);
    ok(&mut m, op::SAP, 212, 0, 1000);
    ok(&mut m, op::ROR, 0, 0, 20_000);
    m.run_ms(300);
    assert_eq!(count(&m), 0, "the ideal encoder follows the motor");
    assert_eq!(gap(&mut m, 207, 0), 0);
    // The encoder counter moved by 5000 counts behind the motor's back: a deviation.
    let e = gap(&mut m, 209, 0);
    ok(&mut m, op::SAP, 209, 0, e - 5000);
    m.run_ms(20);
    assert_eq!(count(&m), 1);
    assert_eq!(gap(&mut m, 207, 0), 1);
    assert_eq!((gap(&mut m, 2, 0), gap(&mut m, 3, 0)), (0, 0), "stopped at once");
    let mut m = module_of(ModuleType::Tmcm1311);
    counting_plain(&mut m, 15);
    ok(&mut m, op::ROR, 0, 0, 20_000);
    m.run_ms(300);
    assert_eq!(count(&m), 0);
    // Interrupts of the other module type do not exist.
    assert_eq!(direct(&mut m, op::EI, 4, 0, 0).0, 3);
    assert_eq!(direct(&mut module(), op::EI, 21, 0, 0).0, 3);
}

/// DI 255 holds a request back until EI 255; DI n drops it.
#[test]
fn the_global_switch() {
    let mut m = module();
    counting(&mut m, 40, 3);
    m.run_ms(10);
    ok(&mut m, op::DI, 255, 0, 0);
    m.io.driven[1] = Some(false);
    m.run_ms(20);
    assert_eq!(count(&m), 0);
    ok(&mut m, op::EI, 255, 0, 0);
    m.run_ms(10);
    assert_eq!(count(&m), 1, "the held request runs after EI 255");
    ok(&mut m, op::DI, 255, 0, 0);
    m.io.driven[1] = Some(true);
    m.run_ms(10);
    ok(&mut m, op::DI, 40, 0, 0);
    ok(&mut m, op::EI, 255, 0, 0);
    m.run_ms(10);
    assert_eq!(count(&m), 1, "DI 40 dropped the request");
}
