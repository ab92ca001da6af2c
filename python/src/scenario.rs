//! `tmc429.run_scenario` and `tmc429.export_vectors`: scenario files (docs/scenarios.md) on
//! the golden model, and its test vectors (docs/vectors.md), as `tmc429 run` and
//! `tmc429 vectors` make them.

use std::path::{Path, PathBuf};

use pyo3::exceptions::{PyOSError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use tmc429_scenario::{plot, vectors as svectors, Engine, Options, Report, Scenario};
use tmc429_testbench::vectors::{self, scenario as builtin, Format, Unit};

fn value_err(e: String) -> PyErr {
    PyValueError::new_err(e)
}

/// A scenario file, parsed (errors with file and line).
fn load(path: &Path) -> Result<Scenario, String> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("{}: cannot read: {e}", path.display()))?;
    tmc429_scenario::parse(&text, &path.display().to_string())
        .map_err(|errs| errs.iter().map(|e| e.to_string()).collect::<Vec<_>>().join("\n"))
}

/// The outcome of a scenario run on the golden model.
#[pyclass(module = "tmc429", get_all, frozen)]
pub struct ScenarioReport {
    pub name: String,
    pub variant: &'static str,
    pub fclk: u64,
    /// CLK edges simulated.
    pub cycles: u64,
    /// Every expectation held.
    pub ok: bool,
    /// The summary `tmc429 run` prints.
    pub summary: String,
    /// One dict per expectation: name, line, passed, detail.
    pub expectations: Vec<Py<PyDict>>,
    /// One dict per motor: steps, x_actual, peak_hz, peak_accel_hz_per_s.
    pub motors: Vec<Py<PyDict>>,
    /// The files written (VCD, plot, vectors).
    pub files: Vec<PathBuf>,
}

#[pymethods]
impl ScenarioReport {
    fn __repr__(&self) -> String {
        format!("ScenarioReport('{}', ok={}, cycles={})", self.name, self.ok, self.cycles)
    }
}

fn report(py: Python<'_>, r: &Report, files: Vec<PathBuf>) -> PyResult<ScenarioReport> {
    let mut expectations = Vec::new();
    for e in &r.expects {
        let d = PyDict::new(py);
        d.set_item("name", &e.name)?;
        d.set_item("line", e.line)?;
        d.set_item("passed", e.passed)?;
        d.set_item("detail", &e.detail)?;
        expectations.push(d.unbind());
    }
    let mut motors = Vec::new();
    for m in &r.motors {
        let d = PyDict::new(py);
        d.set_item("steps", m.steps)?;
        d.set_item("x_actual", m.x_actual)?;
        d.set_item("peak_hz", m.peak_hz(r.fclk))?;
        d.set_item("peak_accel_hz_per_s", m.peak_accel_hz_per_s(r.fclk))?;
        motors.push(d.unbind());
    }
    Ok(ScenarioReport {
        name: r.name.clone(),
        variant: r.chip.name(),
        fclk: r.fclk,
        cycles: r.cycles,
        ok: r.ok(),
        summary: r.summary(),
        expectations,
        motors,
        files,
    })
}

/// Runs a scenario file on the golden model (`tmc429 run FILE`). `vcd`: a VCD of the run;
/// `plot`: position, velocity and acceleration per motor (FILE.svg or FILE.png); `vectors`: a
/// directory for the golden model's test vectors of the run. A failed expectation is reported
/// in the result (`ok`), not raised.
#[pyfunction]
#[pyo3(signature = (path, *, vcd = None, plot = None, vectors = None))]
fn run_scenario(
    py: Python<'_>,
    path: PathBuf,
    vcd: Option<PathBuf>,
    plot: Option<PathBuf>,
    vectors: Option<PathBuf>,
) -> PyResult<ScenarioReport> {
    let sc = load(&path).map_err(value_err)?;
    if let Some(p) = &plot {
        if !matches!(p.extension().and_then(|e| e.to_str()), Some("svg" | "png")) {
            return Err(value_err(format!("plot={}: expected a file name ending in .svg or .png", p.display())));
        }
    }
    let mut opt = Options::new(Engine::Model);
    opt.vcd = vcd.clone();
    opt.record_pins = vectors.is_some();
    let mut r = py.detach(|| tmc429_scenario::run(&sc, &opt, &mut |_, _| {})).map_err(value_err)?;
    let mut files: Vec<PathBuf> = vcd.into_iter().collect();
    if let Some(p) = plot {
        plot::write(&r, &p).map_err(value_err)?;
        files.push(p);
    }
    if let Some(d) = vectors {
        std::fs::create_dir_all(&d).map_err(|e| PyOSError::new_err(format!("vectors={}: cannot create: {e}", d.display())))?;
        files.extend(svectors::write(&sc, r.pins.take(), &d).map_err(value_err)?);
    }
    report(py, &r, files)
}

/// Test vectors from the golden model (`tmc429 vectors`): `unit` "spi", "ramp", "lut", "chain"
/// or "chip"; `scenario` a built-in name (`tmc429 vectors --list`), a scenario file (.toml)
/// or a datagram script; `format` "pins", "csv" or "all". `variant`, `fclk`, `seed`, `cycles`
/// and `sck_half` apply to built-in scenarios and scripts. Returns the files written.
#[pyfunction]
#[pyo3(signature = (scenario, out, *, unit = "chip", format = "all", variant = "tmc429", fclk = None, seed = 1, cycles = 100_000, sck_half = None))]
#[allow(clippy::too_many_arguments)]
fn export_vectors(
    py: Python<'_>,
    scenario: &str,
    out: PathBuf,
    unit: &str,
    format: &str,
    variant: &str,
    fclk: Option<u64>,
    seed: u64,
    cycles: u64,
    sck_half: Option<u32>,
) -> PyResult<Vec<PathBuf>> {
    let unit: Unit = unit.parse().map_err(value_err)?;
    let format: Format = format.parse().map_err(value_err)?;
    let forms = vectors::forms(unit, format).map_err(value_err)?;
    let chip = crate::variant(variant)?;
    let fclk = crate::fclk(chip, fclk)?;
    if cycles == 0 {
        return Err(value_err("cycles must be at least 1".into()));
    }
    let make = || -> Result<Vec<PathBuf>, String> {
        std::fs::create_dir_all(&out).map_err(|e| format!("out={}: cannot create: {e}", out.display()))?;
        if scenario.ends_with(".toml") {
            let sc = load(Path::new(scenario))?;
            svectors::unit_ok(unit)?;
            let v = svectors::record(&sc)?;
            return vectors::export_units(&v, &[(unit, forms.clone())], &out);
        }
        let sc = match builtin::builtin(scenario, chip, fclk, seed, cycles) {
            Some(sc) => sc,
            None if Path::new(scenario).is_file() => {
                builtin::from_file(Path::new(scenario), chip, fclk, sck_half.unwrap_or(builtin::SCK_HALF))?
            }
            None => {
                let names: Vec<&str> = builtin::BUILTIN.iter().map(|(n, _)| *n).collect();
                return Err(format!("scenario {scenario}: neither a built-in scenario ({}) nor a readable file", names.join(", ")));
            }
        };
        vectors::export(unit, &sc, &forms, &out)
    };
    py.detach(make).map_err(value_err)
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(run_scenario, m)?)?;
    m.add_function(wrap_pyfunction!(export_vectors, m)?)?;
    m.add_class::<ScenarioReport>()?;
    Ok(())
}
