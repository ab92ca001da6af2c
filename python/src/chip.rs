//! `tmc429.Chip`: the golden model at pin level, one call per CLK edge.

use pyo3::prelude::*;
use pyo3::types::PyDict;

use tmc429_model::{Inputs, Tmc429};
use tmc429_verif::pinword;

use crate::pins::{inputs_arg, Outputs, Probes};
use crate::regs;

/// The chip at pin level: `tick(inputs)` is one rising CLK edge (contract C1): the inputs are
/// the pin levels just before it, the outputs the levels just after it.
#[pyclass(module = "tmc429", unsendable)]
pub struct Chip {
    model: Tmc429,
    fclk: u64,
    last: Inputs,
}

#[pymethods]
impl Chip {
    /// A chip in its power-on state. `variant`: "tmc428", "tmc429" or "tmc4210"; `fclk`: the CLK
    /// frequency in Hz (default and maximum: 16 MHz TMC428, 32 MHz otherwise), for `seconds`.
    #[new]
    #[pyo3(signature = (variant = "tmc429", fclk = None))]
    fn new(variant: &str, fclk: Option<u64>) -> PyResult<Self> {
        let v = crate::variant(variant)?;
        let fclk = crate::fclk(v, fclk)?;
        Ok(Chip { model: Tmc429::new(v), fclk, last: Inputs::default() })
    }

    /// One rising CLK edge with these input pins (`Inputs` or an input word); the outputs after it.
    fn tick(&mut self, inputs: &Bound<'_, PyAny>) -> PyResult<Outputs> {
        self.last = inputs_arg(inputs)?;
        Ok(self.model.tick(&self.last).into())
    }

    /// One edge with the input word `word` (bit k = `INPUT_PINS[k]`); the output word after it
    /// (bit k = `OUTPUT_PINS[k]`). The fast form of `tick`.
    fn tick_word(&mut self, word: u32) -> u32 {
        self.last = pinword::unpack_inputs(word);
        pinword::pack_outputs(&self.model.tick(&self.last))
    }

    /// `cycles` edges with the same input pins (default: the last ones); the outputs after the last.
    #[pyo3(signature = (cycles, inputs = None))]
    fn run(&mut self, cycles: u64, inputs: Option<&Bound<'_, PyAny>>) -> PyResult<Outputs> {
        if let Some(i) = inputs {
            self.last = inputs_arg(i)?;
        }
        for _ in 0..cycles {
            self.model.tick(&self.last);
        }
        Ok(self.model.outputs().into())
    }

    /// Back to the power-on state (the RTL's synchronous reset): registers, RAM, pins, cycle 0.
    fn reset(&mut self) {
        self.model.reset();
        self.last = Inputs::default();
    }

    /// "tmc428", "tmc429" or "tmc4210".
    #[getter]
    fn variant(&self) -> &'static str {
        self.model.chip().name()
    }

    /// The CLK frequency in Hz.
    #[getter]
    fn fclk(&self) -> u64 {
        self.fclk
    }

    /// CLK edges since power-on or reset.
    #[getter]
    fn cycle(&self) -> u64 {
        self.model.cycle()
    }

    /// Time since power-on or reset in seconds (cycle / fclk).
    #[getter]
    fn seconds(&self) -> f64 {
        self.model.cycle() as f64 / self.fclk as f64
    }

    /// The output pins after the last edge.
    #[getter]
    fn outputs(&self) -> Outputs {
        self.model.outputs().into()
    }

    /// The internal state the co-simulation compares (motors, driver chain, status byte).
    #[getter]
    fn probes(&self) -> Probes {
        self.model.probes().into()
    }

    /// The status byte `INT CDGW RS3 xEQt3 RS2 xEQt2 RS1 xEQt1` of the current state (C10).
    #[getter]
    fn status(&self) -> u8 {
        self.model.status()
    }

    /// The value a µC read of a register or field would return now, without an SPI frame
    /// (no side effects): `peek("x_actual", motor=0)`, `peek("rm", motor=1)`,
    /// `peek("ram_microstep_table", word=3)`. A field reads sign-extended if it is signed; a
    /// register reads as its 24-bit data word.
    #[pyo3(signature = (name, *, motor = None, word = None))]
    fn peek(&self, name: &str, motor: Option<u8>, word: Option<u8>) -> PyResult<i64> {
        regs::peek(&self.model, name, motor, word)
    }

    /// The fields of a register by name, as a µC read would return them now (no side effects).
    #[pyo3(signature = (register, *, motor = None, word = None))]
    fn peek_fields<'py>(&self, py: Python<'py>, register: &str, motor: Option<u8>, word: Option<u8>) -> PyResult<Bound<'py, PyDict>> {
        let t = regs::resolve(self.model.chip(), register, motor, word)?;
        regs::fields_of(py, t.reg, self.model.read_register(t.a7))
    }

    fn __repr__(&self) -> String {
        format!("Chip('{}', fclk={}, cycle={})", self.variant(), self.fclk, self.model.cycle())
    }
}
