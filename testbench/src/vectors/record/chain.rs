//! The driver-chain master's boundary (`tmc429_chain`): its pins and chain.csv.

use std::fmt::Write as _;

use tmc429_model::events::{Event, EventDecoder};
use tmc429_model::microstep;
use tmc429_model::{chain, Inputs, Outputs, Tmc429};

use super::super::files::AtomicFile;
use super::super::pins::{input, output, Layout, Meta, PinWriter};
use super::{Csv, Recorder};

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
        output("cs_pre_nx", 1),
        output("sck_pre_nx", 1),
        output("sdo_nx", 1),
        output("motor_pre_nx", 2),
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
        let mut v = input_columns(rst, i, nx, ram_q, clk2_div_w);
        v.extend(output_columns(rd, new, d, hs));
        self.w.line(&v)
    }
}

/// The input columns of a line: the inputs of the edge (`i`), the ones the unit reads from
/// the next state (`nx`), the RAM word and the µC's clk2_div write.
fn input_columns(rst: bool, i: &chain::ChainInputs, nx: &chain::ChainInputs, ram_q: u8, clk2_div_w: Option<u8>) -> Vec<u64> {
    let tri = |a: [u8; 3], w: u32| (a[2] as u64) << (2 * w) | (a[1] as u64) << w | a[0] as u64;
    vec![
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
    ]
}

/// The output columns of a line: the RAM read, the handshake, the state after the edge (`new`)
/// and the next-state outputs (`d`: the state one more edge on).
fn output_columns(rd: Option<(u8, bool)>, new: &chain::Chain, d: &chain::Chain, hs: chain::Handshake) -> Vec<u64> {
    let take = hs.take;
    vec![
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
    ]
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
            "combinational outputs (ram_re, ram_addr, take, ret_cw, ret_dgw, cs_pre_nx, sck_pre_nx, sdo_nx, \
             motor_pre_nx) of the state after the edge with the line's inputs (cs_pre_nx, sck_pre_nx, \
             motor_pre_nx: the next levels before a start overrides them); ram_addr compared while ram_re (0 otherwise); ram_q is the cell read at \
             the last edge with ram_re"
                .into(),
        );
        self.w.finish(meta)
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
