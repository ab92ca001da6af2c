//! A seed means the same stimulus wherever it is used — `tmc429 cosim --seed`, the Python
//! package's `Stimulus` and cocotb harness, the C library's DPI-C stimulus: the input pins of the
//! first 100 000 edges of every variant, profile and seeds 1 and 2, hashed (FNV-1a over the
//! packed input word of each edge), and the transactions started, as the generators gave them
//! when they moved into this crate.
//!
//! A deliberate change of the generators changes these numbers: then every recorded seed (docs,
//! bug reports) means another run, and the table is updated with the new values this test prints.

use tmc429_model::Chip;
use tmc429_verif::lockstep::PinSource;
use tmc429_verif::pinword::pack_inputs;
use tmc429_verif::stimulus::Profile;

const CYCLES: u64 = 100_000;

/// (variant, profile, seed, FNV-1a of the input words, transactions started)
const FINGERPRINTS: [(&str, &str, u64, u64, u64); 30] = [
    ("tmc428", "motion", 1, 0xf62f2e679932868a, 66),
    ("tmc428", "motion", 2, 0x4fe4b1cec1bf9cae, 75),
    ("tmc428", "motion-core", 1, 0xc86295b3ceca7242, 66),
    ("tmc428", "motion-core", 2, 0x4fe4b1cec1bf9cae, 75),
    ("tmc428", "drivers", 1, 0x1e240f67d097b4c0, 213),
    ("tmc428", "drivers", 2, 0x20eb5914b3bfbc1d, 173),
    ("tmc428", "registers", 1, 0x651dcf01d91cfc51, 220),
    ("tmc428", "registers", 2, 0xd0be5d311e4f68d8, 250),
    ("tmc428", "full", 1, 0xfb6f41f4b3d5c4b9, 217),
    ("tmc428", "full", 2, 0x3318990c8af86309, 249),
    ("tmc429", "motion", 1, 0xf62f2e679932868a, 66),
    ("tmc429", "motion", 2, 0x74017176b7edcdd6, 58),
    ("tmc429", "motion-core", 1, 0xc86295b3ceca7242, 66),
    ("tmc429", "motion-core", 2, 0x74017176b7edcdd6, 58),
    ("tmc429", "drivers", 1, 0xa89d34e116483b19, 213),
    ("tmc429", "drivers", 2, 0x7ac52b5af67ba13b, 189),
    ("tmc429", "registers", 1, 0xcf2d19454d673067, 227),
    ("tmc429", "registers", 2, 0x0b95205a7d19baa9, 254),
    ("tmc429", "full", 1, 0x558ef43773a0e548, 226),
    ("tmc429", "full", 2, 0x4ee1e0329f94ca3e, 255),
    ("tmc4210", "motion", 1, 0x4b82235552543190, 69),
    ("tmc4210", "motion", 2, 0x2159d8c33310d55e, 76),
    ("tmc4210", "motion-core", 1, 0x4b82235552543190, 69),
    ("tmc4210", "motion-core", 2, 0x2159d8c33310d55e, 76),
    ("tmc4210", "drivers", 1, 0x2d8d133bc257961a, 178),
    ("tmc4210", "drivers", 2, 0x46f40f22d9236485, 157),
    ("tmc4210", "registers", 1, 0x0a6f6e24e2f9225e, 223),
    ("tmc4210", "registers", 2, 0x3db05244fe4ecbd7, 202),
    ("tmc4210", "full", 1, 0x7fac19e84ff32c78, 222),
    ("tmc4210", "full", 2, 0xdbe32fe13bbc05fe, 201),
];

/// The hash of the input words of the first `cycles` edges and the transactions started.
pub fn fingerprint(chip: Chip, profile: Profile, seed: u64, cycles: u64) -> (u64, u64) {
    let mut src = PinSource::new(chip, profile, seed);
    let idle = tmc429_model::Outputs::IDLE;
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    let mut txns = 0;
    for _ in 0..cycles {
        let s = src.step(&idle, None);
        txns += s.started.is_some() as u64;
        h = (h ^ pack_inputs(&s.inputs) as u64).wrapping_mul(0x0000_0100_0000_01b3);
    }
    (h, txns)
}

#[test]
fn seeds_give_the_recorded_stimulus() {
    let mut wrong = Vec::new();
    for (chip, profile, seed, hash, txns) in FINGERPRINTS {
        let got = fingerprint(chip.parse().unwrap(), Profile::parse(profile).unwrap(), seed, CYCLES);
        if got != (hash, txns) {
            wrong.push(format!("    (\"{chip}\", \"{profile}\", {seed}, {:#018x}, {}),", got.0, got.1));
        }
    }
    assert!(wrong.is_empty(), "the stimulus of these seeds changed:\n{}", wrong.join("\n"));
}
