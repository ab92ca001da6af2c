//! The lock-step pair's wire format (`tmc429_testbench::rtl::wire`): the RTL side decodes
//! exactly the edges the model side encoded, every field at its full width, whether a word
//! changed from the edge before or not.
#![cfg(not(tmc429_no_rtl))] // needs Verilator (testbench/build.rs)

use proptest::prelude::*;
use tmc429_model::{ChainProbe, Inputs, MotorProbe, Outputs, Probes};
use tmc429_testbench::rtl::wire::{Decoder, Encoder};
use tmc429_testbench::rtl::Expected;

/// Values drawn one after the other from a list of random words.
struct Draw<'a>(std::slice::Iter<'a, u64>);

impl Draw<'_> {
    fn word(&mut self) -> u64 {
        *self.0.next().expect("enough words drawn")
    }
    fn bit(&mut self) -> bool {
        self.word() & 1 != 0
    }
}

fn motor(d: &mut Draw) -> MotorProbe {
    MotorProbe {
        x_target: d.word() as u32,
        x_actual: d.word() as u32,
        v_internal: d.word() as i32,
        v_target: d.word() as i32,
        a_actual: d.word() as i32,
        ustep: d.word() as u32,
        step: d.word() as u8,
        dir: d.word() as u8,
        pulse_acc: d.word() as u16,
    }
}

/// One edge from 70 random words; `keep` (a bit per part) keeps parts of `last` as they
/// were, so that some words are unchanged and not sent.
fn edge(w: &[u64], keep: u8, last: &(Inputs, Outputs, Probes)) -> (Inputs, Outputs, Probes) {
    let mut d = Draw(w.iter());
    let inp = Inputs {
        nscs_c: d.bit(),
        sck_c: d.bit(),
        sdi_c: d.bit(),
        sdi_s: d.bit(),
        ref1: d.bit(),
        ref2: d.bit(),
        ref3: d.bit(),
        refr1: d.bit(),
        refr2: d.bit(),
        refr3: d.bit(),
    };
    let out = Outputs {
        nint_sdo_c: d.bit(),
        sdoz_c: d.bit(),
        sdoz_c_oe: d.bit(),
        nscs_s: d.bit(),
        sck_s: d.bit(),
        sdo_s: d.bit(),
        sdi_s_o: d.bit(),
        sdi_s_oe: d.bit(),
        nscs2: d.bit(),
        nscs3: d.bit(),
        poscmp: d.bit(),
    };
    let mut p = Probes {
        motor: [motor(&mut d), motor(&mut d), motor(&mut d)],
        chain: ChainProbe {
            state: d.word() as u8,
            cell: d.word() as u8,
            motor: d.word() as u8,
            bit_count: d.word() as u8,
            pending: d.word() as u8,
            cover_waiting: d.word() as u8,
            readback: d.word(),
        },
        prescaler: d.word() as u32,
        power_down: d.word() as u8,
        status: d.word() as u8,
    };
    for m in 0..3 {
        if keep >> m & 1 != 0 {
            p.motor[m] = last.2.motor[m];
        }
    }
    if keep & 8 != 0 {
        p.chain = last.2.chain;
    }
    let out = if keep & 16 != 0 { last.1 } else { out };
    (inp, out, p)
}

proptest! {
    #[test]
    fn decoded_edges_equal_the_encoded(edges in prop::collection::vec((prop::collection::vec(any::<u64>(), 70), any::<u8>()), 1..40)) {
        let mut last = (Inputs::default(), Outputs::IDLE, Probes::default());
        let mut sent = Vec::new();
        let mut batch = Vec::new();
        let mut enc = Encoder::new();
        for (w, keep) in &edges {
            last = edge(w, *keep, &last);
            let e = Expected::new(&last.0, &last.1, &last.2);
            enc.push(&e, &mut batch);
            sent.push(e);
        }
        let mut dec = Decoder::new();
        let mut at = 0;
        for e in &sent {
            prop_assert_eq!(dec.next(&batch, &mut at), Some(e));
        }
        prop_assert_eq!(at, batch.len());
        prop_assert!(dec.next(&batch, &mut at).is_none());
    }
}

/// An edge equal to the one before is its header alone; the first edge after the zero state
/// sends only the words that differ from zero.
#[test]
fn unchanged_words_are_not_sent() {
    let mut enc = Encoder::new();
    let mut batch = Vec::new();
    let mut p = Probes::default();
    p.prescaler = 7;
    let e = Expected::new(&Inputs::default(), &Outputs::IDLE, &p);
    enc.push(&e, &mut batch);
    assert_eq!(batch.len(), 2, "header and the word with the prescaler");
    enc.push(&e, &mut batch);
    assert_eq!(batch.len(), 3, "the header alone");
    let mut dec = Decoder::new();
    let mut at = 0;
    assert_eq!(dec.next(&batch, &mut at), Some(&e));
    assert_eq!(dec.next(&batch, &mut at), Some(&e));
    assert_eq!(at, 3);
}
