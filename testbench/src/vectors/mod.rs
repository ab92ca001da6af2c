//! Test vectors from the golden model, for replay in any Verilog simulator or on a tester
//! (docs/vectors.md).
//!
//! - [`pins`]: the pin-level form (`.hex` + `.cols` + `.meta`);
//! - [`pinmap`], [`stil`], [`evcd`]: the chip's pins for testers and simulators (STIL, EVCD,
//!   pin VCD);
//! - [`record`]: what each unit's boundary shows per CLK edge, as pin-level lines or CSV rows;
//! - [`lut`]: the microstep unit's complete tables;
//! - [`scenario`]: built-in scenarios and scenario files;
//! - [`export`]: runs a scenario on the model and writes the files of one unit.

mod builtin;
pub mod evcd;
pub mod files;
pub mod lut;
pub mod pinmap;
pub mod pins;
pub mod record;
pub mod scenario;
pub mod stil;

use std::fmt;
use std::path::{Path, PathBuf};
use std::str::FromStr;

use tmc429_model::{Package, Tmc429};

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
    /// and the driver-chain master have it; the chip has pin-level vectors only, and the
    /// tester forms of its pins (STIL, EVCD, pin VCD).
    pub fn has(self, f: Form) -> bool {
        match f {
            Form::Pins => true,
            Form::Csv => self != Unit::Chip,
            Form::Stil | Form::Evcd | Form::Vcd => self == Unit::Chip,
        }
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
    /// STIL (IEEE 1450) of the chip's pins, `.stil`.
    Stil,
    /// Extended VCD (`$dumpports`) of the chip's pins, `.evcd`.
    Evcd,
    /// Four-state VCD of the chip's pins, `.vcd`.
    Vcd,
}

impl Form {
    /// The file extension of a single-file form.
    pub fn extension(self) -> &'static str {
        match self {
            Form::Pins => "hex",
            Form::Csv => "csv",
            Form::Stil => "stil",
            Form::Evcd => "evcd",
            Form::Vcd => "vcd",
        }
    }
}

/// The `--format` choice.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    Pins,
    Csv,
    Stil,
    Evcd,
    Vcd,
    /// The pin-level and CSV forms the unit has.
    All,
}

impl FromStr for Format {
    type Err = String;
    fn from_str(s: &str) -> Result<Format, String> {
        match s {
            "pins" => Ok(Format::Pins),
            "csv" => Ok(Format::Csv),
            "stil" => Ok(Format::Stil),
            "evcd" => Ok(Format::Evcd),
            "vcd" => Ok(Format::Vcd),
            "all" => Ok(Format::All),
            _ => Err(format!("unknown format '{s}': expected pins, csv, stil, evcd, vcd or all")),
        }
    }
}

/// The forms to write for a unit, or why the request cannot be met.
pub fn forms(unit: Unit, format: Format) -> Result<Vec<Form>, String> {
    let want: Vec<Form> = match format {
        Format::Pins => vec![Form::Pins],
        Format::Csv => vec![Form::Csv],
        Format::Stil => vec![Form::Stil],
        Format::Evcd => vec![Form::Evcd],
        Format::Vcd => vec![Form::Vcd],
        Format::All => vec![Form::Pins, Form::Csv],
    };
    let have: Vec<Form> = want.iter().copied().filter(|f| unit.has(*f)).collect();
    if have.is_empty() {
        return Err(match (unit, format) {
            (Unit::Chip, _) => "unit chip has no CSV form: use --format pins, stil, evcd or vcd".to_string(),
            (_, Format::Stil | Format::Evcd | Format::Vcd) => {
                format!("unit {unit}: STIL, EVCD and pin VCD are forms of the chip's pins: use --unit chip")
            }
            _ => format!("unit {unit} has no {format:?} vectors"),
        });
    }
    Ok(have)
}

/// File stem of a unit's vectors for a scenario: `DIR/UNIT-SCENARIO-CHIP`, with `-PACKAGE`
/// for a package that lacks pins of the variant (C90).
pub fn stem(dir: &Path, unit: Unit, sc: &Scenario) -> PathBuf {
    if sc.package == Package::full(sc.chip) {
        dir.join(format!("{}-{}-{}", unit, sc.name, sc.chip))
    } else {
        dir.join(format!("{}-{}-{}-{}", unit, sc.name, sc.chip, sc.package))
    }
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
                f => return Err(format!("unit lut: no {f:?} form")),
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
                (Unit::Chip, Form::Stil) => {
                    Box::new(record::ChipForm(stil::ChipStil::create(&stem.with_extension("stil"), &meta(unit, sc))?))
                }
                (Unit::Chip, Form::Evcd | Form::Vcd) => {
                    let d = if *f == Form::Evcd { evcd::Dialect::Evcd } else { evcd::Dialect::Vcd };
                    Box::new(record::ChipForm(evcd::ChipDump::create(&stem.with_extension(f.extension()), d, &meta(unit, sc))?))
                }
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
    let mut chip = Tmc429::with_package(sc.chip, sc.package)?;
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
    Meta {
        unit: unit.name(),
        chip: sc.chip,
        package: sc.package,
        fclk: sc.fclk,
        scenario: sc.name.clone(),
        seed: sc.seed,
        cycles: 0,
        replay: "ready",
        notes,
    }
}
