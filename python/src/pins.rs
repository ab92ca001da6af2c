//! The pins and the probe bundle as Python classes (`tmc429.Inputs`, `Outputs`, `Probes`):
//! the fields of `tmc429_model::{Inputs, Outputs, Probes}` under the same names, and the pins
//! packed into one word per direction (`tmc429_verif::pinword`).

use pyo3::prelude::*;
use pyo3::types::PyDict;

use tmc429_model as model;
use tmc429_model::motor_regs::sext24;
use tmc429_verif::pinword;

/// The input pins before a CLK edge (TMC429 §1.5 names; the TMC4210 uses REF1 as REF_L, REF2
/// as GP_IN, REF3 as REF_R). The default is the idle bus: nSCS_C and SCK_C high, switches open,
/// the REFR inputs pulled up.
#[pyclass(module = "tmc429", get_all, set_all, eq, from_py_object)]
#[derive(Clone, Copy, PartialEq, Eq)]
pub struct Inputs {
    pub nscs_c: bool,
    pub sck_c: bool,
    pub sdi_c: bool,
    pub sdi_s: bool,
    pub ref1: bool,
    pub ref2: bool,
    pub ref3: bool,
    pub refr1: bool,
    pub refr2: bool,
    pub refr3: bool,
}

impl From<model::Inputs> for Inputs {
    fn from(i: model::Inputs) -> Self {
        let model::Inputs { nscs_c, sck_c, sdi_c, sdi_s, ref1, ref2, ref3, refr1, refr2, refr3 } = i;
        Inputs { nscs_c, sck_c, sdi_c, sdi_s, ref1, ref2, ref3, refr1, refr2, refr3 }
    }
}

impl From<Inputs> for model::Inputs {
    fn from(i: Inputs) -> Self {
        let Inputs { nscs_c, sck_c, sdi_c, sdi_s, ref1, ref2, ref3, refr1, refr2, refr3 } = i;
        model::Inputs { nscs_c, sck_c, sdi_c, sdi_s, ref1, ref2, ref3, refr1, refr2, refr3 }
    }
}

#[pymethods]
impl Inputs {
    /// Pins given by name; the others at their idle levels.
    #[new]
    #[pyo3(signature = (**pins))]
    fn new(pins: Option<&Bound<'_, PyDict>>) -> PyResult<Self> {
        let mut w = pinword::pack_inputs(&model::Inputs::default());
        for (k, v) in pins.into_iter().flatten() {
            let name: String = k.extract()?;
            let bit = pinword::INPUT_NAMES.iter().position(|n| *n == name).ok_or_else(|| {
                pyo3::exceptions::PyTypeError::new_err(format!(
                    "Inputs: unknown pin '{name}': expected one of {}",
                    pinword::INPUT_NAMES.join(", ")
                ))
            })?;
            let level: bool = v.extract()?;
            w = (w & !(1 << bit)) | (level as u32) << bit;
        }
        Ok(pinword::unpack_inputs(w).into())
    }

    /// The pins of a word: bit k is `INPUT_PINS[k]`.
    #[staticmethod]
    fn from_word(word: u32) -> Self {
        pinword::unpack_inputs(word).into()
    }

    /// The pins as a word: bit k is `INPUT_PINS[k]`.
    #[getter]
    fn word(&self) -> u32 {
        pinword::pack_inputs(&(*self).into())
    }

    fn __repr__(&self) -> String {
        let bits = pinword::input_bits(&(*self).into());
        let f: Vec<String> = pinword::INPUT_NAMES.iter().zip(bits).map(|(n, b)| format!("{n}={}", b as u8)).collect();
        format!("Inputs({})", f.join(", "))
    }
}

/// The output pins after a CLK edge. In Step/Dir mode (TMC429 `en_sd` = 1, TMC4210) the
/// driver-chain pins carry STEP/DIR (TMC429 §10).
#[pyclass(module = "tmc429", get_all, frozen, eq, from_py_object)]
#[derive(Clone, Copy, PartialEq, Eq)]
pub struct Outputs {
    pub nint_sdo_c: bool,
    pub sdoz_c: bool,
    pub sdoz_c_oe: bool,
    pub nscs_s: bool,
    pub sck_s: bool,
    pub sdo_s: bool,
    pub sdi_s_o: bool,
    pub sdi_s_oe: bool,
    pub nscs2: bool,
    pub nscs3: bool,
    pub poscmp: bool,
}

impl From<model::Outputs> for Outputs {
    fn from(o: model::Outputs) -> Self {
        let model::Outputs { nint_sdo_c, sdoz_c, sdoz_c_oe, nscs_s, sck_s, sdo_s, sdi_s_o, sdi_s_oe, nscs2, nscs3, poscmp } = o;
        Outputs { nint_sdo_c, sdoz_c, sdoz_c_oe, nscs_s, sck_s, sdo_s, sdi_s_o, sdi_s_oe, nscs2, nscs3, poscmp }
    }
}

impl From<Outputs> for model::Outputs {
    fn from(o: Outputs) -> Self {
        let Outputs { nint_sdo_c, sdoz_c, sdoz_c_oe, nscs_s, sck_s, sdo_s, sdi_s_o, sdi_s_oe, nscs2, nscs3, poscmp } = o;
        model::Outputs { nint_sdo_c, sdoz_c, sdoz_c_oe, nscs_s, sck_s, sdo_s, sdi_s_o, sdi_s_oe, nscs2, nscs3, poscmp }
    }
}

#[pymethods]
impl Outputs {
    /// The pins of a word: bit k is `OUTPUT_PINS[k]`.
    #[staticmethod]
    fn from_word(word: u32) -> Self {
        pinword::unpack_outputs(word).into()
    }

    /// The pins as a word: bit k is `OUTPUT_PINS[k]`.
    #[getter]
    fn word(&self) -> u32 {
        pinword::pack_outputs(&(*self).into())
    }

    fn __repr__(&self) -> String {
        let w = self.word();
        let f: Vec<String> = pinword::output_names().iter().enumerate().map(|(k, n)| format!("{n}={}", (w >> k) & 1)).collect();
        format!("Outputs({})", f.join(", "))
    }
}

/// Internal state of one motor (the probe bundle the co-simulation compares).
#[pyclass(module = "tmc429", get_all, frozen, from_py_object)]
#[derive(Clone, Copy)]
pub struct MotorProbe {
    /// x_target, sign-extended from 24 bits.
    pub x_target: i32,
    /// x_actual, sign-extended from 24 bits.
    pub x_actual: i32,
    /// Internal velocity: sign, 11 integer and 8 fraction bits (TMC428 §8.6).
    pub v_internal: i32,
    pub v_target: i32,
    pub a_actual: i32,
    /// Full-wave microstep index 0..255.
    pub ustep: u32,
    /// 1 in the cycle the motor made a step.
    pub step: bool,
    /// Direction of the last step: True = negative.
    pub dir: bool,
    pub pulse_acc: u16,
}

/// Driver-chain state (SPI master, Step/Dir).
#[pyclass(module = "tmc429", get_all, frozen, from_py_object)]
#[derive(Clone, Copy)]
pub struct ChainProbe {
    pub state: u8,
    pub cell: u8,
    pub motor: u8,
    pub bit_count: u8,
    pub pending: bool,
    pub cover_waiting: bool,
    pub readback: u64,
}

/// Everything the co-simulation compares besides the pins.
#[pyclass(module = "tmc429", get_all, frozen)]
pub struct Probes {
    pub motor: Vec<MotorProbe>,
    pub chain: ChainProbe,
    /// The pre-divider counter (C40).
    pub prescaler: u32,
    pub power_down: bool,
    /// The status byte as it would be sent now (C10).
    pub status: u8,
}

impl From<model::Probes> for Probes {
    fn from(p: model::Probes) -> Self {
        let motor = p
            .motor
            .iter()
            .map(|m| MotorProbe {
                x_target: sext24(m.x_target),
                x_actual: sext24(m.x_actual),
                v_internal: m.v_internal,
                v_target: m.v_target,
                a_actual: m.a_actual,
                ustep: m.ustep,
                step: m.step != 0,
                dir: m.dir != 0,
                pulse_acc: m.pulse_acc,
            })
            .collect();
        let c = &p.chain;
        let chain = ChainProbe {
            state: c.state,
            cell: c.cell,
            motor: c.motor,
            bit_count: c.bit_count,
            pending: c.pending != 0,
            cover_waiting: c.cover_waiting != 0,
            readback: c.readback,
        };
        Probes { motor, chain, prescaler: p.prescaler, power_down: p.power_down != 0, status: p.status }
    }
}

/// `Inputs` from an `Inputs` or a word.
pub fn inputs_arg(v: &Bound<'_, PyAny>) -> PyResult<model::Inputs> {
    if let Ok(i) = v.extract::<Inputs>() {
        return Ok(i.into());
    }
    match v.extract::<u32>() {
        Ok(w) if w < 1 << pinword::INPUT_NAMES.len() => Ok(pinword::unpack_inputs(w)),
        _ => Err(pyo3::exceptions::PyTypeError::new_err("expected tmc429.Inputs or an input word 0..1023 (bit k = INPUT_PINS[k])")),
    }
}
