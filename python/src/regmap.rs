//! `tmc429.registers(variant)`: the register map (`tmc429_model::regmap`, the one source) as
//! Python objects.

use pyo3::prelude::*;

use tmc429_model::regmap::{self, Space};

/// One field of a 24-bit data word.
#[pyclass(module = "tmc429", get_all, frozen, from_py_object)]
#[derive(Clone)]
pub struct Field {
    pub name: &'static str,
    /// Position of the least significant bit.
    pub lsb: u8,
    pub width: u8,
    pub signed: bool,
    /// "R", "W", "RW" or "W1C" (write 1 to clear).
    pub access: &'static str,
    pub doc: &'static str,
}

#[pymethods]
impl Field {
    fn __repr__(&self) -> String {
        format!("Field('{}', lsb={}, width={}, {})", self.name, self.lsb, self.width, self.access)
    }
}

/// One register of a variant.
#[pyclass(module = "tmc429", get_all, frozen)]
pub struct Register {
    pub name: &'static str,
    /// "motor", "global" or "ram".
    pub space: &'static str,
    /// The 7-bit addresses (A7 = RRS, SMDA/ADDR, IDX; TMC428 §7): one per motor for motor
    /// registers, one for a global register, 32 words for a RAM half.
    pub addresses: Vec<u32>,
    pub fields: Vec<Field>,
    /// The value read after power-on (motor 0 for motor registers).
    pub reset: u32,
    /// Side effects of a write or read.
    pub effect: &'static str,
    /// Where the datasheets describe it.
    pub section: &'static str,
}

#[pymethods]
impl Register {
    fn __repr__(&self) -> String {
        format!("Register('{}', {}, addresses={:?})", self.name, self.space, self.addresses)
    }
}

/// The registers of a variant ("tmc428", "tmc429", "tmc4210") in the order of the map.
#[pyfunction]
#[pyo3(signature = (variant = "tmc429"))]
fn registers(variant: &str) -> PyResult<Vec<Register>> {
    let chip = crate::variant(variant)?;
    let motors = if chip == tmc429_model::Chip::Tmc4210 { 1 } else { 3 };
    Ok(regmap::REGISTERS
        .iter()
        .filter(|r| r.chips.contains(chip))
        .map(|r| {
            let (space, addresses) = match r.space {
                Space::Motor => ("motor", (0..motors).map(|m| r.a7(m) as u32).collect()),
                Space::Global => ("global", vec![r.a7(0) as u32]),
                Space::Ram => ("ram", (0..32).map(|w| (r.a7(0) + w) as u32).collect()),
            };
            let fields = r
                .fields
                .iter()
                .map(|f| Field { name: f.name, lsb: f.lsb, width: f.width, signed: f.signed, access: f.access.as_str(), doc: f.doc })
                .collect();
            Register { name: r.name, space, addresses, fields, reset: r.reset, effect: r.effect, section: r.section }
        })
        .collect())
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(registers, m)?)?;
    m.add_class::<Register>()?;
    m.add_class::<Field>()?;
    Ok(())
}
