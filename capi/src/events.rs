//! Events (docs/c-api.md "Semantics"): the driver-chain datagrams, Step/Dir pulses and INT
//! changes decoded from the pins into a bounded queue per handle, drained by the caller.

use std::ffi::{c_char, c_int};

use tmc429_model::events::Event;

use crate::{
    attach_decoder, guard, lock_queue, out_ref, tmc429_event_t, with_sim, TMC429_ERR_ARG, TMC429_ERR_LENGTH, TMC429_ERR_NULL,
    TMC429_EVENT_CHAIN, TMC429_EVENT_INT, TMC429_EVENT_STEP, TMC429_OK,
};

/// Turns event decoding on (1) or off (0); off runs faster. Turning it on restarts the
/// decoder: it reports an INT that is high at the first edge after. The queue is kept.
#[no_mangle]
pub extern "C" fn tmc429_events_enable(h: u64, on: c_int) -> c_int {
    guard(|| {
        let on = match on {
            0 => false,
            1 => true,
            _ => return Err(TMC429_ERR_ARG),
        };
        with_sim(h, |s| {
            if on && !s.events_on {
                attach_decoder(&mut s.host, &s.queue);
            } else if !on && s.events_on {
                s.host.take_observer();
            }
            s.events_on = on;
            Ok(TMC429_OK)
        })
    })
}

/// Number of events waiting in the queue.
///
/// # Safety
/// Each pointer must be NULL (reported as `TMC429_ERR_NULL`) or valid and aligned for the
/// documented number of elements.
#[no_mangle]
pub unsafe extern "C" fn tmc429_events_pending(h: u64, out: *mut usize) -> c_int {
    guard(|| {
        let out = out_ref(out)?;
        with_sim(h, |s| {
            *out = lock_queue(&s.queue).events.len();
            Ok(TMC429_OK)
        })
    })
}

/// Moves up to `cap` (≥ 1) of the oldest events into `buf`, oldest first; returns how many.
///
/// # Safety
/// Each pointer must be NULL (reported as `TMC429_ERR_NULL`) or valid and aligned for the
/// documented number of elements.
#[no_mangle]
pub unsafe extern "C" fn tmc429_events_drain(h: u64, buf: *mut tmc429_event_t, cap: usize) -> c_int {
    guard(|| {
        if buf.is_null() {
            return Err(TMC429_ERR_NULL);
        }
        if cap == 0 {
            return Err(TMC429_ERR_LENGTH);
        }
        with_sim(h, |s| {
            let mut q = lock_queue(&s.queue);
            let n = q.events.len().min(cap).min(c_int::MAX as usize);
            for (i, e) in q.events.drain(..n).enumerate() {
                // SAFETY: buf is non-null and valid for `cap` ≥ n elements (caller's contract).
                unsafe { buf.add(i).write(to_c_event(&e)) };
            }
            Ok(n as c_int)
        })
    })
}

/// Events lost because the queue held `TMC429_EVENT_QUEUE_CAPACITY` events.
///
/// # Safety
/// Each pointer must be NULL (reported as `TMC429_ERR_NULL`) or valid and aligned for the
/// documented number of elements.
#[no_mangle]
pub unsafe extern "C" fn tmc429_events_dropped(h: u64, out: *mut u64) -> c_int {
    guard(|| {
        let out = out_ref(out)?;
        with_sim(h, |s| {
            *out = lock_queue(&s.queue).dropped;
            Ok(TMC429_OK)
        })
    })
}

/// Writes the event as one line of `tmc429 spi --events` (no newline), NUL-terminated, into
/// `buf` of `cap` bytes; returns the length without the NUL. `TMC429_ERR_LENGTH` when the line
/// and its NUL do not fit (64 bytes do for nbits ≤ 64); `TMC429_ERR_ARG` for an unknown kind,
/// a motor above 2 or a flag (negative, level) other than 0 or 1.
///
/// # Safety
/// Each pointer must be NULL (reported as `TMC429_ERR_NULL`) or valid and aligned for the
/// documented number of elements.
#[no_mangle]
pub unsafe extern "C" fn tmc429_event_format(ev: *const tmc429_event_t, buf: *mut c_char, cap: usize) -> c_int {
    guard(|| {
        // SAFETY: non-null checked; validity is the caller's contract.
        let ev = unsafe { ev.as_ref() }.ok_or(TMC429_ERR_NULL)?;
        if buf.is_null() {
            return Err(TMC429_ERR_NULL);
        }
        let e = from_c_event(ev)?;
        // A chain line pads the bits to nbits/4 digits: refuse before formatting what cannot fit.
        if ev.kind == TMC429_EVENT_CHAIN && ev.nbits.div_ceil(4) as usize >= cap {
            return Err(TMC429_ERR_LENGTH);
        }
        let line = e.to_string();
        if line.len() + 1 > cap {
            return Err(TMC429_ERR_LENGTH);
        }
        // SAFETY: buf valid for cap ≥ len + 1 bytes.
        unsafe {
            std::ptr::copy_nonoverlapping(line.as_ptr(), buf as *mut u8, line.len());
            *buf.add(line.len()) = 0;
        }
        Ok(line.len() as c_int)
    })
}

/// The C form of an event.
pub fn to_c_event(e: &Event) -> tmc429_event_t {
    let mut c = tmc429_event_t { cycle: e.cycle(), ..Default::default() };
    match *e {
        Event::Chain { nbits, bits, .. } => {
            c.kind = TMC429_EVENT_CHAIN;
            c.nbits = nbits;
            c.bits = bits;
        }
        Event::Step { motor, negative, .. } => {
            c.kind = TMC429_EVENT_STEP;
            c.motor = motor;
            c.negative = negative as u8;
        }
        Event::Int { level, .. } => {
            c.kind = TMC429_EVENT_INT;
            c.level = level as u8;
        }
    }
    c
}

/// The model's form of a C event (`TMC429_ERR_ARG` for an unknown kind or a field out of range).
pub fn from_c_event(c: &tmc429_event_t) -> Result<Event, c_int> {
    let cycle = c.cycle;
    match c.kind {
        TMC429_EVENT_CHAIN => Ok(Event::Chain { cycle, nbits: c.nbits, bits: c.bits }),
        TMC429_EVENT_STEP if c.motor <= 2 && c.negative <= 1 => Ok(Event::Step { cycle, motor: c.motor, negative: c.negative != 0 }),
        TMC429_EVENT_INT if c.level <= 1 => Ok(Event::Int { cycle, level: c.level != 0 }),
        _ => Err(TMC429_ERR_ARG),
    }
}
