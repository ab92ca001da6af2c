//! Reference switches, stops, latch, interrupts and position compare (TMC428 §8.12–§8.16, §9.6,
//! Table 9-3; TMC429 §8.2.4; contract C60–C65).

mod common;
use common::*;

use tmc429_model::host::Host;
use tmc429_model::regmap::global_a7;
use tmc429_model::Chip;

const REF_SWITCHES: u8 = 14;

fn set_refs(h: &mut Host, r1: bool, r2: bool, r3: bool) {
    let p = h.pins_mut();
    p.ref1 = r1;
    p.ref2 = r2;
    p.ref3 = r3;
}

/// Table 9-3 rows (refmux = 0): $7C bits r1 l1 r2 l2 r3 l3 (bits 0..5) and the RS status bits.
#[test]
fn switch_mapping() {
    let mut h = host(Chip::Tmc428);
    set_refs(&mut h, true, false, true);
    h.wait(4);
    assert_eq!(h.read(global_a7(REF_SWITCHES)), 0b10_0010, "L1 = REF1, L3 = REF3");
    assert_eq!(h.status(), 0x15 | 0x02 | 0x20, "RS1, RS3");
    h.write(global_a7(15), 0x20_0F00); // mot1r
    assert_eq!(h.read(global_a7(REF_SWITCHES)), 0b00_0011, "R1 = REF3, motor 3 none");
    set_refs(&mut h, false, true, false);
    h.wait(4);
    assert_eq!(h.read(global_a7(REF_SWITCHES)), 0b00_1000, "L2 = REF2");
    // TMC429: en_refr maps REFR1..3 to the right switches; inv_ref inverts all.
    let mut h = host(Chip::Tmc429);
    {
        let p = h.pins_mut();
        p.refr1 = true;
        p.refr2 = false;
        p.refr3 = true;
    }
    h.wait(4);
    assert_eq!(h.read(global_a7(REF_SWITCHES)), 0, "REFR ignored while en_refr = 0");
    h.write(global_a7(4), 0x100);
    assert_eq!(h.read(global_a7(REF_SWITCHES)), 0b01_0001);
    h.write(global_a7(4), 0x101);
    assert_eq!(h.read(global_a7(REF_SWITCHES)), 0b10_1110, "inverted: REF1..3 open = active, REFR2 low = active");
    // TMC4210: REF_L = REF1 (l1), GP_IN = REF2 (bit 3), REF_R = REF3 with mot1r (r1).
    let mut h = host(Chip::Tmc4210);
    set_refs(&mut h, true, true, true);
    h.wait(4);
    assert_eq!(h.read(global_a7(REF_SWITCHES)), 0b00_1010);
    h.write(global_a7(15), 0x20_0000);
    assert_eq!(h.read(global_a7(REF_SWITCHES)), 0b00_1011);
}

fn velocity_mode(h: &mut Host, m: u8, v: i32, a_max: u32) {
    motion_setup(h, m, 0, 0, 0, 2047, a_max, 0, 2);
    wr(h, m, V_TARGET, v as u32 & 0xFFF);
}

/// C61 hard stop: V := 0 while the left switch is active and the motor moves left; motion to the
/// right is allowed; the STOP and STOP_LEFT_HIGH events fire.
#[test]
fn hard_stop_left() {
    let mut h = host(Chip::Tmc428);
    wr(&mut h, 0, INTERRUPT, 0xFF00);
    velocity_mode(&mut h, 0, -1000, 2047);
    h.wait(5000);
    assert_eq!(h.chip().motor(0).v_actual(), -1000);
    wr(&mut h, 0, INTERRUPT, 0xFFFF); // clear what happened so far

    // Put the pin up 10 edges before motor 0's condition slot (its commit phase 14).
    while h.chip().probes().prescaler & 31 != tmc429_model::PHASE_COMMIT[0] - 10 {
        h.wait(1);
    }
    set_refs(&mut h, true, false, false);
    // C4: the switch is in the old state from the 3rd edge on; C61: it is not evaluated before
    // the slot, which sets stop_hard; C52: V := 0 in the edge after the slot.
    for _ in 0..10 {
        h.wait(1);
        assert!(!h.chip().motor(0).stop_hard, "no stop before the slot");
        assert_eq!(h.chip().motor(0).v, -1000 * 256);
    }
    assert_eq!(h.chip().probes().prescaler & 31, tmc429_model::PHASE_COMMIT[0]);
    h.wait(1);
    assert!(h.chip().motor(0).stop_hard, "the condition of the slot is registered");
    assert_eq!(h.chip().motor(0).v, -1000 * 256, "the action comes one edge later (C52)");
    h.wait(1);
    assert_eq!(h.chip().motor(0).v, 0, "stopped in the edge after the slot");
    let x = h.chip().motor(0).x_actual;
    h.wait(10_000);
    assert_eq!(h.chip().motor(0).x_actual, x, "held");
    // The left switch is also the reference switch, active outside a window of 0: REF_WRONG.
    assert_eq!(rd(&mut h, 0, INTERRUPT) & 0xFF, (INT_STOP | INT_STOP_LEFT_HIGH | INT_REF_WRONG) as u32);
    // Away from the switch.
    wr(&mut h, 0, V_TARGET, 500);
    h.wait(5000);
    assert_eq!(h.chip().motor(0).v_actual(), 500);
    // DISABLE_STOP_L: the switch does not stop.
    wr(&mut h, 0, REF_CONF_RM, 0x0102);
    wr(&mut h, 0, V_TARGET, (-300i32) as u32 & 0xFFF);
    h.wait(5000);
    assert_eq!(h.chip().motor(0).v_actual(), -300);
}

const INT_REF_WRONG: u8 = 2;
const INT_STOP: u8 = 8;
const INT_STOP_LEFT_HIGH: u8 = 64;

/// C61 soft stop: the ramp target is 0 while the switch holds, so V falls by a_max per ramp tick.
#[test]
fn soft_stop_right() {
    let mut h = host(Chip::Tmc428);
    h.write(global_a7(15), 0x20_0F00); // mot1r: REF3 = right switch of motor 1
    velocity_mode(&mut h, 0, 1000, 2047);
    wr(&mut h, 0, REF_CONF_RM, 0x0402); // SOFT_STOP, VELOCITY_MODE
    h.wait(5000);
    wr(&mut h, 0, A_MAX, 256);
    set_refs(&mut h, false, false, true);
    let c = h.chip_mut();
    let mut prev = c.motor(0).v;
    let mut ticks = 0;
    let idle = h.pins();
    let c = h.chip_mut();
    while c.motor(0).v != 0 {
        c.tick(&idle);
        let v = c.motor(0).v;
        if v != prev {
            assert_eq!(prev - v, 256);
            ticks += 1;
        }
        prev = v;
    }
    assert_eq!(ticks, 1000, "1000·256 / a_max 256 ramp ticks");
}

/// C61: DX_REF_TOLERANCE "disables automatic stopping by a switch around the origin" (TMC429
/// §8.1.14) and the definition of the reference switch by ref_RnL "has no effect on the stop
/// function of the reference switches" (§8.1.11.2): the window |x_actual| < dx_ref_tolerance
/// masks the stop of the left and of the right switch, whatever ref_RnL.
#[test]
fn reference_tolerance() {
    // (ref_RnL, moving right on REFR1) → the stop position: the first |x| ≥ 100 on the way.
    for (rnl, right) in [(false, false), (true, false), (false, true), (true, true)] {
        let mut h = host(Chip::Tmc429);
        h.write(global_a7(4), 0x100); // en_refr: R1 = REFR1
        {
            let p = h.pins_mut();
            p.refr1 = false;
        }
        wr(&mut h, 0, DX_REF_TOL, 100);
        let start = if right { -50i32 } else { 50 };
        wr(&mut h, 0, X_ACTUAL, start as u32 & 0xFF_FFFF);
        velocity_mode(&mut h, 0, if right { 200 } else { -200 }, 2047);
        wr(&mut h, 0, REF_CONF_RM, (rnl as u32) << 11 | 2);
        if right {
            h.pins_mut().refr1 = true;
        } else {
            set_refs(&mut h, true, false, false);
        }
        h.wait(20_000);
        let x = s24(h.chip().motor(0).x_actual);
        assert!(x.abs() < 100 && x != start, "rnl {rnl} right {right}: moved through the switch inside the window: {x}");
        h.wait(2_000_000);
        assert_eq!(s24(h.chip().motor(0).x_actual), if right { 100 } else { -100 }, "rnl {rnl} right {right}");
        assert_eq!(h.chip().motor(0).v, 0);
    }
}

/// C62: the latch takes x_actual on either edge of the reference switch while lp = 1 and the
/// motor moves, then clears lp.
#[test]
fn latch_on_both_edges() {
    for rising in [true, false] {
        let mut h = host(Chip::Tmc428);
        wr(&mut h, 0, REF_CONF_RM, 0x0102); // left switch does not stop; VELOCITY
        set_refs(&mut h, !rising, false, false);
        velocity_mode(&mut h, 0, 1500, 2047);
        wr(&mut h, 0, REF_CONF_RM, 0x0102);
        h.wait(3000);
        wr(&mut h, 0, X_LATCHED, 0);
        assert_eq!(rd(&mut h, 0, REF_CONF_RM) >> 16, 1);
        h.wait(5000);
        let x_at_edge = h.chip().motor(0).x_actual;
        set_refs(&mut h, rising, false, false);
        // The edge reaches the latch after the 2 synchronizer flops.
        h.wait(3);
        assert_eq!(rd(&mut h, 0, REF_CONF_RM) >> 16, 0, "lp cleared");
        let latched = rd(&mut h, 0, X_LATCHED);
        assert!(latched >= x_at_edge && latched <= x_at_edge + 1, "latched {latched}, at edge {x_at_edge}");
        assert_ne!(latched, 0);
    }
}

/// TMC429 §8.1.15: "An event at the reference switch ... takes effect only during motion (when
/// V_ACTUAL ≠ 0)": with 0 < |V| < 256 (V_ACTUAL = 0, C42) an edge of the switch does not latch;
/// at |V| ≥ 256 it does (C62).
#[test]
fn latch_only_while_v_actual_is_not_0() {
    let mut h = host(Chip::Tmc428);
    // VELOCITY_MODE to v_target 1 with a_max 1: V grows by 1/256 per ramp tick (32 CLK).
    motion_setup(&mut h, 0, 0, 0, 0, 2047, 1, 0, 2);
    wr(&mut h, 0, REF_CONF_RM, 0x0102); // the left switch does not stop
    wr(&mut h, 0, X_LATCHED, 0);
    wr(&mut h, 0, V_TARGET, 1);
    h.wait(100 * 32);
    let v = h.chip().motor(0).v;
    assert!(v > 0 && v < 256, "V = {v}");
    assert_eq!(rd(&mut h, 0, V_ACTUAL), 0);
    set_refs(&mut h, true, false, false);
    h.wait(3);
    assert_eq!(rd(&mut h, 0, REF_CONF_RM) >> 16, 1, "no latch while V_ACTUAL = 0: lp still 1");
    h.wait(300 * 32);
    assert_eq!(rd(&mut h, 0, V_ACTUAL), 1);
    let x = h.chip().motor(0).x_actual;
    set_refs(&mut h, false, false, false);
    h.wait(3);
    assert_eq!(rd(&mut h, 0, REF_CONF_RM) >> 16, 0, "latched while V_ACTUAL = 1");
    assert_eq!(rd(&mut h, 0, X_LATCHED), x);
}

/// C63: REF_WRONG (switch active outside the window) and REF_MISS (position 0 with the switch
/// inactive); STOP_LEFT_LOW on release.
#[test]
fn reference_interrupts() {
    let mut h = host(Chip::Tmc428);
    wr(&mut h, 0, INTERRUPT, 0xFF00);
    wr(&mut h, 0, INTERRUPT, 0xFFFF);
    wr(&mut h, 0, DX_REF_TOL, 10);
    wr(&mut h, 0, X_ACTUAL, 20);
    set_refs(&mut h, true, false, false);
    h.wait(4);
    assert_eq!(rd(&mut h, 0, INTERRUPT) & 0xFF, 0x02 | 0x40, "REF_WRONG, STOP_LEFT_HIGH");
    wr(&mut h, 0, INTERRUPT, 0xFFFF);
    set_refs(&mut h, false, false, false);
    h.wait(4);
    assert_eq!(rd(&mut h, 0, INTERRUPT) & 0xFF, 0x10, "STOP_LEFT_LOW");
    wr(&mut h, 0, X_ACTUAL, 0);
    assert_eq!(rd(&mut h, 0, INTERRUPT) & 0xFF, 0x10 | 0x04 | 0x01, "REF_MISS, and POS_END (x_target is 0)");
}

/// C52, C61: the condition slot applies the conditions of the edge before it. A switch that
/// reaches the old state in the slot's own edge (phase 14) stops the motor one frame later, in
/// the next slot; one that is there in the edge before (phase 13) stops it in this slot.
#[test]
fn switch_stop_takes_the_edge_before_the_slot() {
    for (lead, slots) in [(2u32, 2u32), (3, 1)] {
        let mut h = host(Chip::Tmc428);
        velocity_mode(&mut h, 0, -1000, 2047);
        h.wait(5000);
        assert_eq!(h.chip().motor(0).v_actual(), -1000);
        // C4: a pin set `lead` edges before the slot is in the old state of the slot's edge
        // (lead 2) or of the edge before it (lead 3)
        while h.chip().probes().prescaler & 31 != tmc429_model::PHASE_COMMIT[0] - lead {
            h.wait(1);
        }
        set_refs(&mut h, true, false, false);
        h.wait(lead.into());
        assert_eq!(h.chip().probes().prescaler & 31, tmc429_model::PHASE_COMMIT[0], "the slot's edge is next");
        h.wait(1);
        assert_eq!(h.chip().motor(0).stop_hard, slots == 1, "lead {lead}: after this slot");
        h.wait(31);
        assert!(!h.chip().motor(0).stop_hard || slots == 1, "lead {lead}: before the next slot");
        h.wait(1);
        assert!(h.chip().motor(0).stop_hard, "lead {lead}: after the next slot");
    }
}

/// C65: position compare on TMC429 — POSCMP pin level and the I flag with mask M.
#[test]
fn position_compare() {
    let mut h = host(Chip::Tmc429);
    h.wait(2);
    assert!(h.outputs().poscmp, "x_actual 0 = pos_comp 0 at reset");
    h.write(global_a7(5), 40);
    h.write(global_a7(6), 0x100); // M
    h.write(global_a7(4), 0x40); // pos_comp_sel = motor 2
    assert!(!h.outputs().poscmp);
    velocity_mode(&mut h, 1, 2047, 2047);
    let c = h.chip_mut();
    let idle = tmc429_model::Inputs::default();
    let mut n = 0;
    while c.motor(1).x_actual != 40 {
        c.tick(&idle);
        n += 1;
        assert!(n < 100_000);
    }
    assert!(!c.outputs().poscmp);
    c.tick(&idle);
    assert!(c.outputs().poscmp, "POSCMP one edge after the match");
    assert!(!c.global().pc_i, "I follows the registered match: not yet");
    c.tick(&idle);
    assert!(c.global().pc_i, "I set one edge after POSCMP rises (C65)");
    assert!(c.int());
    assert_eq!(h.read(global_a7(6)), 0x101, "I set");
    assert_eq!(h.status() & 0x80, 0x80, "INT");
    h.write(global_a7(6), 0x101);
    assert_eq!(h.read(global_a7(6)), 0x100, "I cleared by writing 1");
    // TMC428 has no position compare: the pin stays low.
    let mut h = host(Chip::Tmc428);
    h.wait(5);
    assert!(!h.outputs().poscmp);
}

/// C63: STOP_RIGHT_HIGH and STOP_RIGHT_LOW on the right switch (mot1r: REF3 = R1).
#[test]
fn right_switch_interrupts() {
    let mut h = host(Chip::Tmc428);
    h.write(global_a7(15), 0x20_0F00);
    wr(&mut h, 0, INTERRUPT, 0xF000);
    set_refs(&mut h, false, false, true);
    h.wait(4);
    assert_eq!(rd(&mut h, 0, INTERRUPT), 0xF080, "STOP_RIGHT_HIGH");
    wr(&mut h, 0, INTERRUPT, 0xF0FF);
    set_refs(&mut h, false, false, false);
    h.wait(4);
    assert_eq!(rd(&mut h, 0, INTERRUPT), 0xF020, "STOP_RIGHT_LOW");
}

/// C41 with C61: a snapshot acts only from its commit (motor 0: phase 14) on. Motor at V = 0 (a_max 0)
/// on an active left switch in VELOCITY_MODE: a negative v_target makes vt < 0, which starts a
/// stop condition — in motor 1's first condition slot (C61: its commit phase) after the commit,
/// not in the commit's own edge, whose slot reads the old target.
#[test]
fn target_snapshot_acts_from_the_commit() {
    use tmc429_model::{Inputs, Tmc429, PHASE_COMMIT, PHASE_SNAPSHOT};
    let mut c = Tmc429::new(Chip::Tmc429);
    let inp = Inputs { ref1: true, ..Inputs::default() };
    c.tick(&inp); // past frame 0's snapshot of motor 1 (a target of 0)
    c.write_register(0x0B, 0xFF00); // all interrupts of motor 1 enabled
    c.write_register(0x03, 2047); // v_max
    c.write_register(0x04, (-50i32) as u32 & 0xFFF); // v_target
    c.write_register(0x0A, 2); // VELOCITY_MODE, a_max stays 0: V stays 0
                               // settle the switch (C4), then run to the cycle before motor 1's snapshot
    for _ in 0..4 {
        c.tick(&inp);
    }
    c.write_register(0x0B, 0xFFFF); // clear the switch events
    while c.probes().prescaler & 31 != PHASE_SNAPSHOT[0] {
        c.tick(&inp);
    }
    let m = c.motor(0);
    assert_eq!((m.vt, m.vt_next, m.int_flags & INT_STOP), (0, 0, 0));
    c.tick(&inp); // snapshot edge
    assert_eq!((c.motor(0).vt, c.motor(0).vt_next), (0, -50));
    while c.probes().prescaler & 31 != PHASE_COMMIT[0] {
        c.tick(&inp);
        assert_eq!(c.motor(0).int_flags & INT_STOP, 0, "no stop before the commit");
    }
    c.tick(&inp); // commit edge: vt changes in its new state; the slot read the old vt
    assert_eq!(c.motor(0).vt, -50);
    assert_eq!(c.motor(0).int_flags & INT_STOP, 0);
    c.tick(&inp);
    // the condition is evaluated in motor 1's next condition slot, its commit phase (C61)
    while c.probes().prescaler & 31 != PHASE_COMMIT[0] {
        c.tick(&inp);
        assert_eq!(c.motor(0).int_flags & INT_STOP, 0, "no stop before the slot");
    }
    c.tick(&inp); // the slot: V = 0, vt < 0, left switch active: STOP
    assert_eq!(c.motor(0).int_flags & INT_STOP, INT_STOP);
    assert_eq!(c.motor(0).v, 0);
}

/// C52, C61, C63: the conditions are taken in the motor's condition slot only, so a switch level
/// that comes and goes between two slots is not seen: no stop, no event; the same level held over
/// a slot stops the motor in that slot's edge.
#[test]
fn a_switch_level_between_two_slots_is_not_seen() {
    use tmc429_model::{Inputs, Tmc429, PHASE_COMMIT};
    let mut c = Tmc429::new(Chip::Tmc429);
    let idle = Inputs::default();
    let on = Inputs { ref1: true, ..Inputs::default() };
    c.write_register(0x0B, 0xFF00); // all interrupts of motor 1 enabled
    c.write_register(0x03, 2047); // v_max
    c.write_register(0x05, (-100i32) as u32 & 0xFFF); // v_actual: moving left
    c.write_register(0x0A, 3); // HOLD_MODE: V stays as written
    while c.probes().prescaler & 31 != PHASE_COMMIT[0] + 1 {
        c.tick(&idle);
    }
    // REF1 high for 20 edges right after the slot: in the old state (two synchronizer flops, C4)
    // from the slot's third edge on for 20 edges, back low before the next slot
    for _ in 0..20 {
        c.tick(&on);
    }
    for _ in 0..64 {
        c.tick(&idle);
    }
    let m = c.motor(0);
    assert_eq!((m.stop_hard, m.int_flags, m.v), (false, 0, -100 * 256), "not seen");
    // held over the slot: stopped, STOP and STOP_LEFT_HIGH (REF_WRONG: outside a window of 0)
    while c.probes().prescaler & 31 != (PHASE_COMMIT[0] + 32 - 3) % 32 {
        c.tick(&idle);
    }
    for _ in 0..3 {
        c.tick(&on);
    }
    assert!(!c.motor(0).stop_hard);
    c.tick(&on); // the slot
    assert!(c.motor(0).stop_hard);
    assert_eq!(c.motor(0).int_flags, INT_STOP | INT_STOP_LEFT_HIGH | INT_REF_WRONG);
    c.tick(&on);
    assert_eq!(c.motor(0).v, 0);
}
