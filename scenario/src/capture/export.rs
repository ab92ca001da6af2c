//! Captures made from a simulation of the chip (`tmc429 capture export`): the pins of a scenario
//! or an SPI script, run on the golden model or the Verilated RTL, sampled as a logic analyzer
//! samples them — at its own rate, with a random phase and jitter when asked — and written as a
//! sigrok session file or a pin-only, flat VCD. A planted difference ([`Plant`]) edits the
//! chip's pins before sampling, as a chip that differs from the model would.
//!
//! Times: power-on at 0, edge n (n ≥ 1) at n·T. The µC's and the switches' levels of edge n
//! change at (n − 1 + u)·T, u in (0, 1) (½ without a seed; random per cycle with one, as an
//! asynchronous µC's edges fall anywhere in the cycle); the chip's outputs after edge n change at
//! n·T + [`OUTPUT_DELAY_NS`].

use tmc429_model::host::Host;
use tmc429_model::script::{self, Line};
use tmc429_model::{Chip, Inputs, Outputs, Tmc429};
use tmc429_testbench::rtl::{Rtl, Variant};

use super::pins::{Pin, ALL};
use super::{Capture, Channel};
use crate::run::{run, Engine, Options};
use crate::scenario::Scenario;

/// Clock-to-output delay of the chip's outputs in the exported captures.
pub const OUTPUT_DELAY_NS: f64 = 5.0;

/// What to simulate: a scenario file, or an SPI script of `tmc429 spi`.
pub enum Source {
    Scenario(Box<Scenario>),
    Script { chip: Chip, fclk: u64, sck_half: u32, lines: Vec<Line> },
}

/// A difference planted in the chip's pins.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Plant {
    /// The last bit of the last 32-bit read frame flipped on SDO (nINT_SDO_C and SDOZ_C).
    ReplyBit,
    /// One STEP pulse of motor 0 removed (Step/Dir mode), from the middle of the run.
    MissingStep,
    /// One SDO_S bit of a driver-chain datagram from the middle of the run flipped.
    Datagram,
}

impl std::str::FromStr for Plant {
    type Err = String;
    fn from_str(s: &str) -> Result<Plant, String> {
        match s {
            "reply-bit" => Ok(Plant::ReplyBit),
            "missing-step" => Ok(Plant::MissingStep),
            "datagram" => Ok(Plant::Datagram),
            _ => Err(format!("unknown difference '{s}': expected reply-bit, missing-step or datagram")),
        }
    }
}

/// How to sample.
#[derive(Clone, Copy, Debug)]
pub struct Sampling {
    /// Sample rate, Hz.
    pub rate: u64,
    /// Random phase, µC edge times, lead-in and trigger point from this seed; `None`: phase 0,
    /// µC edges mid-cycle, capture from power-on.
    pub seed: Option<u64>,
    /// Peak sampling jitter, ns (uniform in ±jitter; less than half a sample period).
    pub jitter_ns: f64,
}

/// The chip's pins of a run: per pin its level at power-on and the times (ns) it changes.
pub struct PinTrace {
    pub chip: Chip,
    pub fclk: u64,
    pub initial: Vec<bool>,
    pub changes: Vec<Vec<f64>>,
    /// Edges simulated (after the lead-in).
    pub cycles: u64,
    /// Idle cycles before the source's first edge.
    pub lead_in: u64,
}

/// SplitMix64: the deterministic random numbers of a seed.
pub fn mix(mut z: u64) -> u64 {
    z = z.wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// A uniform number in [0, 1) from `seed` and `k`.
pub fn unit(seed: u64, k: u64) -> f64 {
    (mix(seed ^ mix(k)) >> 11) as f64 / (1u64 << 53) as f64
}

/// The input pins of every cycle of a source (recorded from its run on the golden model).
fn record_inputs(src: &Source) -> Result<(Chip, u64, Vec<Inputs>), String> {
    match src {
        Source::Scenario(sc) => {
            let mut opt = Options::new(Engine::Model);
            opt.samples = 1;
            opt.record_pins = true;
            let report = run(sc, &opt, &mut |_, _| {})?;
            let pins = report.pins.ok_or("the run recorded no pins")?;
            Ok((sc.chip, sc.fclk, pins.iter().collect()))
        }
        Source::Script { chip, fclk, sck_half, lines } => {
            let rec = std::sync::Arc::new(std::sync::Mutex::new(Vec::new()));
            let r2 = rec.clone();
            let mut host = Host::new(*chip);
            host.set_sck_half(*sck_half).map_err(|e| e.to_string())?;
            host.set_observer(Box::new(move |_, i, _| r2.lock().unwrap().push(*i)));
            script::run(&mut host, lines, Default::default(), &mut std::io::sink()).map_err(|e| e.to_string())?;
            // a few idle cycles after the last frame, so that its end is in the capture
            host.wait(64);
            host.take_observer();
            let v = std::mem::take(&mut *rec.lock().unwrap());
            Ok((*chip, *fclk, v))
        }
    }
}

/// Runs the source on `engine` (model or RTL) after `lead_in` idle cycles and traces the pins.
pub fn trace(src: &Source, engine: Engine, seed: Option<u64>) -> Result<PinTrace, String> {
    let (chip, fclk, inputs) = record_inputs(src)?;
    let lead_in = seed.map_or(0, |s| 1000 + (unit(s, 1) * 60_000.0) as u64);
    let mut tick: Box<dyn FnMut(&Inputs) -> Outputs> = match engine {
        Engine::Model | Engine::Cosim => {
            let mut m = Tmc429::new(chip);
            Box::new(move |i| m.tick(i))
        }
        Engine::Rtl => {
            let mut r = Rtl::try_new(Variant::Chip(chip)).map_err(|e| format!("{e}, or use --engine model"))?;
            Box::new(move |i| r.tick(i))
        }
    };
    let t = 1e9 / fclk as f64;
    let idle = Inputs::default();
    let out0 = Tmc429::new(chip).outputs();
    let initial: Vec<bool> = ALL.iter().map(|p| p.level(&idle, &out0)).collect();
    let mut level = initial.clone();
    let mut changes = vec![Vec::new(); ALL.len()];
    let mut prev_in = idle;
    let all = std::iter::repeat_n(idle, lead_in as usize).chain(inputs.iter().copied());
    for (k, inp) in all.enumerate() {
        let n = k as u64 + 1;
        let u = seed.map_or(0.5, |s| 0.05 + 0.9 * unit(s, 1000 + n));
        let out = tick(&inp);
        for (j, p) in ALL.iter().enumerate() {
            let l = p.level(&inp, &out);
            if l != level[j] {
                level[j] = l;
                let from_input = p.is_input() && (*p != Pin::SdiS || !out.sdi_s_oe) && p.level(&prev_in, &out) != p.level(&inp, &out);
                changes[j].push(if from_input { (n as f64 - 1.0 + u) * t } else { n as f64 * t + OUTPUT_DELAY_NS });
            }
        }
        prev_in = inp;
    }
    for c in changes.iter_mut() {
        c.sort_by(f64::total_cmp);
    }
    Ok(PinTrace { chip, fclk, initial, changes, cycles: inputs.len() as u64, lead_in })
}

impl PinTrace {
    /// Inverts pin `p` between the times `a` and `b` (ns).
    fn flip(&mut self, p: Pin, a: f64, b: f64) {
        let j = ALL.iter().position(|&q| q == p).unwrap();
        let c = &mut self.changes[j];
        c.push(a);
        c.push(b);
        c.sort_by(f64::total_cmp);
        // two toggles at one time cancel
        let mut out: Vec<f64> = Vec::with_capacity(c.len());
        for &x in c.iter() {
            if out.last() == Some(&x) {
                out.pop();
            } else {
                out.push(x);
            }
        }
        *c = out;
    }

    fn pin(&self, p: Pin) -> &[f64] {
        &self.changes[ALL.iter().position(|&q| q == p).unwrap()]
    }

    fn level_at(&self, p: Pin, t: f64) -> bool {
        let j = ALL.iter().position(|&q| q == p).unwrap();
        self.initial[j] ^ (self.changes[j].partition_point(|&x| x <= t) & 1 == 1)
    }

    /// µC frames: (nSCS_C fall, SCK_C rising edges, nSCS_C rise), times in ns.
    fn frames(&self) -> Vec<(f64, Vec<f64>, f64)> {
        let cs = self.pin(Pin::NscsC);
        let sck = self.pin(Pin::SckC);
        let mut out = Vec::new();
        for w in cs.chunks_exact(2) {
            let (fall, rise) = (w[0], w[1]);
            let rises: Vec<f64> = sck.iter().copied().filter(|&x| x > fall && x < rise && self.level_at(Pin::SckC, x)).collect();
            out.push((fall, rises, rise));
        }
        out
    }

    /// Plants a difference; returns what was planted and when (ns), for the user and for tests.
    pub fn plant(&mut self, what: Plant) -> Result<(String, f64), String> {
        let t = 1e9 / self.fclk as f64;
        match what {
            Plant::ReplyBit => {
                let frames = self.frames();
                let (k, (_, rises, _)) = frames
                    .iter()
                    .enumerate()
                    .rev()
                    .find(|(_, (_, r, _))| r.len() == 32 && self.level_at(Pin::SdiC, r[7]))
                    .ok_or("no 32-bit read frame to change a reply bit of")?;
                let x = rises[31];
                self.flip(Pin::NintSdoC, x - 1.5 * t, x + 1.5 * t);
                self.flip(Pin::SdozC, x - 1.5 * t, x + 1.5 * t);
                Ok((format!("reply bit 0 of µC frame {} flipped", k + 1), x))
            }
            Plant::MissingStep => {
                let step = self.pin(Pin::SdoS).to_vec();
                // STEP1 active high (inv_stp = 0): a step is a change to high
                let rises: Vec<usize> = (0..step.len()).filter(|&i| self.level_at(Pin::SdoS, step[i]) && i + 1 < step.len()).collect();
                if rises.len() < 2 {
                    return Err("no STEP pulses of motor 0 (SDO_S) to remove: the source does not run in Step/Dir mode".into());
                }
                let p = rises.len() / 2;
                let i = rises[p];
                self.flip(Pin::SdoS, step[i], step[i + 1]);
                Ok((format!("step {} of motor 0 removed", p + 1), step[i]))
            }
            Plant::Datagram => {
                let cs = self.pin(Pin::NscsS).to_vec();
                // datagrams: nSCS_S low (the power-on polarity) until it rises again
                let spans: Vec<(f64, f64)> =
                    (0..cs.len().saturating_sub(1)).filter(|&i| !self.level_at(Pin::NscsS, cs[i])).map(|i| (cs[i], cs[i + 1])).collect();
                if spans.is_empty() {
                    return Err("no driver-chain datagrams (nSCS_S) to change: the source sends none".into());
                }
                let k = spans.len() / 2;
                let (a, b) = spans[k];
                let sck: Vec<f64> =
                    self.pin(Pin::SckS).iter().copied().filter(|&x| x > a && x < b && self.level_at(Pin::SckS, x)).collect();
                let bit = 5.min(sck.len().saturating_sub(1));
                let r = *sck.get(bit).ok_or("a datagram without SCK_S edges")?;
                let falls: Vec<f64> =
                    self.pin(Pin::SckS).iter().copied().filter(|&x| x > a && x < b && !self.level_at(Pin::SckS, x)).collect();
                let from = falls.iter().copied().filter(|&x| x < r).last().unwrap_or(r - t);
                let to = falls.iter().copied().find(|&x| x > r).unwrap_or(r + t);
                self.flip(Pin::SdoS, from, to);
                Ok((format!("position {bit} of chain datagram {} flipped", k + 1), a))
            }
        }
    }

    /// The time (ns) of the capture's first sample: with a seed somewhere in the lead-in (the
    /// trigger comes after power-on), at a random phase of the sample clock.
    pub fn start(&self, s: &Sampling) -> f64 {
        match s.seed {
            Some(seed) => unit(seed, 2) * 0.9 * self.lead_in as f64 * 1e9 / self.fclk as f64 + unit(seed, 3) * 1e9 / s.rate as f64,
            None => 0.0,
        }
    }

    /// The capture a logic analyzer makes of these pins.
    pub fn sample(&self, s: &Sampling) -> Capture {
        let period = 1e9 / s.rate as f64;
        let jitter = s.jitter_ns.min(0.45 * period);
        let seed = s.seed.unwrap_or(0);
        let t0 = self.start(s);
        let at = |j: u64| t0 + j as f64 * period + if jitter > 0.0 { (2.0 * unit(seed, 1 << 40 | j) - 1.0) * jitter } else { 0.0 };
        // first sample at or after x
        let first = |x: f64| -> u64 {
            if x <= at(0) {
                return 0;
            }
            let j0 = ((x - t0) / period).ceil().max(1.0) as u64;
            (j0.saturating_sub(1)..=j0 + 1).find(|&j| at(j) >= x).unwrap_or(j0 + 1)
        };
        let end_ns = (self.lead_in + self.cycles + 1) as f64 * 1e9 / self.fclk as f64;
        let length = first(end_ns);
        let channels = ALL
            .iter()
            .enumerate()
            .map(|(j, p)| {
                let initial = self.level_at(*p, at(0));
                let mut edges: Vec<u64> =
                    self.changes[j].iter().filter(|&&x| x > at(0)).map(|&x| first(x)).filter(|&e| e < length).collect();
                // toggles that land in one sample cancel
                let mut out: Vec<u64> = Vec::with_capacity(edges.len());
                for e in edges.drain(..) {
                    if out.last() == Some(&e) {
                        out.pop();
                    } else {
                        out.push(e);
                    }
                }
                Channel { name: p.name().to_string(), initial, edges: out }
            })
            .collect();
        Capture { samplerate: s.rate, length, channels }
    }
}
