//! The chip's pins (`tmc429_top`), line by line and in the tester forms.

use tmc429_model::{Inputs, Outputs, Tmc429};

use super::super::files::AtomicFile;
use super::super::pins::{input, output, Layout, Meta, PinWriter};
use super::Recorder;

/// Output pins the reference RTL does not drive: none, the RTL is complete (docs/rtl.md)
/// and chip-level vectors compare every pin. A pin listed here would be recorded and left out
/// of the `.meta` mask (`not_compared`).
pub const RTL_PENDING_PINS: &[&str] = &[];

/// The pins of `tmc429_top` (rtl/tmc429_top.v), inputs then outputs.
pub fn chip_layout() -> Layout {
    Layout::new(vec![
        input("rst", 1),
        input("nscs_c", 1),
        input("sck_c", 1),
        input("sdi_c", 1),
        input("sdi_s", 1),
        input("ref1", 1),
        input("ref2", 1),
        input("ref3", 1),
        input("refr1", 1),
        input("refr2", 1),
        input("refr3", 1),
        output("nint_sdo_c", 1),
        output("sdoz_c", 1),
        output("sdoz_c_oe", 1),
        output("nscs_s", 1),
        output("sck_s", 1),
        output("sdo_s", 1),
        output("sdi_s_o", 1),
        output("sdi_s_oe", 1),
        output("nscs2", 1),
        output("nscs3", 1),
        output("poscmp", 1),
    ])
    .without(RTL_PENDING_PINS)
}

/// One line of [`chip_layout`] values.
fn pin_values(rst: bool, i: &Inputs, o: &Outputs) -> [u64; 22] {
    [
        rst,
        i.nscs_c,
        i.sck_c,
        i.sdi_c,
        i.sdi_s,
        i.ref1,
        i.ref2,
        i.ref3,
        i.refr1,
        i.refr2,
        i.refr3,
        o.nint_sdo_c,
        o.sdoz_c,
        o.sdoz_c_oe,
        o.nscs_s,
        o.sck_s,
        o.sdo_s,
        o.sdi_s_o,
        o.sdi_s_oe,
        o.nscs2,
        o.nscs3,
        o.poscmp,
    ]
    .map(|b| b as u64)
}

pub struct ChipPins {
    w: PinWriter,
}

impl ChipPins {
    pub fn create(stem: &std::path::Path) -> Result<ChipPins, String> {
        Ok(ChipPins { w: PinWriter::create(stem, chip_layout())? })
    }
}

impl Recorder for ChipPins {
    fn reset(&mut self, chip: &Tmc429) -> Result<(), String> {
        self.w.line(&pin_values(true, &Inputs::default(), &chip.outputs()))
    }
    #[inline]
    fn edge(&mut self, _chip: &Tmc429, inp: &Inputs, out: &Outputs) -> Result<(), String> {
        self.w.line(&pin_values(false, inp, out))
    }
    fn finish(self: Box<Self>, meta: &Meta) -> Result<Vec<AtomicFile>, String> {
        self.w.finish(meta.clone())
    }
}

/// A writer of the chip's pins in one of the tester forms (STIL, EVCD, pin VCD), line by line.
pub trait PinForm {
    /// One line of [`chip_layout`] values.
    fn line(&mut self, v: &[u64; 22]) -> Result<(), String>;
    /// Ends the file; it is returned not yet committed.
    fn close(self) -> Result<AtomicFile, String>;
}

/// The chip's pins at every edge, written by a [`PinForm`].
pub struct ChipForm<W>(pub W);

impl<W: PinForm> Recorder for ChipForm<W> {
    fn reset(&mut self, chip: &Tmc429) -> Result<(), String> {
        self.0.line(&pin_values(true, &Inputs::default(), &chip.outputs()))
    }
    #[inline]
    fn edge(&mut self, _chip: &Tmc429, inp: &Inputs, out: &Outputs) -> Result<(), String> {
        self.0.line(&pin_values(false, inp, out))
    }
    fn finish(self: Box<Self>, _meta: &Meta) -> Result<Vec<AtomicFile>, String> {
        Ok(vec![self.0.close()?])
    }
}
