//! The ramp unit's boundary (`tmc429_ramp`): its pins and ramp.csv.

use tmc429_model::motor_regs::{self, sext24};
use tmc429_model::ramp;
use tmc429_model::{schedule, Inputs, Outputs, Tmc429};

use super::super::files::AtomicFile;
use super::super::pins::{input, output, Layout, LineEncoder, Meta, PinWriter};
use super::{Csv, Recorder};

/// The ports of `tmc429_ramp` (rtl/tmc429_ramp.v, rtl/README.md "The ramp unit"), inputs then
/// outputs.
pub fn ramp_layout() -> Layout {
    Layout::new(vec![
        input("rst", 1),
        input("run", 1),
        input("sample_tick", 1),
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
pub fn ramp_values(rst: bool, i: &ramp::RampInputs, m: &motor_regs::Motor) -> [u64; 33] {
    let o = ramp::ramp_ports(m, i);
    [
        rst as u64,
        i.run as u64,
        i.sample_tick as u64,
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
