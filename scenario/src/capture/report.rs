//! The report of `tmc429 capture compare`: per kind of answer what was compared and agreed, and
//! each difference with its time and the decoded transaction.

use std::fmt::Write as _;

use tmc429_model::events::Event;
use tmc429_model::regmap::{self, Addr};
use tmc429_model::script;

use super::compare::{Aligned, Options};
use super::frames::{CapFrame, Frames};
use super::pins::Pin;
use super::replay::{FrameModel, Setup, Timebase};
use super::{fmt_hz, fmt_ms};

/// One difference between the chip and the model.
#[derive(Clone, Debug, PartialEq)]
pub struct Difference {
    /// Capture time, s.
    pub time: f64,
    pub text: String,
}

/// A kind of answer: how many were compared, agreed, and agreed only within the capture's
/// resolution (a value the model held within the timing tolerance of the chip's).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Tally {
    pub name: &'static str,
    /// `None`: nothing to compare, for the reason in `absent`.
    pub compared: Option<usize>,
    pub absent: &'static str,
    pub agreed: usize,
    pub within: usize,
}

/// The whole comparison.
#[derive(Clone, Debug)]
pub struct Outcome {
    pub header: Vec<String>,
    pub tallies: Vec<Tally>,
    pub differences: Vec<Difference>,
    pub notes: Vec<String>,
}

impl Outcome {
    pub fn agrees(&self) -> bool {
        self.differences.is_empty()
    }

    /// The report, with at most `max` differences listed.
    pub fn text(&self, max: usize) -> String {
        let mut s = String::new();
        for h in &self.header {
            let _ = writeln!(s, "{h}");
        }
        for t in &self.tallies {
            let _ = match t.compared {
                None => writeln!(s, "{:<17}{}", format!("{}:", t.name), t.absent),
                Some(n) => {
                    let within = if t.within > 0 { format!(" ({} within the capture's resolution)", t.within) } else { String::new() };
                    writeln!(s, "{:<17}{n} compared, {} agree{within}", format!("{}:", t.name), t.agreed)
                }
            };
        }
        for n in &self.notes {
            let _ = writeln!(s, "note: {n}");
        }
        for (i, d) in self.differences.iter().take(max).enumerate() {
            let _ = writeln!(s, "difference {} at {}: {}", i + 1, fmt_ms(d.time), d.text);
        }
        if self.differences.len() > max {
            let _ = writeln!(s, "… and {} more differences (--max-differences)", self.differences.len() - max);
        }
        let _ = match self.differences.len() {
            0 => writeln!(s, "result: the chip agrees with the model"),
            n => writeln!(s, "result: {n} difference{}", if n == 1 { "" } else { "s" }),
        };
        s
    }
}

/// Builds the report of an aligned replay.
pub fn build(s: &Setup, fr: &Frames, al: &Aligned, tol: u64, opt: &Options, file: &str) -> Outcome {
    let tb = al.tb;
    let header = header(s, al, tol, opt, file);
    let mut diffs = Vec::new();
    let mut tallies = frame_tallies(s, fr, &al.run.frames, &mut diffs);
    let win = (al.run.first, al.run.last);
    let has = |p: Pin| s.map.get(p).is_some();
    let stepdir = al.run.model.iter().chain(&al.run.chip).any(|e| matches!(e, Event::Step { .. }));
    let ints = |v: &[Event]| v.iter().filter(|e| matches!(e, Event::Int { .. })).copied().collect::<Vec<_>>();
    let mut t = Tally { name: "nINT edges", absent: "not captured (nINT_SDO_C)", ..Default::default() };
    if has(Pin::NintSdoC) {
        t.compared = Some(match_events(&ints(&al.run.model), &ints(&al.run.chip), tol, win, &tb, "nINT", &mut t, &mut diffs));
    }
    tallies.push(t);
    let chains = |v: &[Event]| v.iter().filter(|e| matches!(e, Event::Chain { .. })).copied().collect::<Vec<_>>();
    let mut t = Tally { name: "chain datagrams", absent: "not captured (nSCS_S, SCK_S, SDO_S)", ..Default::default() };
    if stepdir && chains(&al.run.model).is_empty() {
        t.absent = "none (Step/Dir mode)";
    } else if has(Pin::NscsS) && has(Pin::SckS) && has(Pin::SdoS) {
        t.compared = Some(match_events(&chains(&al.run.model), &chains(&al.run.chip), tol, win, &tb, "chain datagram", &mut t, &mut diffs));
    }
    tallies.push(t);
    tallies.extend(step_tallies(s, al, tol, opt, stepdir, &mut diffs));
    diffs.sort_by(|a, b| a.time.total_cmp(&b.time));
    let mut notes = Vec::new();
    if !stepdir && al.run.model.iter().chain(&al.run.chip).all(|e| matches!(e, Event::Int { .. })) {
        notes.push("no driver-chain datagram or step in the capture: the chip's CLK phase is unknown, so replies that depend on motion may differ by its timing".into());
    }
    Outcome { header, tallies, differences: diffs, notes }
}

/// The report's header: the capture, the pins it has, the chip's CLK as fitted, the tolerance.
fn header(s: &Setup, al: &Aligned, tol: u64, opt: &Options, file: &str) -> Vec<String> {
    let cap = s.cap;
    let tb = al.tb;
    let ppm = (tb.fclk / opt.fclk as f64 - 1.0) * 1e6;
    let mut header = vec![
        format!(
            "capture {file}: {}, {} samples ({}), {} channels",
            fmt_hz(cap.samplerate as f64),
            cap.length,
            fmt_ms(cap.seconds(cap.length)),
            cap.channels.len()
        ),
        format!(
            "pins: {}",
            s.map
                .pins()
                .map(|(p, k)| if p.name() == cap.channels[k].name {
                    p.name().to_string()
                } else {
                    format!("{}={}", p.name(), cap.channels[k].name)
                })
                .collect::<Vec<_>>()
                .join(" ")
        ),
        format!(
            "chip: {}, --fclk {}; its CLK fits {} ({ppm:+.1} ppm), the prescaler as if powered on at {} (modulo 2^20 CLK; {} replays)",
            opt.chip,
            fmt_hz(opt.fclk as f64),
            fmt_hz(tb.fclk),
            fmt_ms(tb.t0),
            al.iterations
        ),
    ];
    header.push(format!("timing tolerance: ±{tol} CLK ({:.0} ns)", tol as f64 / tb.fclk * 1e9));
    header
}

/// The Step/Dir pulses of each motor, model against chip, where the capture has its STEP and
/// DIR pins.
fn step_tallies(s: &Setup, al: &Aligned, tol: u64, opt: &Options, stepdir: bool, diffs: &mut Vec<Difference>) -> Vec<Tally> {
    let (tb, win) = (al.tb, (al.run.first, al.run.last));
    let has = |p: Pin| s.map.get(p).is_some();
    let mut tallies = Vec::new();
    let step_pins = [(Pin::SdoS, Pin::SckS), (Pin::NscsS, Pin::SdiS), (Pin::Nscs2, Pin::Nscs3)];
    for (m, (sp, dp)) in step_pins.iter().enumerate().take(if opt.chip == tmc429_model::Chip::Tmc4210 { 1 } else { 3 }) {
        let steps =
            |v: &[Event]| v.iter().filter(|e| matches!(e, Event::Step { motor, .. } if *motor as usize == m)).copied().collect::<Vec<_>>();
        let name: &'static str = ["steps motor 0", "steps motor 1", "steps motor 2"][m];
        let mut t = Tally { name, absent: "not captured (STEP and DIR)", ..Default::default() };
        if !stepdir {
            t.absent = "none (no Step/Dir pulses)";
        } else if has(*sp) && has(*dp) {
            t.compared =
                Some(match_events(&steps(&al.run.model), &steps(&al.run.chip), tol, win, &tb, &format!("motor {m} step"), &mut t, diffs));
        }
        tallies.push(t);
    }
    tallies
}

/// The decoded transaction of a frame, with the given reply.
fn describe(chip: tmc429_model::Chip, f: &CapFrame, reply: u64) -> String {
    match f.datagram() {
        Some(d) => script::decode(chip, d, reply as u32),
        None if f.nbits() >= 8 => {
            format!("{}-bit frame, nothing executed | {}", f.nbits(), script::decode_status((reply >> (f.nbits() - 8)) as u8))
        }
        None => format!("{}-bit frame, nothing executed", f.nbits()),
    }
}

/// What bit `b` (0 = last sent) of a 32-bit reply is: a status bit or a field bit.
fn bit_name(chip: tmc429_model::Chip, d: u32, b: u32) -> String {
    if b >= 24 {
        return format!("status {}", script::STATUS_BITS[(b - 24) as usize]);
    }
    let a7 = (d >> 25) as u8;
    match (regmap::lookup(chip, a7), Addr::from_a7(a7)) {
        (Some(_), Addr::Ram(a)) => {
            let cell = 2 * a as u32 + (b >= 8) as u32;
            format!("cell{cell} bit {}", b % 8)
        }
        (Some((r, _)), _) => match r.fields.iter().find(|f| b >= f.lsb as u32 && b < (f.lsb + f.width) as u32) {
            Some(f) => format!("{} bit {}", f.name, b - f.lsb as u32),
            None => format!("unused data bit {b}"),
        },
        (None, _) => format!("data bit {b}"),
    }
}

/// How a frame's reply compares: its status byte and the rest, each `Some(within)` when it
/// agrees (`within`: only within the capture's resolution), and the bits that differ.
struct FrameCheck {
    status: Option<bool>,
    rest: Option<bool>,
    bad: u64,
}

fn check_frame(f: &CapFrame, m: &FrameModel) -> FrameCheck {
    let n = f.nbits();
    // the status byte: the first 8 bits (or fewer)
    let sb = n.min(8);
    let (cs, ms) = (f.miso >> (n - sb), m.reply >> (n - sb));
    let status = if cs == ms { Some(false) } else { m.status.iter().any(|&v| (v as u64) >> (8 - sb) == cs).then_some(true) };
    let rest_mask = if n > 8 { (1u64 << (n - 8)) - 1 } else { 0 };
    let (cr, mr) = (f.miso & rest_mask, m.reply & rest_mask);
    let rest = if cr == mr { Some(false) } else { (super::compare::is_read(f) && m.data.contains(&(cr as u32))).then_some(true) };
    let mut bad = f.miso ^ m.reply;
    if status.is_some() {
        bad &= rest_mask;
    }
    if rest.is_some() {
        bad &= !rest_mask;
    }
    FrameCheck { status, rest, bad }
}

/// The difference of a frame whose reply differs in `bad`.
fn frame_difference(s: &Setup, i: usize, f: &CapFrame, m: &FrameModel, bad: u64) -> Difference {
    let n = f.nbits();
    let bits: Vec<String> = (0..n)
        .rev()
        .filter(|b| bad >> b & 1 == 1)
        .map(|b| {
            let what = f.datagram().map(|d| format!(" ({})", bit_name(s.chip, d, b))).unwrap_or_default();
            format!("reply bit {b}{what} is {} on the chip, {} in the model", f.miso >> b & 1, m.reply >> b & 1)
        })
        .collect();
    let digits = n.div_ceil(4) as usize;
    let model = describe(s.chip, f, m.reply);
    let model = model.split(" | ").next().unwrap_or(&model).splitn(3, ' ').nth(2).map(|t| format!(" ({t})")).unwrap_or_default();
    Difference {
        time: s.cap.seconds(f.start),
        text: format!(
            "µC frame {} ({}): {}; chip ${:0digits$X}, model ${:0digits$X}{model} (CLK edge {})",
            i + 1,
            describe(s.chip, f, f.miso),
            bits.join(", "),
            f.miso,
            m.reply,
            m.end_cycle
        ),
    }
}

fn tally(t: &mut Tally, r: Option<bool>) {
    *t.compared.get_or_insert(0) += 1;
    if let Some(within) = r {
        t.agreed += 1;
        t.within += within as usize;
    }
}

fn frame_tallies(s: &Setup, fr: &Frames, fm: &[FrameModel], diffs: &mut Vec<Difference>) -> Vec<Tally> {
    let mut frames = Tally { name: "µC frames", compared: Some(0), ..Default::default() };
    let mut status = Tally { name: "status bytes", compared: Some(0), ..Default::default() };
    let mut data = Tally { name: "read data", compared: Some(0), ..Default::default() };
    for (i, (f, m)) in fr.frames.iter().zip(fm).enumerate() {
        if f.nbits() == 0 || f.nbits() > 64 {
            continue;
        }
        let c = check_frame(f, m);
        tally(&mut status, c.status);
        if super::compare::is_read(f) {
            tally(&mut data, c.rest);
        }
        let whole = match (c.status, c.rest) {
            (Some(a), Some(b)) => Some(a || b),
            _ => None,
        };
        tally(&mut frames, whole);
        if whole.is_none() {
            diffs.push(frame_difference(s, i, f, m, c.bad));
        }
    }
    vec![frames, status, data]
}

fn describe_event(e: &Event) -> String {
    match *e {
        Event::Chain { nbits, bits, .. } => {
            let digits = nbits.div_ceil(4).max(1) as usize;
            format!("{nbits} bits ${bits:0digits$X}")
        }
        Event::Step { negative, .. } => (if negative { "-" } else { "+" }).to_string(),
        Event::Int { level, .. } => if level { "nINT falls (INT active)" } else { "nINT rises (INT inactive)" }.to_string(),
    }
}

/// Pairs the model's and the chip's events of one kind in time order (within `tol` CLK they
/// agree in time; within 4·`tol` they are the same event with a timing difference) and records
/// the differences. Returns the number compared.
#[allow(clippy::too_many_arguments)]
fn match_events(
    model: &[Event],
    chip: &[Event],
    tol: u64,
    win: (u64, u64),
    tb: &Timebase,
    what: &str,
    t: &mut Tally,
    diffs: &mut Vec<Difference>,
) -> usize {
    let inside = |e: &&Event| e.cycle() >= win.0 + tol && e.cycle() + tol <= win.1;
    let model: Vec<Event> = model.iter().filter(inside).copied().collect();
    let chip: Vec<Event> = chip.iter().filter(inside).copied().collect();
    let near = 4 * tol;
    let (mut i, mut j) = (0, 0);
    let mut compared = 0;
    let at = |c: u64| tb.time(c as f64);
    while i < model.len() || j < chip.len() {
        compared += 1;
        let (m, c) = (model.get(i), chip.get(j));
        match (m, c) {
            (Some(m), Some(c)) if m.cycle().abs_diff(c.cycle()) <= near => {
                let dt = c.cycle() as i64 - m.cycle() as i64;
                let same = same_content(m, c);
                if dt.unsigned_abs() <= tol && same {
                    t.agreed += 1;
                } else if same {
                    diffs.push(Difference {
                        time: at(m.cycle()),
                        text: format!("{what} {} ({}): on the chip {dt:+} CLK from the model", i + 1, describe_event(m)),
                    });
                } else {
                    diffs.push(Difference { time: at(m.cycle()), text: format!("{what} {}: {}", i + 1, content_diff(m, c)) });
                }
                i += 1;
                j += 1;
            }
            (Some(m), c) if c.is_none_or(|c| m.cycle() < c.cycle()) => {
                diffs.push(Difference {
                    time: at(m.cycle()),
                    text: format!("{what} {} ({}): in the model, missing on the chip", i + 1, describe_event(m)),
                });
                i += 1;
            }
            (_, Some(c)) => {
                diffs.push(Difference {
                    time: at(c.cycle()),
                    text: format!("{what} ({}): on the chip, not in the model", describe_event(c)),
                });
                j += 1;
            }
            _ => break,
        }
    }
    compared
}

fn same_content(a: &Event, b: &Event) -> bool {
    match (*a, *b) {
        (Event::Chain { nbits: n1, bits: b1, .. }, Event::Chain { nbits: n2, bits: b2, .. }) => n1 == n2 && b1 == b2,
        (Event::Step { negative: a, .. }, Event::Step { negative: b, .. }) => a == b,
        (Event::Int { level: a, .. }, Event::Int { level: b, .. }) => a == b,
        _ => false,
    }
}

fn content_diff(m: &Event, c: &Event) -> String {
    match (*m, *c) {
        (Event::Chain { nbits: n1, bits: b1, .. }, Event::Chain { nbits: n2, bits: b2, .. }) if n1 == n2 => {
            let diff = b1 ^ b2;
            let pos: Vec<String> = (0..n1).filter(|p| diff >> (n1 - 1 - p) & 1 == 1).map(|p| p.to_string()).collect();
            format!("position {} differs: chip {}, model {}", pos.join(", "), describe_event(c), describe_event(m))
        }
        _ => format!("chip {}, model {}", describe_event(c), describe_event(m)),
    }
}
