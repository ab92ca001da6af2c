//! Recorders: what one unit's boundary shows at every CLK edge, written as pin-level lines or
//! as transaction-level CSV rows.
//!
//! Cycle numbering (all forms): line 0 of a `.hex` file is the reset edge (`rst` = 1); line k
//! (k ≥ 1) is the k-th CLK edge after reset, the model's `Tmc429::cycle()` after that edge. The
//! CSV `cycle` columns use the same numbers.

mod chain;
mod chip;
mod ramp;
mod spi;

pub use chain::{chain_csv_header, chain_layout, decode_signals, ChainCsv, ChainPins};
pub use chip::{chip_layout, ChipForm, ChipPins, PinForm, RTL_PENDING_PINS};
pub use ramp::{ramp_layout, ramp_values, RampCsv, RampPins, RAMP_CSV_HEADER};
pub use spi::{spi_layout, SpiCsv, SpiPins, SPI_CSV_HEADER};

use super::files::AtomicFile;
use super::pins::Meta;
use tmc429_model::{Inputs, Outputs, Tmc429};

/// One unit boundary in one form.
pub trait Recorder {
    /// The reset edge: `chip` is the power-on state after it.
    fn reset(&mut self, chip: &Tmc429) -> Result<(), String>;
    /// One CLK edge with the pins `inp`; `chip` and `out` are the state and pins after it.
    fn edge(&mut self, chip: &Tmc429, inp: &Inputs, out: &Outputs) -> Result<(), String>;
    /// The finished files, not yet committed.
    fn finish(self: Box<Self>, meta: &Meta) -> Result<Vec<AtomicFile>, String>;
}

/// A CSV file with a header line.
pub struct Csv {
    f: AtomicFile,
    row: String,
}

impl Csv {
    pub fn create(path: &std::path::Path, header: &str) -> Result<Csv, String> {
        let mut f = AtomicFile::create(path)?;
        f.write_all(header.as_bytes())?;
        f.write_all(b"\n")?;
        Ok(Csv { f, row: String::new() })
    }
    /// Appends a field (quoted when it holds a comma or a quote).
    pub fn field(&mut self, v: impl std::fmt::Display) -> &mut Self {
        if !self.row.is_empty() {
            self.row.push(',');
        }
        let s = v.to_string();
        if s.contains(',') || s.contains('"') {
            self.row.push('"');
            self.row.push_str(&s.replace('"', "\"\""));
            self.row.push('"');
        } else {
            self.row.push_str(&s);
        }
        self
    }
    pub fn end_row(&mut self) -> Result<(), String> {
        self.row.push('\n');
        let r = self.f.write_all(self.row.as_bytes());
        self.row.clear();
        r
    }
    pub fn finish(self) -> AtomicFile {
        self.f
    }
}
