//! Microstep unit: the 256-entry full-wave index expanded through the quarter-wave LUT to the
//! sine (coil A) and cosine (coil B) DAC values, phase and fast-decay bits, and the primary
//! signal vector of one motor (TMC428 §11 Table 11-1, §12 Tables 12-3/12-4; TMC429 §11.5;
//! contract C70–C74).
//!
//! Everything here is combinational. The driver chain keeps a snapshot of each motor's index,
//! current scale, direction and step flag from the start of a datagram and evaluates one bit
//! per SCK_S period: [`lut_cell`] names the LUT cell the bit's code needs (read one edge before
//! the bit, contract C80) and [`signal_bit`] forms the bit from it. [`signals`] is the whole
//! vector at once (the definition the per-bit form is tested against).

/// Primary signal codes (TMC428 Table 11-1).
pub const DAC_A_0: u8 = 0x00;
pub const PH_A: u8 = 0x06;
pub const FD_A: u8 = 0x07;
pub const DAC_B_0: u8 = 0x08;
pub const PH_B: u8 = 0x0E;
pub const FD_B: u8 = 0x0F;
pub const ZERO: u8 = 0x10;
pub const ONE: u8 = 0x11;
pub const DIRECTION: u8 = 0x12;
pub const STEP: u8 = 0x13;

/// Bits of the codes $14–$1F of a signal vector: unused codes read 1 (contract C74).
pub const UNUSED_CODES: u32 = 0xFFF0_0000;

/// First LUT cell of the RAM (TMC428 Table 10-1).
pub const LUT_BASE: usize = 64;

/// LUT indices of coil A (sine) and coil B (cosine) for full-wave index `w` (contract C71):
/// quadrant q = w[7:6], j = w[5:0]; q even: sin j, cos min(63, 64 − j); q odd: the reverse.
#[inline]
pub fn lut_indices(w: u8) -> (u8, u8) {
    let j = w & 63;
    let mirror = (64 - j).min(63);
    if (w >> 6) & 1 == 0 {
        (j, mirror)
    } else {
        (mirror, j)
    }
}

/// PH_A, PH_B, FD_A, FD_B of full-wave index `w` before polarities (TMC428 Table 12-3).
#[inline]
pub fn quadrant_bits(w: u8) -> (bool, bool, bool, bool) {
    match w >> 6 {
        0 => (true, true, false, true),
        1 => (true, false, true, false),
        2 => (false, false, false, true),
        _ => (false, true, true, false),
    }
}

/// DAC value scaled by i_scale (TMC428 Table 8-1; contract C76): %000 is 1, otherwise
/// `(dac · i_scale) >> 3`.
#[inline]
pub fn scale(dac: u8, i_scale: u8) -> u8 {
    let k = i_scale & 7;
    if k == 0 {
        dac & 63
    } else {
        (((dac & 63) as u16 * k as u16) >> 3) as u8
    }
}

/// RAM cell (64 + LUT index) that a bit of code `code` reads for full-wave index `w`
/// (contract C71, C80): coil A (sine) for codes with bit 3 clear ($00–$07), coil B (cosine)
/// for bit 3 set ($08–$0F). Codes from $10 need no LUT value; they name a cell all the same.
#[inline]
pub fn lut_cell(w: u8, code: u8) -> usize {
    let (si, ci) = lut_indices(w);
    LUT_BASE + if code & 0x08 == 0 { si } else { ci } as usize
}

/// Bit `code` of the primary signal vector (C72–C74) of a motor with full-wave index `w`,
/// where `lut` is the LUT cell [`lut_cell`]`(w, code)`: equal to bit `code` of [`signals`].
#[inline]
pub fn signal_bit(code: u8, w: u8, lut: u8, i_scale: u8, negative: bool, step: bool, pol: Polarity) -> bool {
    signal_bit_scaled(code, w, scale(lut, i_scale), negative, step, pol)
}

/// Bit `code` of the primary signal vector from the already scaled DAC value `dac`
/// ([`scale`] of the LUT cell the code reads): the form the driver chain evaluates, with the
/// scaled value registered between the two (contract C80).
#[inline]
pub fn signal_bit_scaled(code: u8, w: u8, dac: u8, negative: bool, step: bool, pol: Polarity) -> bool {
    let (ph_a, ph_b, fd_a, fd_b) = quadrant_bits(w);
    match code & 0x1F {
        c @ (0..=5 | 8..=13) => ((dac >> (c & 7)) & 1 != 0) ^ pol.dac_ab,
        PH_A => ph_a ^ pol.ph_ab,
        FD_A => fd_a ^ pol.fd_ab,
        PH_B => ph_b ^ pol.ph_ab,
        FD_B => fd_b ^ pol.fd_ab,
        ZERO => false,
        ONE => true,
        DIRECTION => negative,
        STEP => step,
        _ => true,
    }
}

/// The inputs of the microstep unit at its RTL boundary (`tmc429_microstep`, rtl/README.md
/// "Unit ports"): three combinational functions the driver chain uses one after the other.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct UnitInputs {
    /// Full-wave index (the snapshot's microstep count).
    pub w: u8,
    /// Coil of the LUT value needed: false A (sine), true B (cosine) = bit 3 of the code.
    pub coil_b: bool,
    /// The LUT value read (RAM cell 64 + `lut_idx`).
    pub lut: u8,
    /// Current scale (Table 8-1, C76).
    pub i_scale: u8,
    /// Primary signal code of the bit (Table 11-1).
    pub code: u8,
    /// Scaled LUT value for `code` (registered by the chain, C80).
    pub dac_q: u8,
    pub negative: bool,
    pub step: bool,
    pub pol: Polarity,
}

/// The outputs of the microstep unit at its RTL boundary.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct UnitOutputs {
    /// LUT index for (`w`, `coil_b`) (C71): the cell 64 + `lut_idx` is read.
    pub lut_idx: u8,
    /// `lut` scaled by `i_scale` (C76).
    pub dac: u8,
    /// Bit `code` of the signal vector formed from `dac_q` (C72–C74).
    pub bit_out: bool,
}

/// The microstep unit at its RTL boundary: [`lut_cell`], [`scale`] and [`signal_bit_scaled`]
/// side by side, as `tmc429_microstep` computes them.
pub fn unit_ports(i: &UnitInputs) -> UnitOutputs {
    UnitOutputs {
        lut_idx: (lut_cell(i.w, (i.coil_b as u8) << 3) - LUT_BASE) as u8,
        dac: scale(i.lut, i.i_scale),
        bit_out: signal_bit_scaled(i.code, i.w, i.dac_q & 63, i.negative, i.step, i.pol),
    }
}

/// Global-register polarity bits that act on the signal vector (TMC428 §9.7).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Polarity {
    pub ph_ab: bool,
    pub fd_ab: bool,
    pub dac_ab: bool,
}

/// The sequencer outputs of one motor as a 32-bit vector indexed by primary signal code
/// (bit c = value of code c): DAC_A, PH_A, FD_A, DAC_B, PH_B, FD_B, Zero, One, Direction,
/// Step, and 1 for the unused codes $14–$1F (contract C72–C74).
pub fn signals(ram: &[u8; 128], w: u8, i_scale: u8, negative: bool, step: bool, pol: Polarity) -> u32 {
    let (si, ci) = lut_indices(w);
    let mut dac_a = scale(ram[LUT_BASE + si as usize], i_scale) as u32;
    let mut dac_b = scale(ram[LUT_BASE + ci as usize], i_scale) as u32;
    if pol.dac_ab {
        dac_a ^= 63;
        dac_b ^= 63;
    }
    let (ph_a, ph_b, fd_a, fd_b) = quadrant_bits(w);
    let b = |x: bool, code: u8| (x as u32) << code;
    (dac_a << DAC_A_0)
        | b(ph_a ^ pol.ph_ab, PH_A)
        | b(fd_a ^ pol.fd_ab, FD_A)
        | (dac_b << DAC_B_0)
        | b(ph_b ^ pol.ph_ab, PH_B)
        | b(fd_b ^ pol.fd_ab, FD_B)
        | b(true, ONE)
        | b(negative, DIRECTION)
        | b(step, STEP)
        | UNUSED_CODES
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn indices_reproduce_table_12_4_quadrant_starts() {
        // First sin entry of quadrant 2 is 63, of quadrant 3 is 0 (Table 12-4).
        assert_eq!(lut_indices(64), (63, 0));
        assert_eq!(lut_indices(65), (63, 1));
        assert_eq!(lut_indices(66), (62, 2));
        assert_eq!(lut_indices(128), (0, 63));
        assert_eq!(lut_indices(192), (63, 0));
        assert_eq!(lut_indices(0), (0, 63));
        assert_eq!(lut_indices(1), (1, 63));
    }

    #[test]
    fn per_bit_form_equals_the_vector() {
        // Every index, code, scale and polarity, with a RAM whose LUT is the sine table
        // and one whose cells are all different.
        let mut rams = [[0u8; 128]; 2];
        rams[0][LUT_BASE..].copy_from_slice(&crate::ram::SINE_LUT);
        for (i, c) in rams[1].iter_mut().enumerate() {
            *c = (i as u8).wrapping_mul(37) & 63;
        }
        for ram in &rams {
            for w in 0..=255u8 {
                for k in 0..8u8 {
                    for p in 0..32u8 {
                        let pol = Polarity { ph_ab: p & 1 != 0, fd_ab: p & 2 != 0, dac_ab: p & 4 != 0 };
                        let (neg, step) = (p & 8 != 0, p & 16 != 0);
                        let v = signals(ram, w, k, neg, step, pol);
                        for code in 0..32u8 {
                            let lut = ram[lut_cell(w, code)];
                            assert_eq!(signal_bit(code, w, lut, k, neg, step, pol), (v >> code) & 1 != 0);
                        }
                    }
                }
            }
        }
        // Table 12-4: index 64 reads sin 63 (coil A), cos 0 (coil B).
        assert_eq!(lut_cell(64, 0x05), LUT_BASE + 63);
        assert_eq!(lut_cell(64, 0x0D), LUT_BASE);
    }

    #[test]
    fn unit_ports_table_12_4_and_8_1() {
        // Table 12-4: index 64 reads sin 63 (coil A), cos 0 (coil B); Table 8-1: 59 * 4 >> 3 = 29.
        let i = UnitInputs { w: 64, lut: 59, i_scale: 4, code: PH_A, ..Default::default() };
        assert_eq!(unit_ports(&i), UnitOutputs { lut_idx: 63, dac: 29, bit_out: true });
        let i = UnitInputs { w: 64, coil_b: true, code: 0x0D, dac_q: 0b10_0000, ..Default::default() };
        assert_eq!(unit_ports(&i), UnitOutputs { lut_idx: 0, dac: 0, bit_out: true });
        let i = UnitInputs { code: 0x0D, dac_q: 0b01_1111, pol: Polarity { dac_ab: true, ..Default::default() }, ..i };
        assert!(unit_ports(&i).bit_out);
        // Zero, Direction, unused $14 (C74)
        assert!(!unit_ports(&UnitInputs { code: ZERO, ..i }).bit_out);
        assert!(unit_ports(&UnitInputs { code: DIRECTION, negative: true, ..i }).bit_out);
        assert!(unit_ports(&UnitInputs { code: 0x14, ..i }).bit_out);
    }

    #[test]
    fn scale_table_8_1() {
        assert_eq!(scale(63, 0), 63);
        assert_eq!(scale(63, 1), 7);
        assert_eq!(scale(59, 4), 29);
        assert_eq!(scale(24, 4), 12);
        assert_eq!(scale(63, 7), 55);
    }
}
