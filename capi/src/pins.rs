//! The pin-level entry (docs/c-api.md "Pin level and SystemVerilog DPI-C"): one call per CLK
//! edge with the input pins in one word and the output pins and probes out, and the seeded
//! stimulus of `tmc429 cosim` with its transaction log and first-mismatch report, so that a
//! SystemVerilog testbench (`capi/sv/tmc429_pkg.sv`) or any cycle-based testbench runs the model
//! beside a design under test. Words: bit k is the k-th pin of `tmc429_model::Inputs` /
//! `Outputs` (`tmc429_verif::pinword`); probes: the compared signals after the pins, in the order
//! of `tmc429_verif::signals::SIGNALS` (names by `tmc429_probe_name`).

use std::collections::BTreeMap;
use std::ffi::{c_char, c_int, CString};
use std::sync::{Arc, Mutex, OnceLock};

use tmc429_model::Outputs;
use tmc429_verif::lockstep::{Mismatch, PinSource};
use tmc429_verif::pinword::{pack_inputs, pack_outputs, unpack_inputs, unpack_outputs};
use tmc429_verif::signals::{flatten, Compare, N_PINS, N_SIGNALS, SIGNALS};
use tmc429_verif::stimulus::Profile;

use crate::{chip_of, guard, out_ref, with_sim, TMC429_ERR_ARG, TMC429_ERR_HANDLE, TMC429_ERR_INTERNAL, TMC429_OK};

/// Input pins in an input word (bits 0..9).
pub const TMC429_INPUT_PINS: u32 = 10;
/// Output pins in an output word (bits 0..10).
pub const TMC429_OUTPUT_PINS: u32 = 11;
/// Probes of `tmc429_tick_pins`.
pub const TMC429_PROBE_COUNT: u32 = 37;
const _: () = assert!(TMC429_PROBE_COUNT as usize == N_SIGNALS - N_PINS);

/// The input word of an idle bus with the switches open: nSCS_C, SCK_C and REFR1..3 high (the
/// levels before the first edge and during reset).
pub const TMC429_IDLE_INPUTS: u32 = 0x383;
const _: () = assert!(TMC429_IDLE_INPUTS == 0b11_1000_0011);

pub const TMC429_PROFILE_MOTION: c_int = 0;
pub const TMC429_PROFILE_MOTION_CORE: c_int = 1;
pub const TMC429_PROFILE_DRIVERS: c_int = 2;
pub const TMC429_PROFILE_REGISTERS: c_int = 3;
pub const TMC429_PROFILE_FULL: c_int = 4;

/// One rising CLK edge with the input pins of `inputs` (bit k: nSCS_C, SCK_C, SDI_C, SDI_S,
/// REF1..3, REFR1..3 for k = 0..9; higher bits must be 0); the output pins after it in
/// `*outputs` (bit k: nINT_SDO_C, SDOZ_C, SDOZ_C enable, nSCS_S, SCK_S, SDO_S, SDI_S out, SDI_S
/// enable, nSCS2, nSCS3, POSCMP for k = 0..10) and, unless `probes` is NULL, the
/// `TMC429_PROBE_COUNT` probes in `probes[]` (names: `tmc429_probe_name`). The pins stay as
/// given until the next call (or an SPI transfer, which drives the SPI pins itself).
///
/// # Safety
/// `outputs` must be valid for one `uint32_t`; `probes` NULL or valid for
/// `TMC429_PROBE_COUNT` values.
#[no_mangle]
pub unsafe extern "C" fn tmc429_tick_pins(h: u64, inputs: u32, outputs: *mut u32, probes: *mut u64) -> c_int {
    guard(|| {
        let out = out_ref(outputs)?;
        if inputs >> TMC429_INPUT_PINS != 0 {
            return Err(TMC429_ERR_ARG);
        }
        with_sim(h, |s| {
            *s.host.pins_mut() = unpack_inputs(inputs);
            s.host.wait(1);
            let o = s.host.outputs();
            *out = pack_outputs(&o);
            if !probes.is_null() {
                let all = flatten(&o, &s.host.chip().probes());
                // SAFETY: non-null; the caller provides TMC429_PROBE_COUNT elements (see header).
                let dst = unsafe { std::slice::from_raw_parts_mut(probes, TMC429_PROBE_COUNT as usize) };
                dst.copy_from_slice(&all[N_PINS..]);
            }
            Ok(TMC429_OK)
        })
    })
}

/// The output word after the last edge (after create or reset: the reset state, C2).
///
/// # Safety
/// `outputs` must be valid for one `uint32_t`.
#[no_mangle]
pub unsafe extern "C" fn tmc429_output_word(h: u64, outputs: *mut u32) -> c_int {
    guard(|| {
        let out = out_ref(outputs)?;
        with_sim(h, |s| {
            *out = pack_outputs(&s.host.outputs());
            Ok(TMC429_OK)
        })
    })
}

/// The name of probe `index` (0..TMC429_PROBE_COUNT-1) as the co-simulation's VCD scopes it,
/// e.g. "motor0.x_target", "chain.readback", "top.status"; "" for another index. Static,
/// NUL-terminated, never NULL.
#[no_mangle]
pub extern "C" fn tmc429_probe_name(index: u32) -> *const c_char {
    static NAMES: OnceLock<Vec<CString>> = OnceLock::new();
    static EMPTY: &[u8] = b"\0";
    let names = NAMES.get_or_init(|| {
        SIGNALS[N_PINS..].iter().map(|s| CString::new(format!("{}.{}", s.scope, s.name)).expect("signal names have no NUL")).collect()
    });
    names.get(index as usize).map_or(EMPTY.as_ptr() as *const c_char, |n| n.as_ptr())
}

// ---------------------------------------------------------------------------------------------
// The seeded stimulus.

struct Stim {
    src: PinSource,
    seed: u64,
    mismatch: Option<Mismatch>,
    /// The last report, NUL-terminated, owned here for `tmc429_stim_report`.
    report: CString,
}

/// Stimulus handles carry this bit, so that a chip handle passed where a stimulus handle is
/// expected (or the reverse) is detected as `TMC429_ERR_HANDLE`.
const STIM_BIT: u64 = 1 << 63;

struct Stims {
    next: u64,
    map: BTreeMap<u64, Arc<Mutex<Stim>>>,
}

static STIMS: Mutex<Stims> = Mutex::new(Stims { next: STIM_BIT | 1, map: BTreeMap::new() });

fn stims() -> std::sync::MutexGuard<'static, Stims> {
    STIMS.lock().unwrap_or_else(|e| e.into_inner())
}

fn with_stim<R>(h: u64, f: impl FnOnce(&mut Stim) -> Result<R, c_int>) -> Result<R, c_int> {
    let st = stims().map.get(&h).cloned().ok_or(TMC429_ERR_HANDLE)?;
    let mut g = st.lock().map_err(|_| TMC429_ERR_INTERNAL)?;
    f(&mut g)
}

fn profile_of(p: c_int) -> Result<Profile, c_int> {
    Ok(match p {
        TMC429_PROFILE_MOTION => Profile::Motion,
        TMC429_PROFILE_MOTION_CORE => Profile::MotionCore,
        TMC429_PROFILE_DRIVERS => Profile::Drivers,
        TMC429_PROFILE_REGISTERS => Profile::Registers,
        TMC429_PROFILE_FULL => Profile::Full,
        _ => return Err(TMC429_ERR_ARG),
    })
}

fn outputs_of(word: u32) -> Result<Outputs, c_int> {
    if word >> TMC429_OUTPUT_PINS != 0 {
        return Err(TMC429_ERR_ARG);
    }
    Ok(unpack_outputs(word))
}

/// The stimulus of `tmc429 cosim --chip VARIANT --profile PROFILE --seed SEED` (the same seed
/// gives the same pins, edge for edge). `variant`: `TMC429_CHIP_*`; `profile`:
/// `TMC429_PROFILE_*`. The handle goes to `*out`.
///
/// # Safety
/// `out` must be valid for one `uint64_t`.
#[no_mangle]
pub unsafe extern "C" fn tmc429_stim_create(variant: c_int, profile: c_int, seed: u64, out: *mut u64) -> c_int {
    guard(|| {
        let out = out_ref(out)?;
        let src = PinSource::new(chip_of(variant)?, profile_of(profile)?, seed);
        let st = Arc::new(Mutex::new(Stim { src, seed, mismatch: None, report: CString::default() }));
        let mut r = stims();
        let h = r.next;
        r.next += 1;
        r.map.insert(h, st);
        *out = h;
        Ok(TMC429_OK)
    })
}

/// Destroys a stimulus; the handle is invalid afterwards.
#[no_mangle]
pub extern "C" fn tmc429_stim_destroy(h: u64) -> c_int {
    guard(|| {
        let st = stims().map.remove(&h).ok_or(TMC429_ERR_HANDLE)?;
        drop(st);
        Ok(TMC429_OK)
    })
}

/// The input word of the next edge in `*inputs`. `model_outputs` and `dut_outputs`: the output
/// words of the model and of the design after the last edge (before the first: their reset
/// states); the µC's samples of their data pins make the replies of the transaction log.
///
/// # Safety
/// `inputs` must be valid for one `uint32_t`.
#[no_mangle]
pub unsafe extern "C" fn tmc429_stim_next(h: u64, model_outputs: u32, dut_outputs: u32, inputs: *mut u32) -> c_int {
    guard(|| {
        let inputs = out_ref(inputs)?;
        let (mo, d) = (outputs_of(model_outputs)?, outputs_of(dut_outputs)?);
        with_stim(h, |st| {
            *inputs = pack_inputs(&st.src.step(&mo, Some(&d)).inputs);
            Ok(TMC429_OK)
        })
    })
}

/// Compares the design's output word after the last edge with the model's: every pin, SDOZ_C and
/// SDI_S data only while both sides enable them. Returns 0 when they agree, 1 at a mismatch
/// (then and at every later check; `tmc429_stim_report` describes the first), or an error.
#[no_mangle]
pub extern "C" fn tmc429_stim_check(h: u64, model_outputs: u32, dut_outputs: u32) -> c_int {
    guard(|| {
        let (mo, d) = (outputs_of(model_outputs)?, outputs_of(dut_outputs)?);
        with_stim(h, |st| {
            if st.mismatch.is_none() {
                st.mismatch = st.src.check_pins(&mo, &d, Compare::pins());
            }
            Ok(st.mismatch.is_some() as c_int)
        })
    })
}

/// Edges, SPI frames and pin-change transactions so far.
///
/// # Safety
/// Each pointer must be valid for one `uint64_t`.
#[no_mangle]
pub unsafe extern "C" fn tmc429_stim_counts(h: u64, cycles: *mut u64, frames: *mut u64, pin_changes: *mut u64) -> c_int {
    guard(|| {
        let (c, f, p) = (out_ref(cycles)?, out_ref(frames)?, out_ref(pin_changes)?);
        with_stim(h, |st| {
            (*c, *f, *p) = (st.src.cycle(), st.src.frames(), st.src.pin_changes());
            Ok(TMC429_OK)
        })
    })
}

/// The report of the first mismatch as `tmc429 cosim` prints it (the differing pins, the last
/// SPI transactions decoded with both sides' replies), `label` naming the design (NULL: "dut");
/// "" without a mismatch or for an invalid handle. NUL-terminated, owned by the handle, valid
/// until the next call on it; never NULL.
///
/// # Safety
/// `label` must be NULL or a NUL-terminated string.
#[no_mangle]
pub unsafe extern "C" fn tmc429_stim_report(h: u64, label: *const c_char) -> *const c_char {
    static EMPTY: &[u8] = b"\0";
    // SAFETY: NULL or NUL-terminated (the caller's contract).
    let label = if label.is_null() { "dut".into() } else { unsafe { std::ffi::CStr::from_ptr(label) }.to_string_lossy().into_owned() };
    let made = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        with_stim(h, |st| {
            let text = st.mismatch.as_ref().map(|m| m.report(&label, st.src.chip(), st.seed)).unwrap_or_default();
            st.report = CString::new(text).unwrap_or_default();
            Ok(st.report.as_ptr())
        })
    }));
    match made {
        Ok(Ok(p)) => p,
        _ => EMPTY.as_ptr() as *const c_char,
    }
}
