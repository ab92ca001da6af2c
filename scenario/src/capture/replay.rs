//! Replays a capture into the golden model: the captured input pins (the µC's bus, switches,
//! SDI_S) drive the model edge by edge on a [`Timebase`] (the chip's CLK in capture time), and
//! the pins the chip answered are read back on the same CLK: driver-chain datagrams and
//! Step/Dir steps through the model's pin decoder ([`EventDecoder`]), nINT outside frames, and
//! the reply bits at the µC's sampling points.

use tmc429_model::events::{Event, EventDecoder};
use tmc429_model::{Chip, Inputs, Outputs, Tmc429};

use super::frames::CapFrame;
use super::pins::{Pin, PinMap};
use super::Capture;

/// Cycles nSCS_C must be high before nINT_SDO_C counts as nINT: the pin leaves the last data bit
/// a few cycles after nSCS_C rises (synchronizer, TMC428 §6.2).
pub const NINT_SETTLE: u64 = 8;

/// The chip's CLK in capture time: edge n (n ≥ 1 after power-on) at `t0 + n / fclk` seconds
/// from the capture's first sample.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Timebase {
    pub fclk: f64,
    pub t0: f64,
}

impl Timebase {
    pub fn time(&self, n: f64) -> f64 {
        self.t0 + n / self.fclk
    }
    /// The first edge at or after time `t` (at least edge 1).
    pub fn cycle_at(&self, t: f64) -> u64 {
        ((t - self.t0) * self.fclk - 1e-9).ceil().max(1.0) as u64
    }
}

/// What a capture gives the replay.
pub struct Setup<'a> {
    pub cap: &'a Capture,
    pub map: &'a PinMap,
    pub chip: Chip,
    /// The pin the µC reads (SDOZ_C when captured, else nINT_SDO_C).
    pub data: Pin,
    pub frames: &'a [CapFrame],
}

/// The model's side of one captured frame.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct FrameModel {
    /// The model's data output at the µC's sampling points, bit per rising SCK_C edge.
    pub reply: u64,
    /// Status bytes the model presented within the capture's resolution of nSCS_C falling.
    pub status: Vec<u8>,
    /// Read data of a read's register within the capture's resolution of its 8th SCK_C edge.
    pub data: Vec<u32>,
    /// The CLK edge at which the model saw nSCS_C rise.
    pub end_cycle: u64,
}

/// Events of both sides in CLK edges of the timebase, within the capture.
pub struct Run {
    pub model: Vec<Event>,
    pub chip: Vec<Event>,
    pub frames: Vec<FrameModel>,
    /// Edges of the capture's first and last sample.
    pub first: u64,
    pub last: u64,
    /// Edges with a driver-chain chip select active, model and chip (pulse lengths that give
    /// away a wrong sample rate or --fclk).
    pub chain_busy: [u64; 2],
    /// Edges with STEP1 active in Step/Dir mode, model and chip.
    pub step_busy: [u64; 2],
    /// The largest pulse_div or ramp_div of the motors at the end: the prescaler bits above the
    /// 32-cycle frame that the events depend on.
    pub max_div: u8,
}

/// Adds one edge of the chain's chip select or STEP1 being active to `busy`.
fn count_busy(chip: &Tmc429, o: &Outputs, chain: &mut u64, step: &mut u64) {
    use tmc429_model::regmap::f;
    let g = chip.global();
    if chip.chip() != Chip::Tmc428 && g.ifc(f::EN_SD) || chip.chip() == Chip::Tmc4210 {
        *step += (o.sdo_s != g.ifc(f::INV_STP)) as u64;
    } else {
        *chain += ((o.nscs_s == (g.g(f::POL_NSCS_S) != 0)) || !o.nscs2 || !o.nscs3) as u64;
    }
}

/// A channel read in ascending sample order.
struct Cursor<'a> {
    ch: &'a super::Channel,
    next: usize,
    level: bool,
}

impl<'a> Cursor<'a> {
    fn new(ch: &'a super::Channel) -> Self {
        Cursor { ch, next: 0, level: ch.initial }
    }
    fn at(&mut self, s: u64) -> bool {
        while self.next < self.ch.edges.len() && self.ch.edges[self.next] <= s {
            self.level = !self.level;
            self.next += 1;
        }
        self.level
    }
}

/// nINT as the µC sees it outside frames (active low).
struct NintWatch {
    high_for: u64,
    level: Option<bool>,
}

impl NintWatch {
    fn observe(&mut self, cs_high: bool, pin: bool, sdo_int: bool, cycle: u64, out: &mut Vec<Event>) {
        self.high_for = if cs_high { self.high_for + 1 } else { 0 };
        if sdo_int || self.high_for >= NINT_SETTLE {
            if self.level.is_some_and(|l| l != pin) {
                out.push(Event::Int { cycle, level: !pin });
            }
            self.level = Some(pin);
        }
    }
}

/// Half-width, in CLK edges, of the windows in which a value counts as seen: two samples and two
/// CLK periods (the capture's resolution and the synchronizer's).
pub fn window(cap: &Capture, fclk: f64) -> u64 {
    (2.0 * fclk / cap.samplerate as f64).ceil() as u64 + 2
}

/// The input pins' changes in CLK edges: a change first seen at sample s happened at
/// (s − ½) samples on average, and the chip samples it at the first edge after that.
fn schedule(cap: &Capture, map: &PinMap, tb: &Timebase) -> (Inputs, Vec<(u64, Pin, bool)>) {
    let mut init = Inputs::default();
    let mut v = Vec::new();
    for (p, k) in map.pins().filter(|(p, _)| p.is_input()) {
        let ch = &cap.channels[k];
        p.set_input(&mut init, ch.initial);
        let mut level = ch.initial;
        for &e in &ch.edges {
            level = !level;
            v.push((tb.cycle_at((e as f64 - 0.5) / cap.samplerate as f64), p, level));
        }
    }
    v.sort_by_key(|x| x.0);
    (init, v)
}

/// The model's frame windows: (from, to, frame, is_read_data).
fn windows(s: &Setup, tb: &Timebase, w: u64) -> Vec<(u64, u64, usize, bool)> {
    let fs = s.cap.samplerate as f64;
    let mut v = Vec::new();
    for (i, f) in s.frames.iter().enumerate() {
        let nf = tb.cycle_at((f.start as f64 - 0.5) / fs);
        v.push((nf.saturating_sub(w), nf + w + 4, i, false));
        if f.nbits() >= 8 && (f.mosi >> (f.nbits() - 8)) & 1 == 1 {
            let n8 = tb.cycle_at((f.rises[7] as f64 - 0.5) / fs);
            v.push((n8.saturating_sub(w), n8 + w + 4, i, true));
        }
    }
    v.sort_by_key(|x| x.0);
    v
}

/// One side's pin decoding: driver-side events, nINT outside frames, pulse lengths.
struct Side {
    dec: EventDecoder,
    nint: NintWatch,
    events: Vec<Event>,
    chain_busy: u64,
    step_busy: u64,
}

impl Side {
    fn new() -> Side {
        Side { dec: EventDecoder::new(), nint: NintWatch { high_for: 0, level: None }, events: Vec::new(), chain_busy: 0, step_busy: 0 }
    }
    /// Edge `n` with the outputs `o`; `nint` is the nINT_SDO_C level when this side has it.
    fn observe(&mut self, chip: &Tmc429, o: &Outputs, nscs_c: bool, nint: Option<bool>, n: u64) {
        let ev = &mut self.events;
        self.dec.observe(chip, o, n, &mut |e| push(ev, e));
        count_busy(chip, o, &mut self.chain_busy, &mut self.step_busy);
        if let Some(l) = nint {
            let sdo_int = chip.global().ifc(tmc429_model::regmap::f::SDO_INT);
            self.nint.observe(nscs_c, l, sdo_int, n, &mut self.events);
        }
    }
}

/// The model's side of the captured frames, collected edge by edge.
struct FrameProbe {
    frames: Vec<FrameModel>,
    /// The model's reply bits: its data output one edge after it takes the rising SCK_C edge,
    /// while its synchronizer holds it (the output changes only after the next falling edge),
    /// so that the capture's resolution of the µC's edges cannot move the sampling point onto a
    /// change of the output: (edge, frame).
    samples: Vec<(u64, usize)>,
    wins: Vec<(u64, u64, usize, bool)>,
    a7s: Vec<u8>,
    next_sample: usize,
    next_win: usize,
    active: Vec<(u64, usize, bool)>,
}

impl FrameProbe {
    fn new(s: &Setup, tb: &Timebase) -> FrameProbe {
        let fs = s.cap.samplerate as f64;
        let mut frames: Vec<FrameModel> = vec![FrameModel::default(); s.frames.len()];
        for (m, f) in frames.iter_mut().zip(s.frames) {
            m.end_cycle = tb.cycle_at((f.end as f64 - 0.5) / fs);
        }
        let samples = s
            .frames
            .iter()
            .enumerate()
            .flat_map(|(i, f)| f.rises.iter().map(move |&r| (tb.cycle_at((r as f64 - 0.5) / fs) + 1, i)))
            .collect();
        let a7s = s.frames.iter().map(|f| if f.nbits() >= 8 { (f.mosi >> (f.nbits() - 7)) as u8 & 0x7F } else { 0 }).collect();
        let wins = windows(s, tb, window(s.cap, tb.fclk));
        FrameProbe { frames, samples, wins, a7s, next_sample: 0, next_win: 0, active: Vec::new() }
    }

    /// After edge `n`: the values seen within the frames' windows, the reply bits sampled.
    fn after_edge(&mut self, chip: &Tmc429, out: &Outputs, data: Pin, n: u64) {
        while self.next_win < self.wins.len() && self.wins[self.next_win].0 <= n {
            let w = self.wins[self.next_win];
            self.active.push((w.1, w.2, w.3));
            self.next_win += 1;
        }
        let (frames, a7s) = (&mut self.frames, &self.a7s);
        self.active.retain(|&(to, i, is_data)| {
            if is_data {
                let v = chip.read_register(a7s[i]) & 0xFF_FFFF;
                if !frames[i].data.contains(&v) {
                    frames[i].data.push(v);
                }
            } else if !frames[i].status.contains(&chip.status()) {
                frames[i].status.push(chip.status());
            }
            to > n
        });
        while self.next_sample < self.samples.len() && self.samples[self.next_sample].0 <= n {
            let i = self.samples[self.next_sample].1;
            self.frames[i].reply = (self.frames[i].reply << 1) | data_level(data, out) as u64;
            self.next_sample += 1;
        }
    }
}

/// Replays the capture on `tb`, up to capture time `until` (s; the whole capture with `None`).
pub fn run(s: &Setup, tb: &Timebase, until: Option<f64>) -> Run {
    let cap = s.cap;
    let fs = cap.samplerate as f64;
    let (mut inp, sched) = schedule(cap, s.map, tb);
    let first = tb.cycle_at(0.0);
    let end = (cap.length as f64 - 1.0) / fs;
    let last = tb.cycle_at(until.map_or(end, |u| u.min(end)));
    let mut chip = Tmc429::new(s.chip);
    let (mut model, mut captured) = (Side::new(), Side::new());
    let mut outs: Vec<(Pin, Cursor)> =
        s.map.pins().filter(|(p, _)| !p.is_input() || *p == Pin::SdiS).map(|(p, k)| (p, Cursor::new(&cap.channels[k]))).collect();
    let mut probe = FrameProbe::new(s, tb);
    let mut si = 0;
    for n in 1..=last {
        while si < sched.len() && sched[si].0 <= n {
            sched[si].1.set_input(&mut inp, sched[si].2);
            si += 1;
        }
        let out = chip.tick(&inp);
        probe.after_edge(&chip, &out, s.data, n);
        if n < first {
            model.dec.observe(&chip, &out, n, &mut |_| {});
            continue;
        }
        model.observe(&chip, &out, inp.nscs_c, Some(out.nint_sdo_c), n);
        // the capture's outputs at this edge's time
        let smp = ((tb.time(n as f64) * fs).round().max(0.0) as u64).min(cap.length - 1);
        let mut co = out;
        let mut nint_pin = None;
        for (p, c) in outs.iter_mut() {
            let l = c.at(smp);
            set_output(*p, &mut co, l);
            if *p == Pin::NintSdoC {
                nint_pin = Some(l);
            }
        }
        captured.observe(&chip, &co, inp.nscs_c, nint_pin, n);
    }
    let max_div = (0..chip.motor_count()).map(|m| chip.motor(m).pulse_div.max(chip.motor(m).ramp_div)).max().unwrap_or(0);
    Run {
        model: model.events,
        chip: captured.events,
        frames: probe.frames,
        first,
        last,
        chain_busy: [model.chain_busy, captured.chain_busy],
        step_busy: [model.step_busy, captured.step_busy],
        max_div,
    }
}

fn push(v: &mut Vec<Event>, e: Event) {
    if !matches!(e, Event::Int { .. }) {
        v.push(e);
    }
}

/// The level of the data pin the µC reads.
fn data_level(p: Pin, o: &Outputs) -> bool {
    match p {
        Pin::SdozC => !o.sdoz_c_oe || o.sdoz_c,
        _ => o.nint_sdo_c,
    }
}

/// Puts a captured output level into the outputs the chip-side decoder sees.
fn set_output(p: Pin, o: &mut Outputs, l: bool) {
    match p {
        Pin::NintSdoC => o.nint_sdo_c = l,
        Pin::SdozC => o.sdoz_c = l,
        Pin::NscsS => o.nscs_s = l,
        Pin::SckS => o.sck_s = l,
        Pin::SdoS => o.sdo_s = l,
        Pin::Nscs2 => o.nscs2 = l,
        Pin::Nscs3 => o.nscs3 = l,
        Pin::Poscmp => o.poscmp = l,
        Pin::SdiS if o.sdi_s_oe => o.sdi_s_o = l,
        _ => {}
    }
}
