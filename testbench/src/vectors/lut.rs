//! lut.csv: the microstep unit as complete tables (contract C71–C76; [428] §12, Tables 12-3,
//! 12-4, 8-1). For each LUT, each usrs (0..7), each direction and each i_scale (0..7), the
//! full-wave index walks one electrical period from 0 in steps of ±2^(6 − usrs) (usrs 7 as 6,
//! C72), and each row gives the index and the unit's outputs for it.

use tmc429_model::microstep::{self, Polarity};
use tmc429_model::ram;

use super::files::AtomicFile;
use super::pins::{input, output, Layout, Meta, PinWriter};
use super::record::{decode_signals, Csv};

/// The LUTs of the golden set: name and the 64 quarter-wave values.
pub fn luts() -> [(&'static str, [u8; 64]); 2] {
    [("sine", ram::SINE_LUT), ("rhomb", rhomb())]
}

/// The triangular shape of [428] §12.3: f_rhomb(φ) = (2/π)·φ with φ_i = (π/2)·i/64, i.e.
/// y(i) = int(½ + 64·i/64) = i (0..63; within the 0..63 range of the RAM). The shape parameter
/// σ = −1 of §12.3's superposition.
pub fn rhomb() -> [u8; 64] {
    let mut y = [0u8; 64];
    for (i, v) in y.iter_mut().enumerate() {
        *v = i as u8;
    }
    y
}

/// One row of the tables: LUT name and values, usrs, direction, i_scale, the step number k
/// and the full-wave index w it reaches.
struct Row {
    name: &'static str,
    lut: [u8; 64],
    usrs: u8,
    neg: bool,
    i_scale: u8,
    k: u16,
    w: u8,
}

/// Every row, in the order of the CSV: per LUT, usrs, direction, i_scale, the walk of one
/// electrical period in steps of ±2^(6 − usrs) (usrs 7 as 6, C72).
fn rows() -> impl Iterator<Item = Row> {
    luts().into_iter().flat_map(|(name, lut)| {
        (0..8u8).flat_map(move |usrs| {
            let inc = 1u16 << (6 - usrs.min(6));
            [false, true].into_iter().flat_map(move |neg| {
                (0..8u8).flat_map(move |i_scale| {
                    (0..256 / inc).map(move |k| {
                        let w = if neg { (256 - (k * inc) % 256) % 256 } else { k * inc } as u8;
                        Row { name, lut, usrs, neg, i_scale, k, w }
                    })
                })
            })
        })
    })
}

pub const LUT_CSV_HEADER: &str = "lut,usrs,direction,i_scale,step,index,dac_a,dac_b,ph_a,ph_b,fd_a,fd_b";

/// Writes the tables; the file is returned uncommitted.
pub fn write(path: &std::path::Path) -> Result<AtomicFile, String> {
    let mut csv = Csv::create(path, LUT_CSV_HEADER)?;
    for row in rows() {
        let mut r = [0u8; 128];
        r[microstep::LUT_BASE..].copy_from_slice(&row.lut);
        let s = decode_signals(microstep::signals(&r, row.w, row.i_scale, row.neg, false, Polarity::default()));
        csv.field(row.name).field(row.usrs).field(if row.neg { "-" } else { "+" }).field(row.i_scale);
        csv.field(row.k).field(row.w).field(s[0]).field(s[3]).field(s[1]).field(s[4]).field(s[2]).field(s[5]);
        csv.end_row()?;
    }
    Ok(csv.finish())
}

/// The ports of `tmc429_microstep` (rtl/tmc429_microstep.v, rtl/README.md "Unit ports"),
/// inputs then outputs. The unit is combinational and has no `rst`.
pub fn lut_layout() -> Layout {
    Layout::new(vec![
        input("w", 8),
        input("coil_b", 1),
        input("lut", 6),
        input("i_scale", 3),
        input("code", 5),
        input("dac_q", 6),
        input("negative", 1),
        input("step", 1),
        input("pol_ph_ab", 1),
        input("pol_fd_ab", 1),
        input("pol_dac_ab", 1),
        output("lut_idx", 6),
        output("dac", 6),
        output("bit_out", 1),
    ])
}

/// The unit's inputs of line `n` of the pin-level tables: the table row (LUT, full-wave index
/// `w`, i_scale, direction) and coil `coil_b` (two lines per row, coil A then coil B).
/// `lut` is the LUT cell the unit names for (`w`, `coil_b`), `dac_q` its scaled value (what
/// the chain registers, C80). The code keeps the coil's bit 3 and walks the other bits over
/// 16 rows, so every code $00–$1F appears; Step and the three polarities walk over the rows
/// above that (every combination within 256 rows).
pub fn pin_inputs(lut: &[u8; 64], row: u64, w: u8, i_scale: u8, negative: bool, coil_b: bool) -> microstep::UnitInputs {
    let idx = microstep::lut_cell(w, (coil_b as u8) << 3) - microstep::LUT_BASE;
    let v = lut[idx];
    let code = (((row / 8) % 2) as u8) << 4 | (coil_b as u8) << 3 | (row % 8) as u8;
    let p = (row / 16) % 16;
    microstep::UnitInputs {
        w,
        coil_b,
        lut: v,
        i_scale,
        code,
        dac_q: microstep::scale(v, i_scale),
        negative,
        step: p & 1 != 0,
        pol: Polarity { ph_ab: p & 2 != 0, fd_ab: p & 4 != 0, dac_ab: p & 8 != 0 },
    }
}

/// Writes the pin-level tables (`.hex`, `.cols`, `.meta`): for every row of the CSV tables
/// ([`write`], same order) one line for coil A and one for coil B, the inputs of
/// [`pin_inputs`] and the outputs of the model's unit ([`microstep::unit_ports`]). Line k is
/// row k / 2. The files are returned uncommitted.
pub fn write_pins(stem: &std::path::Path, mut meta: Meta) -> Result<Vec<AtomicFile>, String> {
    let mut pw = PinWriter::create(stem, lut_layout())?;
    for (n, row) in rows().enumerate() {
        for coil_b in [false, true] {
            let i = pin_inputs(&row.lut, n as u64, row.w, row.i_scale, row.neg, coil_b);
            let o = microstep::unit_ports(&i);
            pw.line(&[
                i.w as u64,
                i.coil_b as u64,
                i.lut as u64,
                i.i_scale as u64,
                i.code as u64,
                i.dac_q as u64,
                i.negative as u64,
                i.step as u64,
                i.pol.ph_ab as u64,
                i.pol.fd_ab as u64,
                i.pol.dac_ab as u64,
                o.lut_idx as u64,
                o.dac as u64,
                o.bit_out as u64,
            ])?;
        }
    }
    meta.notes.push(
        "one line per table row and coil (row k / 2 of the lut CSV, coil A then B); combinational: no rst, \
         no reset line"
            .into(),
    );
    pw.finish(meta)
}
