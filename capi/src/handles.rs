//! The chip behind a handle: the registry of handles, the host and event queue of each, and the
//! guard every C function runs its body under (module documentation of the crate: "Handles").

use std::collections::{BTreeMap, VecDeque};
use std::ffi::c_int;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::{Arc, Mutex};

use tmc429_model::events::{Event, EventDecoder};
use tmc429_model::host::Host;
use tmc429_model::{Chip, Tmc429};

use crate::{TMC429_ERR_ARG, TMC429_ERR_HANDLE, TMC429_ERR_INTERNAL, TMC429_ERR_NULL, TMC429_EVENT_QUEUE_CAPACITY};

pub(crate) struct Queue {
    pub(crate) events: VecDeque<Event>,
    pub(crate) dropped: u64,
}

pub(crate) type SharedQueue = Arc<Mutex<Queue>>;

pub(crate) fn lock_queue(q: &SharedQueue) -> std::sync::MutexGuard<'_, Queue> {
    // Pushing and draining cannot panic half-way; a poisoned queue is still consistent.
    q.lock().unwrap_or_else(|e| e.into_inner())
}

pub(crate) struct Sim {
    pub(crate) host: Host,
    pub(crate) fclk: u64,
    /// Remainder (in µs·Hz) of `tmc429_advance_us` calls, so repeated calls do not drift.
    pub(crate) us_rem: u64,
    /// Filled by the observer of `host` (which owns the decoder), emptied by the drain.
    pub(crate) queue: SharedQueue,
    pub(crate) events_on: bool,
}

/// Installs a fresh pin-level decoder as the host's observer of the edges that may change a
/// pin (the fast path's edges change none). The decoder lives in the closure; the shared queue
/// is locked only when an event occurs, not at every edge.
pub(crate) fn attach_decoder(host: &mut Host, queue: &SharedQueue) {
    let q = Arc::clone(queue);
    let mut dec = EventDecoder::new();
    host.set_change_observer(Box::new(move |chip: &Tmc429, _inp, out| {
        dec.observe(chip, out, chip.cycle(), &mut |e| {
            let mut q = lock_queue(&q);
            if q.events.len() < TMC429_EVENT_QUEUE_CAPACITY as usize {
                q.events.push_back(e);
            } else {
                q.dropped += 1;
            }
        });
    }));
}

impl Sim {
    pub(crate) fn new(chip: Chip, fclk: u64) -> Sim {
        let queue = Arc::new(Mutex::new(Queue { events: VecDeque::new(), dropped: 0 }));
        let mut host = Host::new(chip);
        attach_decoder(&mut host, &queue);
        Sim { host, fclk, us_rem: 0, queue, events_on: true }
    }
}

pub(crate) struct Registry {
    pub(crate) next: u64,
    pub(crate) map: BTreeMap<u64, Arc<Mutex<Sim>>>,
}

static REGISTRY: Mutex<Registry> = Mutex::new(Registry { next: 1, map: BTreeMap::new() });

pub(crate) fn registry() -> std::sync::MutexGuard<'static, Registry> {
    // Nothing panics while the registry lock is held; a poisoned lock still holds a valid map.
    REGISTRY.lock().unwrap_or_else(|e| e.into_inner())
}

/// Runs `f` and turns a panic into `TMC429_ERR_INTERNAL`.
pub(crate) fn guard(f: impl FnOnce() -> Result<c_int, c_int>) -> c_int {
    match catch_unwind(AssertUnwindSafe(f)) {
        Ok(Ok(v)) => v,
        Ok(Err(e)) => e,
        Err(_) => TMC429_ERR_INTERNAL,
    }
}

/// Runs `f` on the chip of handle `h`.
pub(crate) fn with_sim<R>(h: u64, f: impl FnOnce(&mut Sim) -> Result<R, c_int>) -> Result<R, c_int> {
    let sim = registry().map.get(&h).cloned().ok_or(TMC429_ERR_HANDLE)?;
    // A poisoned lock means a panic inside an earlier call: the state may be torn.
    let mut g = sim.lock().map_err(|_| TMC429_ERR_INTERNAL)?;
    f(&mut g)
}

/// # Safety
/// `p` is NULL or valid and aligned for one `T`.
pub(crate) unsafe fn out_ref<'a, T>(p: *mut T) -> Result<&'a mut T, c_int> {
    // SAFETY: non-null checked; alignment and validity are the caller's contract (see header).
    unsafe { p.as_mut() }.ok_or(TMC429_ERR_NULL)
}

pub(crate) fn chip_of(variant: c_int) -> Result<Chip, c_int> {
    u32::try_from(variant).ok().and_then(Chip::from_rtl_param).ok_or(TMC429_ERR_ARG)
}
