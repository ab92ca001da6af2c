//! The built-in scenarios' scripts ([`super::scenario::BUILTIN`]): datagram scripts made with a
//! small builder, each a sequence of writes, reads, waits and pin changes.

use tmc429_model::regmap::{self, Addr};
use tmc429_model::script::{Command, Line, Pin};
use tmc429_model::{pmulpdiv, Chip};

/// The script of built-in scenario `name` for `chip` (`None` for a name that is not a script).
pub(super) fn script(name: &str, chip: Chip) -> Option<Vec<Line>> {
    let b = match name {
        "datasheet" => datasheet(),
        "registers" => registers(chip),
        "chip-hold" => chip_hold(),
        "reference-search" => reference_search(),
        "ramp-modes" => ramp_modes(),
        "ramp-boundary" => ramp_boundary(),
        "ramp-p-examples" => ramp_p_examples(),
        "ramp-unit" => ramp_unit(),
        "chain-unit" => chain_unit(),
        "chain-datasheet" => chain_datasheet(),
        // the lut unit's tables need no pins
        "tables" => B::default(),
        _ => return None,
    };
    Some(b.lines)
}

/// Script builder.
#[derive(Default)]
struct B {
    lines: Vec<Line>,
}

impl B {
    fn push(&mut self, command: Command) -> &mut Self {
        let line = self.lines.len() + 1;
        self.lines.push(Line { line, command });
        self
    }
    fn w(&mut self, a7: u8, data: u32) -> &mut Self {
        self.push(Command::Datagram(regmap::datagram(a7, false, data)))
    }
    fn r(&mut self, a7: u8) -> &mut Self {
        self.push(Command::Datagram(regmap::datagram(a7, true, 0)))
    }
    /// Motor register write.
    fn m(&mut self, motor: u8, idx: u8, data: u32) -> &mut Self {
        self.w(regmap::motor_a7(motor, idx), data & 0xFF_FFFF)
    }
    fn g(&mut self, jdx: u8, data: u32) -> &mut Self {
        self.w(regmap::global_a7(jdx), data)
    }
    fn wait(&mut self, c: u64) -> &mut Self {
        self.push(Command::Wait(c))
    }
    fn pin(&mut self, p: Pin, level: bool) -> &mut Self {
        self.push(Command::Pins(vec![(p, level)]))
    }
    fn status8(&mut self) -> &mut Self {
        self.push(Command::Bits { n: 8, value: 0 })
    }
    /// RAMP-mode parameters of the [428] §8.11 method for a_max, ramp_div, pulse_div.
    fn p_of(&mut self, motor: u8, a_max: u32, rd: u32, pd: u32, reduction: f32) -> &mut Self {
        let p = pmulpdiv::calc(a_max as i32, rd as i32, pd as i32, reduction);
        let v = p.register_value().expect("built-in p examples are representable");
        self.m(motor, 12, pd << 12 | rd << 8).m(motor, 6, a_max).m(motor, 9, v)
    }
}

const IDX_RM: u8 = 10;
const HOLD: u32 = 3;

/// Data of a write that keeps a chip replayable without motion core and driver chain: rm
/// HOLD_MODE, v_actual 0, no continuous update, no refmux, no cover datagram (`None`: read it
/// instead).
fn hold_safe(a7: u8, data: u32) -> Option<u32> {
    match Addr::from_a7(a7) {
        Addr::Motor(_, 10) => Some(data | HOLD),
        Addr::Motor(_, 5) => Some(data & !0xFFF),
        Addr::Global(3) => None,
        Addr::Global(15) => Some(data & !(1 << 16 | 1 << 20)),
        _ => Some(data),
    }
}

fn registers(chip: Chip) -> B {
    let mut b = B::default();
    for m in 0..3 {
        b.m(m, IDX_RM, HOLD);
    }
    let mut a7s: Vec<u8> = (0u8..0x40).filter(|a| regmap::lookup(chip, *a).is_some()).collect();
    // RAM: the first and last word of each half (every word is a register of the same kind)
    a7s.extend([0x40u8, 0x5F, 0x60, 0x7F].iter().filter(|a| regmap::lookup(chip, **a).is_some()));
    for a7 in a7s {
        // a different pattern per address catches a decode error
        let data = (a7 as u32).wrapping_mul(0x9E_3779) & 0xFF_FFFF ^ 0x5A_A55A;
        match hold_safe(a7, data) {
            Some(d) => b.w(a7, d),
            None => b.r(a7),
        };
        b.r(a7);
    }
    b
}

fn datasheet() -> B {
    let mut b = B::default();
    b.push(Command::Datagram(0x1A00_0123)); // write dx_ref_tolerance[1] = $123
    b.push(Command::Datagram(0x1B00_0000)); // read it: $15000123 (E1)
    b.push(Command::Datagram(0xFE00_2321)); // RAM ADDR 63: cells 126, 127 (E2)
    b.push(Command::Datagram(0xFF00_0000)); // read: $15002321
    b.status8();
    b.push(Command::Datagram(0x7300_0000)); // type_version
    b
}

fn chip_hold() -> B {
    let mut b = B::default();
    for m in 0..3 {
        b.m(m, IDX_RM, HOLD);
    }
    // CDGW: a datagram_low_word write arms it; an 8-bit frame reads the status byte
    b.g(0, 0).status8();
    // interrupts of motor 0: every mask bit; REF1 high raises STOP_LEFT_HIGH
    b.m(0, 11, 0xFF00).r(regmap::motor_a7(0, 11));
    b.pin(Pin::Ref1, true).wait(20).status8().r(regmap::motor_a7(0, 11));
    b.pin(Pin::Ref1, false).wait(20).m(0, 11, 0xFFFF).r(regmap::motor_a7(0, 11));
    // position compare (TMC429/TMC4210): M = 1, pos_comp = 100, x_actual := 100
    b.g(6, 0x100).g(5, 100).m(0, 1, 100).wait(10).r(regmap::global_a7(6));
    // sdo_int: the data leaves on SDOZ_C only, nINT_SDO_C is nINT
    b.g(4, 0x002).r(regmap::motor_a7(0, 1)).g(6, 0x101).g(4, 0);
    // POS_END of motor 1, REF_MISS of motor 2, right switches with en_refr (TMC429)
    b.m(1, 11, 0x0100).m(1, 0, 5).m(1, 1, 5).m(1, 11, 0x0101);
    b.m(2, 11, 0x0400).m(2, 1, 7).m(2, 1, 0).r(regmap::motor_a7(2, 11)).m(2, 11, 0);
    b.g(4, 0x100).pin(Pin::Refr2, false).wait(10).r(regmap::global_a7(14)).pin(Pin::Refr2, true);
    // REFR3 low (r3 0 on the QFN32; the SOP24 lacks REFR3: its pull-up reads high, C90)
    b.pin(Pin::Refr3, false).wait(10).r(regmap::global_a7(14)).pin(Pin::Refr3, true);
    b.g(4, 0x001).pin(Pin::Ref3, true).wait(10).r(regmap::global_a7(14)).pin(Pin::Ref3, false).g(4, 0);
    // power down, asleep for a while, the next frame wakes the chip
    b.g(8, 0).wait(200).r(regmap::global_a7(9)).r(regmap::global_a7(6));
    b.m(0, 11, 0).g(6, 0).status8();
    b
}

fn reference_search() -> B {
    let mut b = B::default();
    // motor 0: VELOCITY_MODE toward the left switch, hard stop; then zero and move off
    b.m(0, 2, 20).m(0, 3, 400).p_of(0, 1000, 2, 0, 0.05).m(0, 13, 0);
    b.m(0, 11, 0x0800); // STOP interrupt
    b.m(0, IDX_RM, 2).m(0, 4, (-300i32) as u32 & 0xFFF);
    // v_actual while it accelerates: V negative with a nonzero low byte, read rounded toward 0
    b.wait(6000).r(regmap::motor_a7(0, 5));
    b.pin(Pin::Ref1, true).wait(400).r(regmap::motor_a7(0, 1)).status8();
    // zero the position at the switch, leave it in RAMP_MODE
    b.m(0, IDX_RM, 0).m(0, 1, 0).m(0, 0, 0).m(0, 11, 0x08FF);
    b.m(0, 0, 40).wait(2000).pin(Pin::Ref1, false).wait(24_000).r(regmap::motor_a7(0, 1));
    b
}

fn ramp_modes() -> B {
    let mut b = B::default();
    // motor 0 RAMP_MODE, motor 1 SOFT_MODE, motor 2 VELOCITY_MODE; ramp_div 2, pulse_div 0
    for m in 0..3 {
        b.m(m, 2, 20).m(m, 3, 600).p_of(m, 2000, 2, 0, 0.05);
    }
    b.m(1, IDX_RM, 1).m(2, IDX_RM, 2);
    b.m(0, 0, 300).m(1, 0, (-200i32) as u32).m(2, 4, 500);
    b.wait(45_000).m(2, 4, (-250i32) as u32 & 0xFFF);
    b.wait(20_000).m(2, 4, 0).m(0, 0, 100);
    b.wait(35_000);
    // HOLD_MODE: V only by a v_actual write
    b.m(2, IDX_RM, HOLD).m(2, 5, 200).wait(4_000).m(2, 5, 0).wait(1_000);
    b
}

fn ramp_boundary() -> B {
    let mut b = B::default();
    // motor 0: VELOCITY_MODE at the limits (a_max 2047 = 8 units of v per ramp tick), then
    // v_target -2048 (acts as -2047), then a_max 0 freezes V where it is
    b.m(0, 3, 2047).m(0, 6, 2047).m(0, 12, 0).m(0, IDX_RM, 2).m(0, 4, 2047);
    b.wait(9_000).m(0, 4, 0x800).wait(18_000).m(0, 6, 0).m(0, 4, 0).wait(3_000);
    // motor 1: RAMP_MODE with v_min > v_max (the clamp yields v_max), a short move
    b.m(1, 2, 100).m(1, 3, 50).p_of(1, 64, 1, 0, 0.05).m(1, 0, 12);
    // motor 2: RAMP_MODE across the 24-bit signed boundary 2^23 - 1 → -2^23
    b.m(2, 1, 0x7F_FFF0).m(2, 2, 1).m(2, 3, 600).p_of(2, 2000, 2, 0, 0.05).m(2, 0, 0x80_0010);
    b.wait(18_000);
    // pmul 127 / pdiv 15 (kept, C22): the target law at its smallest p, v_min carries the move
    b.m(2, 2, 40).m(2, 9, 0x7F0F).m(2, 0, 0x7F_FFF8).wait(40_000);
    b
}

fn ramp_p_examples() -> B {
    let mut b = B::default();
    // pmulpdiv.c ([429] §8.1.10.2.3): a_max 1000 rd 3 pd 3, 5 % → p_mul 237 pdiv 2; 2047/0/0, 5 % → 243/1;
    // 128/0/0, 0 % → 128/4 (p = 1). v_min > 0: the √-law aims one step short (C50) and v_min
    // carries the last step (C52).
    b.m(0, 2, 50).m(0, 3, 1000).p_of(0, 1000, 3, 3, 0.05).m(0, 0, 60);
    b.m(1, 2, 1).m(1, 3, 2047).p_of(1, 2047, 0, 0, 0.05).m(1, 0, 400);
    b.m(2, 2, 10).m(2, 3, 200).p_of(2, 128, 0, 0, 0.0).m(2, 0, 150);
    b.wait(PEX_WAIT);
    b
}

const PEX_WAIT: u64 = 100_000;

/// The ramp unit's pin-level golden set: ramp_div = pulse_div = 0 (a ramp and a pulse tick in
/// every frame), so each case takes a few frames.
fn ramp_unit() -> B {
    let mut b = B::default();
    // motor 0: RAMP_MODE, pmulpdiv.c row 2047/0/0 5 % (p_mul 243, pdiv 1), ustep_count write
    b.m(0, 2, 50).m(0, 3, 2047).p_of(0, 2047, 0, 0, 0.05).m(0, 15, 0x80).m(0, 0, 60);
    // motor 1: SOFT_MODE with SOFT_STOP and the same parameters, latch armed, moving left
    b.m(1, 2, 10).m(1, 3, 2047).p_of(1, 2047, 0, 0, 0.05).m(1, IDX_RM, 0x400 | 1).m(1, 14, 0);
    b.m(1, 0, (-1500i32) as u32);
    // motor 2: VELOCITY_MODE at a_max 2047 (8 units per ramp tick), v_max 300, usrs 7, from
    // x = 2^23 - 2 across the signed boundary
    b.m(2, 1, 0x7F_FFFE).m(2, 3, 300).m(2, 6, 2047).m(2, 12, 7).m(2, IDX_RM, 2).m(2, 4, 2047);
    // REF2 (motor 1's left switch) stops motor 1 softly and latches its position
    b.wait(1500).pin(Pin::Ref2, true).wait(800).pin(Pin::Ref2, false).wait(1200);
    // v_target -2048 acts as -2047, clamped to -v_max: back across 2^23; then a_max 0 freezes V
    b.m(2, 4, 0x800).wait(3000).m(2, 6, 0).wait(300);
    // HOLD_MODE: V only by v_actual writes (-2048 as -2047, C23)
    b.m(2, IDX_RM, HOLD).m(2, 5, 0x800).wait(300).m(2, 5, 0).wait(200);
    // the tolerance window's bounds (C61): |x_actual| = tol - 1 and tol on both sides, the
    // largest tolerance at x = -4096 (the window's low bits all 0), tolerance 0 and 1 at 0, -1
    let bounds: [(u32, &[i32]); 4] =
        [(100, &[99, 100, -99, -100]), (4095, &[4094, 4095, -4094, -4095, -4096]), (0, &[0, -1]), (1, &[0, 1, -1, 0])];
    for (tol, xs) in bounds {
        b.m(2, 13, tol);
        for &x in xs {
            b.m(2, 1, x as u32).wait(20);
        }
    }
    b
}

fn chain_datasheet() -> B {
    let mut b = B::default();
    // Table 11-3: the 18 configuration datagrams of Table 11-2
    let cells = regmap_cells();
    for (addr, pair) in cells.chunks(2).enumerate() {
        b.w(regmap::ram_a7(addr as u8), (pair[1] as u32) << 8 | pair[0] as u32);
    }
    // Table 12-2: the quarter sine wave
    for k in 0..32u8 {
        let y = tmc429_model::ram::SINE_LUT;
        b.w(regmap::ram_a7(32 + k), (y[2 * k as usize + 1] as u32) << 8 | y[2 * k as usize] as u32);
    }
    // LSMD = 2, clk2_div 7 (1 MHz SCK_S at 16 MHz)
    b.g(15, 0x0702);
    // a cover datagram of length 0 sends the unchanged datagram: w = (0,0,0) → $05F05F07F
    b.g(2, 0).g(3, 0).wait(800);
    // w = (16,16,16) → $35D35D37D; with i_scale %100 → $1CF1CF1EF
    for m in 0..3 {
        b.m(m, 15, 16);
    }
    b.g(3, 0).wait(800);
    for m in 0..3 {
        b.m(m, 8, 4 << 20 | 4 << 16 | 4 << 12);
    }
    b.g(3, 0).wait(800);
    for m in 0..3 {
        b.m(m, 8, 0).m(m, 15, 0);
    }
    // w = (100,0,0) → $55805F07F
    b.m(0, 15, 100).g(3, 0).wait(800).m(0, 15, 0);
    // cover example: cover_pos 0, cover_len 12, $000ABC → $ABC05F07F
    b.g(2, 12).g(3, 0xABC).wait(800);
    b
}

/// The driver-chain master's pin-level golden set (unit `chain`): the TMC429's power-on RAM
/// (Table 11-2 with One, the sine LUT), clk2_div 0 (LO 1, HI 15 edges, TMC428 §9.7), LSMD 2.
fn chain_unit() -> B {
    let mut b = B::default();
    b.g(15, 0x0002);
    // a cover datagram of length 0 sends the unchanged datagram: w = (0,0,0)
    b.g(2, 0).g(3, 0).wait(700);
    // w = 16 and i_scale %100 for motor 0; SDI_S high during the datagram (readback)
    b.m(0, 15, 16).m(0, 8, 4 << 20 | 4 << 16 | 4 << 12).g(3, 0).wait(200).pin(Pin::SdiS, true).wait(500);
    b.pin(Pin::SdiS, false);
    // cover $ABC at position 3, length 12 (C85); a datagram_low_word write arms CDGW (C88)
    b.g(2, 3 << 8 | 12).g(0, 0).g(3, 0xABC).wait(700);
    // a datagram aborted by en_sd = 1 (C89): cover and CDGW return to waiting, then restart
    b.g(0, 0).g(3, 0x5A5).wait(150).g(4, 1 << 5).wait(50).g(4, 0).wait(700);
    b
}

/// Table 11-2 as RAM cells 0..35.
fn regmap_cells() -> [u8; 36] {
    tmc429_model::ram::TABLE_11_2
}
