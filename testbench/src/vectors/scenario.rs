//! Scenarios: what the µC and the switches do, as pin levels per CLK cycle.
//!
//! A scenario is a datagram script (the `tmc429 spi` format, `model/src/script.rs`) run by a
//! virtual µC at a fixed SCK_C half period, exactly as `tmc429 spi` runs it, or the seeded
//! random traffic of the co-simulation (`stimulus.rs`), or pin levels recorded from another
//! run ([`Source::Recorded`]: a TOML scenario of `tmc429 run`, whose events depend on the
//! chip's state, is run once on the model and its pins recorded, scenario/src/vectors.rs).
//! Built-in scenarios are scripts made here; a scenario file given to [`from_file`] is a
//! script.

use std::collections::VecDeque;
use std::path::Path;

use tmc429_model::regmap::{self, Addr};
use tmc429_model::script::{self, Command, Line, Pin};
use tmc429_model::{pmulpdiv, Chip, Inputs, Package};

use crate::stimulus::{Driver, Profile, Stimulus};

/// Where the pin levels come from.
#[derive(Clone, Debug)]
pub enum Source {
    /// A datagram script; the µC's SCK_C half period in CLK cycles.
    Script { lines: Vec<Line>, sck_half: u32 },
    /// The co-simulation's seeded random traffic for `cycles` CLK cycles.
    Random { cycles: u64, profile: Profile },
    /// Pin levels recorded from a run: runs of equal levels, (levels, number of CLK cycles).
    Recorded(PinRuns),
}

/// Pin levels per CLK cycle, run-length encoded (a 60 ms run at 32 MHz is a few thousand
/// runs, not 1.9 M entries).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct PinRuns {
    runs: Vec<(Inputs, u32)>,
    cycles: u64,
}

impl PinRuns {
    pub fn new() -> PinRuns {
        PinRuns::default()
    }
    /// Appends the levels of the next CLK cycle.
    pub fn push(&mut self, i: Inputs) {
        self.cycles += 1;
        match self.runs.last_mut() {
            Some((last, n)) if *last == i && *n < u32::MAX => *n += 1,
            _ => self.runs.push((i, 1)),
        }
    }
    /// Number of CLK cycles recorded.
    pub fn cycles(&self) -> u64 {
        self.cycles
    }
    /// The levels, one per CLK cycle.
    pub fn iter(&self) -> impl Iterator<Item = Inputs> + '_ {
        self.runs.iter().flat_map(|&(i, n)| std::iter::repeat(i).take(n as usize))
    }
}

/// A scenario for one chip.
#[derive(Clone, Debug)]
pub struct Scenario {
    pub name: String,
    pub chip: Chip,
    /// The package: the pins it lacks are tied off (C90); [`Package::full`] by default.
    pub package: Package,
    pub fclk: u64,
    pub seed: u64,
    pub source: Source,
    /// What the scenario does (recorded in `.meta`).
    pub notes: Vec<String>,
}

/// The built-in scenarios: name and what they are for.
pub const BUILTIN: &[(&str, &str)] = &[
    ("datasheet", "the datagram examples of [428] §6.5 (write, read, RAM, status by an 8-bit frame)"),
    ("registers", "every register of the chip written and read back; motors in HOLD_MODE, no driver-chain datagram"),
    ("chip-hold", "switches, interrupts, nINT, position compare, sdo_int, power down and wake-up; motors in HOLD_MODE"),
    ("reference-search", "motor 0 searches REF1 in VELOCITY_MODE (v_actual read while it accelerates), stops, is zeroed and moves off in RAMP_MODE"),
    ("ramp-modes", "RAMP_MODE, SOFT_MODE and VELOCITY_MODE moves, a reversal and HOLD_MODE with a v_actual write"),
    ("ramp-boundary", "v_max 2047 / a_max 2047, v_target -2048, a_max 0, v_min > v_max, a move across x = 2^23"),
    ("ramp-p-examples", "RAMP_MODE moves with the pmul/pdiv of the [428] §8.11 method (pmulpdiv.c of [429] §8.1.10.2.3)"),
    ("ramp-unit", "the ramp unit in few cycles: RAMP_MODE and SOFT_MODE with the [428] §8.11 p example 2047/0/0, a soft switch stop and the latch, VELOCITY_MODE at a_max 2047 across x = 2^23 and back, a_max 0, HOLD_MODE with a v_actual write of -2048, usrs 7, a ustep_count write, the tolerance window at its bounds"),
    ("chain-datasheet", "Table 11-2 configuration, Table 12-2 LUT, the datagrams they give and a cover datagram"),
    ("chain-unit", "the driver-chain master in few cycles: power-on Table 11-2 and LUT, clk2_div 0 (asymmetric SCK_S), a cover datagram of length 0 and one of 12 bits at position 3, i_scale %100, a datagram-word write (CDGW), SDI_S readback, a datagram aborted by en_sd and restarted"),
    ("tables", "lut unit: complete tables, every usrs, both directions, every i_scale, sine and rhomb LUT"),
    ("random", "the co-simulation's seeded random register traffic (--seed, --cycles)"),
];

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

/// Looks up a built-in scenario. `cycles`: length of `random`.
pub fn builtin(name: &str, chip: Chip, fclk: u64, seed: u64, cycles: u64) -> Option<Scenario> {
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
        "random" => {
            return Some(Scenario {
                name: name.into(),
                chip,
                package: Package::full(chip),
                fclk,
                seed,
                source: Source::Random { cycles, profile: Profile::Registers },
                notes: vec!["co-simulation stimulus, register profile (docs/cosim.md)".into()],
            })
        }
        _ => return None,
    };
    let desc = BUILTIN.iter().find(|(n, _)| *n == name).map(|(_, d)| d.to_string()).unwrap_or_default();
    // The datasheet examples run on a chip where the motors hold (the reset state's RAMP_MODE
    // with x = x_target = 0 never moves, and nothing here changes that).
    Some(Scenario {
        name: name.into(),
        chip,
        package: Package::full(chip),
        fclk,
        seed: 0,
        source: Source::Script { lines: b.lines, sck_half: SCK_HALF },
        notes: vec![desc],
    })
}

/// SCK_C half period of the built-in scenarios: the minimum of [428] Table 6-1 (C11).
pub const SCK_HALF: u32 = 3;

/// A scenario file: a datagram script (`tmc429 spi` format).
pub fn from_file(path: &Path, chip: Chip, fclk: u64, sck_half: u32) -> Result<Scenario, String> {
    let text = tmc429_model::text::read_file(path)?;
    let name = path.display().to_string();
    let lines = script::parse(&text, &name).map_err(|errs| errs.iter().map(|e| e.to_string()).collect::<Vec<_>>().join("\n"))?;
    let stem = path.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_else(|| "script".into());
    Ok(Scenario {
        name: stem,
        chip,
        package: Package::full(chip),
        fclk,
        seed: 0,
        source: Source::Script { lines, sck_half },
        notes: vec![format!("datagram script {}", path.display())],
    })
}

impl Scenario {
    /// The pin levels, one [`Inputs`] per CLK cycle.
    pub fn inputs(&self) -> Box<dyn Iterator<Item = Inputs> + '_> {
        match &self.source {
            Source::Script { lines, sck_half } => {
                Box::new(ScriptInputs { lines: lines.iter(), pins: Inputs::default(), half: *sck_half, buf: VecDeque::new(), wait: 0 })
            }
            Source::Random { cycles, profile } => {
                let mut stim = Stimulus::new(self.chip, *profile, self.seed);
                let mut drv = Driver::default();
                Box::new((0..*cycles).map(move |_| {
                    if drv.ready() {
                        drv.start(stim.next_txn());
                    }
                    drv.step().0
                }))
            }
            Source::Recorded(runs) => Box::new(runs.iter()),
        }
    }
}

/// The virtual µC of `tmc429 spi` (model/src/host.rs) as a pin-level stream: a frame is nSCS_C
/// low for `half` cycles, per bit SCK_C low with the data for `half` cycles then high for
/// `half` cycles, then nSCS_C high for `half` cycles.
struct ScriptInputs<'a> {
    lines: std::slice::Iter<'a, Line>,
    pins: Inputs,
    half: u32,
    buf: VecDeque<Inputs>,
    wait: u64,
}

impl ScriptInputs<'_> {
    fn hold(&mut self) {
        for _ in 0..self.half {
            self.buf.push_back(self.pins);
        }
    }
    fn frame(&mut self, value: u32, nbits: u32) {
        self.pins.nscs_c = false;
        self.hold();
        for i in (0..nbits).rev() {
            self.pins.sck_c = false;
            self.pins.sdi_c = (value >> i) & 1 != 0;
            self.hold();
            self.pins.sck_c = true;
            self.hold();
        }
        self.pins.nscs_c = true;
        self.hold();
    }
}

impl Iterator for ScriptInputs<'_> {
    type Item = Inputs;
    fn next(&mut self) -> Option<Inputs> {
        loop {
            if let Some(i) = self.buf.pop_front() {
                return Some(i);
            }
            if self.wait > 0 {
                self.wait -= 1;
                return Some(self.pins);
            }
            match &self.lines.next()?.command {
                Command::Datagram(d) => self.frame(*d, 32),
                Command::Bits { n, value } => self.frame(*value, *n),
                Command::Wait(c) => self.wait = *c,
                Command::Pins(set) => {
                    for (p, v) in set {
                        p.set(&mut self.pins, *v);
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use tmc429_model::host::Host;

    /// The pin stream of a script equals what `tmc429 spi`'s virtual µC drives.
    #[test]
    fn script_inputs_equal_host() {
        let sc = builtin("datasheet", Chip::Tmc429, 32_000_000, 0, 0).unwrap();
        let mine: Vec<Inputs> = sc.inputs().collect();
        let mut host = Host::new(Chip::Tmc429);
        host.set_sck_half(SCK_HALF).unwrap();
        let seen = std::sync::Arc::new(std::sync::Mutex::new(Vec::new()));
        let s2 = seen.clone();
        host.set_observer(Box::new(move |_c, i, _o| s2.lock().unwrap().push(*i)));
        let Source::Script { lines, .. } = &sc.source else { unreachable!() };
        let mut sink = Vec::new();
        script::run(&mut host, lines, Default::default(), &mut sink).unwrap();
        assert_eq!(*seen.lock().unwrap(), mine);
        // 5 frames of 32 bits and one of 8, each (1 + 2·bits + 1)·3 cycles
        assert_eq!(mine.len(), 5 * 198 + 54);
    }

    /// Recorded pins replay exactly: run-length encoding keeps every cycle, and the vectors of
    /// a recorded scenario equal those of the script it was recorded from.
    #[test]
    fn recorded_pins_replay_exactly() {
        let sc = builtin("chip-hold", Chip::Tmc429, 32_000_000, 0, 0).unwrap();
        let mut runs = PinRuns::new();
        for i in sc.inputs() {
            runs.push(i);
        }
        let n = sc.inputs().count();
        assert_eq!(runs.cycles(), n as u64);
        assert!(runs.runs.len() < n / 2, "{} runs for {n} cycles", runs.runs.len());
        assert!(runs.iter().eq(sc.inputs()));
        let rec = Scenario { source: Source::Recorded(runs), ..sc.clone() };
        let dir = std::env::temp_dir().join(format!("tmc429-recorded-{}", std::process::id()));
        let (a, b) = (dir.join("script"), dir.join("recorded"));
        for (d, s) in [(&a, &sc), (&b, &rec)] {
            std::fs::create_dir_all(d).unwrap();
            let set = [
                (crate::vectors::Unit::Chip, vec![crate::vectors::Form::Pins]),
                (crate::vectors::Unit::Spi, vec![crate::vectors::Form::Csv]),
            ];
            let files = crate::vectors::export_units(s, &set, d).unwrap();
            assert_eq!(files.len(), 4);
        }
        for f in ["chip-chip-hold-tmc429.hex", "chip-chip-hold-tmc429.meta", "spi-chip-hold-tmc429.csv"] {
            assert_eq!(std::fs::read(a.join(f)).unwrap(), std::fs::read(b.join(f)).unwrap(), "{f}");
        }
        std::fs::remove_dir_all(&dir).ok();
    }

    #[test]
    fn every_builtin_resolves() {
        for (name, _) in BUILTIN {
            let s = builtin(name, Chip::Tmc429, 32_000_000, 1, 100).unwrap();
            assert_eq!(s.inputs().next().is_some(), *name != "tables", "{name}");
        }
        assert!(builtin("nope", Chip::Tmc429, 1, 0, 0).is_none());
    }
}
