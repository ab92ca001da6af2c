//! Test vectors of a scenario file (docs/vectors.md): `tmc429 run FILE --vectors DIR`,
//! `tmc429 demo` and `tmc429 vectors --scenario FILE.toml`.
//!
//! A scenario's events may wait for a condition on the chip (`when`, docs/scenarios.md), so its
//! pin levels are known only by running it: the scenario runs once on the golden model, its
//! input pins are recorded per CLK cycle, and the vector exporter replays them on the model
//! ([`vectors::scenario::Source::Recorded`]). The vectors are the golden model's whatever the
//! engine of the run: a co-simulation that stops at a mismatch still gets the whole scenario.

use std::path::{Path, PathBuf};

use tmc429_testbench::vectors::{self, scenario::PinRuns, scenario::Source, Form, Unit};

use crate::run::{run, Engine, Options};
use crate::scenario::Scenario;

/// The vector exporter's scenario for `sc`, with the pin levels a run recorded
/// ([`Options::record_pins`] on the model engine).
pub fn vector_scenario(sc: &Scenario, pins: PinRuns) -> vectors::Scenario {
    vectors::Scenario {
        name: file_name(&sc.name),
        chip: sc.chip,
        package: tmc429_model::Package::full(sc.chip),
        fclk: sc.fclk,
        seed: 0,
        source: Source::Recorded(pins),
        notes: vec![format!(
            "scenario file {} (docs/scenarios.md): {} CLK cycles, input pins recorded from its run on the golden model",
            sc.file, sc.duration
        )],
    }
}

/// Runs `sc` on the golden model and records its input pins.
pub fn record(sc: &Scenario) -> Result<vectors::Scenario, String> {
    let mut opt = Options::new(Engine::Model);
    opt.samples = 1;
    opt.record_pins = true;
    let report = run(sc, &opt, &mut |_, _| {})?;
    let pins = report.pins.expect("record_pins keeps the pins");
    Ok(vector_scenario(sc, pins))
}

/// The files [`write`] makes for `sc` in `dir`, in the order it lists them.
pub fn files(sc: &Scenario, dir: &Path) -> Vec<PathBuf> {
    let v = vector_scenario(sc, PinRuns::new());
    let mut out = Vec::new();
    for (unit, forms) in vectors::scenario_set() {
        let stem = vectors::stem(dir, unit, &v);
        for f in forms {
            match f {
                Form::Pins => out.extend(["hex", "cols", "meta"].map(|e| stem.with_extension(e))),
                f => out.push(stem.with_extension(f.extension())),
            }
        }
    }
    out
}

/// Writes the vectors of `sc` to `dir`: chip pins (`.hex`, `.cols`, `.meta`) and the CSV of
/// the SPI frames, ramp ticks and driver-chain datagrams (`vectors::scenario_set`). `pins`: the
/// input pins of a full run on the model, if there was one; otherwise the model runs `sc` first.
/// The files appear together when complete. Returns their paths.
pub fn write(sc: &Scenario, pins: Option<PinRuns>, dir: &Path) -> Result<Vec<PathBuf>, String> {
    let v = match pins {
        Some(p) if p.cycles() == sc.duration => vector_scenario(sc, p),
        _ => record(sc)?,
    };
    vectors::export_units(&v, &vectors::scenario_set(), dir)
}

/// The units a scenario file gives, for `tmc429 vectors --scenario FILE.toml --unit U`.
pub fn unit_ok(unit: Unit) -> Result<(), String> {
    match unit {
        Unit::Lut => Err("unit lut: the microstep unit's vectors are complete tables: use --scenario tables".into()),
        _ => Ok(()),
    }
}

/// A scenario name as a file-name part: letters, digits, `.`, `_` and `-` kept, anything else
/// `_`.
pub fn file_name(name: &str) -> String {
    let s: String = name.chars().map(|c| if c.is_ascii_alphanumeric() || "._-".contains(c) { c } else { '_' }).collect();
    if s.is_empty() {
        "scenario".into()
    } else {
        s
    }
}
