//! The training input of the profile-guided build (build/pgo_pins.rs): the golden pin-level
//! vectors read as the words cpp/pgo_train.cc replays.

#[path = "../build/pgo_pins.rs"]
mod pgo_pins;

use std::fs;
use std::path::{Path, PathBuf};

use pgo_pins::{set_words, training_pins, PINS};

fn golden() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../vectors/golden")
}

fn words(bytes: &[u8]) -> Vec<u16> {
    bytes.chunks(2).map(|w| u16::from_le_bytes([w[0], w[1]])).collect()
}

/// The bit of pin `name` in a word.
fn bit(name: &str) -> u16 {
    1 << PINS.iter().position(|p| p.0 == name).unwrap()
}

/// A set written into a scratch directory: its columns and lines.
fn scratch_set(tag: &str, cols: &str, hex: &str) -> (PathBuf, PathBuf) {
    let dir = std::env::temp_dir().join(format!("tmc429-pgo-pins-{}-{tag}", std::process::id()));
    fs::create_dir_all(&dir).unwrap();
    let (c, h) = (dir.join("s.cols"), dir.join("s.hex"));
    fs::write(&c, cols).unwrap();
    fs::write(&h, hex).unwrap();
    (c, h)
}

#[test]
fn columns_from_the_most_significant_bit_and_absent_refr_pins_pulled_up() {
    // 16 bits: sentinel 4, rst, nscs_c, sck_c, sdi_c, sdi_s, ref1..3, nint_sdo_c out, check 3
    let cols = "_sentinel 4 in\nrst 1 in\nnscs_c 1 in\nsck_c 1 in\nsdi_c 1 in\nsdi_s 1 in\nref1 1 in\nref2 1 in\nref3 1 in\n\
                nint_sdo_c 1 out\n_check 3 out\n";
    // A = the sentinel; 0xAF80: rst, nscs_c, sck_c, sdi_c, sdi_s high; 0xA0 40: ref1 high only
    let (c, h) = scratch_set("cols", cols, "AF80\nA040\n");
    let w = words(&set_words(&c, &h).unwrap());
    let refr = bit("refr1") | bit("refr2") | bit("refr3");
    assert_eq!(w, vec![bit("rst") | bit("nscs_c") | bit("sck_c") | bit("sdi_c") | bit("sdi_s") | refr, bit("ref1") | refr]);
}

#[test]
fn a_bad_line_names_its_file_and_line() {
    let (c, h) = scratch_set("bad", "rst 1 in\nnscs_c 1 in\n", "3\nx\n");
    let e = set_words(&c, &h).unwrap_err();
    assert!(e.ends_with("s.hex:2: expected a hexadecimal word"), "{e}");
    let (c, h) = scratch_set("badcols", "rst 1\n", "1\n");
    let e = set_words(&c, &h).unwrap_err();
    assert!(e.ends_with("s.cols:1: expected `name width in|out`"), "{e}");
}

/// The sets of vectors/golden/SETS of unit `chip` for the variant `chip`.
fn chip_sets(chip: &str) -> usize {
    let sets = fs::read_to_string(golden().join("SETS")).unwrap();
    sets.lines().filter(|l| matches!(l.split_whitespace().collect::<Vec<_>>()[..], ["chip", _, c, ..] if c == chip)).count()
}

/// Every variant trains on each of its golden pin-level sets (vectors/golden/SETS): one word per
/// line, each set beginning with its reset edge.
#[test]
fn each_variant_replays_its_golden_chip_sets() {
    for chip in ["tmc428", "tmc429", "tmc4210"] {
        let (bytes, read) = training_pins(&golden(), chip).unwrap();
        let sets = chip_sets(chip);
        assert!(sets >= 3, "{chip}: {sets} sets");
        let hex: Vec<&PathBuf> = read.iter().filter(|p| p.extension().is_some_and(|x| x == "hex")).collect();
        assert_eq!(hex.len(), sets, "{chip}: {hex:?}");
        let w = words(&bytes);
        let mut at = 0;
        for h in hex {
            let lines = fs::read_to_string(h).unwrap().lines().count();
            assert_eq!(w[at] & bit("rst"), bit("rst"), "{}: line 0 is the reset edge", h.display());
            assert!(w[at + 1..at + lines].iter().all(|x| x & bit("rst") == 0), "{}", h.display());
            at += lines;
        }
        assert_eq!(at, w.len(), "{chip}");
    }
}
