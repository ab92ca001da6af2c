//! Registers and fields by name, from the one register map (`tmc429_model::regmap`): the
//! address a name means for a motor or RAM word, the data word of a write of fields, and the
//! fields of a word. Shared by `Chip.peek` and the virtual µC (`Host`).

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use tmc429_model::regmap::{self, Field, Register, Space};
use tmc429_model::Chip;
use tmc429_scenario::scenario::{field_range, writable, Write, WriteData};

/// A register (or one of its fields) at one address.
#[derive(Clone, Copy)]
pub struct Target {
    pub reg: &'static Register,
    pub field: Option<&'static Field>,
    pub a7: u8,
    pub motor: Option<u8>,
}

fn err<T>(msg: String) -> PyResult<T> {
    Err(PyValueError::new_err(msg))
}

fn motors(chip: Chip) -> u8 {
    if chip == Chip::Tmc4210 {
        1
    } else {
        3
    }
}

/// The register or field `name` on `chip`, for `motor` (motor registers, 0..2) or RAM `word`
/// (0..31 of the half the register names).
pub fn resolve(chip: Chip, name: &str, motor: Option<u8>, word: Option<u8>) -> PyResult<Target> {
    let on_chip = || regmap::REGISTERS.iter().filter(|r| r.chips.contains(chip));
    let found = match on_chip().find(|r| r.name.eq_ignore_ascii_case(name)) {
        // A register of one field of its own name (x_actual) reads as that field: signed.
        Some(r) => Some((r, r.field(name).filter(|_| r.fields.len() == 1))),
        None => on_chip().find_map(|r| r.field(name).map(|f| (r, Some(f)))),
    };
    let Some((reg, field)) = found else {
        if regmap::REGISTERS.iter().any(|r| r.name.eq_ignore_ascii_case(name) || r.field(name).is_some()) {
            return err(format!("'{name}' does not exist on the {chip}"));
        }
        let names: Vec<&str> = on_chip().map(|r| r.name).collect();
        return err(format!("unknown register or field '{name}': expected one of {} or one of their fields", names.join(", ")));
    };
    let a7 = match reg.space {
        Space::Motor => {
            let Some(m) = motor else {
                return err(format!("'{name}' is a motor register or field: give motor=0..{}", motors(chip) - 1));
            };
            if m >= motors(chip) {
                return err(format!("motor={m}: the {chip} has motors 0..{}", motors(chip) - 1));
            }
            reg.a7(m)
        }
        Space::Global if motor.is_some() => return err(format!("'{name}' is a global register or field: leave motor out")),
        Space::Global => reg.a7(0),
        Space::Ram => {
            let Some(w) = word else { return err(format!("'{name}' is a RAM register: give word=0..31")) };
            if w > 31 {
                return err(format!("word={w}: a RAM half has words 0..31"));
            }
            reg.a7(0) + w
        }
    };
    if reg.space != Space::Ram && word.is_some() {
        return err(format!("word= is for the RAM registers, not '{name}'"));
    }
    Ok(Target { reg, field, a7, motor })
}

/// The raw bits of `value` for field `f` of `reg`, checked against its range.
pub fn field_bits(reg: &Register, f: &Field, value: i64) -> PyResult<u32> {
    let (lo, hi) = field_range(f);
    if !(lo..=hi).contains(&value) {
        let signed = if f.signed { ", signed" } else { "" };
        return err(format!("{}.{} = {value} out of range: expected {lo}..{hi} ({} bits{signed})", reg.name, f.name, f.width));
    }
    Ok((value as u32) & (((1u64 << f.width) - 1) as u32))
}

/// The write a name, a whole value or named fields mean: `write("x_target", 1000, motor=0)`,
/// `write("ref_conf_rm", motor=0, rm=2)`, `write("rm", 2, motor=0)`.
pub fn write_of(t: &Target, value: Option<i64>, fields: Option<&Bound<'_, PyDict>>) -> PyResult<Write> {
    let reg = t.reg;
    if !writable(reg) {
        return err(format!("{} is read-only", reg.name));
    }
    let named: Vec<(String, i64)> = match fields {
        Some(d) => d.iter().map(|(k, v)| Ok((k.extract::<String>()?, v.extract::<i64>()?))).collect::<PyResult<_>>()?,
        None => Vec::new(),
    };
    let data = match (t.field, value, named.is_empty()) {
        (Some(f), Some(v), true) => WriteData::Fields(vec![(*f, field_bits(reg, f, v)?)]),
        (None, Some(v), true) => {
            if !(-(1i64 << 23)..1 << 24).contains(&v) {
                return err(format!("{} = {v} out of range: a data word has 24 bits", reg.name));
            }
            WriteData::Whole((v as u32) & 0xFF_FFFF)
        }
        (None, None, false) => {
            let mut fs = Vec::new();
            for (k, v) in named {
                let Some(f) = reg.field(&k) else {
                    let names: Vec<&str> = reg.fields.iter().map(|f| f.name).collect();
                    return err(format!("{} has no field '{k}': expected one of {}", reg.name, names.join(", ")));
                };
                fs.push((*f, field_bits(reg, f, v)?));
            }
            WriteData::Fields(fs)
        }
        (Some(f), _, _) => return err(format!("{}.{}: give exactly one value", reg.name, f.name)),
        (None, Some(_), false) => return err(format!("{}: give a value or fields, not both", reg.name)),
        (None, None, true) => return err(format!("{}: give a value or fields", reg.name)),
    };
    Ok(Write { a7: t.a7, reg, motor: t.motor, data, line: 0 })
}

/// The value of a target in a data word: the field's (sign-extended) or the whole word.
pub fn value_of(t: &Target, data: u32) -> i64 {
    match t.field {
        Some(f) => f.value(data),
        None => data as i64,
    }
}

/// What a µC read of a register or field would return now (no side effects).
pub fn peek(chip: &tmc429_model::Tmc429, name: &str, motor: Option<u8>, word: Option<u8>) -> PyResult<i64> {
    let t = resolve(chip.chip(), name, motor, word)?;
    Ok(value_of(&t, chip.read_register(t.a7)))
}

/// The fields of a data word by name, signed fields sign-extended.
pub fn fields_of<'py>(py: Python<'py>, reg: &Register, data: u32) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    for f in reg.fields {
        d.set_item(f.name, f.value(data))?;
    }
    Ok(d)
}
