//! `tmc429.Stimulus` and `tmc429.Reference`: the seeded transaction-level stimulus of
//! `tmc429 cosim` (the same seed, the same run), and the golden model driven by it — the
//! reference a design under test is compared with edge by edge (the cocotb harness,
//! docs/verify-your-rtl.md).

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

use tmc429_model::Chip;
use tmc429_verif::lockstep::{access, Mismatch, Reference as ModelSide};
use tmc429_verif::pinword;
use tmc429_verif::signals::Compare;
use tmc429_verif::stimulus::{Profile, Stimulus as Gen, Txn};

use crate::pins::{Outputs, Probes};

fn profile(name: &str) -> PyResult<Profile> {
    Profile::parse(name)
        .ok_or_else(|| PyValueError::new_err(format!("unknown profile '{name}': expected motion, motion-core, drivers, registers or full")))
}

/// One transaction of the stimulus: an SPI frame, a change of the other input pins, or idle
/// time. `kind` says which fields are meaningful.
#[pyclass(module = "tmc429", get_all, frozen)]
pub struct Transaction {
    /// "frame", "pins" or "idle".
    pub kind: &'static str,
    /// frame: the 32-bit datagram `A7 << 25 | RW << 24 | DATA` (TMC428 §6.2).
    pub datagram: u32,
    /// frame: SCK_C periods (1..64; only 32 executes, C12); bits after the first 32 in `extra`.
    pub nbits: u8,
    pub extra: u32,
    /// frame: SCK_C half period, nSCS_C setup and hold, nSCS_C high time after it (CLK cycles).
    pub half: u32,
    pub setup: u32,
    pub hold: u32,
    pub gap: u32,
    /// frame: the access decoded by register name, as the mismatch report shows it.
    pub access: String,
    /// pins: levels of REF1..3, REFR1..3, SDI_S (an input word's bits 4..9 and 3).
    pub levels: u32,
    /// pins: cycles the levels are held; idle: cycles nothing changes; frame: cycles on the pins.
    pub cycles: u64,
}

#[pymethods]
impl Transaction {
    fn __repr__(&self) -> String {
        match self.kind {
            "frame" => format!("Transaction(frame {}, {} bits, half {})", self.access, self.nbits, self.half),
            "pins" => format!("Transaction(pins 0x{:03x} for {} cycles)", self.levels, self.cycles),
            _ => format!("Transaction(idle {} cycles)", self.cycles),
        }
    }
}

fn transaction(chip: Chip, t: Txn) -> Transaction {
    let mut out = Transaction {
        kind: "idle",
        datagram: 0,
        nbits: 0,
        extra: 0,
        half: 0,
        setup: 0,
        hold: 0,
        gap: 0,
        access: String::new(),
        levels: 0,
        cycles: 0,
    };
    match t {
        Txn::Frame(f) => {
            out.kind = "frame";
            (out.datagram, out.nbits, out.extra, out.half, out.setup, out.hold, out.gap) =
                (f.datagram, f.nbits, f.extra, f.half, f.setup, f.hold, f.gap);
            out.access = access(chip, &f);
            out.cycles = f.cycles();
        }
        Txn::Pins { levels, hold } => {
            out.kind = "pins";
            let i = tmc429_model::Inputs {
                sdi_s: levels.sdi_s,
                ref1: levels.ref_[0],
                ref2: levels.ref_[1],
                ref3: levels.ref_[2],
                refr1: levels.refr[0],
                refr2: levels.refr[1],
                refr3: levels.refr[2],
                ..Default::default()
            };
            out.levels = pinword::pack_inputs(&i) & !0b111;
            out.cycles = hold as u64;
        }
        Txn::Idle(n) => out.cycles = n as u64,
    }
    out
}

/// The transactions of `tmc429 cosim --chip VARIANT --profile PROFILE --seed SEED`, in order.
#[pyclass(module = "tmc429", unsendable)]
pub struct Stimulus {
    gen: Gen,
}

#[pymethods]
impl Stimulus {
    #[new]
    #[pyo3(signature = (variant = "tmc429", profile = "motion", seed = 1))]
    fn new(variant: &str, profile: &str, seed: u64) -> PyResult<Self> {
        Ok(Stimulus { gen: Gen::new(crate::variant(variant)?, self::profile(profile)?, seed) })
    }

    /// The next transaction.
    fn next_transaction(&mut self) -> Transaction {
        let t = self.gen.next_txn();
        transaction(self.gen.chip(), t)
    }

    fn __iter__(slf: PyRef<'_, Self>) -> PyRef<'_, Self> {
        slf
    }

    fn __next__(&mut self) -> Transaction {
        self.next_transaction()
    }
}

/// The golden model driven by the seeded stimulus of `tmc429 cosim`, edge by edge, with its
/// coverage and transaction log: the reference a design under test is compared with.
///
/// Each edge: `step()` gives the input word to apply before the edge (bit k = `INPUT_PINS[k]`)
/// and runs the model's edge; after the design's edge, `check(word)` compares its output word
/// (bit k = `OUTPUT_PINS[k]`) with the model's — every output pin, SDOZ_C and SDI_S data only
/// while both sides enable them. `exchange(word)` does both in one call.
#[pyclass(module = "tmc429", unsendable)]
pub struct Reference {
    side: ModelSide,
    seed: u64,
    profile: Profile,
    /// The output pins compared.
    mask: Compare,
    mismatch: Option<Mismatch>,
}

#[pymethods]
impl Reference {
    /// `absent`: output pins the design does not have (`OUTPUT_PINS` names), not compared.
    #[new]
    #[pyo3(signature = (variant = "tmc429", profile = "motion", seed = 1, absent = Vec::new()))]
    fn new(variant: &str, profile: &str, seed: u64, absent: Vec<String>) -> PyResult<Self> {
        let p = self::profile(profile)?;
        let mut mask = Compare::pins();
        for name in &absent {
            if !pinword::output_names().contains(&name.as_str()) {
                return Err(PyValueError::new_err(format!(
                    "absent: '{name}' is not an output pin: expected one of {}",
                    pinword::output_names().join(", ")
                )));
            }
            mask = mask.without(&format!("top.{name}"));
        }
        Ok(Reference { side: ModelSide::new(crate::variant(variant)?, p, seed), seed, profile: p, mask, mismatch: None })
    }

    /// The next edge: its input word; runs the model's edge. `dut`: the design's output word
    /// after the last edge, for the replies in the transaction log.
    #[pyo3(signature = (dut = None))]
    fn step(&mut self, dut: Option<u32>) -> u32 {
        let d = dut.map(pinword::unpack_outputs);
        let (inputs, _, _) = self.side.step(d.as_ref());
        pinword::pack_inputs(&inputs)
    }

    /// Compares the design's output word after the last edge (before the first: its reset
    /// state) with the model's. False at a mismatch, which `mismatch_report` then describes;
    /// after the first mismatch every check is False.
    fn check(&mut self, dut: u32) -> bool {
        if self.mismatch.is_none() {
            self.mismatch = self.side.check_pins(&pinword::unpack_outputs(dut), self.mask);
        }
        self.mismatch.is_none()
    }

    /// `check(dut)`, then `step(dut)`: the next input word, or None at a mismatch.
    fn exchange(&mut self, dut: u32) -> Option<u32> {
        if !self.check(dut) {
            return None;
        }
        Some(self.step(Some(dut)))
    }

    /// Runs `cycles` edges of the model alone.
    fn run(&mut self, cycles: u64) {
        for _ in 0..cycles {
            self.side.step(None);
        }
    }

    /// The input word before the first edge and during reset: the idle bus, switches open.
    #[getter]
    fn idle_word(&self) -> u32 {
        pinword::pack_inputs(&self.side.source().idle_inputs())
    }

    /// The model's output word after the last edge.
    #[getter]
    fn output_word(&self) -> u32 {
        pinword::pack_outputs(&self.side.outputs())
    }

    /// The model's output pins after the last edge.
    #[getter]
    fn outputs(&self) -> Outputs {
        self.side.outputs().into()
    }

    /// The model's internal state after the last edge.
    #[getter]
    fn probes(&self) -> Probes {
        self.side.model().probes().into()
    }

    #[getter]
    fn variant(&self) -> &'static str {
        self.side.source().chip().name()
    }

    #[getter]
    fn profile(&self) -> &'static str {
        self.profile.name()
    }

    #[getter]
    fn seed(&self) -> u64 {
        self.seed
    }

    /// Edges run.
    #[getter]
    fn cycle(&self) -> u64 {
        self.side.source().cycle()
    }

    /// SPI frames started.
    #[getter]
    fn frames(&self) -> u64 {
        self.side.source().frames()
    }

    /// Pin-change transactions started.
    #[getter]
    fn pin_changes(&self) -> u64 {
        self.side.source().pin_changes()
    }

    /// The cycle of the first mismatch (0: the reset states), or None.
    #[getter]
    fn mismatch_cycle(&self) -> Option<u64> {
        self.mismatch.as_ref().map(|m| m.cycle)
    }

    /// The report of the first mismatch as `tmc429 cosim` prints it (the differing pins, the
    /// last SPI transactions decoded with both sides' replies); None without a mismatch.
    /// `label` names the design under test.
    fn mismatch_report(&self, label: &str) -> Option<String> {
        self.mismatch.as_ref().map(|m| m.report(label, self.side.source().chip(), self.seed))
    }

    /// The coverage bins of `tmc429 cosim --coverage` and their hit counts.
    fn coverage(&self) -> std::collections::BTreeMap<String, u64> {
        self.side.coverage().bins().clone()
    }

    /// The coverage table and the bins never hit, as `tmc429 cosim --coverage` prints them.
    fn coverage_table(&self) -> String {
        self.side.coverage().table()
    }

    /// The bins never hit.
    fn missed_bins(&self) -> Vec<String> {
        self.side.coverage().missed().into_iter().map(String::from).collect()
    }
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<Stimulus>()?;
    m.add_class::<Transaction>()?;
    m.add_class::<Reference>()?;
    Ok(())
}
