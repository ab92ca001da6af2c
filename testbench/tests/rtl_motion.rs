//! The motion core of the Verilated RTL alone, driven through its SPI pins: the target-velocity
//! laws of C50 (values computed from the contract's formulas), moves that end exactly on the
//! target (C52), VELOCITY_MODE reaching v_target (C51), the hard switch stop (C61) and the latch
//! (C62). Register values are read back over SPI as a µC would.
#![cfg(not(tmc429_no_rtl))] // needs Verilator (testbench/build.rs)

use tmc429_model::{Chip, Inputs};
use tmc429_testbench::stimulus::Frame;
use tmc429_testbench::{Rtl, Variant};

/// Sends one 32-bit frame through the pins (REF1 at `ref1`) and returns the 32 bits read on
/// the data pin.
fn frame(rtl: &mut Rtl, f: Frame, ref1: bool) -> u32 {
    rtl.spi_frame(f, Inputs { ref1, ..Inputs::default() }) as u32
}

struct Chip1 {
    rtl: Rtl,
    ref1: bool,
}

impl Chip1 {
    fn new(chip: Chip) -> Chip1 {
        Chip1 { rtl: Rtl::new(Variant::Chip(chip)), ref1: false }
    }
    /// Write to register `idx` of motor `m` (0-based).
    fn wr(&mut self, m: u8, idx: u8, data: u32) {
        frame(&mut self.rtl, Frame::write(m << 4 | idx, data & 0xFF_FFFF), self.ref1);
    }
    /// Read register `idx` of motor `m`: the 24 data bits.
    fn rd(&mut self, m: u8, idx: u8) -> u32 {
        frame(&mut self.rtl, Frame::read(m << 4 | idx), self.ref1) & 0xFF_FFFF
    }
    /// The status byte of a read of motor 1's x_target.
    fn status(&mut self) -> u8 {
        (frame(&mut self.rtl, Frame::read(0), self.ref1) >> 24) as u8
    }
    fn wait(&mut self, n: u64) {
        let inp = tmc429_model::Inputs { ref1: self.ref1, ..Default::default() };
        for _ in 0..n {
            self.rtl.tick(&inp);
        }
    }
    /// Dividers, v_min/v_max, a_max, pmul/pdiv, then the mode (as the model tests' motion_setup).
    #[allow(clippy::too_many_arguments)]
    fn setup(&mut self, m: u8, pulse_div: u32, ramp_div: u32, v_min: u32, v_max: u32, a_max: u32, pmul_pdiv: u32, rm: u32) {
        self.wr(m, CLK_CONFIG, pulse_div << 12 | ramp_div << 8);
        self.wr(m, V_MIN, v_min);
        self.wr(m, V_MAX, v_max);
        self.wr(m, A_MAX, a_max);
        self.wr(m, PMUL_PDIV, pmul_pdiv);
        self.wr(m, REF_CONF_RM, rm);
    }
}

const X_TARGET: u8 = 0;
const X_ACTUAL: u8 = 1;
const V_MIN: u8 = 2;
const V_MAX: u8 = 3;
const V_TARGET: u8 = 4;
const V_ACTUAL: u8 = 5;
const A_MAX: u8 = 6;
const A_ACTUAL: u8 = 7;
const PMUL_PDIV: u8 = 9;
const REF_CONF_RM: u8 = 10;
const INTERRUPT: u8 = 11;
const CLK_CONFIG: u8 = 12;
const X_LATCHED: u8 = 14;

/// p = p_mul/2^(3+pdiv) = 1: pmul byte $80 (p_mul 128), pdiv 4.
const P_ONE: u32 = 0x8004;

/// v_target after the first ramp tick of a move of `dx` from 0 (C41: snapshot, commit, tick).
fn first_tick(chip: Chip, m: u8, rm: u32, dx: u32, v_min: u32, v_max: u32, pmul_pdiv: u32) -> u32 {
    let mut c = Chip1::new(chip);
    c.setup(m, 0, 0, v_min, v_max, 1, pmul_pdiv, rm);
    c.wr(m, X_TARGET, dx);
    c.wait(64);
    c.rd(m, V_TARGET)
}

/// The C50 RAMP_MODE law with h = ⌈a_max/128⌉ (pulse_div = ramp_div):
/// min((isqrt(Y) − h) >> 2, 2047), Y = (p_mul·(|dx|−1)·2^12) >> pdiv.
fn ramp_law(y: u64, a_max: u64) -> u32 {
    (y.isqrt().saturating_sub(a_max.div_ceil(128)) >> 2).min(2047) as u32
}

/// C50 RAMP_MODE: sign(dx)·clamp((isqrt(Y) − h) >> 2, v_min, v_max).
#[test]
fn ramp_mode_square_root_law() {
    // isqrt(128·299·4096 >> 4) = isqrt(9797632) = 3130, h = 1: 782
    assert_eq!(first_tick(Chip::Tmc429, 0, 0, 300, 1, 2047, P_ONE), 782);
    // dx = 1: isqrt(0) = 0, v_min carries the motor over the last step
    assert_eq!(first_tick(Chip::Tmc428, 1, 0, 1, 3, 2047, P_ONE), 3);
    // clamped to v_max; negative dx gives a negative target
    assert_eq!(first_tick(Chip::Tmc429, 2, 0, 100_000, 1, 500, P_ONE), 500);
    assert_eq!(first_tick(Chip::Tmc4210, 0, 0, (-300i32) as u32 & 0xFF_FFFF, 1, 2047, P_ONE), (-782i32) as u32 & 0xFFF);
    // v_min > v_max: v_max
    assert_eq!(first_tick(Chip::Tmc429, 0, 0, 1, 40, 20, P_ONE), 20);
    // every pdiv, p_mul 255, for dx = 1000
    for pdiv in 0..16u32 {
        let want = ramp_law(((255u64 * 999) << 12) >> pdiv, 1);
        assert_eq!(first_tick(Chip::Tmc429, 1, 0, 1000, 0, 2047, 0xFF00 | pdiv), want, "pdiv {pdiv}");
    }
    // |dx| is limited to 2^19 − 1 (C43): isqrt((128·(2^19−2)·4096) >> 15) = 2896, 723
    assert_eq!(first_tick(Chip::Tmc429, 0, 0, 0x7F_FFFF, 0, 2047, 0x800F), 723);
    assert_eq!(ramp_law((128 * ((1 << 19) - 2) * 4096) >> 15, 1), 723);
}

/// C50 RAMP_MODE's h = ⌈a_max/128⌉ when ramp_div ≥ pulse_div, 0 below.
#[test]
fn ramp_mode_aims_below_by_half_a_ramp_tick_of_deceleration() {
    let tick = |a_max: u32, pd: u32, rd: u32, dx: u32| {
        let mut c = Chip1::new(Chip::Tmc429);
        c.setup(1, pd, rd, 1, 2047, a_max, P_ONE, 0);
        c.wr(1, X_TARGET, dx);
        c.wait(64);
        c.rd(1, V_TARGET)
    };
    // (3130 − 16) >> 2 = 778; ramp_div below pulse_div: 3130 >> 2 = 782
    assert_eq!(tick(2047, 0, 0, 300), 778);
    assert_eq!(tick(2047, 0, 1, 300), 778);
    assert_eq!(tick(2047, 1, 0, 300), 782);
    assert_eq!(tick(129, 0, 0, 300), ramp_law(9797632, 129));
    // dx = 2: (isqrt(32768) − 16) >> 2 = 41
    assert_eq!(tick(2047, 0, 0, 2), 41);
}

/// C50 SOFT_MODE: sign(dx)·clamp((p_mul·|dx|) >> (3+pdiv), v_min, v_max).
#[test]
fn soft_mode_linear_law() {
    assert_eq!(first_tick(Chip::Tmc429, 0, 1, 300, 1, 2047, P_ONE), 300);
    assert_eq!(first_tick(Chip::Tmc428, 2, 1, 5000, 1, 2047, P_ONE), 2047);
    assert_eq!(first_tick(Chip::Tmc429, 1, 1, 2, 5, 2047, P_ONE), 5);
    for pdiv in 0..16u32 {
        let want = ((200u64 * 40_000) >> (3 + pdiv)).min(2047) as u32;
        assert_eq!(
            first_tick(Chip::Tmc429, 0, 1, (-40_000i32) as u32 & 0xFF_FFFF, 0, 2047, 0xC800 | pdiv),
            (-(want as i32)) as u32 & 0xFFF,
            "pdiv {pdiv}"
        );
    }
}

/// C52: a RAMP_MODE move with the datasheet's p (pmulpdiv, a_max 100, 5 % reduction) ends exactly
/// on x_target and stops: x_actual, v_actual and a_actual read back, xEQt and POS_END set.
#[test]
fn ramp_mode_move_ends_on_target() {
    for chip in Chip::ALL {
        let mut c = Chip1::new(chip);
        let p = tmc429_model::pmulpdiv::calc(100, 2, 0, 0.05).register_value().unwrap();
        c.wr(0, INTERRUPT, 0x0100); // POS_END enabled
        c.setup(0, 0, 2, 2, 1000, 100, p, 0);
        c.wr(0, X_TARGET, 30_000);
        c.wait(100_000);
        assert_eq!(c.status() & 1, 0, "{chip}: moving");
        assert_ne!(c.rd(0, V_ACTUAL), 0);
        c.wait(3_000_000);
        assert_eq!(c.rd(0, X_ACTUAL), 30_000, "{chip}");
        assert_eq!(c.rd(0, V_ACTUAL), 0, "{chip}");
        assert_eq!(c.rd(0, A_ACTUAL), 0, "{chip}");
        assert_eq!(c.rtl.probes().motor[0].v_internal, 0);
        assert_eq!(c.status() & 0x81, 0x81, "{chip}: xEQt1 and INT");
        assert_eq!(c.rd(0, INTERRUPT), 0x0101, "{chip}: POS_END");
        // and back to a negative target
        c.wr(0, X_TARGET, (-5i32) as u32 & 0xFF_FFFF);
        c.wait(3_000_000);
        assert_eq!(c.rd(0, X_ACTUAL), 0xFF_FFFB, "{chip}");
        assert_eq!(c.rd(0, V_ACTUAL), 0, "{chip}");
    }
}

/// C51: in VELOCITY_MODE V climbs by a_max per ramp tick and lands on 256·v_target; v_actual
/// and v_target read back; in HOLD_MODE a write of v_actual sets V (C23).
#[test]
fn velocity_mode_reaches_v_target() {
    let mut c = Chip1::new(Chip::Tmc429);
    c.setup(1, 0, 0, 0, 2047, 7, 0, 2);
    c.wr(1, V_TARGET, (-600i32) as u32 & 0xFFF);
    c.wait(32 * 4);
    // a few ramp ticks of −7/256
    assert_eq!(c.rd(1, A_ACTUAL), (-7i32) as u32 & 0xFFF);
    c.wait(32 * (600 * 256 / 7 + 100));
    assert_eq!(c.rd(1, V_ACTUAL), (-600i32) as u32 & 0xFFF);
    assert_eq!(c.rd(1, A_ACTUAL), 0);
    assert_eq!(c.rtl.probes().motor[1].v_internal, -600 * 256);
    c.wr(1, REF_CONF_RM, 3); // HOLD_MODE: V changes only by writes
    c.wr(1, V_ACTUAL, 0x800); // −2048 is stored as −2047 (C23)
    assert_eq!(c.rtl.probes().motor[1].v_internal, -2047 * 256);
    assert_eq!(c.rd(1, V_ACTUAL), (-2047i32) as u32 & 0xFFF);
}

/// C61, C62: a hard stop on the left switch while moving left, the latch armed by a write to
/// x_latched takes x_actual at the switch edge; both in motor 1's condition slot (its commit
/// phase 14).
#[test]
fn hard_switch_stop_and_latch() {
    let mut c = Chip1::new(Chip::Tmc428);
    c.wr(0, INTERRUPT, 0xFF00);
    c.setup(0, 0, 0, 0, 2047, 2047, 0, 2);
    c.wr(0, V_TARGET, (-1000i32) as u32 & 0xFFF);
    c.wr(0, X_LATCHED, 0);
    c.wait(5000);
    assert_eq!(c.rd(0, V_ACTUAL), (-1000i32) as u32 & 0xFFF);
    assert_eq!(c.rd(0, REF_CONF_RM) >> 16 & 1, 1, "lp armed");
    // the pin goes up 10 edges before the slot; the switch is in the old state from the 3rd
    // edge on (C4), but nothing acts on it before the slot
    while c.rtl.probes().prescaler & 31 != tmc429_model::PHASE_COMMIT[0] - 10 {
        c.wait(1);
    }
    c.ref1 = true;
    for _ in 0..10 {
        c.wait(1);
        assert_eq!(c.rtl.probes().motor[0].v_internal, -1000 * 256, "no stop before the slot");
    }
    // the slot's edge latches x_actual of its old state (C62) and registers the stop condition
    // (C61); V := 0 and no step from the next edge on (C52)
    let x_edge = c.rtl.probes().motor[0].x_actual;
    c.wait(1);
    assert_eq!(c.rtl.probes().motor[0].v_internal, -1000 * 256, "the stop acts one edge after its condition (C52)");
    let x = c.rtl.probes().motor[0].x_actual;
    c.wait(1);
    assert_eq!(c.rtl.probes().motor[0].v_internal, 0, "stopped in the edge after the slot (C61, C52)");
    c.wait(10_000);
    assert_eq!(c.rd(0, X_ACTUAL), x, "held");
    assert_eq!(c.rd(0, X_LATCHED), x_edge, "latched at the edge");
    assert_eq!(c.rd(0, REF_CONF_RM) >> 16 & 1, 0, "lp cleared");
    // STOP, STOP_LEFT_HIGH and REF_WRONG (left switch active outside a window of 0)
    assert_eq!(c.rd(0, INTERRUPT) & 0xFF, 0x08 | 0x40 | 0x02);
    // away from the switch
    c.wr(0, V_TARGET, 500);
    c.wait(5000);
    assert_eq!(c.rd(0, V_ACTUAL), 500);
}
