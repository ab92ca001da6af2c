//! C ABI of the golden model: a virtual TMC428/TMC429/TMC4210 on the other end of a firmware's
//! SPI bus. The header is `capi/include/tmc429.h`; `tests/header.rs` checks it against
//! the `extern "C"` items of every module. User documentation: `docs/c-api.md`.
//!
//! # Conventions
//! - Every function returns `int`: `TMC429_OK` (0) or a non-negative count where documented on
//!   success, a negative `TMC429_ERR_*` code on failure. [`tmc429_abi_version`] and
//!   [`tmc429_strerror`] cannot fail.
//! - Every pointer argument must be non-null (else `TMC429_ERR_NULL`), properly aligned and valid
//!   for the documented number of elements (the C caller's side of the contract).
//!   Functions that take raw pointers are `unsafe fn` for Rust callers for that reason.
//! - Nothing unwinds across the boundary: every body runs under `catch_unwind`; a panic (a bug in
//!   the model or here, never an input) returns `TMC429_ERR_INTERNAL` and retires the handle.
//!
//! # Handles
//! A handle is a 64-bit number, never a pointer. Handles come from a process-wide registry and
//! are never reused within a process (a 64-bit counter from 1), so a destroyed, never-created or
//! zero handle is detected and returns `TMC429_ERR_HANDLE`; no call dereferences memory of a
//! destroyed chip. Different handles may be used from different threads at the same time; calls
//! on one handle from several threads are serialized by a lock.

mod pins;
pub use pins::*;

use std::ffi::{c_char, c_int, c_uint};
use std::sync::{Arc, Mutex};

use tmc429_model::host::MIN_SCK_HALF;
use tmc429_model::motor_regs::sext24;

mod bytewise;
pub use bytewise::*;
mod events;
pub use events::*;
mod handles;
use handles::*;
mod types;
pub use types::*;

// ---------------------------------------------------------------------------------------------
// Constants (mirrored as #defines in tmc429.h; tests/header.rs checks every value).

/// Version of this ABI; bumped on any change of the interface: a function or return code added,
/// a signature or struct changed. 2: the pin level (`pins`); 3: byte-wise SPI and the register
/// peek (`bytewise`).
pub const TMC429_ABI_VERSION: u32 = 3;

pub const TMC429_OK: c_int = 0;
/// A pointer argument is NULL.
pub const TMC429_ERR_NULL: c_int = -1;
/// The handle is 0, was never created, or was destroyed.
pub const TMC429_ERR_HANDLE: c_int = -2;
/// An SPI transfer length of 0 or more than 4 bytes, or a buffer too small.
pub const TMC429_ERR_LENGTH: c_int = -3;
/// An argument is out of its range (variant, fclk, SCK rate, pin, level, motor, event kind).
pub const TMC429_ERR_ARG: c_int = -4;
/// An internal error (a panic was caught); the handle is retired and only destroy works on it.
pub const TMC429_ERR_INTERNAL: c_int = -5;
/// The call does not fit the chip-select state: a byte transfer or deselect while nSCS_C is high,
/// a select or a whole-frame transfer while it is low.
pub const TMC429_ERR_STATE: c_int = -6;

pub const TMC429_CHIP_TMC428: c_int = 0;
pub const TMC429_CHIP_TMC429: c_int = 1;
pub const TMC429_CHIP_TMC4210: c_int = 2;

pub const TMC429_PIN_REF1: c_int = 0;
pub const TMC429_PIN_REF2: c_int = 1;
pub const TMC429_PIN_REF3: c_int = 2;
pub const TMC429_PIN_REFR1: c_int = 3;
pub const TMC429_PIN_REFR2: c_int = 4;
pub const TMC429_PIN_REFR3: c_int = 5;
pub const TMC429_PIN_SDI_S: c_int = 6;

pub const TMC429_EVENT_CHAIN: u32 = 0;
pub const TMC429_EVENT_STEP: u32 = 1;
pub const TMC429_EVENT_INT: u32 = 2;

/// Events kept at most; further events are counted by `tmc429_events_dropped` and lost.
pub const TMC429_EVENT_QUEUE_CAPACITY: u32 = 1_048_576;

// ---------------------------------------------------------------------------------------------
// The functions.

/// The ABI version this library implements (`TMC429_ABI_VERSION`).
#[no_mangle]
pub extern "C" fn tmc429_abi_version() -> u32 {
    TMC429_ABI_VERSION
}

/// A static, NUL-terminated description of an error code (never NULL).
#[no_mangle]
pub extern "C" fn tmc429_strerror(code: c_int) -> *const c_char {
    let s: &'static [u8] = match code {
        TMC429_ERR_NULL => b"null pointer argument\0",
        TMC429_ERR_HANDLE => b"invalid handle (zero, never created or destroyed)\0",
        TMC429_ERR_LENGTH => b"length out of range (SPI transfer: 1..4 bytes) or buffer too small\0",
        TMC429_ERR_ARG => b"argument out of range\0",
        TMC429_ERR_INTERNAL => b"internal error (handle retired)\0",
        TMC429_ERR_STATE => b"wrong chip-select state (byte transfer without select, or select twice)\0",
        c if c >= 0 => b"success\0",
        _ => b"unknown error code\0",
    };
    s.as_ptr() as *const c_char
}

/// Creates a chip in its power-on state. `variant`: `TMC429_CHIP_*`. `fclk_hz`: the CLK frequency
/// (0 = the variant's maximum: 16 MHz TMC428, 32 MHz otherwise; more than the maximum is an
/// error); it converts microseconds and SCK rates to CLK cycles. SCK starts at 4 CLK per half
/// period. The event queue is on.
///
/// # Safety
/// Each pointer must be NULL (reported as `TMC429_ERR_NULL`) or valid and aligned for the
/// documented number of elements.
#[no_mangle]
pub unsafe extern "C" fn tmc429_create(variant: c_int, fclk_hz: u32, out: *mut u64) -> c_int {
    guard(|| {
        let out = out_ref(out)?;
        let chip = chip_of(variant)?;
        let max = chip.default_fclk();
        let fclk = if fclk_hz == 0 { max } else { fclk_hz as u64 };
        if fclk > max {
            return Err(TMC429_ERR_ARG);
        }
        let sim = Arc::new(Mutex::new(Sim::new(chip, fclk)));
        let mut r = registry();
        let h = r.next;
        r.next += 1;
        r.map.insert(h, sim);
        *out = h;
        Ok(TMC429_OK)
    })
}

/// Destroys a chip. The handle is invalid afterwards (every call returns `TMC429_ERR_HANDLE`,
/// including a second destroy).
#[no_mangle]
pub extern "C" fn tmc429_destroy(h: u64) -> c_int {
    guard(|| {
        let sim = registry().map.remove(&h).ok_or(TMC429_ERR_HANDLE)?;
        // Dropped here, outside the registry lock (or later by a call still holding it).
        drop(sim);
        Ok(TMC429_OK)
    })
}

/// Power-on reset of the chip (register, RAM and pins as after create); the cycle counter
/// restarts at 0, the input pins return to idle (switches open, REFR pulled up), the event queue
/// and the dropped count are cleared. SCK rate and fclk are kept.
#[no_mangle]
pub extern "C" fn tmc429_reset(h: u64) -> c_int {
    guard(|| {
        with_sim(h, |s| {
            let chip = s.host.chip().chip();
            let half = s.host.sck_half();
            let mut n = Sim::new(chip, s.fclk);
            n.host.set_sck_half(half).map_err(|_| TMC429_ERR_INTERNAL)?;
            if !s.events_on {
                n.host.take_observer();
                n.events_on = false;
            }
            *s = n;
            Ok(TMC429_OK)
        })
    })
}

/// SCK_C half period in CLK cycles (at least 3, TMC428 Table 6-1).
#[no_mangle]
pub extern "C" fn tmc429_set_sck_half(h: u64, clk_cycles: u32) -> c_int {
    guard(|| with_sim(h, |s| s.host.set_sck_half(clk_cycles).map(|_| TMC429_OK).map_err(|_| TMC429_ERR_ARG)))
}

/// SCK_C frequency in Hz: the half period becomes ceil(fclk / (2·hz)) CLK cycles (the real rate
/// is the requested one or the next lower that is a whole number of CLK cycles). 0 or a rate
/// above fclk/6 rounded up to a whole Hz (fewer than 3 CLK per half period, TMC428 Table 6-1) is
/// `TMC429_ERR_ARG`.
#[no_mangle]
pub extern "C" fn tmc429_set_sck_hz(h: u64, hz: u32) -> c_int {
    guard(|| {
        with_sim(h, |s| {
            // Faster than fclk/6 would need fewer than 3 CLK per half period (TMC428 Table 6-1);
            // fclk/6 rounded up to a whole Hz is accepted and gives 3.
            if hz == 0 || hz as u64 > s.fclk.div_ceil(6) {
                return Err(TMC429_ERR_ARG);
            }
            let half = s.fclk.div_ceil(2 * hz as u64);
            let half = u32::try_from(half).map_err(|_| TMC429_ERR_ARG)?;
            if half < MIN_SCK_HALF {
                return Err(TMC429_ERR_ARG);
            }
            s.host.set_sck_half(half).map(|_| TMC429_OK).map_err(|_| TMC429_ERR_ARG)
        })
    })
}

/// The SCK_C half period in CLK cycles now in use.
///
/// # Safety
/// Each pointer must be NULL (reported as `TMC429_ERR_NULL`) or valid and aligned for the
/// documented number of elements.
#[no_mangle]
pub unsafe extern "C" fn tmc429_get_sck_half(h: u64, out: *mut u32) -> c_int {
    guard(|| {
        let out = out_ref(out)?;
        with_sim(h, |s| {
            *out = s.host.sck_half();
            Ok(TMC429_OK)
        })
    })
}

/// One SPI frame of `len` (1..4) bytes, MSB first: nSCS_C low, `8·len` SCK_C periods, nSCS_C
/// high (then one more half period). `rx` receives the `len` bytes the chip sent; it may be
/// the same buffer as `tx`. Only a 4-byte frame is a datagram the chip executes; a 1-byte frame
/// reads the status byte (TMC429 §6.2). Time advances by `(2 + 2·8·len)` half periods.
///
/// # Safety
/// Each pointer must be NULL (reported as `TMC429_ERR_NULL`) or valid and aligned for the
/// documented number of elements.
#[no_mangle]
pub unsafe extern "C" fn tmc429_spi_transfer(h: u64, tx: *const u8, rx: *mut u8, len: usize) -> c_int {
    guard(|| {
        if tx.is_null() || rx.is_null() {
            return Err(TMC429_ERR_NULL);
        }
        if !(1..=4).contains(&len) {
            return Err(TMC429_ERR_LENGTH);
        }
        let mut value = 0u32;
        for i in 0..len {
            // SAFETY: tx is non-null and valid for `len` bytes (caller's contract).
            value = (value << 8) | unsafe { *tx.add(i) } as u32;
        }
        let reply = with_sim(h, |s| {
            if s.host.selected() {
                return Err(TMC429_ERR_STATE);
            }
            Ok(s.host.frame(value, 8 * len as u32))
        })?;
        for i in 0..len {
            // SAFETY: rx is non-null and valid for `len` bytes; tx is no longer read.
            unsafe { *rx.add(i) = (reply >> (8 * (len - 1 - i))) as u8 };
        }
        Ok(TMC429_OK)
    })
}

/// Advances `cycles` CLK edges with the input pins as they are.
#[no_mangle]
pub extern "C" fn tmc429_advance_cycles(h: u64, cycles: u64) -> c_int {
    guard(|| {
        with_sim(h, |s| {
            s.host.wait(cycles);
            Ok(TMC429_OK)
        })
    })
}

/// Advances `us` microseconds: floor((us·fclk + r) / 10^6) CLK edges, where the remainder r of
/// earlier calls is carried, so n calls of 1 µs advance as one call of n µs.
#[no_mangle]
pub extern "C" fn tmc429_advance_us(h: u64, us: u64) -> c_int {
    guard(|| {
        with_sim(h, |s| {
            let total = us as u128 * s.fclk as u128 + s.us_rem as u128;
            let cycles = u64::try_from(total / 1_000_000).map_err(|_| TMC429_ERR_ARG)?;
            s.us_rem = (total % 1_000_000) as u64;
            s.host.wait(cycles);
            Ok(TMC429_OK)
        })
    })
}

/// CLK edges since power-on (or the last `tmc429_reset`).
///
/// # Safety
/// Each pointer must be NULL (reported as `TMC429_ERR_NULL`) or valid and aligned for the
/// documented number of elements.
#[no_mangle]
pub unsafe extern "C" fn tmc429_get_cycle(h: u64, out: *mut u64) -> c_int {
    guard(|| {
        let out = out_ref(out)?;
        with_sim(h, |s| {
            *out = s.host.cycle();
            Ok(TMC429_OK)
        })
    })
}

/// Sets an input pin (`TMC429_PIN_*`) to `level` 0 or 1 from the next CLK edge on. Pins pass the
/// chip's two-flop synchronizer (acted on two edges later). A pin the variant lacks (REFR on the
/// TMC428/TMC4210) is accepted and has no effect.
#[no_mangle]
pub extern "C" fn tmc429_set_pin(h: u64, pin: c_int, level: c_int) -> c_int {
    guard(|| {
        let v = match level {
            0 => false,
            1 => true,
            _ => return Err(TMC429_ERR_ARG),
        };
        if !(TMC429_PIN_REF1..=TMC429_PIN_SDI_S).contains(&pin) {
            return Err(TMC429_ERR_ARG);
        }
        with_sim(h, |s| {
            let p = s.host.pins_mut();
            match pin {
                TMC429_PIN_REF1 => p.ref1 = v,
                TMC429_PIN_REF2 => p.ref2 = v,
                TMC429_PIN_REF3 => p.ref3 = v,
                TMC429_PIN_REFR1 => p.refr1 = v,
                TMC429_PIN_REFR2 => p.refr2 = v,
                TMC429_PIN_REFR3 => p.refr3 = v,
                _ => p.sdi_s = v,
            }
            Ok(TMC429_OK)
        })
    })
}

/// All output pins after the last CLK edge.
///
/// # Safety
/// Each pointer must be NULL (reported as `TMC429_ERR_NULL`) or valid and aligned for the
/// documented number of elements.
#[no_mangle]
pub unsafe extern "C" fn tmc429_get_outputs(h: u64, out: *mut tmc429_outputs_t) -> c_int {
    guard(|| {
        let out = out_ref(out)?;
        with_sim(h, |s| {
            let o = s.host.outputs();
            *out = tmc429_outputs_t {
                nint_sdo_c: o.nint_sdo_c as u8,
                sdoz_c: o.sdoz_c as u8,
                sdoz_c_oe: o.sdoz_c_oe as u8,
                nscs_s: o.nscs_s as u8,
                sck_s: o.sck_s as u8,
                sdo_s: o.sdo_s as u8,
                sdi_s_o: o.sdi_s_o as u8,
                sdi_s_oe: o.sdi_s_oe as u8,
                nscs2: o.nscs2 as u8,
                nscs3: o.nscs3 as u8,
                poscmp: o.poscmp as u8,
                reserved: 0,
            };
            Ok(TMC429_OK)
        })
    })
}

/// Levels of the STEP and DIR pins (bit m = motor m) as the pins carry them in Step/Dir mode
/// (TMC429 §10: STEP1..3 = SDO_S, nSCS_S, nSCS2; DIR1..3 = SCK_S, SDI_S, nSCS3). In SPI mode
/// these are the driver-chain pins' levels.
///
/// # Safety
/// Each pointer must be NULL (reported as `TMC429_ERR_NULL`) or valid and aligned for the
/// documented number of elements.
#[no_mangle]
pub unsafe extern "C" fn tmc429_get_step_dir(h: u64, step: *mut u8, dir: *mut u8) -> c_int {
    guard(|| {
        let step = out_ref(step)?;
        let dir = out_ref(dir)?;
        with_sim(h, |s| {
            let o = s.host.outputs();
            *step = o.sdo_s as u8 | (o.nscs_s as u8) << 1 | (o.nscs2 as u8) << 2;
            *dir = o.sck_s as u8 | (o.sdi_s_o as u8) << 1 | (o.nscs3 as u8) << 2;
            Ok(TMC429_OK)
        })
    })
}

/// Probes of motor `motor` (0..2; the TMC4210 has motor 0 only).
///
/// # Safety
/// Each pointer must be NULL (reported as `TMC429_ERR_NULL`) or valid and aligned for the
/// documented number of elements.
#[no_mangle]
pub unsafe extern "C" fn tmc429_get_motor_probe(h: u64, motor: c_uint, out: *mut tmc429_motor_probe_t) -> c_int {
    guard(|| {
        let out = out_ref(out)?;
        with_sim(h, |s| {
            let chip = s.host.chip();
            let m = motor as usize;
            if m >= chip.motor_count() {
                return Err(TMC429_ERR_ARG);
            }
            let p = chip.probes().motor[m];
            *out = tmc429_motor_probe_t {
                x_target: sext24(p.x_target),
                x_actual: sext24(p.x_actual),
                v_internal: p.v_internal,
                v_actual: chip.motor(m).v_actual(),
                v_target: p.v_target,
                a_actual: p.a_actual,
                ustep: p.ustep,
                step: p.step,
                dir: p.dir,
                reserved: 0,
            };
            Ok(TMC429_OK)
        })
    })
}

/// The status byte `INT CDGW RS3 xEQt3 RS2 xEQt2 RS1 xEQt1` of the current state (what the chip
/// would send if a frame started now), without SPI traffic.
///
/// # Safety
/// Each pointer must be NULL (reported as `TMC429_ERR_NULL`) or valid and aligned for the
/// documented number of elements.
#[no_mangle]
pub unsafe extern "C" fn tmc429_get_status(h: u64, out: *mut u8) -> c_int {
    guard(|| {
        let out = out_ref(out)?;
        with_sim(h, |s| {
            *out = s.host.chip().status();
            Ok(TMC429_OK)
        })
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_panic_becomes_an_error_code() {
        let prev = std::panic::take_hook();
        std::panic::set_hook(Box::new(|_| {}));
        let r = guard(|| panic!("boom"));
        std::panic::set_hook(prev);
        assert_eq!(r, TMC429_ERR_INTERNAL);
    }

    #[test]
    fn sign_extension_of_24_bit_positions() {
        assert_eq!(sext24(0xFF_FFFF), -1);
        assert_eq!(sext24(0x80_0000), -8_388_608);
        assert_eq!(sext24(0x7F_FFFF), 8_388_607);
    }
}
