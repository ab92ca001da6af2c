//! The chip's pins packed into one word per direction, bit k = the k-th field of
//! [`Inputs`] / [`Outputs`] (docs/model-contract.md C1: inputs are the levels before an edge,
//! outputs the levels after it). The cocotb harness's wrapper and the DPI-C entry use these
//! words (docs/verify-your-rtl.md).

use tmc429_model::{Inputs, Outputs};

use crate::signals::{N_PINS, SIGNALS};

/// The input pins, bit 0 first.
pub const INPUT_NAMES: [&str; 10] = ["nscs_c", "sck_c", "sdi_c", "sdi_s", "ref1", "ref2", "ref3", "refr1", "refr2", "refr3"];

/// The output pins, bit 0 first (the first [`N_PINS`] compared signals).
pub fn output_names() -> [&'static str; N_PINS] {
    std::array::from_fn(|k| SIGNALS[k].name)
}

/// The input pins in the order of [`INPUT_NAMES`].
pub fn input_bits(i: &Inputs) -> [bool; 10] {
    [i.nscs_c, i.sck_c, i.sdi_c, i.sdi_s, i.ref1, i.ref2, i.ref3, i.refr1, i.refr2, i.refr3]
}

fn pack(bits: &[bool]) -> u32 {
    bits.iter().enumerate().fold(0, |w, (k, b)| w | (*b as u32) << k)
}

/// The inputs as a word, bit k = `INPUT_NAMES[k]`.
pub fn pack_inputs(i: &Inputs) -> u32 {
    pack(&input_bits(i))
}

/// The inputs of a word made by [`pack_inputs`] (bits above 9 are ignored).
pub fn unpack_inputs(w: u32) -> Inputs {
    let b = |k: u32| (w >> k) & 1 == 1;
    Inputs {
        nscs_c: b(0),
        sck_c: b(1),
        sdi_c: b(2),
        sdi_s: b(3),
        ref1: b(4),
        ref2: b(5),
        ref3: b(6),
        refr1: b(7),
        refr2: b(8),
        refr3: b(9),
    }
}

/// The outputs as a word, bit k = `output_names()[k]`.
pub fn pack_outputs(o: &Outputs) -> u32 {
    pack(&[o.nint_sdo_c, o.sdoz_c, o.sdoz_c_oe, o.nscs_s, o.sck_s, o.sdo_s, o.sdi_s_o, o.sdi_s_oe, o.nscs2, o.nscs3, o.poscmp])
}

/// The outputs of a word made by [`pack_outputs`] (bits above 10 are ignored).
pub fn unpack_outputs(w: u32) -> Outputs {
    let b = |k: u32| (w >> k) & 1 == 1;
    Outputs {
        nint_sdo_c: b(0),
        sdoz_c: b(1),
        sdoz_c_oe: b(2),
        nscs_s: b(3),
        sck_s: b(4),
        sdo_s: b(5),
        sdi_s_o: b(6),
        sdi_s_oe: b(7),
        nscs2: b(8),
        nscs3: b(9),
        poscmp: b(10),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn words_round_trip_and_follow_the_field_order() {
        for w in 0..1u32 << 10 {
            assert_eq!(pack_inputs(&unpack_inputs(w)), w);
        }
        for w in 0..1u32 << 11 {
            assert_eq!(pack_outputs(&unpack_outputs(w)), w);
        }
        // Idle bus and open switches: nSCS_C, SCK_C and the REFR pull-ups high.
        assert_eq!(pack_inputs(&Inputs::default()), 0b11_1000_0011);
        assert_eq!(output_names()[0], "nint_sdo_c");
        assert_eq!(output_names()[10], "poscmp");
        let o = Outputs { poscmp: true, ..Outputs::IDLE };
        assert_eq!(pack_outputs(&o) >> 10, 1);
    }
}
