//! The directed driver-side sequences of [`Profile::Drivers`](super::Profile::Drivers): driver-chain configurations,
//! global parameters, cover datagrams, microstep indices and current scales, Step/Dir, a
//! datagram without end, the readback. The order of the `pick` calls is the stimulus of a
//! seed: each sequence draws its values in the order written here.

use tmc429_model::Chip;

use super::{motors, Frame, Txn};

/// A write frame.
fn w(a7: u8, d: u32) -> Txn {
    Txn::Frame(Frame::write(a7, d))
}

/// One driver-chain configuration cell: code (bits 4..0) and NxM (bit 5).
fn cell(code: u8, nxm: bool) -> u8 {
    (code & 0x1F) | (nxm as u8) << 5
}

/// RAM word writes for configuration cells 0..: a7 = $40 + word, odd cell in bits 13..8.
fn ram_config_writes(cells: &[u8]) -> Vec<Txn> {
    cells
        .chunks(2)
        .enumerate()
        .map(|(w, p)| {
            let odd = p.get(1).copied().unwrap_or(0) as u32;
            Txn::Frame(Frame::write(0x40 | w as u8, odd << 8 | p[0] as u32))
        })
        .collect()
}

/// A directed driver-side sequence for [`Profile::Drivers`](super::Profile::Drivers), drawn from `pick` (a value per
/// call: `pick(n)` in 0..n).
pub fn driver_sequence(chip: Chip, pick: &mut dyn FnMut(u32) -> u32) -> Vec<Txn> {
    let spi_chip = chip != Chip::Tmc4210;
    let mut seq = match pick(9) {
        0 | 1 if spi_chip => chain_configuration(pick),
        2 if spi_chip => {
            // Polarities, csCommonIndividual, LSMD, refmux, continuous_update.
            let gp = pick(256);
            let clk2 = if pick(3) == 0 { pick(256) } else { pick(16) };
            vec![w(0x3F, gp | clk2 << 8 | pick(2) << 16 | pick(2) << 20 | pick(2) << 21)]
        }
        3 if spi_chip => cover_datagrams(pick),
        4 => ustep_and_scales(chip, pick),
        5 if chip != Chip::Tmc428 => step_dir(chip, pick),
        8 if spi_chip && pick(4) == 0 => endless_datagram(pick),
        6 if spi_chip => {
            // The readback and CDGW: a datagram-word write, then the words read.
            vec![
                w(0x30 | pick(2) as u8, pick(1 << 24)),
                w(0x33, pick(1 << 24)),
                Txn::Idle(200 + pick(4000)),
                Txn::Frame(Frame::read(0x30)),
                Txn::Frame(Frame::read(0x31)),
            ]
        }
        _ => {
            // Let the chain run: wait, read the switches.
            vec![Txn::Idle(100 + pick(5000)), Txn::Frame(Frame::read(0x3E))]
        }
    };
    if seq.is_empty() {
        seq.push(Txn::Idle(1 + pick(500)));
    }
    seq
}

/// A configuration: TMC428 Table 11-2 (three 12-bit drivers) or a random valid chain of lsmd +
/// 1 drivers, each 1..12 cells with NxM on its last cell; then the global parameters.
fn chain_configuration(pick: &mut dyn FnMut(u32) -> u32) -> Vec<Txn> {
    let lsmd = pick(4);
    let cells: Vec<u8> = if pick(2) == 0 {
        tmc429_model::ram::TABLE_11_2.to_vec()
    } else {
        let mut v = Vec::new();
        for _ in 0..=lsmd.min(2) {
            let n = 1 + pick(12);
            for k in 0..n {
                v.push(cell(pick(32) as u8, k == n - 1));
            }
        }
        v
    };
    let mut seq = ram_config_writes(&cells);
    let clk2 = if pick(4) == 0 { pick(256) } else { pick(16) };
    seq.push(w(0x3F, pick(8) << 4 | clk2 << 8 | pick(2) << 16 | pick(2) << 20 | lsmd));
    seq
}

/// A cover datagram: position, length, data; sometimes a second one at once; then the
/// position read back.
fn cover_datagrams(pick: &mut dyn FnMut(u32) -> u32) -> Vec<Txn> {
    let pos = if pick(4) == 0 { 63 } else { pick(64) };
    let mut seq = vec![w(0x32, pos << 8 | pick(32)), w(0x33, pick(1 << 24))];
    if pick(3) == 0 {
        seq.push(w(0x33, pick(1 << 24)));
    }
    seq.push(Txn::Frame(Frame::read(0x32)));
    seq
}

/// Microstep indices (TMC429 IDX 15), current scales and short ramp_div.
fn ustep_and_scales(chip: Chip, pick: &mut dyn FnMut(u32) -> u32) -> Vec<Txn> {
    let mut seq = Vec::new();
    for m in 0..motors(chip) as u8 {
        if pick(2) == 0 {
            seq.push(w(m << 4 | 15, pick(256)));
        }
        if pick(3) == 0 {
            seq.push(w(m << 4 | 8, pick(1 << 24)));
        }
        if pick(3) == 0 {
            seq.push(w(m << 4 | 12, pick(3) << 8 | pick(8)));
        }
    }
    if chip != Chip::Tmc4210 && pick(2) == 0 {
        seq.push(w(0x33, pick(1 << 24))); // request a datagram with them
    }
    seq
}

/// Step/Dir bits of if_configuration: en_sd, step_half, inv_stp, inv_dir (inv_ref, sdo_int,
/// pos_comp_sel, en_refr random); en_sd = 1 in one of three. On the TMC429 sometimes while a
/// datagram is under way (C89: it is aborted).
fn step_dir(chip: Chip, pick: &mut dyn FnMut(u32) -> u32) -> Vec<Txn> {
    let mut seq = Vec::new();
    if chip == Chip::Tmc429 && pick(2) == 0 {
        seq.push(w(0x34, pick(512) & !0x20));
        seq.push(w(0x3F, pick(8) << 8 | pick(4)));
        seq.push(w(0x33, pick(1 << 24)));
        seq.push(Txn::Idle(pick(400)));
    }
    let en_sd = if pick(3) == 0 { 0x20 } else { 0 };
    seq.push(w(0x34, (pick(512) & !0x20) | en_sd));
    seq.push(w(0x3F, pick(2) << 16 | pick(16) << 8 | pick(2) << 20));
    seq
}

/// No NxM bit anywhere: the datagram never ends (C84) and the bit counter saturates; then an
/// NxM bit ends it.
fn endless_datagram(pick: &mut dyn FnMut(u32) -> u32) -> Vec<Txn> {
    let cells: Vec<u8> = (0..64).map(|_| cell(pick(32) as u8, false)).collect();
    let mut seq = ram_config_writes(&cells);
    seq.push(w(0x3F, pick(3) << 8 | pick(256) & 0xFC));
    seq.push(w(0x33, pick(1 << 24)));
    seq.push(Txn::Idle(3000 + pick(3000)));
    let word = pick(32) as u8;
    seq.push(w(0x40 | word, 0x20 << 8 | 0x20));
    seq
}
