//! lut.csv: the microstep unit as complete tables (contract C71–C76; [428] §12, Tables 12-3,
//! 12-4, 8-1). For each LUT, each usrs (0..7), each direction and each i_scale (0..7), the
//! full-wave index walks one electrical period from 0 in steps of ±2^(6 − usrs) (usrs 7 as 6,
//! C72), and each row gives the index and the unit's outputs for it.

use tmc429_model::microstep::{self, Polarity};
use tmc429_model::ram;

use super::files::AtomicFile;
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

pub const LUT_CSV_HEADER: &str = "lut,usrs,direction,i_scale,step,index,dac_a,dac_b,ph_a,ph_b,fd_a,fd_b";

/// Writes the tables; the file is returned uncommitted.
pub fn write(path: &std::path::Path) -> Result<AtomicFile, String> {
    let mut csv = Csv::create(path, LUT_CSV_HEADER)?;
    for (name, lut) in luts() {
        let mut r = [0u8; 128];
        r[microstep::LUT_BASE..].copy_from_slice(&lut);
        for usrs in 0..8u8 {
            let inc = 1u16 << (6 - usrs.min(6));
            let n = 256 / inc;
            for neg in [false, true] {
                for i_scale in 0..8u8 {
                    for k in 0..n {
                        let w = if neg { (256 - (k * inc) % 256) % 256 } else { k * inc } as u8;
                        let s = decode_signals(microstep::signals(&r, w, i_scale, neg, false, Polarity::default()));
                        csv.field(name).field(usrs).field(if neg { "-" } else { "+" }).field(i_scale);
                        csv.field(k).field(w).field(s[0]).field(s[3]).field(s[1]).field(s[4]).field(s[2]).field(s[5]);
                        csv.end_row()?;
                    }
                }
            }
        }
    }
    Ok(csv.finish())
}
