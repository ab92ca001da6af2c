//! The lock-step pair on two threads (docs/cosim.md "How it works", docs/performance.md).
//!
//! The stimulus is open-loop ([`crate::stimulus::Stimulus::next_txn`] never reads an output),
//! so the model side — stimulus, pin driver, golden model, coverage — can run ahead of the RTL.
//! [`run_pair`] runs the model side on the calling thread and the Verilated RTL on a second
//! thread; the model side makes each edge as [`Expected`] (the inputs of the edge and the
//! model's outputs and probes after it, in the bridge's layout) and hands the edges through a
//! bounded channel, each as the words of it that changed since the edge before
//! ([`crate::rtl::wire`]: two words per edge on the regression's stimulus, where the struct is
//! 136 bytes, so that the RTL side's core reads little of the model side's memory). The RTL
//! side decodes them, applies the same inputs and compares every cycle under the [`Compare`]
//! mask, exactly as the single-thread loop does (inside the bridge while the states are
//! equal: [`Rtl::tick_agrees`]). It stops at the first disagreement and reports only its
//! cycle: the caller makes the full report by running the single-thread loop again (the
//! stimulus is seeded), so the report is the same whichever way the run was made.

#[cfg(not(tmc429_no_rtl))]
use std::sync::mpsc::{sync_channel, TryRecvError};

use tmc429_model::{Outputs, Probes};

#[cfg(not(tmc429_no_rtl))]
use crate::rtl::wire::{Decoder, Encoder};
#[cfg(not(tmc429_no_rtl))]
use crate::rtl::Rtl;
use crate::rtl::{Expected, Variant};
#[cfg(not(tmc429_no_rtl))]
use crate::signals::agree;
use crate::signals::Compare;

/// CLK cycles `fill` is asked for in one call.
pub const BATCH: usize = 1024;

/// Calls of `fill` per message to the RTL side: each message the RTL side takes may wake the
/// model side, which waits while the channel is full, and a wake-up costs microseconds.
#[cfg(not(tmc429_no_rtl))]
const FILLS: usize = 8;

/// Messages in flight between the two sides (about 130 KB each: two words per edge on the
/// regression's stimulus): bounds the memory and how far
/// the model side runs past a mismatch. 4 messages are a few milliseconds of the RTL's work,
/// so that on a busy machine the RTL thread can go on while the model thread waits for a core.
#[cfg(not(tmc429_no_rtl))]
const DEPTH: usize = 4;

/// Runs the model side (`fill`, on this thread) and the RTL of `variant` (on a second thread)
/// in lock-step. `reset`: the model's outputs and probes before the first edge. `fill` appends
/// the next edges to its (empty) argument, each as [`Expected::new`] of its inputs and the
/// model's outputs and probes after it — any number, usually [`BATCH`] — and returns whether
/// more follow; it is not called again after a mismatch was found.
///
/// Returns the first cycle whose states differ under `compare` (1 = the first edge, 0 = the
/// reset states), or `None` if every step agreed; `Err` if the RTL cannot be made (a build
/// without Verilator: [`crate::rtl::MISSING`]).
#[cfg(not(tmc429_no_rtl))]
pub fn run_pair<F>(variant: Variant, compare: Compare, reset: (Outputs, Probes), mut fill: F) -> Result<Option<u64>, String>
where
    F: FnMut(&mut Vec<Expected>) -> bool,
{
    let (tx, rx) = sync_channel::<Vec<u64>>(DEPTH);
    // emptied batches go back to the model side, so that no batch is allocated per round
    let (back_tx, back_rx) = sync_channel::<Vec<u64>>(DEPTH + 2);
    std::thread::scope(|s| {
        let rtl_side = s.spawn(move || -> Result<Option<u64>, String> {
            let mut rtl = Rtl::try_new(variant)?;
            if !agree(compare, &reset.0, &reset.1, &rtl.outputs(), &rtl.probes()) {
                return Ok(Some(0));
            }
            let mut wire = Decoder::new();
            let mut n = 0u64;
            for batch in rx {
                let mut at = 0;
                while let Some(e) = wire.next(&batch, &mut at) {
                    n += 1;
                    if !rtl.tick_agrees(e, compare) {
                        return Ok(Some(n));
                    }
                }
                let _ = back_tx.try_send(batch);
            }
            Ok(None)
        });
        let mut wire = Encoder::new();
        let mut edges = Vec::with_capacity(BATCH);
        loop {
            let mut buf = match back_rx.try_recv() {
                Ok(b) => b,
                Err(TryRecvError::Empty | TryRecvError::Disconnected) => Vec::with_capacity(4 * FILLS * BATCH),
            };
            buf.clear();
            let mut more = true;
            for _ in 0..FILLS {
                edges.clear();
                more = fill(&mut edges);
                for e in &edges {
                    wire.push(e, &mut buf);
                }
                if !more {
                    break;
                }
            }
            // a send fails when the RTL side has stopped (mismatch or error)
            if (!buf.is_empty() && tx.send(buf).is_err()) || !more {
                break;
            }
        }
        drop(tx);
        rtl_side.join().unwrap_or_else(|e| std::panic::resume_unwind(e))
    })
}

/// Without Verilator there is no RTL side: [`crate::rtl::MISSING`], as [`Rtl::try_new`] gives.
#[cfg(tmc429_no_rtl)]
pub fn run_pair<F>(_variant: Variant, _compare: Compare, _reset: (Outputs, Probes), _fill: F) -> Result<Option<u64>, String>
where
    F: FnMut(&mut Vec<Expected>) -> bool,
{
    Err(crate::rtl::MISSING.to_string())
}
