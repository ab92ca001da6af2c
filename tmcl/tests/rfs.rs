//! Reference search ([TMCL] §5.7.13, §9): every mode 1..8 of axis parameter 193 with and
//! without +128 (reversed home switch polarity) on the model's switches, the search ending
//! with position 0 at the documented switching point; WAIT RFS; RFS STOP; a mode 5 search
//! without a home switch ending at the second end switch; both module types.

mod common;
use common::*;

use tmcl::chip::ModelChip;
use tmcl::io::World;
use tmcl::personality::ModuleType;
use tmcl::proto::op;
use tmcl::Module;

/// Left end switch: pressed at and below −3000 (modes 3 and 4: a cam from −3500 to −3000
/// that can be driven through); right end switch at and above 4000; home switch 1000..1200.
fn world(m: &mut Module<ModelChip>, ax: usize, passable_left: bool) {
    m.world.left[ax] = Some(if passable_left { (-3500, -3000) } else { World::left_end(-3000) });
    m.world.right[ax] = Some(World::right_end(4000));
    m.world.home[ax] = Some((1000, 1200));
}

/// Moves axis `ax` to `x` (the end switches do not stop it: they are disabled for the move).
fn go(m: &mut Module<ModelChip>, ax: u8, x: i32) {
    ok(m, op::SAP, 12, ax, 1);
    ok(m, op::SAP, 13, ax, 1);
    ok(m, op::MVP, 0, ax, x);
    run_until(m, 20_000, |m| gap(m, 1, ax) == x && gap(m, 3, ax) == 0);
    ok(m, op::SAP, 12, ax, 0);
    ok(m, op::SAP, 13, ax, 0);
}

/// Starts a search and runs until RFS STATUS answers 0; returns the milliseconds it took.
fn search(m: &mut Module<ModelChip>, ax: u8, mode: i32) -> u64 {
    ok(m, op::SAP, 193, ax, mode);
    ok(m, op::RFS, 0, ax, 0);
    assert_ne!(direct(m, op::RFS, 2, ax, 0).1, 0, "mode {mode}: a search is active");
    run_until(m, 30_000, |m| direct(m, op::RFS, 2, ax, 0).1 == 0)
}

/// (mode, start position, mechanical position that becomes position 0).
const CASES: &[(i32, i32, i32)] = &[
    // Left switch (its edge at −3000).
    (1, 0, -3000),
    (2, 0, -3000),
    // From both sides: the centre of the cam −3500..−3000.
    (3, 0, -3250),
    (4, 0, -3250),
    // Home switch in negative direction, reversing at the left end switch: its lower edge.
    (5, 0, 1000),
    (5, 2000, 1200),
    // Home switch in positive direction, reversing at the right end switch.
    (6, 0, 1000),
    (6, 3000, 1200),
    (7, 0, 1000),
    (8, 2000, 1200),
];

/// +128: the home switch reads active outside 1000..1200; the search ends at an edge of the
/// window all the same (modes 1..4 use no home switch: as without +128).
const REVERSED: &[(i32, i32, i32)] = &[
    (129, 0, -3000),
    (130, 0, -3000),
    (131, 0, -3250),
    (132, 0, -3250),
    // Active at the start: leaves it backwards, at the left end switch the other way.
    (133, 0, 1000),
    (134, 0, 1000),
    (134, 2000, 1200),
    (135, 1100, 1200),
    (136, 1100, 1000),
];

fn check_case(kind: ModuleType, mode: i32, start: i32, zero: i32) {
    let mut m = module_of(kind);
    world(&mut m, 0, matches!(mode & 0x7f, 3 | 4));
    ok(&mut m, op::SAP, 194, 0, speed(kind, 300));
    ok(&mut m, op::SAP, 195, 0, speed(kind, 50));
    go(&mut m, 0, start);
    let mech0 = m.chip.mechanical_position_of(0);
    let ms = search(&mut m, 0, mode);
    let x = gap(&mut m, 1, 0);
    let mech = m.chip.mechanical_position_of(0) - mech0 + start;
    // Position 0 sits at the switching point, within the polling latency at switch speed.
    assert!(
        (mech - x - zero).abs() <= 3,
        "{kind:?} mode {mode} from {start}: position {x} at mechanical {mech}, 0 should be at {zero} ({ms} ms)"
    );
    assert_eq!(gap(&mut m, 3, 0), 0, "at rest");
    assert_eq!(gap(&mut m, 8, 0), 1, "on its target");
    if mode & 0x7f == 2 || mode & 0x7f == 3 {
        // Parameter 196: the right switch (met at search speed) from position 0.
        let d = gap(&mut m, 196, 0);
        assert!((d - (4000 - zero)).abs() <= 20, "mode {mode}: distance {d}");
    }
    // The end switch stops work again after the search.
    ok(&mut m, op::MVP, 0, 0, -5000 - zero);
    m.run_ms(50);
    run_until(&mut m, 20_000, |m| gap(m, 3, 0) == 0);
    let left = m.chip.mechanical_position_of(0) - mech0 + start;
    assert!((left + 3000).abs() <= 40, "mode {mode}: the left end switch stopped the axis at {left}");
}

/// TMC429 units (TMCM-3110) or pps (TMCM-1311) of a TMC429 velocity at pulse_div 3.
fn speed(kind: ModuleType, v: i32) -> i32 {
    match kind {
        ModuleType::Tmcm3110 => v,
        ModuleType::Tmcm1311 => (tmcl::units::pps_of(16_000_000, v, 3)).round() as i32,
    }
}

#[test]
fn every_mode_tmcm3110() {
    for &(mode, start, zero) in CASES.iter().chain(REVERSED) {
        check_case(ModuleType::Tmcm3110, mode, start, zero);
    }
}

#[test]
fn every_mode_tmcm1311() {
    for &(mode, start, zero) in CASES.iter().chain(REVERSED) {
        check_case(ModuleType::Tmcm1311, mode, start, zero);
    }
}

/// Mode 5 without a home switch: the left end switch reverses the search, the right one ends
/// it; no position 0 is set and the axis stands at the right end switch.
#[test]
fn home_search_without_a_home_switch_ends_at_the_second_end_switch() {
    let mut m = module();
    world(&mut m, 0, false);
    m.world.home[0] = None;
    ok(&mut m, op::SAP, 194, 0, 300);
    go(&mut m, 0, 500);
    search(&mut m, 0, 5);
    m.run_ms(200);
    assert_eq!(gap(&mut m, 3, 0), 0);
    let x = gap(&mut m, 1, 0);
    assert!((4000..=4100).contains(&x), "stands at the right end switch: {x} (no new position 0)");
    assert_eq!(gap(&mut m, 10, 0), 1);
}

/// RFS STOP ends a search at once (ramped stop); WAIT RFS in a program waits for the end of
/// a search ([TMCL] §5.7.22) and the program carries on.
#[test]
fn rfs_stop_and_wait_rfs() {
    let mut m = module();
    world(&mut m, 1, false);
    ok(&mut m, op::SAP, 194, 1, 300);
    ok(&mut m, op::RFS, 0, 1, 0);
    m.run_ms(50);
    assert_ne!(direct(&mut m, op::RFS, 2, 1, 0).1, 0);
    ok(&mut m, op::RFS, 1, 1, 0);
    assert_eq!(direct(&mut m, op::RFS, 2, 1, 0), (100, 0), "no search after STOP");
    run_until(&mut m, 2000, |m| gap(m, 3, 1) == 0);
    assert_eq!(gap(&mut m, 2, 1), 0);
    let code = tmcl::asm::assemble(
        std::path::Path::new("w.tmc"),
        "RFS START, 1\nWAIT RFS, 1, 0\nGAP 1, 1\nAGP 7, 2\nSGP 8, 2, 1\nSTOP\n",
        &tmcl::asm::FileSystem,
    )
    .unwrap()
    .code;
    m.load_program(&code).unwrap();
    ok(&mut m, op::APP_RUN, 0, 0, 0);
    m.run_ms(100);
    assert_eq!(m.user_var(8), 0, "waits while the search runs");
    run_until(&mut m, 20_000, |m| m.user_var(8) == 1);
    assert_eq!(direct(&mut m, op::RFS, 2, 1, 0), (100, 0));
    assert!(m.user_var(7).abs() <= 3, "position {} right after the search", m.user_var(7));
}
