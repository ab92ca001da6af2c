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

use tmc429_model::script::{self, Command, Line};
use tmc429_model::{Chip, Inputs, Package};

use super::builtin;
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

/// Looks up a built-in scenario. `cycles`: length of `random`.
pub fn builtin(name: &str, chip: Chip, fclk: u64, seed: u64, cycles: u64) -> Option<Scenario> {
    let lines = match name {
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
        _ => builtin::script(name, chip)?,
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
        source: Source::Script { lines, sck_half: SCK_HALF },
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
