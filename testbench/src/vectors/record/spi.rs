//! The µC SPI slave's boundary (`tmc429_spi_slave`): its pins and spi.csv.

use tmc429_model::regmap::{self, Addr};
use tmc429_model::{script, Chip, Inputs, Outputs, Tmc429};

use super::super::files::AtomicFile;
use super::super::pins::{input, output, Layout, Meta, PinWriter};
use super::{Csv, Recorder};

/// The ports of `tmc429_spi_slave` (rtl/tmc429_spi_slave.v), inputs then outputs.
pub fn spi_layout() -> Layout {
    Layout::new(vec![
        input("rst", 1),
        input("nscs_c", 1),
        input("sck_c", 1),
        input("sdi_c", 1),
        input("status", 8),
        input("rd_data", 24),
        input("rd_round", 1),
        output("rd_addr", 7),
        output("frame_start", 1),
        output("exec", 1),
        output("cmd", 32),
        output("active", 1),
        output("sdo", 1),
    ])
}

pub struct SpiPins {
    w: PinWriter,
    /// status, rd_data and rd_round the register file presents before the next edge.
    pre: (u8, u32, bool),
}

impl SpiPins {
    pub fn create(stem: &std::path::Path) -> Result<SpiPins, String> {
        Ok(SpiPins { w: PinWriter::create(stem, spi_layout())?, pre: (0, 0, false) })
    }
    fn line(&mut self, rst: bool, i: &Inputs, chip: &Tmc429) -> Result<(), String> {
        let p = chip.spi_ports();
        let v = [
            rst as u64,
            i.nscs_c as u64,
            i.sck_c as u64,
            i.sdi_c as u64,
            self.pre.0 as u64,
            self.pre.1 as u64,
            self.pre.2 as u64,
            p.rd_addr as u64,
            p.frame_start as u64,
            p.exec as u64,
            p.cmd as u64,
            p.active as u64,
            p.sdo as u64,
        ];
        self.pre = (p.status, p.rd_data, p.rd_round);
        self.w.line(&v)
    }
}

impl Recorder for SpiPins {
    fn reset(&mut self, chip: &Tmc429) -> Result<(), String> {
        let p = chip.spi_ports();
        self.pre = (p.status, p.rd_data, p.rd_round);
        self.line(true, &Inputs::default(), chip)
    }
    #[inline]
    fn edge(&mut self, chip: &Tmc429, inp: &Inputs, _out: &Outputs) -> Result<(), String> {
        self.line(false, inp, chip)
    }
    fn finish(self: Box<Self>, meta: &Meta) -> Result<Vec<AtomicFile>, String> {
        self.w.finish(meta.clone())
    }
}

/// The data pin the µC reads: SDOZ_C while enabled, else nINT_SDO_C.
fn data_pin(o: &Outputs) -> bool {
    if o.sdoz_c_oe {
        o.sdoz_c
    } else {
        o.nint_sdo_c
    }
}

/// spi.csv: every µC frame, decoded from the pins (what a logic analyser on the bus sees).
pub struct SpiCsv {
    csv: Csv,
    chip: Chip,
    prev_in: Inputs,
    prev_out: Outputs,
    /// Frame in progress: start cycle, bits sent, bits received, count.
    frame: Option<(u64, u64, u64, u32)>,
}

pub const SPI_CSV_HEADER: &str = "start_cycle,end_cycle,nbits,sent,received,kind,register,fields,status";

impl SpiCsv {
    pub fn create(path: &std::path::Path, chip: Chip) -> Result<SpiCsv, String> {
        let t = Tmc429::new(chip);
        Ok(SpiCsv { csv: Csv::create(path, SPI_CSV_HEADER)?, chip, prev_in: Inputs::default(), prev_out: t.outputs(), frame: None })
    }

    fn row(&mut self, start: u64, end: u64, sent: u64, recv: u64, n: u32) -> Result<(), String> {
        let digits = (n as usize).div_ceil(4).max(1);
        let (kind, reg, fields) = if n == 32 {
            let d = sent as u32;
            let a7 = ((d >> 25) & 0x7F) as u8;
            let read = (d >> 24) & 1 == 1;
            let data = if read { recv as u32 & 0xFF_FFFF } else { d & 0xFF_FFFF };
            let fields = match (regmap::lookup(self.chip, a7), Addr::from_a7(a7)) {
                (Some(_), Addr::Ram(a)) => {
                    format!("cell{}={} cell{}={}", 2 * a as u32 + 1, (data >> 8) & 63, 2 * a as u32, data & 63)
                }
                (Some((r, _)), _) => regmap::decode_fields(r, data),
                (None, _) => String::new(),
            };
            (if read { "read" } else { "write" }, regmap::display_name(self.chip, a7), fields)
        } else if n < 32 {
            ("short", String::new(), String::new())
        } else {
            ("long", String::new(), String::new())
        };
        let status = if n >= 8 { script::decode_status((recv >> (n - 8)) as u8) } else { String::new() };
        let c = &mut self.csv;
        c.field(start).field(end).field(n);
        c.field(format!("{:0digits$X}", sent & mask(n)));
        c.field(format!("{:0digits$X}", recv & mask(n)));
        c.field(kind).field(reg).field(fields).field(status);
        c.end_row()
    }
}

fn mask(n: u32) -> u64 {
    if n >= 64 {
        u64::MAX
    } else {
        (1u64 << n) - 1
    }
}

impl Recorder for SpiCsv {
    fn reset(&mut self, chip: &Tmc429) -> Result<(), String> {
        self.prev_out = chip.outputs();
        Ok(())
    }
    fn edge(&mut self, chip: &Tmc429, inp: &Inputs, out: &Outputs) -> Result<(), String> {
        let cycle = chip.cycle();
        if !inp.nscs_c && self.prev_in.nscs_c {
            self.frame = Some((cycle, 0, 0, 0));
        }
        if let Some((_, sent, recv, n)) = self.frame.as_mut() {
            if !inp.nscs_c && inp.sck_c && !self.prev_in.sck_c {
                // the µC samples the data pin as SCK_C rises (the level after the last edge)
                *sent = *sent << 1 | inp.sdi_c as u64;
                *recv = *recv << 1 | data_pin(&self.prev_out) as u64;
                *n += 1;
            }
        }
        if inp.nscs_c && !self.prev_in.nscs_c {
            if let Some((start, sent, recv, n)) = self.frame.take() {
                self.row(start, cycle, sent, recv, n)?;
            }
        }
        self.prev_in = *inp;
        self.prev_out = *out;
        Ok(())
    }
    fn finish(self: Box<Self>, _meta: &Meta) -> Result<Vec<AtomicFile>, String> {
        Ok(vec![self.csv.finish()])
    }
}
