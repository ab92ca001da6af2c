//! `tmc429 capture compare`: a capture of a chip's pins against the golden model.
//!
//! The captured µC frames and switch levels drive the model ([`super::replay`]); what the chip
//! answered — every reply bit, the status bytes, nINT outside frames, the driver-chain datagrams
//! and the Step/Dir steps — is compared with what the model answers. The chip's CLK is not in
//! the capture: its phase (how long the chip ran before the capture) is found from the first
//! driver-side events, and its frequency, given by `--fclk`, is refined from all of them
//! ([`align`]).

use tmc429_model::events::Event;
use tmc429_model::Chip;

use super::frames::{self, CapFrame, Frames};
use super::pins::{Pin, PinMap};
use super::replay::{self, Run, Setup, Timebase};
use super::report::{self, Outcome};
use super::{Capture, CaptureError};

/// Options of a comparison.
#[derive(Clone, Debug)]
pub struct Options {
    pub chip: Chip,
    /// The chip's CLK frequency as given (Hz).
    pub fclk: u64,
    /// `--pin` assignments.
    pub assign: Vec<(Pin, String)>,
    /// Timing tolerance in ns (default: two samples and two CLK periods).
    pub tolerance_ns: Option<f64>,
}

/// Period of the prescaler (2^20 CLK, [`tmc429_model::PRESCALER_BITS`]): the model's power-on
/// may move by whole periods without changing anything the pins show.
fn prescaler_period(fclk: f64) -> f64 {
    (1u64 << tmc429_model::PRESCALER_BITS) as f64 / fclk
}

/// Moves the power-on by whole prescaler periods so that it falls before the capture's first
/// input activity, by at most one period.
fn normalize(tb: &mut Timebase, first_activity: f64) {
    let p = prescaler_period(tb.fclk);
    let latest = first_activity - 64.0 / tb.fclk;
    while tb.t0 > latest {
        tb.t0 -= p;
    }
    while tb.t0 + p <= latest {
        tb.t0 += p;
    }
}

/// Timing events of the driver side: chain datagrams, and the steps of each motor.
fn streams(ev: &[Event]) -> [Vec<u64>; 4] {
    let mut s: [Vec<u64>; 4] = Default::default();
    for e in ev {
        match *e {
            Event::Chain { cycle, .. } => s[0].push(cycle),
            Event::Step { cycle, motor, .. } => s[1 + motor as usize].push(cycle),
            Event::Int { .. } => {}
        }
    }
    s
}

/// Per stream, (model cycle, chip − model) of its events paired in order, at most `n`.
fn offsets(run: &Run, n: usize) -> [Vec<(u64, f64)>; 4] {
    let (m, c) = (streams(&run.model), streams(&run.chip));
    std::array::from_fn(|k| m[k].iter().zip(&c[k]).take(n).map(|(a, b)| (*a, *b as f64 - *a as f64)).collect())
}

/// The offset most of the pairs agree on within `tol` (the earliest such on a tie): robust
/// against pairs that no longer correspond once one event is extra or missing.
fn mode(v: &[(u64, f64)], tol: f64) -> f64 {
    let support = |d: f64| v.iter().filter(|x| (x.1 - d).abs() <= tol).count();
    let mut best = (0, 0.0);
    for x in v {
        let s = support(x.1);
        if s > best.0 {
            best = (s, x.1);
        }
    }
    best.1
}

/// Least-squares slope of offset over model cycle.
fn slope(v: &[(u64, f64)]) -> Option<f64> {
    if v.len() < 4 {
        return None;
    }
    let n = v.len() as f64;
    let mx = v.iter().map(|x| x.0 as f64).sum::<f64>() / n;
    let my = v.iter().map(|x| x.1).sum::<f64>() / n;
    let sxx: f64 = v.iter().map(|x| (x.0 as f64 - mx).powi(2)).sum();
    let sxy: f64 = v.iter().map(|x| (x.0 as f64 - mx) * (x.1 - my)).sum();
    (sxx > 0.0).then(|| sxy / sxx)
}

/// The alignment found: the timebase, the runs it took, and the final run.
pub struct Aligned {
    pub tb: Timebase,
    pub iterations: usize,
    pub run: Run,
}

/// (model cycle, chip − model) of the driver-side events that pair within `window` CLK with
/// the same content: what a drift of the chip's CLK is fitted on.
fn matched_offsets(run: &Run, window: f64) -> Vec<(u64, f64)> {
    let key = |e: &Event| match *e {
        Event::Chain { nbits, bits, .. } => Some((0u8, nbits as u64, bits)),
        Event::Step { motor, negative, .. } => Some((1 + motor, negative as u64, 0)),
        Event::Int { .. } => None,
    };
    let mut out = Vec::new();
    for k in 0..4u8 {
        let m: Vec<&Event> = run.model.iter().filter(|e| key(e).is_some_and(|x| x.0 == k)).collect();
        let c: Vec<&Event> = run.chip.iter().filter(|e| key(e).is_some_and(|x| x.0 == k)).collect();
        let (mut i, mut j) = (0, 0);
        while i < m.len() && j < c.len() {
            let d = c[j].cycle() as f64 - m[i].cycle() as f64;
            if d.abs() <= window {
                if key(m[i]) == key(c[j]) {
                    out.push((m[i].cycle(), d));
                }
                i += 1;
                j += 1;
            } else if d > 0.0 {
                i += 1;
            } else {
                j += 1;
            }
        }
    }
    out.sort_by_key(|x| x.0);
    out
}

/// The number of driver-side events on which the model and the chip agree within `tol` CLK.
fn agreement(run: &Run, tol: f64) -> usize {
    matched_offsets(run, tol).len()
}

/// Capture time up to which the phase is searched: a little after the chip's 40th driver-side
/// event (the whole capture when it has fewer).
fn search_window(run: &Run, tb: &Timebase) -> Option<f64> {
    let ev: Vec<u64> = run.chip.iter().filter(|e| !matches!(e, Event::Int { .. })).map(|e| e.cycle()).collect();
    ev.get(40).map(|&c| tb.time(c as f64) + 2e-3)
}

/// Moves the power-on until the model's driver-side events agree with the chip's. Each round
/// takes the offset of the stream furthest off whose first event comes first, and tries it
/// alone and combined with ±32·2^j CLK (one prescaler bit above the 32-cycle frame, up to the
/// largest divider in use: a motion starts on the ramp tick after the µC's write, so a phase off
/// by whole frames shows only in some of the events); it keeps the move that makes the most
/// events agree within the search window.
fn lock_phase(s: &Setup, tb: &mut Timebase, first_activity: f64, tol: f64, replays: &mut usize) -> Run {
    *replays += 1;
    let full = replay::run(s, tb, None);
    let until = search_window(&full, tb);
    let mut run = if until.is_some() {
        *replays += 1;
        replay::run(s, tb, until)
    } else {
        full
    };
    let mut score = agreement(&run, tol);
    let driver = |r: &Run| r.model.iter().chain(&r.chip).any(|e| !matches!(e, Event::Int { .. }));
    if !driver(&run) {
        return run;
    }
    for _ in 0..8 {
        let per: Vec<(f64, u64)> = offsets(&run, 16).iter().filter(|v| !v.is_empty()).map(|v| (mode(v, tol), v[0].0)).collect();
        let d = per.iter().filter(|x| x.0.abs() > tol).min_by_key(|x| x.1).map_or(0.0, |x| x.0);
        let mut cands = vec![d];
        for j in 0..=run.max_div.min(14) {
            let g = (32u64 << j) as f64;
            cands.extend([d + g, d - g]);
        }
        let mut best: Option<(usize, Timebase, Run)> = None;
        for c in cands.into_iter().filter(|c| *c != 0.0) {
            let mut t2 = *tb;
            t2.t0 += c / t2.fclk;
            normalize(&mut t2, first_activity);
            *replays += 1;
            let r2 = replay::run(s, &t2, until);
            let a2 = agreement(&r2, tol);
            if best.as_ref().is_none_or(|b| a2 > b.0) {
                best = Some((a2, t2, r2));
            }
        }
        match best {
            Some((a2, t2, r2)) if a2 > score => (score, *tb, run) = (a2, t2, r2),
            _ => break,
        }
    }
    if until.is_none() {
        return run;
    }
    *replays += 1;
    replay::run(s, tb, None)
}

/// Finds the chip's timebase: the phase from the first driver-side events ([`lock_phase`]), then
/// the frequency from the drift of all events over the capture, within ±0.2 % of `--fclk`.
pub fn align(s: &Setup, fclk: f64, first_activity: f64, tol: f64) -> Aligned {
    let mut tb = Timebase { fclk, t0: 0.0 };
    normalize(&mut tb, first_activity);
    let mut replays = 0;
    let mut run = lock_phase(s, &mut tb, first_activity, tol, &mut replays);
    for _ in 0..4 {
        let fit = matched_offsets(&run, 8.0 * tol);
        let span = (run.last - run.first) as f64;
        match slope(&fit) {
            Some(k) if k.abs() < 2e-3 && k.abs() * span > tol / 2.0 => {
                // keep the first pair where it is, change the rate
                let (pivot, o) = fit[0];
                let t_pivot = tb.time(pivot as f64 + o);
                tb.fclk /= 1.0 + k;
                tb.t0 = t_pivot - (pivot as f64 + o) / tb.fclk;
                normalize(&mut tb, first_activity);
                run = lock_phase(s, &mut tb, first_activity, tol, &mut replays);
            }
            _ => break,
        }
    }
    Aligned { tb, iterations: replays, run }
}

/// Checks that the capture resolves the µC's bus and agrees with `--fclk` (TMC428 Table 6-1:
/// SCK_C high and low at least 3 CLK).
fn check_bus(cap: &Capture, fr: &Frames, fclk: f64, file: &str) -> Result<(), CaptureError> {
    let Some(h) = fr.min_half else { return Ok(()) };
    let rate = super::fmt_hz(cap.samplerate as f64);
    if h < 2 {
        return Err(CaptureError(format!(
            "{file}: SCK_C stays high or low for a single sample ({rate}): the sample rate is too low for this bus; sample at least 4 times per SCK_C period"
        )));
    }
    let clk = (h + 1) as f64 * fclk / cap.samplerate as f64;
    if clk < tmc429_model::host::MIN_SCK_HALF as f64 {
        return Err(CaptureError(format!(
            "{file}: SCK_C high or low for {h} samples = {clk:.2} CLK at --fclk {fclk_s}, below the 3 CLK of TMC428 Table 6-1: is the sample rate ({rate}) or --fclk ({fclk_s}) wrong?",
            fclk_s = super::fmt_hz(fclk)
        )));
    }
    Ok(())
}

/// Checks that the chip's datagrams and step pulses are as long as the model's: a capture whose
/// sample rate (or `--fclk`) is wrong stretches them all by one factor.
fn check_rate(run: &Run, cap: &Capture, fclk: f64, file: &str) -> Result<(), CaptureError> {
    let count = |ev: &[Event], chain: bool| {
        ev.iter().filter(|e| matches!(e, Event::Chain { .. }) == chain && !matches!(e, Event::Int { .. })).count() as f64
    };
    for (busy, chain, what) in [(run.chain_busy, true, "driver-chain datagrams"), (run.step_busy, false, "STEP pulses")] {
        let (nm, nc) = (count(&run.model, chain), count(&run.chip, chain));
        if nm < 2.0 || nc < 2.0 || busy[0] == 0 || busy[1] == 0 {
            continue;
        }
        let ratio = (busy[1] as f64 / nc) / (busy[0] as f64 / nm);
        if !(0.95..=1.05).contains(&ratio) {
            return Err(CaptureError(format!(
                "{file}: the chip's {what} last {ratio:.2} times as long as the model's: is the sample rate ({}) or --fclk ({}) wrong?",
                super::fmt_hz(cap.samplerate as f64),
                super::fmt_hz(fclk)
            )));
        }
    }
    Ok(())
}

/// Compares a capture file with the model.
pub fn compare(path: &std::path::Path, opt: &Options) -> Result<Outcome, CaptureError> {
    let file = path.display().to_string();
    let cap = super::read(path)?;
    compare_capture(&cap, &file, opt)
}

/// Compares a capture with the model.
pub fn compare_capture(cap: &Capture, file: &str, opt: &Options) -> Result<Outcome, CaptureError> {
    let map = PinMap::resolve(cap, &opt.assign, file)?;
    let data = if opt.chip != Chip::Tmc428 && map.get(Pin::SdozC).is_some() { Pin::SdozC } else { Pin::NintSdoC };
    if map.get(data).is_none() {
        return Err(CaptureError(format!(
            "{file}: no channel for nINT_SDO_C: the TMC428 answers the µC on it (map a channel with --pin nINT_SDO_C=CHANNEL)"
        )));
    }
    let fr = frames::decode(cap, &map, data, file)?;
    if let Some(u) = fr.unfinished {
        return Err(CaptureError(format!(
            "{file}: the capture ends inside a µC frame (nSCS_C low since {}): the file is truncated, or the capture stopped too early (capture until the bus is idle)",
            super::fmt_ms(cap.seconds(u))
        )));
    }
    let fclk = opt.fclk as f64;
    check_bus(cap, &fr, fclk, file)?;
    if fr.frames.is_empty() {
        return Err(CaptureError(format!("{file}: no µC frame in the capture (nSCS_C never low): nothing to compare")));
    }
    let first_activity = (first_input_change(cap, &map) as f64 - 0.5) / cap.samplerate as f64;
    let setup = Setup { cap, map: &map, chip: opt.chip, data, frames: &fr.frames };
    let tol = match opt.tolerance_ns {
        Some(ns) => (ns * 1e-9 * fclk).ceil(),
        None => replay::window(cap, fclk) as f64,
    };
    let al = align(&setup, fclk, first_activity, tol);
    check_rate(&al.run, cap, fclk, file)?;
    Ok(report::build(&setup, &fr, &al, tol as u64, opt, file))
}

/// The first sample at which an input pin changes (the µC's or a switch's activity).
fn first_input_change(cap: &Capture, map: &PinMap) -> u64 {
    map.pins().filter(|(p, _)| p.is_input()).filter_map(|(_, k)| cap.channels[k].edges.first().copied()).min().unwrap_or(cap.length)
}

/// A 32-bit read frame (RW = 1, TMC428 §6.2).
pub fn is_read(f: &CapFrame) -> bool {
    f.nbits() == 32 && (f.mosi >> 24) & 1 == 1
}
