//! The lock-step pair on two threads (docs/cosim.md "How it works", docs/performance.md).
//!
//! The stimulus is open-loop ([`crate::stimulus::Stimulus::next_txn`] never reads an output),
//! so the model side — stimulus, pin driver, golden model, coverage — can run ahead of the RTL.
//! [`run_pair`] runs the model side on the calling thread and the Verilated RTL on a second
//! thread; the model side hands over batches of [`Expected`] (the inputs of one edge and the
//! model's outputs and probes after it, in the bridge's layout, made on the model side) through
//! a bounded channel, and the RTL side applies the same inputs and compares
//! every cycle under the [`Compare`] mask, exactly as the single-thread loop does (inside the
//! bridge while the states are equal: [`Rtl::tick_agrees`]). It stops at the first
//! disagreement and reports only its cycle: the caller makes
//! the full report by running the single-thread loop again (the stimulus is seeded), so the
//! report is the same whichever way the run was made.

use std::sync::mpsc::{sync_channel, TryRecvError};

use tmc429_model::{Outputs, Probes};

use crate::rtl::{Expected, Rtl, Variant};
use crate::signals::{agree, Compare};

/// CLK cycles per batch handed from the model side to the RTL side.
pub const BATCH: usize = 1024;

/// Batches in flight between the two sides (about 2 MB): bounds the memory and how far the
/// model side runs past a mismatch. 16 batches are a few milliseconds of the RTL's work, so
/// that on a busy machine the RTL thread can go on while the model thread waits for a core.
const DEPTH: usize = 16;

/// Runs the model side (`fill`, on this thread) and the RTL of `variant` (on a second thread)
/// in lock-step. `reset`: the model's outputs and probes before the first edge. `fill` appends
/// the next edges to its (empty) argument, each as [`Expected::new`] of its inputs and the
/// model's outputs and probes after it — any number, usually [`BATCH`] — and returns whether
/// more follow; it is not called again after a mismatch was found.
///
/// Returns the first cycle whose states differ under `compare` (1 = the first edge, 0 = the
/// reset states), or `None` if every step agreed; `Err` if the RTL cannot be made (a build
/// without Verilator: [`crate::rtl::MISSING`]).
pub fn run_pair<F>(variant: Variant, compare: Compare, reset: (Outputs, Probes), mut fill: F) -> Result<Option<u64>, String>
where
    F: FnMut(&mut Vec<Expected>) -> bool,
{
    let (tx, rx) = sync_channel::<Vec<Expected>>(DEPTH);
    // emptied batches go back to the model side, so that no batch is allocated per round
    let (back_tx, back_rx) = sync_channel::<Vec<Expected>>(DEPTH + 2);
    std::thread::scope(|s| {
        let rtl_side = s.spawn(move || -> Result<Option<u64>, String> {
            let mut rtl = Rtl::try_new(variant)?;
            if !agree(compare, &reset.0, &reset.1, &rtl.outputs(), &rtl.probes()) {
                return Ok(Some(0));
            }
            let mut n = 0u64;
            for batch in rx {
                for e in &batch {
                    n += 1;
                    if !rtl.tick_agrees(e, compare) {
                        return Ok(Some(n));
                    }
                }
                let _ = back_tx.try_send(batch);
            }
            Ok(None)
        });
        loop {
            let mut buf = match back_rx.try_recv() {
                Ok(b) => b,
                Err(TryRecvError::Empty | TryRecvError::Disconnected) => Vec::with_capacity(BATCH),
            };
            buf.clear();
            let more = fill(&mut buf);
            // a send fails when the RTL side has stopped (mismatch or error)
            if (!buf.is_empty() && tx.send(buf).is_err()) || !more {
                break;
            }
        }
        drop(tx);
        rtl_side.join().unwrap_or_else(|e| std::panic::resume_unwind(e))
    })
}
