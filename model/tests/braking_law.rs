//! The RAMP_MODE braking law (C50) keeps the datasheets' promise over the whole valid
//! parameter space (TMC429 §8.1.10, §8.1.10.2; TMC428 §8.10): no step past the target, no
//! step backwards, the move ends on x_target with V = 0 (v_min ≥ 1; with v_min = 0 it rests at
//! or short of it, TMC429 §8.1.3), and the move time stays close to the ideal trapezoid.
//!
//! `grid_every_divider_pair` walks every (pulse_div, ramp_div) in 0..13 × 0..13 with a_max at
//! the ends and the middle of its window (TMC429 §8.1.7.1.1, erratum E10), several v_max and
//! v_min, p from the datasheet method with 1 % and 5 % reduction (§8.1.10.2.2, TMC428 §8.11)
//! and moves from 1 step to 2^22; the property tests draw the rest, targets changed on the fly
//! and x_actual written while moving among it. Both run the motor frame by frame
//! (common/frames.rs), which `frames_equal_the_chip` holds to the chip cycle by cycle.

mod common;
use common::frames::{Frames, Run};

use proptest::prelude::*;
use tmc429_model::motor_regs::{Motor, RAMP_MODE};
use tmc429_model::pmulpdiv;
use tmc429_model::regmap::motor_a7;
use tmc429_model::{Chip, Inputs, Tmc429};

/// The worst move time over the ideal trapezoid that docs/model-contract.md (C50) reports for
/// the grid below, with p reduced 1 % and 5 % ([`Worst`]).
const WORST_RATIO: [f64; 2] = [1.033, 1.046];

/// The a_max window of TMC429 §8.1.7.1.1 (with erratum E10): lower limit 2^(rd−pd−1), halved
/// for v_max ≤ 2048/√2, at least 1; upper limit 2^(rd−pd+12) − 1, at most 2047.
fn a_max_window(pd: u8, rd: u8, v_max: u16) -> Option<(u16, u16)> {
    let e = rd as i32 - pd as i32;
    let mut lo = if e - 1 > 0 { 1u32 << (e - 1) } else { 1 };
    if v_max <= 1448 {
        lo = (lo / 2).max(1);
    }
    let hi = if e + 12 < 0 { 0 } else { ((1u64 << (e + 12)) - 1).min(2047) as u32 };
    (lo <= hi && lo <= 2047).then_some((lo as u16, hi as u16))
}

/// One move from rest: the motor at `start`, the target `dist` steps away.
#[derive(Clone, Copy, Debug)]
struct Move {
    pd: u8,
    rd: u8,
    a_max: u16,
    v_min: u16,
    v_max: u16,
    reduction: f32,
    start: i32,
    dist: i32,
}

impl Move {
    /// The motor with its registers set as a µC would: p from `pmulpdiv`; where the datasheet
    /// method finds no pair (p reduced below the smallest p, 1/512: a_max at the lower limit
    /// halved for v_max ≤ 1448, TMC429 §8.1.7.1.1) the smallest p, p_mul 128 and pdiv 13.
    /// Also says whether that fallback was taken.
    fn motor(&self) -> (Motor, bool) {
        let p = pmulpdiv::calc(self.a_max as i32, self.rd as i32, self.pd as i32, self.reduction);
        let (p_mul, p_div) = if p.valid() { (p.p_mul, p.p_div) } else { (128, 13) };
        let mut m = Motor::reset();
        m.pulse_div = self.pd;
        m.ramp_div = self.rd;
        m.a_max = self.a_max;
        m.v_min = self.v_min;
        m.v_max = self.v_max;
        m.pmul = (p_mul - 128) as u8;
        m.pdiv = p_div as u8;
        m.rm = RAMP_MODE;
        m.x_actual = self.start as u32 & 0xFF_FFFF;
        m.x_target = self.start.wrapping_add(self.dist) as u32 & 0xFF_FFFF;
        (m, !p.valid())
    }

    /// The ideal trapezoid's time in frames: accelerate and decelerate at a_max, cruise at
    /// v_max (TMC429 §8.1.13: velocity v is v/(2048·2^pulse_div) steps per frame, a_max adds
    /// a_max/256 to v per 2^ramp_div frames).
    fn ideal_frames(&self) -> f64 {
        let vs = self.v_max as f64 / (2048.0 * (1u64 << self.pd) as f64);
        let acc = self.a_max as f64 / 256.0 / (1u64 << self.rd) as f64 / (2048.0 * (1u64 << self.pd) as f64);
        let d = self.dist.unsigned_abs() as f64;
        if d >= vs * vs / acc {
            d / vs + vs / acc
        } else {
            2.0 * (d / acc).sqrt()
        }
    }

    /// Braking distance from v_max in steps (TMC429 §8.1.10.2: S = v²/(2048·p)).
    fn braking_distance(&self) -> f64 {
        let p = self.a_max as f64 / (128.0 * 2f64.powi(self.rd as i32 - self.pd as i32));
        (self.v_max as f64).powi(2) / (2048.0 * p)
    }

    /// Frames enough for the move: 8 ideal trapezoids plus 4 steps at v_min.
    fn limit(&self) -> u64 {
        let crawl = (4u64 * 2048) << self.pd;
        (self.ideal_frames() * 8.0) as u64 + crawl * 2048 / (self.v_min.max(1) as u64) + (64 << self.rd.max(self.pd))
    }
}

/// Checks one finished run against the promise; the error names what broke.
fn check(mv: &Move, m: &Motor, r: &Run) -> Result<(), String> {
    if r.overshoot > 0 {
        return Err(format!("{} steps past the target", r.overshoot));
    }
    if r.backward {
        return Err("a step backwards".into());
    }
    if !r.stopped {
        return Err(format!("not at rest after {} frames", r.frames));
    }
    if m.v != 0 {
        return Err(format!("rests with V = {}", m.v));
    }
    let left = m.dx() * mv.dist.signum();
    if mv.v_min >= 1 && left != 0 || left < 0 {
        return Err(format!("rests {left} steps before the target"));
    }
    if r.v_peak > mv.v_max as u32 {
        return Err(format!("v {} above v_max", r.v_peak));
    }
    Ok(())
}

/// Runs a move to its end: the motor after it and what the run observed.
fn run_move(mv: &Move) -> (Motor, Run) {
    let mut f = Frames::new(mv.motor().0);
    let r = f.run(mv.dist.signum(), mv.limit());
    (f.m, r)
}

/// The worst move times of the grid over the ideal trapezoid, for moves of at least twice
/// the braking distance from v_max, per p reduction (1 %, 5 %): over all of them, and over
/// those in which one step at v_min takes at most 1 % of the trapezoid (where the
/// quantization of the last steps leaves room to measure the law); with the number of the
/// latter more than 1 % over the trapezoid.
#[derive(Clone, Copy, Debug, Default)]
struct Worst {
    all: [(f64, Option<Move>); 2],
    measured: [(f64, Option<Move>); 2],
    measured_n: [u64; 2],
    over_1_percent: [u64; 2],
    /// The worst measured ratio by ramp_div − pulse_div (index + 13), p reduced 1 %.
    by_e: [f64; 27],
}

impl Worst {
    fn add(&mut self, mv: &Move, ratio: f64) {
        if mv.v_min == 0 || (mv.dist.unsigned_abs() as f64) < 2.0 * mv.braking_distance() {
            return;
        }
        let k = (mv.reduction > 0.02) as usize;
        if ratio > self.all[k].0 {
            self.all[k] = (ratio, Some(*mv));
        }
        let step_at_v_min = 2048.0 * (1u64 << mv.pd) as f64 / mv.v_min as f64;
        if step_at_v_min <= 0.01 * mv.ideal_frames() {
            self.measured_n[k] += 1;
            self.over_1_percent[k] += (ratio > 1.01) as u64;
            if k == 0 {
                let e = (mv.rd as i32 - mv.pd as i32 + 13) as usize;
                self.by_e[e] = self.by_e[e].max(ratio);
            }
            if ratio > self.measured[k].0 {
                self.measured[k] = (ratio, Some(*mv));
            }
        }
    }

    fn merge(&mut self, o: &Worst) {
        for k in 0..2 {
            for (a, b) in [(&mut self.all[k], o.all[k]), (&mut self.measured[k], o.measured[k])] {
                if b.0 > a.0 {
                    *a = b;
                }
            }
            self.measured_n[k] += o.measured_n[k];
            self.over_1_percent[k] += o.over_1_percent[k];
        }
        for (a, b) in self.by_e.iter_mut().zip(o.by_e) {
            *a = a.max(b);
        }
    }
}

/// The grid's moves for one pulse_div: every ramp_div, v_max, a_max at the ends and the
/// geometric middle of its window, v_min, p reduction and move length.
fn grid_moves(pd: u8) -> Vec<Move> {
    let mut out = Vec::new();
    for rd in 0..=13u8 {
        for v_max in [2047u16, 1448, 300, 17] {
            let Some((lo, hi)) = a_max_window(pd, rd, v_max) else { continue };
            let mid = ((lo as f64 * hi as f64).sqrt() as u16).clamp(lo, hi);
            for a_max in [lo, mid, hi] {
                for v_min in [0u16, 1, (v_max / 8).max(1), v_max] {
                    for reduction in [0.01f32, 0.05] {
                        let base = Move { pd, rd, a_max, v_min, v_max, reduction, start: 0, dist: 1 };
                        let brake = base.braking_distance() as i32;
                        let dists = [1, 2, 3, 7, 40, brake / 2 + 1, brake + 3, 2 * brake + 11, (1 << 22) - 5];
                        for (k, &d) in dists.iter().enumerate() {
                            let d = d.clamp(1, 1 << 22);
                            let dist = if k % 2 == 0 { d } else { -d };
                            out.push(Move { dist, start: (k as i32 - 4) * 1_000_003, ..base });
                        }
                    }
                }
            }
        }
    }
    out
}

#[test]
fn grid_every_divider_pair() {
    let results: Vec<(usize, u64, Worst)> = std::thread::scope(|s| {
        let jobs: Vec<_> = (0..=13u8)
            .map(|pd| {
                s.spawn(move || {
                    let moves = grid_moves(pd);
                    let mut smallest_p = 0u64;
                    let mut worst = Worst::default();
                    for mv in &moves {
                        let (m, r) = run_move(mv);
                        smallest_p += mv.motor().1 as u64;
                        if let Err(e) = check(mv, &m, &r) {
                            panic!("{mv:?}: {e}");
                        }
                        worst.add(mv, r.frames as f64 / mv.ideal_frames());
                    }
                    (moves.len(), smallest_p, worst)
                })
            })
            .collect();
        jobs.into_iter().map(|j| j.join().unwrap()).collect()
    });
    let mut worst = Worst::default();
    let (mut moves, mut smallest_p) = (0, 0);
    for (n, s, w) in &results {
        moves += n;
        smallest_p += s;
        worst.merge(w);
    }
    eprintln!("grid: {moves} moves, {smallest_p} with the smallest p (1/512)");
    let by_e: Vec<String> =
        worst.by_e.iter().enumerate().filter(|(_, r)| **r > 0.0).map(|(e, r)| format!("{}: {r:.4}", e as i32 - 13)).collect();
    eprintln!("p reduced 1 %, worst measured ratio by ramp_div − pulse_div: {}", by_e.join(", "));
    for (k, red) in ["1 %", "5 %"].iter().enumerate() {
        eprintln!(
            "p reduced {red}: worst time ratio {:.4} at {:?}; where a step at v_min is at most 1 % of the move ({} moves): {:.4} at {:?}, {} more than 1 % over",
            worst.all[k].0, worst.all[k].1, worst.measured_n[k], worst.measured[k].0, worst.measured[k].1, worst.over_1_percent[k]
        );
        assert!(
            worst.measured[k].0 <= WORST_RATIO[k],
            "p reduced {red}: worst time ratio {} above {}",
            worst.measured[k].0,
            WORST_RATIO[k]
        );
    }
}

/// A move drawn from the whole valid space: pulse_div and ramp_div 0..13, a_max inside its
/// window, v_min 0..v_max, p reduced 1 % to 5 %, 1 to 2^22 steps either way from anywhere.
fn any_move() -> impl Strategy<Value = Move> {
    (0u8..=13, 0u8..=13, 1u16..=2047)
        .prop_filter_map("a_max window", |(pd, rd, v_max)| a_max_window(pd, rd, v_max).map(|w| (pd, rd, v_max, w)))
        .prop_flat_map(|(pd, rd, v_max, (lo, hi))| {
            (Just(pd), Just(rd), lo..=hi, 0..=v_max, Just(v_max), 0.01f32..=0.05, any::<i32>(), 1i32..=1 << 22, any::<bool>(), 0u32..4)
        })
        .prop_map(|(pd, rd, a_max, v_min, v_max, reduction, start, d, neg, short)| {
            // a quarter of the moves short, where the last steps decide
            let d = if short == 0 { d % 64 + 1 } else { d };
            Move { pd, rd, a_max, v_min, v_max, reduction, start: start >> 8, dist: if neg { -d } else { d } }
        })
}

/// Where a change made while moving leaves the motor: V toward the target and not above the
/// braking law's velocity there, so that the move can go on without passing it.
fn under_the_curve(m: &Motor) -> bool {
    let d = m.dx();
    d != 0 && (m.v == 0 || m.v.signum() == d.signum()) && m.v.unsigned_abs() <= m.target_velocity().unsigned_abs() * 256
}

/// Checks the end of a move whose target or position changed on the way: it rests exactly on
/// the target with V = 0 (v_min ≥ 1) after at most one change of direction, and without a
/// step past the target or backwards when the change left it under the braking curve.
fn check_changed(m: &Motor, r: &Run, under: bool, dir: i32) -> Result<(), String> {
    if !r.stopped || m.v != 0 {
        return Err(format!("not at rest (V {})", m.v));
    }
    if m.v_min >= 1 && m.dx() != 0 {
        return Err(format!("rests {} steps from the target", m.dx()));
    }
    if r.reversals > 1 {
        return Err(format!("{} changes of direction", r.reversals));
    }
    if under && (r.overshoot > 0 || r.backward) {
        return Err(format!("passed the target by {} (backward {}) from under the curve, dir {dir}", r.overshoot, r.backward));
    }
    Ok(())
}

/// Runs `mv` for `first` of its frames, applies `change` to the motor, and runs to the end.
fn run_changed(mv: &Move, first: u64, change: impl FnOnce(&mut Motor)) -> Result<(), String> {
    let mut f = Frames::new(mv.motor().0);
    let r = f.run(mv.dist.signum(), first.min(mv.limit()));
    if r.overshoot > 0 || r.backward {
        return Err(format!("passed the target by {} before the change", r.overshoot));
    }
    change(&mut f.m);
    let under = under_the_curve(&f.m);
    let dir = if f.m.dx() != 0 { f.m.dx().signum() } else { mv.dist.signum() };
    f.last_step = 0;
    let r = f.run(dir, 8 * (mv.limit() + Move { dist: f.m.dx().abs().max(1), ..*mv }.limit()));
    check_changed(&f.m, &r, under, dir)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 2000, ..ProptestConfig::default() })]

    #[test]
    fn moves_from_rest_keep_the_promise(mv in any_move()) {
        let (m, r) = run_move(&mv);
        if let Err(e) = check(&mv, &m, &r) {
            prop_assert!(false, "{:?}: {}", mv, e);
        }
    }

    #[test]
    fn targets_changed_on_the_fly(mv in any_move(), at in 0.0f64..1.0, new in any::<i32>(), farther in any::<bool>()) {
        let first = (mv.ideal_frames() * at) as u64;
        let res = run_changed(&mv, first, |m| {
            let to = if farther { m.x_target as i32 + mv.dist.signum() * (new & 0xFFFF) } else { new >> 9 };
            m.x_target = to as u32 & 0xFF_FFFF;
        });
        prop_assert!(res.is_ok(), "{:?} at {:.3}: {}", mv, at, res.unwrap_err());
    }

    #[test]
    fn x_actual_written_while_moving(mv in any_move(), at in 0.0f64..1.0, new in any::<i32>()) {
        let first = (mv.ideal_frames() * at) as u64;
        let res = run_changed(&mv, first, |m| m.x_actual = (new >> 9) as u32 & 0xFF_FFFF);
        prop_assert!(res.is_ok(), "{:?} at {:.3}: {}", mv, at, res.unwrap_err());
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

    /// The frame-level run equals the chip's motion cycle by cycle: x_actual and V after the
    /// first edge of every frame it looks at (motor 2's pulse tick is the frame's last phase,
    /// its step is made in the next frame's first edge, C41, C53), and the frame it stops in
    /// (any motor: the snapshots are at phases 0, 7, 14, C41).
    #[test]
    fn frames_equal_the_chip(motor in 0u8..3, pd in 0u8..=3, drd in -3i8..=5, v_max in 64u16..=2047, v_min in 0u16..=9, red in 0.01f32..=0.05, start in any::<i32>(), d in 1i32..=3000, neg in any::<bool>(), a in 0.0f64..=1.0) {
        let rd = (pd as i8 + drd).max(0) as u8;
        let (lo, hi) = a_max_window(pd, rd, v_max).unwrap();
        let a_max = lo + ((hi - lo) as f64 * a) as u16;
        let mv = Move { pd, rd, a_max, v_min: v_min.min(v_max), v_max, reduction: red, start: start >> 8, dist: if neg { -d } else { d } };
        let limit = mv.limit().min(200_000);
        let (m0, _) = mv.motor();
        // the chip, its registers written as the motor's before the first edge
        let mut chip = Tmc429::new(Chip::Tmc429);
        let reg = |idx: u8, v: u32| (motor_a7(motor, idx), v);
        for (a7, v) in [
            reg(12, (pd as u32) << 12 | (rd as u32) << 8),
            reg(2, m0.v_min as u32),
            reg(3, m0.v_max as u32),
            reg(6, m0.a_max as u32),
            reg(9, (128 + m0.pmul as u32) << 8 | m0.pdiv as u32),
            reg(1, m0.x_actual),
            reg(0, m0.x_target),
        ] {
            chip.write_register(a7, v);
        }
        let mut f = Frames::new(m0);
        f.trace = Some(Vec::new());
        let r = f.run(mv.dist.signum(), limit);
        let trace = f.trace.take().unwrap();
        let idle = Inputs::default();
        let mut cycle = 0u64;
        for &(frame, x, v) in &trace {
            while cycle < frame * 32 + 1 {
                chip.tick(&idle);
                cycle += 1;
            }
            let cm = chip.motor(motor as usize);
            prop_assert_eq!((cm.x_actual, cm.v), (x, v), "frame {} of {:?}", frame, mv);
        }
        if r.stopped {
            // the chip rests where the run stopped
            while cycle < (f.frame + 64) * 32 {
                chip.tick(&idle);
                cycle += 1;
            }
            let cm = chip.motor(motor as usize);
            prop_assert_eq!((cm.x_actual, cm.v), (f.m.x_actual, 0), "end of {:?}", mv);
        }
    }
}

/// With ramp_div < pulse_div the law has no correction (h = 0, C50); this walks every a_max of
/// the window for every pulse_div − ramp_div, p reduced 0 % and 1 %, and every move of 1 to 120
/// steps (where the last steps decide). A long run (several minutes):
/// `cargo test --release -p tmc429-model --test braking_law -- --ignored`.
#[test]
#[ignore]
fn below_pulse_div_every_a_max_and_short_move() {
    std::thread::scope(|s| {
        for diff in 1..=11u8 {
            s.spawn(move || {
                let (pd, rd) = (diff + 1, 1);
                let (lo, hi) = a_max_window(pd, rd, 2047).unwrap();
                for a_max in lo..=hi {
                    for reduction in [0.0f32, 0.01] {
                        for (v_min, v_max) in [(1u16, 2047u16), (1, 300), (3, 2047)] {
                            for dist in 1..=120 {
                                let mv = Move { pd, rd, a_max, v_min, v_max, reduction, start: 0, dist };
                                let (m, r) = run_move(&mv);
                                if let Err(e) = check(&mv, &m, &r) {
                                    panic!("{mv:?}: {e}");
                                }
                            }
                        }
                    }
                }
            });
        }
    });
}
