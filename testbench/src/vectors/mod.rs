//! Test vectors from the golden model, for replay in any Verilog simulator or on a tester
//! (docs/vectors.md).
//!
//! - [`pins`]: the pin-level form (`.hex` + `.cols` + `.meta`);
//! - [`record`]: what each unit's boundary shows per CLK edge, as pin-level lines or CSV rows;
//! - [`lut`]: the microstep unit's complete tables;
//! - [`scenario`]: built-in scenarios and scenario files;
//! - [`export`]: runs a scenario on the model and writes the files of one unit.

pub mod files;
pub mod lut;
pub mod pins;
pub mod record;
pub mod scenario;

use std::fmt;
use std::path::{Path, PathBuf};
use std::str::FromStr;

use tmc429_model::Tmc429;

use pins::Meta;
use record::Recorder;
pub use scenario::Scenario;

/// A unit boundary.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Unit {
    Spi,
    Ramp,
    Lut,
    Chain,
    Chip,
}

impl Unit {
    pub const ALL: [Unit; 5] = [Unit::Spi, Unit::Ramp, Unit::Lut, Unit::Chain, Unit::Chip];

    pub fn name(self) -> &'static str {
        match self {
            Unit::Spi => "spi",
            Unit::Ramp => "ramp",
            Unit::Lut => "lut",
            Unit::Chain => "chain",
            Unit::Chip => "chip",
        }
    }

    /// The forms this unit has today. Pin-level vectors of a unit need the same boundary in the
    /// model as its RTL module: the SPI slave, the ramp/pulse generator, the microstep LUT unit
    /// and the driver-chain master have it; the chip has pin-level vectors only.
    pub fn has(self, f: Form) -> bool {
        matches!((self, f), (Unit::Spi | Unit::Ramp | Unit::Lut | Unit::Chain, _) | (Unit::Chip, Form::Pins))
    }
}

impl fmt::Display for Unit {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Unit {
    type Err = String;
    fn from_str(s: &str) -> Result<Unit, String> {
        Unit::ALL.into_iter().find(|u| u.name() == s).ok_or_else(|| format!("unknown unit '{s}': expected spi, ramp, lut, chain or chip"))
    }
}

/// One form of vectors.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Form {
    Pins,
    Csv,
}

/// The `--format` choice.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    Pins,
    Csv,
    /// Every form the unit has.
    All,
}

impl FromStr for Format {
    type Err = String;
    fn from_str(s: &str) -> Result<Format, String> {
        match s {
            "pins" => Ok(Format::Pins),
            "csv" => Ok(Format::Csv),
            "all" => Ok(Format::All),
            _ => Err(format!("unknown format '{s}': expected pins, csv or all")),
        }
    }
}

/// The forms to write for a unit, or why the request cannot be met.
pub fn forms(unit: Unit, format: Format) -> Result<Vec<Form>, String> {
    let want: Vec<Form> = match format {
        Format::Pins => vec![Form::Pins],
        Format::Csv => vec![Form::Csv],
        Format::All => vec![Form::Pins, Form::Csv],
    };
    let have: Vec<Form> = want.iter().copied().filter(|f| unit.has(*f)).collect();
    if have.is_empty() {
        return Err(match (unit, format) {
            (Unit::Chip, _) => "unit chip has pin-level vectors only: use --format pins".to_string(),
            _ => format!("unit {unit} has no {format:?} vectors"),
        });
    }
    Ok(have)
}

/// File stem of a unit's vectors for a scenario: `DIR/UNIT-SCENARIO-CHIP`.
pub fn stem(dir: &Path, unit: Unit, sc: &Scenario) -> PathBuf {
    dir.join(format!("{}-{}-{}", unit, sc.name, sc.chip))
}

/// Runs `sc` on the golden model and writes the vectors of `unit` in `forms` to `dir`. The files
/// appear together when all are complete. Returns their paths.
pub fn export(unit: Unit, sc: &Scenario, forms: &[Form], dir: &Path) -> Result<Vec<PathBuf>, String> {
    if unit == Unit::Lut {
        if sc.name != "tables" {
            return Err(format!("unit lut: the microstep unit's vectors are complete tables: use --scenario tables, not '{}'", sc.name));
        }
        let st = stem(dir, unit, sc);
        let mut all = Vec::new();
        for f in forms {
            match f {
                Form::Csv => all.push(lut::write(&st.with_extension("csv"))?),
                Form::Pins => {
                    let mut m = meta(unit, sc);
                    m.notes.clear();
                    all.extend(lut::write_pins(&st, m)?);
                }
            }
        }
        return files::commit_all(all);
    }
    export_units(sc, &[(unit, forms.to_vec())], dir)
}

/// The units and forms a scenario of motion gets (`tmc429 run --vectors`, `tmc429 demo`): the
/// chip's pins, and the transaction-level CSV of the SPI frames, the ramp ticks and the
/// driver-chain datagrams.
pub fn scenario_set() -> Vec<(Unit, Vec<Form>)> {
    vec![(Unit::Chip, vec![Form::Pins]), (Unit::Spi, vec![Form::Csv]), (Unit::Ramp, vec![Form::Csv]), (Unit::Chain, vec![Form::Csv])]
}

/// Runs `sc` once on the golden model and writes the vectors of several units (not `lut`,
/// whose vectors are tables) to `dir`. The files appear together when all are complete.
/// Returns their paths.
pub fn export_units(sc: &Scenario, set: &[(Unit, Vec<Form>)], dir: &Path) -> Result<Vec<PathBuf>, String> {
    let mut recs: Vec<(Unit, Box<dyn Recorder>)> = Vec::new();
    for (unit, forms) in set {
        let (unit, stem) = (*unit, stem(dir, *unit, sc));
        for f in forms {
            let r: Box<dyn Recorder> = match (unit, f) {
                (Unit::Chip, Form::Pins) => Box::new(record::ChipPins::create(&stem)?),
                (Unit::Spi, Form::Pins) => Box::new(record::SpiPins::create(&stem)?),
                (Unit::Spi, Form::Csv) => Box::new(record::SpiCsv::create(&stem.with_extension("csv"), sc.chip)?),
                (Unit::Ramp, Form::Pins) => Box::new(record::RampPins::create(&stem)?),
                (Unit::Ramp, Form::Csv) => Box::new(record::RampCsv::create(&stem.with_extension("csv"))?),
                (Unit::Chain, Form::Pins) => Box::new(record::ChainPins::create(&stem)?),
                (Unit::Chain, Form::Csv) => Box::new(record::ChainCsv::create(&stem.with_extension("csv"))?),
                _ => return Err(format!("unit {unit}: no {f:?} form")),
            };
            recs.push((unit, r));
        }
    }
    let mut chip = Tmc429::new(sc.chip);
    for (_, r) in recs.iter_mut() {
        r.reset(&chip)?;
    }
    for inp in sc.inputs() {
        let out = chip.tick(&inp);
        for (_, r) in recs.iter_mut() {
            r.edge(&chip, &inp, &out)?;
        }
    }
    let mut all = Vec::new();
    for (unit, r) in recs {
        all.extend(r.finish(&meta(unit, sc))?);
    }
    files::commit_all(all)
}

/// The `.meta` of a unit's pin-level vectors of `sc` (`cycles` is filled in by the writer).
fn meta(unit: Unit, sc: &Scenario) -> Meta {
    let mut notes = sc.notes.clone();
    notes.push("line 0 is the reset edge (rst = 1); line k is the k-th CLK edge after it".into());
    if unit == Unit::Chip && !record::RTL_PENDING_PINS.is_empty() {
        notes.push(format!("not_compared: pins the reference RTL does not drive yet ({})", record::RTL_PENDING_PINS.join(", ")));
    }
    Meta { unit: unit.name(), chip: sc.chip, fclk: sc.fclk, scenario: sc.name.clone(), seed: sc.seed, cycles: 0, replay: "ready", notes }
}
