//! `tmc429.Host`: the virtual µC wired to a chip — register writes and reads by register and
//! field name over the SPI pins (TMC428 §6.2), switch inputs, and waits.

use pyo3::exceptions::{PyTimeoutError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use tmc429_model::host::Host as ModelHost;
use tmc429_scenario::run::Shadow;

use crate::pins::{Inputs, Outputs, Probes};
use crate::regs;

/// The virtual µC and its chip. Writes and reads are whole SPI frames on the chip's pins, at
/// `sck_half` CLK cycles per SCK_C half period; a write of some fields keeps the other fields
/// as last written (power-on values at first) and writes 0 to write-1-to-clear flags, as a
/// scenario file does (docs/scenarios.md).
#[pyclass(module = "tmc429", unsendable)]
pub struct Host {
    host: ModelHost,
    shadow: Shadow,
    fclk: u64,
}

impl Host {
    /// CLK cycles of `seconds` of chip time.
    fn cycles_of(&self, seconds: f64) -> PyResult<u64> {
        if !(seconds >= 0.0 && seconds.is_finite()) {
            return Err(PyValueError::new_err(format!("{seconds} s: expected a time of 0 s or more")));
        }
        Ok((seconds * self.fclk as f64).round() as u64)
    }

    /// Ticks until `done` holds after an edge, at most `timeout` seconds; the cycles waited.
    fn wait_while(&mut self, timeout: f64, what: &str, mut done: impl FnMut(&tmc429_model::Tmc429) -> bool) -> PyResult<u64> {
        let limit = self.cycles_of(timeout)?;
        let start = self.host.cycle();
        while !done(self.host.chip()) {
            if self.host.cycle() - start >= limit {
                return Err(PyTimeoutError::new_err(format!("{what} not within {timeout} s ({limit} CLK cycles)")));
            }
            self.host.wait(1);
        }
        Ok(self.host.cycle() - start)
    }
}

#[pymethods]
impl Host {
    /// A µC with a chip in its power-on state. `variant`: "tmc428", "tmc429" or "tmc4210";
    /// `fclk`: CLK in Hz (default and maximum: 16 MHz TMC428, 32 MHz otherwise); `sck_half`:
    /// SCK_C half period in CLK cycles (at least 3, TMC428 Table 6-1).
    #[new]
    #[pyo3(signature = (variant = "tmc429", fclk = None, sck_half = 4))]
    fn new(variant: &str, fclk: Option<u64>, sck_half: u32) -> PyResult<Self> {
        let v = crate::variant(variant)?;
        let fclk = crate::fclk(v, fclk)?;
        let mut host = ModelHost::new(v);
        host.set_sck_half(sck_half).map_err(|e| PyValueError::new_err(e.0))?;
        Ok(Host { host, shadow: Shadow::new(v), fclk })
    }

    /// Writes a register or field by name in one SPI datagram: `write("x_target", -300,
    /// motor=0)`, `write("ref_conf_rm", motor=0, rm=2, soft_stop=1)`, `write("en_sd", 1)`,
    /// `write("ram_driver_config", 0x0504, word=3)`. Returns the status byte the chip sent.
    #[pyo3(signature = (name, value = None, *, motor = None, word = None, **fields))]
    fn write(
        &mut self,
        name: &str,
        value: Option<i64>,
        motor: Option<u8>,
        word: Option<u8>,
        fields: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<u8> {
        let t = regs::resolve(self.host.chip().chip(), name, motor, word)?;
        let w = regs::write_of(&t, value, fields)?;
        let data = self.shadow.resolve(&w);
        Ok(self.host.write(t.a7, data))
    }

    /// Reads a register or field by name in one SPI datagram: a field (or a register of one
    /// field, such as x_actual) sign-extended if it is signed, else the 24-bit data word.
    #[pyo3(signature = (name, *, motor = None, word = None))]
    fn read(&mut self, name: &str, motor: Option<u8>, word: Option<u8>) -> PyResult<i64> {
        let t = regs::resolve(self.host.chip().chip(), name, motor, word)?;
        Ok(regs::value_of(&t, self.host.read(t.a7)))
    }

    /// Reads a register in one SPI datagram; its fields by name.
    #[pyo3(signature = (register, *, motor = None, word = None))]
    fn read_fields<'py>(&mut self, py: Python<'py>, register: &str, motor: Option<u8>, word: Option<u8>) -> PyResult<Bound<'py, PyDict>> {
        let t = regs::resolve(self.host.chip().chip(), register, motor, word)?;
        let data = self.host.read(t.a7);
        regs::fields_of(py, t.reg, data)
    }

    /// What a read would return now, without an SPI frame (no side effects, no time passes).
    #[pyo3(signature = (name, *, motor = None, word = None))]
    fn peek(&self, name: &str, motor: Option<u8>, word: Option<u8>) -> PyResult<i64> {
        regs::peek(self.host.chip(), name, motor, word)
    }

    /// A 32-bit datagram `A7 << 25 | RW << 24 | DATA` (TMC428 §6.2); the 32-bit reply.
    fn datagram(&mut self, datagram: u32) -> u32 {
        self.host.datagram(datagram)
    }

    /// A frame of `nbits` (1..32) bits, MSB first; the bits received. Only 32 bits execute (C12).
    fn frame(&mut self, value: u32, nbits: u32) -> PyResult<u32> {
        if !(1..=32).contains(&nbits) {
            return Err(PyValueError::new_err(format!("nbits={nbits}: expected 1..32")));
        }
        Ok(self.host.frame(value, nbits))
    }

    /// The status byte by an 8-bit frame, as vendor drivers read it.
    fn status(&mut self) -> u8 {
        self.host.status()
    }

    /// Sets input pins by name from the next edge on: ref1..ref3, refr1..refr3, sdi_s.
    #[pyo3(signature = (**levels))]
    fn set_pins(&mut self, levels: Option<&Bound<'_, PyDict>>) -> PyResult<()> {
        for (k, v) in levels.into_iter().flatten() {
            let name: String = k.extract()?;
            let level: bool = v.extract()?;
            let p = self.host.pins_mut();
            let pin = match name.as_str() {
                "ref1" => &mut p.ref1,
                "ref2" => &mut p.ref2,
                "ref3" => &mut p.ref3,
                "refr1" => &mut p.refr1,
                "refr2" => &mut p.refr2,
                "refr3" => &mut p.refr3,
                "sdi_s" => &mut p.sdi_s,
                _ => {
                    return Err(PyValueError::new_err(format!(
                        "set_pins: '{name}' is not a pin the µC leaves to you: expected ref1, ref2, ref3, refr1, refr2, refr3 or sdi_s"
                    )))
                }
            };
            *pin = level;
        }
        Ok(())
    }

    /// Lets time pass with the pins as they are: `cycles` CLK edges or `seconds` of chip time.
    /// Returns the cycles waited.
    #[pyo3(signature = (cycles = None, *, seconds = None))]
    fn wait(&mut self, cycles: Option<u64>, seconds: Option<f64>) -> PyResult<u64> {
        let n = match (cycles, seconds) {
            (Some(c), None) => c,
            (None, Some(s)) => self.cycles_of(s)?,
            _ => return Err(PyValueError::new_err("wait: give cycles or seconds")),
        };
        self.host.wait(n);
        Ok(n)
    }

    /// Waits until motor `motor` stands on its target (x_actual = x_target, velocity 0), at most
    /// `timeout` seconds of chip time (TimeoutError then). Returns the cycles waited.
    #[pyo3(signature = (motor, *, timeout = 1.0))]
    fn wait_for_target(&mut self, motor: u8, timeout: f64) -> PyResult<u64> {
        let n = self.host.chip().motor_count() as u8;
        if motor >= n {
            return Err(PyValueError::new_err(format!("motor={motor}: the {} has motors 0..{}", self.host.chip().chip(), n - 1)));
        }
        let m = motor as usize;
        self.wait_while(timeout, &format!("motor {motor} at its target"), |c| {
            let mo = c.motor(m);
            mo.x_actual == mo.x_target && mo.v == 0
        })
    }

    /// Waits until INT is active (an unmasked interrupt flag is set, C64), at most `timeout`
    /// seconds of chip time. Returns the cycles waited.
    #[pyo3(signature = (*, timeout = 1.0))]
    fn wait_for_interrupt(&mut self, timeout: f64) -> PyResult<u64> {
        self.wait_while(timeout, "INT active", |c| c.int())
    }

    /// Waits until `predicate(probes)` is true after an edge, checking every `every` cycles, at
    /// most `timeout` seconds of chip time. Returns the cycles waited.
    #[pyo3(signature = (predicate, *, timeout = 1.0, every = 1))]
    fn wait_until(&mut self, py: Python<'_>, predicate: Py<PyAny>, timeout: f64, every: u64) -> PyResult<u64> {
        let limit = self.cycles_of(timeout)?;
        let start = self.host.cycle();
        loop {
            let p: Probes = self.host.chip().probes().into();
            if predicate.call1(py, (p,))?.is_truthy(py)? {
                return Ok(self.host.cycle() - start);
            }
            if self.host.cycle() - start >= limit {
                return Err(PyTimeoutError::new_err(format!("wait_until: not within {timeout} s ({limit} CLK cycles)")));
            }
            self.host.wait(every.max(1));
        }
    }

    /// SCK_C half period in CLK cycles (at least 3, TMC428 Table 6-1).
    #[getter]
    fn get_sck_half(&self) -> u32 {
        self.host.sck_half()
    }

    #[setter]
    fn set_sck_half(&mut self, half: u32) -> PyResult<()> {
        self.host.set_sck_half(half).map_err(|e| PyValueError::new_err(e.0))
    }

    #[getter]
    fn variant(&self) -> &'static str {
        self.host.chip().chip().name()
    }

    #[getter]
    fn fclk(&self) -> u64 {
        self.fclk
    }

    /// CLK edges since power-on.
    #[getter]
    fn cycle(&self) -> u64 {
        self.host.cycle()
    }

    /// Chip time since power-on in seconds.
    #[getter]
    fn seconds(&self) -> f64 {
        self.host.cycle() as f64 / self.fclk as f64
    }

    /// The input pins as applied now.
    #[getter]
    fn pins(&self) -> Inputs {
        self.host.pins().into()
    }

    /// The output pins after the last edge.
    #[getter]
    fn outputs(&self) -> Outputs {
        self.host.outputs().into()
    }

    /// The chip's internal state now.
    #[getter]
    fn probes(&self) -> Probes {
        self.host.chip().probes().into()
    }

    fn __repr__(&self) -> String {
        format!("Host('{}', fclk={}, cycle={})", self.variant(), self.fclk, self.host.cycle())
    }
}
