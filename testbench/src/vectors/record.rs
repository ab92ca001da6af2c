//! Recorders: what one unit's boundary shows at every CLK edge, written as pin-level lines or
//! as transaction-level CSV rows.
//!
//! Cycle numbering (all forms): line 0 of a `.hex` file is the reset edge (`rst` = 1); line k
//! (k ≥ 1) is the k-th CLK edge after reset, the model's `Tmc429::cycle()` after that edge. The
//! CSV `cycle` columns use the same numbers.

use std::fmt::Write as _;

use tmc429_model::events::{Event, EventDecoder};
use tmc429_model::microstep;
use tmc429_model::motor_regs::{self, sext24};
use tmc429_model::ramp;
use tmc429_model::regmap::{self, Addr};
use tmc429_model::{chain, schedule, script, Chip, Inputs, Outputs, Tmc429};

use super::files::AtomicFile;
use super::pins::{input, output, Layout, LineEncoder, Meta, PinWriter};

/// One unit boundary in one form.
pub trait Recorder {
    /// The reset edge: `chip` is the power-on state after it.
    fn reset(&mut self, chip: &Tmc429) -> Result<(), String>;
    /// One CLK edge with the pins `inp`; `chip` and `out` are the state and pins after it.
    fn edge(&mut self, chip: &Tmc429, inp: &Inputs, out: &Outputs) -> Result<(), String>;
    /// The finished files, not yet committed.
    fn finish(self: Box<Self>, meta: &Meta) -> Result<Vec<AtomicFile>, String>;
}

// ---- chip pins ---------------------------------------------------------------------------

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

// ---- SPI slave pins ------------------------------------------------------------------------

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

// ---- driver-chain master pins -------------------------------------------------------------

/// The ports of `tmc429_chain` (rtl/tmc429_chain.v, rtl/README.md "Unit ports"), inputs then
/// outputs. The testbench compares `ram_addr` only while `ram_re` (the column holds 0 otherwise).
pub fn chain_layout() -> Layout {
    Layout::new(vec![
        input("rst", 1),
        input("run", 1),
        input("spi_mode", 1),
        input("step", 3),
        input("dir", 3),
        input("ustep", 24),
        input("i_scale", 9),
        input("ramp_tick_nx", 3),
        input("clk2_div_we", 1),
        input("clk2_div_wd", 8),
        input("lsmd", 2),
        input("pol_ph_ab", 1),
        input("pol_fd_ab", 1),
        input("pol_dac_ab", 1),
        input("cont_update_nx", 1),
        input("cw", 1),
        input("dgw", 1),
        input("readback_clr", 1),
        input("cover_pos", 6),
        input("cover_len", 5),
        input("cover_datagram", 24),
        input("sdi_s", 1),
        input("ram_q", 6),
        output("ram_re", 1),
        output("ram_addr", 7),
        output("take", 1),
        output("ret_cw", 1),
        output("ret_dgw", 1),
        output("cover_busy", 1),
        output("dgw_busy", 1),
        output("readback", 48),
        output("cs", 1),
        output("sck", 1),
        output("sdo", 1),
        output("motor", 2),
        output("cs_ns", 1),
        output("sck_ns", 1),
        output("sdo_n", 1),
        output("motor_ns", 2),
        output("state", 3),
        output("cidx", 6),
        output("bits", 7),
        output("req", 1),
    ])
}

/// The driver-chain master's boundary, one line per CLK edge. The model has no RAM read port,
/// so this recorder rebuilds it (C80): `ram_re`/`ram_addr` from the chain state
/// ([`chain::ram_read`]), `ram_q` as the cell the model's chain read at the last edge with a read
/// (its `cfg` or `lut`). The next-state outputs (`*_n`) and the take/return handshake (`take`,
/// `ret_cw`, `ret_dgw`, [`chain::Handshake`]) come from one more edge of a copy of the new chain
/// state with the line's inputs ([`Tmc429::chain_step`] of the state before the edge): the RTL's
/// combinational outputs are compared after the edge, with the line's inputs still applied.
pub struct ChainPins {
    w: PinWriter,
    /// The chip before the next edge, and the chain inputs it presents.
    pre: Option<Box<Tmc429>>,
    pre_i: chain::ChainInputs,
    /// The value the RAM read port holds before the next edge.
    ram_q: u8,
}

impl ChainPins {
    pub fn create(stem: &std::path::Path) -> Result<ChainPins, String> {
        Ok(ChainPins { w: PinWriter::create(stem, chain_layout())?, pre: None, pre_i: Default::default(), ram_q: 0 })
    }

    #[allow(clippy::too_many_arguments)]
    fn line(
        &mut self,
        rst: bool,
        i: &chain::ChainInputs,
        nx: &chain::ChainInputs,
        ram_q: u8,
        clk2_div_w: Option<u8>,
        new: &chain::Chain,
        d: &chain::Chain,
        hs: chain::Handshake,
    ) -> Result<(), String> {
        let rd = if i.run && i.spi_mode { chain::ram_read(new, ram_q) } else { None };
        let take = hs.take;
        let tri = |a: [u8; 3], w: u32| (a[2] as u64) << (2 * w) | (a[1] as u64) << w | a[0] as u64;
        let v = [
            rst as u64,
            i.run as u64,
            i.spi_mode as u64,
            i.step as u64,
            i.dir as u64,
            tri(i.ustep, 8),
            tri(i.i_scale, 3),
            nx.ramp_tick as u64,
            clk2_div_w.is_some() as u64,
            clk2_div_w.unwrap_or(0) as u64,
            i.lsmd as u64,
            i.pol_ph_ab as u64,
            i.pol_fd_ab as u64,
            i.pol_dac_ab as u64,
            nx.cont_update as u64,
            i.cw as u64,
            i.dgw as u64,
            i.readback_clr as u64,
            i.cover_pos as u64,
            i.cover_len as u64,
            i.cover_datagram as u64,
            i.sdi_s as u64,
            ram_q as u64,
            rd.is_some() as u64,
            rd.map_or(0, |(c, _)| c as u64),
            take as u64,
            hs.ret_cw as u64,
            hs.ret_dgw as u64,
            new.cover_busy as u64,
            new.dgw_busy as u64,
            new.readback,
            new.cs as u64,
            new.sck as u64,
            new.sdo as u64,
            new.motor as u64,
            // the next CS/SCK/motor unless a datagram starts: at a start (from IDLE or the end
            // of CSOFF) they would hold
            if take { new.cs } else { d.cs } as u64,
            if take { new.sck } else { d.sck } as u64,
            d.sdo as u64,
            if take { new.motor } else { d.motor } as u64,
            new.state as u64,
            new.cell as u64,
            new.bits as u64,
            new.req as u64,
        ];
        self.w.line(&v)
    }
}

impl Recorder for ChainPins {
    fn reset(&mut self, chip: &Tmc429) -> Result<(), String> {
        let c = *chip.chain();
        self.line(true, &Default::default(), &Default::default(), 0, None, &c, &c, chain::Handshake::default())?;
        self.pre = Some(Box::new(chip.clone()));
        self.pre_i = chip.chain_inputs();
        self.ram_q = 0;
        Ok(())
    }
    fn edge(&mut self, chip: &Tmc429, _inp: &Inputs, _out: &Outputs) -> Result<(), String> {
        let pre = self.pre.take().ok_or("chain recorder: edge before reset")?;
        let i = self.pre_i;
        let new = *chip.chain();
        let mut d = new;
        let hs = pre.chain_step(&mut d);
        let q = self.ram_q;
        let post_i = chip.chain_inputs();
        // the timing registers load when clk2_div changes (a write of the same value is no change)
        let w = (post_i.clk2_div != i.clk2_div).then_some(post_i.clk2_div);
        // ramp_tick_nx, cont_update_nx: the inputs of the next edge (the RTL registers them)
        self.line(false, &i, &post_i, q, w, &new, &d, hs)?;
        if i.run && i.spi_mode {
            if let Some((_, cfg)) = chain::ram_read(pre.chain(), q) {
                self.ram_q = if cfg { new.cfg } else { new.lut };
            }
        }
        self.pre = Some(Box::new(chip.clone()));
        self.pre_i = post_i;
        Ok(())
    }
    fn finish(self: Box<Self>, meta: &Meta) -> Result<Vec<AtomicFile>, String> {
        let mut meta = meta.clone();
        meta.notes.push(
            "combinational outputs (ram_re, ram_addr, take, ret_cw, ret_dgw, cs_ns, sck_ns, sdo_n, motor_ns) of \
             the state after the edge with the line's inputs (cs_ns, sck_ns, motor_ns: the next levels unless \
             a datagram starts); ram_addr compared while ram_re (0 otherwise); ram_q is the cell read at \
             the last edge with ram_re"
                .into(),
        );
        self.w.finish(meta)
    }
}

// ---- ramp unit pins -------------------------------------------------------------------------

/// The ports of `tmc429_ramp` (rtl/tmc429_ramp.v, rtl/README.md "The ramp unit"), inputs then
/// outputs.
pub fn ramp_layout() -> Layout {
    Layout::new(vec![
        input("rst", 1),
        input("run", 1),
        input("cond_tick", 1),
        input("ramp_tick", 1),
        input("pulse_tick", 1),
        input("rm", 2),
        input("x_target", 24),
        input("v_min", 11),
        input("a_max", 11),
        input("ref_conf", 4),
        input("usrs", 3),
        input("dx_ref_tolerance", 12),
        input("vt", 12),
        input("sw_l", 1),
        input("sw_r", 1),
        input("we", 1),
        input("widx", 4),
        input("wdata", 24),
        output("x_actual", 24),
        output("v", 20),
        output("v_target", 12),
        output("a_actual", 12),
        output("ustep", 8),
        output("acc", 11),
        output("step", 1),
        output("dir", 1),
        output("x_latched", 24),
        output("lp", 1),
        output("xeqt", 1),
        output("stop", 1),
        output("tol_ok", 1),
        output("v_actual", 12),
    ])
}

/// One line of the ramp unit: the inputs `i` of an edge and the outputs after it
/// ([`ramp::ramp_ports`] of the motor state `m`).
pub fn ramp_values(rst: bool, i: &ramp::RampInputs, m: &motor_regs::Motor) -> [u64; 32] {
    let o = ramp::ramp_ports(m, i);
    [
        rst as u64,
        i.run as u64,
        i.cond_tick as u64,
        i.ramp_tick as u64,
        i.pulse_tick as u64,
        i.rm as u64,
        i.x_target as u64,
        i.v_min as u64,
        i.a_max as u64,
        i.ref_conf as u64,
        i.usrs as u64,
        i.dx_ref_tolerance as u64,
        (i.vt as u32 & 0xFFF) as u64,
        i.sw_l as u64,
        i.sw_r as u64,
        i.we as u64,
        i.widx as u64,
        i.wdata as u64,
        o.x_actual as u64,
        o.v as u64,
        o.v_target as u64,
        o.a_actual as u64,
        o.ustep as u64,
        o.acc as u64,
        o.step as u64,
        o.dir as u64,
        o.x_latched as u64,
        o.lp as u64,
        o.xeqt as u64,
        o.stop as u64,
        o.tol_ok as u64,
        o.v_actual as u64,
    ]
}

/// The ramp unit of every motor, one after the other: the lines of motor 0 (its reset line, then
/// one line per CLK edge), then those of motor 1 from its own reset line, and so on. Each motor
/// is one instance of `tmc429_ramp`; its reset line restarts the replayed instance, which then
/// follows that motor through the same scenario.
pub struct RampPins {
    w: PinWriter,
    enc: LineEncoder,
    /// Lines of motors 1.. (encoded), and their count.
    rest: Vec<(Vec<u8>, u64)>,
    /// The inputs each motor sees before the next edge.
    pre: Vec<ramp::RampInputs>,
}

impl RampPins {
    pub fn create(stem: &std::path::Path) -> Result<RampPins, String> {
        let layout = ramp_layout();
        Ok(RampPins { enc: LineEncoder::new(&layout), w: PinWriter::create(stem, layout)?, rest: Vec::new(), pre: Vec::new() })
    }
    fn line(&mut self, m: usize, rst: bool, i: &ramp::RampInputs, mo: &motor_regs::Motor) -> Result<(), String> {
        let v = ramp_values(rst, i, mo);
        if m == 0 {
            self.w.line(&v)
        } else {
            let (buf, n) = &mut self.rest[m - 1];
            self.enc.encode(&v, buf);
            *n += 1;
            Ok(())
        }
    }
}

impl Recorder for RampPins {
    fn reset(&mut self, chip: &Tmc429) -> Result<(), String> {
        let n = chip.motor_count();
        self.rest = vec![(Vec::new(), 0); n - 1];
        self.pre = (0..n).map(|m| chip.ramp_inputs(m)).collect();
        for m in 0..n {
            self.line(m, true, &ramp::RampInputs::default(), chip.motor(m))?;
        }
        Ok(())
    }
    fn edge(&mut self, chip: &Tmc429, _inp: &Inputs, _out: &Outputs) -> Result<(), String> {
        for m in 0..self.pre.len() {
            let i = self.pre[m];
            self.line(m, false, &i, chip.motor(m))?;
            self.pre[m] = chip.ramp_inputs(m);
        }
        Ok(())
    }
    fn finish(mut self: Box<Self>, meta: &Meta) -> Result<Vec<AtomicFile>, String> {
        for (buf, n) in std::mem::take(&mut self.rest) {
            self.w.encoded_lines(&buf, n)?;
        }
        let mut meta = meta.clone();
        let per = self.w.lines() / self.pre.len().max(1) as u64;
        meta.notes.push(format!(
            "motor m's lines are lines {per}*m .. {per}*m + {}: its reset line, then one line per CLK edge; \
             combinational outputs (xeqt, stop, tol_ok, v_actual) of the state after the edge with the line's inputs",
            per - 1
        ));
        self.w.finish(meta)
    }
}

// ---- CSV -------------------------------------------------------------------------------------

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

/// ramp.csv: every ramp tick of every motor (C40, C51): the state after the tick's edge.
pub struct RampCsv {
    csv: Csv,
    /// Bit m: motor m has a ramp tick at the next edge.
    due: u8,
    /// Steps of each motor since its last ramp tick (signed).
    steps: [i64; 3],
}

pub const RAMP_CSV_HEADER: &str = "cycle,motor,mode,x_target,x_actual,v_internal,v_actual,v_target,a_actual,steps";

impl RampCsv {
    pub fn create(path: &std::path::Path) -> Result<RampCsv, String> {
        Ok(RampCsv { csv: Csv::create(path, RAMP_CSV_HEADER)?, due: 0, steps: [0; 3] })
    }
    fn plan(&mut self, chip: &Tmc429) {
        let c = chip.probes().prescaler;
        self.due = 0;
        if chip.is_powered_down() {
            return;
        }
        for m in 0..chip.motor_count() {
            if schedule::ramp_tick(c, m, chip.motor(m).ramp_div) {
                self.due |= 1 << m;
            }
        }
    }
}

const MODES: [&str; 4] = ["RAMP", "SOFT", "VELOCITY", "HOLD"];

impl Recorder for RampCsv {
    fn reset(&mut self, chip: &Tmc429) -> Result<(), String> {
        self.plan(chip);
        Ok(())
    }
    fn edge(&mut self, chip: &Tmc429, _inp: &Inputs, _out: &Outputs) -> Result<(), String> {
        for m in 0..chip.motor_count() {
            let mo = chip.motor(m);
            if mo.step {
                self.steps[m] += if mo.dir { -1 } else { 1 };
            }
            if (self.due >> m) & 1 != 0 {
                let c = &mut self.csv;
                c.field(chip.cycle()).field(m).field(MODES[mo.rm as usize & 3]);
                c.field(sext24(mo.x_target)).field(sext24(mo.x_actual)).field(mo.v).field(mo.v_actual());
                c.field(tmc429_model::motor_regs::sext12(mo.v_target as u32)).field(mo.a_actual).field(self.steps[m]);
                c.end_row()?;
                self.steps[m] = 0;
            }
        }
        self.plan(chip);
        Ok(())
    }
    fn finish(self: Box<Self>, _meta: &Meta) -> Result<Vec<AtomicFile>, String> {
        Ok(vec![self.csv.finish()])
    }
}

/// chain.csv: every driver-chain datagram: start (the edge that took the snapshot, C80) and end
/// (chip select inactive, C97), the bits as sent on SDO_S, and the signals of each motor it
/// carried (the snapshot of C80, decoded by primary signal code, [428] Table 11-1).
pub struct ChainCsv {
    csv: Csv,
    dec: EventDecoder,
    prev_state: u8,
    /// Datagram in progress: start cycle, snapshot, covering, motors carried so far.
    cur: Option<(u64, [u32; 3], bool, u8)>,
    ended: Vec<Event>,
}

pub fn chain_csv_header() -> String {
    let mut h = String::from("start_cycle,end_cycle,nbits,bits,cover,motors");
    for m in 0..3 {
        for s in ["dac_a", "ph_a", "fd_a", "dac_b", "ph_b", "fd_b", "dir", "step"] {
            let _ = write!(h, ",m{m}_{s}");
        }
    }
    h
}

impl ChainCsv {
    pub fn create(path: &std::path::Path) -> Result<ChainCsv, String> {
        Ok(ChainCsv {
            csv: Csv::create(path, &chain_csv_header())?,
            dec: EventDecoder::new(),
            prev_state: chain::IDLE,
            cur: None,
            ended: Vec::new(),
        })
    }
}

/// The signals of one motor in a snapshot: DAC_A, PH_A, FD_A, DAC_B, PH_B, FD_B, Direction, Step.
pub fn decode_signals(v: u32) -> [u32; 8] {
    let bit = |c: u8| (v >> c) & 1;
    [
        (v >> microstep::DAC_A_0) & 63,
        bit(microstep::PH_A),
        bit(microstep::FD_A),
        (v >> microstep::DAC_B_0) & 63,
        bit(microstep::PH_B),
        bit(microstep::FD_B),
        bit(microstep::DIRECTION),
        bit(microstep::STEP),
    ]
}

impl Recorder for ChainCsv {
    fn reset(&mut self, _chip: &Tmc429) -> Result<(), String> {
        Ok(())
    }
    fn edge(&mut self, chip: &Tmc429, _inp: &Inputs, out: &Outputs) -> Result<(), String> {
        let ch = chip.chain();
        // the end of a datagram is seen on the pins (before a new one may start in this edge)
        let ended = &mut self.ended;
        self.dec.observe(chip, out, chip.cycle(), &mut |e| {
            if let Event::Chain { .. } = e {
                ended.push(e)
            }
        });
        for e in std::mem::take(&mut self.ended) {
            if let (Event::Chain { cycle, nbits, bits }, Some((start, snap, cover, motors))) = (e, self.cur.take()) {
                let c = &mut self.csv;
                let digits = (nbits as usize).div_ceil(4).max(1);
                c.field(start).field(cycle).field(nbits).field(format!("{bits:0digits$X}"));
                c.field(cover as u8).field(motors as u32 + 1);
                for (m, s) in snap.iter().enumerate() {
                    for v in decode_signals(*s) {
                        if m <= motors as usize {
                            c.field(v);
                        } else {
                            c.field("");
                        }
                    }
                }
                c.end_row()?;
            }
        }
        let started = ch.state == chain::SETUP && (self.prev_state == chain::IDLE || self.prev_state == chain::CSOFF);
        if started {
            self.cur = Some((chip.cycle(), ch.snapshot_signals(chip.ram()), ch.cover_busy, 0));
        }
        if let Some(cur) = self.cur.as_mut() {
            cur.3 = cur.3.max(ch.motor);
        }
        self.prev_state = ch.state;
        Ok(())
    }
    fn finish(self: Box<Self>, _meta: &Meta) -> Result<Vec<AtomicFile>, String> {
        Ok(vec![self.csv.finish()])
    }
}
