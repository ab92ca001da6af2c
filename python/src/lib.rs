//! The Python extension `tmc429._native` (the package `tmc429`, python/tmc429): the golden
//! model at pin level, the virtual µC, the register map, scenarios and test vectors, and the
//! seeded stimulus and reference of `tmc429 cosim` (docs/verify-your-rtl.md).

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

use tmc429_model::Chip as Variant;

mod chip;
mod host;
mod pins;
mod regmap;
mod regs;
mod scenario;
mod stimulus;

/// The variant of a name (`tmc428`, `tmc429`, `tmc4210`).
pub(crate) fn variant(name: &str) -> PyResult<Variant> {
    name.parse().map_err(PyValueError::new_err)
}

/// The CLK frequency for `variant`: `fclk` in Hz, or the variant's maximum.
pub(crate) fn fclk(v: Variant, fclk: Option<u64>) -> PyResult<u64> {
    let max = v.default_fclk();
    match fclk {
        None => Ok(max),
        Some(0) => Err(PyValueError::new_err("fclk must be positive (Hz)")),
        Some(f) if f > max => Err(PyValueError::new_err(format!(
            "fclk={f}: the {v} runs at {} MHz at most ({})",
            max / 1_000_000,
            if v == Variant::Tmc428 { "TMC428 §6" } else { "TMC429 §1.4" }
        ))),
        Some(f) => Ok(f),
    }
}

#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("VARIANTS", Variant::ALL.iter().map(|c| c.name()).collect::<Vec<_>>())?;
    m.add("INPUT_PINS", tmc429_verif::pinword::INPUT_NAMES.to_vec())?;
    m.add("OUTPUT_PINS", tmc429_verif::pinword::output_names().to_vec())?;
    m.add("PROFILES", ["motion", "motion-core", "drivers", "registers", "full"].to_vec())?;
    m.add_class::<pins::Inputs>()?;
    m.add_class::<pins::Outputs>()?;
    m.add_class::<pins::MotorProbe>()?;
    m.add_class::<pins::ChainProbe>()?;
    m.add_class::<pins::Probes>()?;
    m.add_class::<chip::Chip>()?;
    m.add_class::<host::Host>()?;
    regmap::register(m)?;
    scenario::register(m)?;
    stimulus::register(m)?;
    Ok(())
}
