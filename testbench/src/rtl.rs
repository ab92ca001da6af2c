//! The Verilated RTL (rtl/tmc429_top.v) behind a cxx bridge: one FFI call per CLK cycle.
//!
//! A build without Verilator (testbench/build.rs sets the cfg `tmc429_no_rtl`) has no bridge:
//! [`AVAILABLE`] is false, [`Rtl::try_new`] returns [`MISSING`], and an [`Rtl`] cannot exist.

use std::fmt;
use std::path::Path;

#[cfg(not(tmc429_no_rtl))]
use tmc429_model::{ChainProbe, MotorProbe};
use tmc429_model::{Chip, Inputs, Outputs, Probes};

#[cfg(not(tmc429_no_rtl))]
pub mod wire;

/// Whether this build has the Verilated RTL (Verilator was found at build time).
pub const AVAILABLE: bool = !cfg!(tmc429_no_rtl);

/// Why the RTL is missing and what to do: the start of the error of every command that needs
/// it (the commands add their own alternative, such as `--engine model`).
pub const MISSING: &str = "Verilator not found: install it with scripts/setup (Debian: apt-get install verilator)";

/// `Ok` when the RTL is built in, else [`MISSING`] with `alternative` (e.g. "or use
/// --engine model") appended after a comma.
pub fn require(alternative: &str) -> Result<(), String> {
    if AVAILABLE {
        Ok(())
    } else if alternative.is_empty() {
        Err(MISSING.to_string())
    } else {
        Err(format!("{MISSING}, {alternative}"))
    }
}

#[cfg(not(tmc429_no_rtl))]
#[cxx::bridge(namespace = "tmc429tb")]
mod ffi {
    /// Mirror of `tmc429_model::Inputs`.
    #[derive(Clone, Copy, Debug, Default, PartialEq)]
    struct RtlInputs {
        nscs_c: bool,
        sck_c: bool,
        sdi_c: bool,
        sdi_s: bool,
        ref1: bool,
        ref2: bool,
        ref3: bool,
        refr1: bool,
        refr2: bool,
        refr3: bool,
    }

    /// Mirror of `tmc429_model::Outputs`.
    #[derive(Clone, Copy, Debug, Default, PartialEq)]
    struct RtlOutputs {
        nint_sdo_c: bool,
        sdoz_c: bool,
        sdoz_c_oe: bool,
        nscs_s: bool,
        sck_s: bool,
        sdo_s: bool,
        sdi_s_o: bool,
        sdi_s_oe: bool,
        nscs2: bool,
        nscs3: bool,
        poscmp: bool,
    }

    /// Mirror of `tmc429_model::MotorProbe`.
    #[derive(Clone, Copy, Debug, Default, PartialEq)]
    struct RtlMotorProbe {
        x_target: u32,
        x_actual: u32,
        v_internal: i32,
        v_target: i32,
        a_actual: i32,
        ustep: u32,
        step: u8,
        dir: u8,
        pulse_acc: u16,
    }

    /// Mirror of `tmc429_model::ChainProbe`.
    #[derive(Clone, Copy, Debug, Default, PartialEq)]
    struct RtlChainProbe {
        state: u8,
        cell: u8,
        motor: u8,
        bit_count: u8,
        pending: u8,
        cover_waiting: u8,
        readback: u64,
    }

    /// Mirror of `tmc429_model::Probes`.
    #[derive(Clone, Copy, Debug, Default, PartialEq)]
    struct RtlProbes {
        m0: RtlMotorProbe,
        m1: RtlMotorProbe,
        m2: RtlMotorProbe,
        chain: RtlChainProbe,
        prescaler: u32,
        power_down: u8,
        status: u8,
    }

    unsafe extern "C++" {
        include!("tmc429-testbench/cpp/rtl_bridge.h");

        type RtlSim;

        fn new_rtl(variant: u32, traced: bool) -> UniquePtr<RtlSim>;
        fn tick(self: Pin<&mut RtlSim>, inp: &RtlInputs, out: &mut RtlOutputs, probes: &mut RtlProbes);
        fn tick_check(self: Pin<&mut RtlSim>, inp: &RtlInputs, out: &RtlOutputs, probes: &RtlProbes) -> bool;
        fn peek(self: &RtlSim, out: &mut RtlOutputs, probes: &mut RtlProbes);
        fn trace_open(self: Pin<&mut RtlSim>, path: &str, period_ps: u64) -> bool;
        fn trace_close(self: Pin<&mut RtlSim>);
        fn cycle(self: &RtlSim) -> u64;
    }
}

/// Which Verilated model: one per chip variant, plus the planted-bug build.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Variant {
    /// The RTL with `CHIP` set for this chip.
    Chip(Chip),
    /// TMC429 built with `PLANT_BUG_STATUS`: the CDGW status bit ignores the
    /// datagram-waiting flag. Exists to prove that the harness catches a one-bit bug.
    PlantedStatusBug,
}

impl Variant {
    pub fn chip(self) -> Chip {
        match self {
            Variant::Chip(c) => c,
            Variant::PlantedStatusBug => Chip::Tmc429,
        }
    }
    #[cfg_attr(tmc429_no_rtl, allow(dead_code))]
    fn code(self) -> u32 {
        match self {
            Variant::Chip(c) => c.rtl_param(),
            Variant::PlantedStatusBug => 3,
        }
    }
}

impl fmt::Display for Variant {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Variant::Chip(c) => write!(f, "{c}"),
            Variant::PlantedStatusBug => f.write_str("tmc429+PLANT_BUG_STATUS"),
        }
    }
}

/// One edge's inputs and the state expected after it (the model's outputs and probes), in the
/// bridge's layout: [`Rtl::tick_agrees`] compares the RTL with it inside the bridge, without
/// copying the RTL's state out. Made on the model side of the two-thread pair (crate::pair).
#[cfg(not(tmc429_no_rtl))]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Expected {
    inp: ffi::RtlInputs,
    out: ffi::RtlOutputs,
    probes: ffi::RtlProbes,
}

/// Builds a `$to` from the same-named fields of `$x`: the model's and the bridge's structs
/// of pins and probes have the same fields (one list per struct, used in both directions).
#[cfg(not(tmc429_no_rtl))]
macro_rules! same_fields {
    (outputs $($to:ident)::+, $x:expr) => {
        $($to)::+ {
            nint_sdo_c: $x.nint_sdo_c,
            sdoz_c: $x.sdoz_c,
            sdoz_c_oe: $x.sdoz_c_oe,
            nscs_s: $x.nscs_s,
            sck_s: $x.sck_s,
            sdo_s: $x.sdo_s,
            sdi_s_o: $x.sdi_s_o,
            sdi_s_oe: $x.sdi_s_oe,
            nscs2: $x.nscs2,
            nscs3: $x.nscs3,
            poscmp: $x.poscmp,
        }
    };
    (motor $($to:ident)::+, $x:expr) => {
        $($to)::+ {
            x_target: $x.x_target,
            x_actual: $x.x_actual,
            v_internal: $x.v_internal,
            v_target: $x.v_target,
            a_actual: $x.a_actual,
            ustep: $x.ustep,
            step: $x.step,
            dir: $x.dir,
            pulse_acc: $x.pulse_acc,
        }
    };
    (chain $($to:ident)::+, $x:expr) => {
        $($to)::+ {
            state: $x.state,
            cell: $x.cell,
            motor: $x.motor,
            bit_count: $x.bit_count,
            pending: $x.pending,
            cover_waiting: $x.cover_waiting,
            readback: $x.readback,
        }
    };
}

#[cfg(not(tmc429_no_rtl))]
impl Expected {
    pub fn new(i: &Inputs, o: &Outputs, p: &Probes) -> Expected {
        let m = |x: &MotorProbe| same_fields!(motor ffi::RtlMotorProbe, x);
        Expected {
            inp: rtl_inputs(i),
            out: same_fields!(outputs ffi::RtlOutputs, o),
            probes: ffi::RtlProbes {
                m0: m(&p.motor[0]),
                m1: m(&p.motor[1]),
                m2: m(&p.motor[2]),
                chain: same_fields!(chain ffi::RtlChainProbe, p.chain),
                prescaler: p.prescaler,
                power_down: p.power_down,
                status: p.status,
            },
        }
    }

    /// The expected outputs and probes, back in the model's types.
    pub fn model(&self) -> (Outputs, Probes) {
        (outputs(&self.out), probes(&self.probes))
    }
}

#[cfg(not(tmc429_no_rtl))]
#[inline]
fn rtl_inputs(i: &Inputs) -> ffi::RtlInputs {
    ffi::RtlInputs {
        nscs_c: i.nscs_c,
        sck_c: i.sck_c,
        sdi_c: i.sdi_c,
        sdi_s: i.sdi_s,
        ref1: i.ref1,
        ref2: i.ref2,
        ref3: i.ref3,
        refr1: i.refr1,
        refr2: i.refr2,
        refr3: i.refr3,
    }
}

#[cfg(not(tmc429_no_rtl))]
#[inline]
fn outputs(o: &ffi::RtlOutputs) -> Outputs {
    same_fields!(outputs Outputs, o)
}

#[cfg(not(tmc429_no_rtl))]
#[inline]
fn probes(p: &ffi::RtlProbes) -> Probes {
    let m = |x: &ffi::RtlMotorProbe| same_fields!(motor MotorProbe, x);
    Probes {
        motor: [m(&p.m0), m(&p.m1), m(&p.m2)],
        chain: same_fields!(chain ChainProbe, p.chain),
        prescaler: p.prescaler,
        power_down: p.power_down,
        status: p.status,
    }
}

/// A Verilated `tmc429_top`, in the reset state after construction.
///
/// Two builds of each variant exist (testbench/build.rs): [`Rtl::new`] takes the one without
/// Verilator's trace code (faster), [`Rtl::new_traced`] the one with it, the only one on which
/// [`Rtl::trace_open`] works.
#[cfg(not(tmc429_no_rtl))]
pub struct Rtl {
    sim: cxx::UniquePtr<ffi::RtlSim>,
    variant: Variant,
    traced: bool,
    out: ffi::RtlOutputs,
    probes: ffi::RtlProbes,
}

#[cfg(not(tmc429_no_rtl))]
impl Rtl {
    /// The model of `variant`, or [`MISSING`] in a build without Verilator.
    pub fn try_new(variant: Variant) -> Result<Rtl, String> {
        Ok(Rtl::new(variant))
    }

    /// The model of `variant` built with Verilator's trace, or [`MISSING`].
    pub fn try_new_traced(variant: Variant) -> Result<Rtl, String> {
        Ok(Rtl::build(variant, true))
    }

    /// The model of `variant` without trace code.
    pub fn new(variant: Variant) -> Rtl {
        Rtl::build(variant, false)
    }

    /// The model of `variant` built with Verilator's trace ([`Rtl::trace_open`]).
    pub fn new_traced(variant: Variant) -> Rtl {
        Rtl::build(variant, true)
    }

    fn build(variant: Variant, traced: bool) -> Rtl {
        let sim = ffi::new_rtl(variant.code(), traced);
        assert!(!sim.is_null(), "every Variant has a Verilated model");
        let mut rtl = Rtl { sim, variant, traced, out: ffi::RtlOutputs::default(), probes: ffi::RtlProbes::default() };
        rtl.sim.peek(&mut rtl.out, &mut rtl.probes);
        rtl
    }

    pub fn variant(&self) -> Variant {
        self.variant
    }

    /// One rising CLK edge.
    #[inline]
    pub fn tick(&mut self, i: &Inputs) -> Outputs {
        self.sim.pin_mut().tick(&rtl_inputs(i), &mut self.out, &mut self.probes);
        self.outputs()
    }

    /// One rising CLK edge with the inputs of `e`, and whether the RTL's outputs and probes after
    /// it agree with `e`'s under `compare` — the same answer as [`tick`](Rtl::tick) followed by
    /// [`signals::agree`](crate::signals::agree), found inside the bridge while they are equal.
    #[inline]
    pub fn tick_agrees(&mut self, e: &Expected, compare: crate::signals::Compare) -> bool {
        if self.sim.pin_mut().tick_check(&e.inp, &e.out, &e.probes) {
            // equal to what tick would have copied out
            self.out = e.out;
            self.probes = e.probes;
            return true;
        }
        self.sim.peek(&mut self.out, &mut self.probes);
        let (mo, mp) = e.model();
        crate::signals::agree(compare, &mo, &mp, &self.outputs(), &self.probes())
    }

    /// Number of ticks since reset.
    pub fn cycle(&self) -> u64 {
        self.sim.cycle()
    }

    /// Sends one µC SPI frame through the pins (the other inputs held at `pins`) and returns the
    /// bits read on the data pin — SDOZ_C while enabled, else nINT_SDO_C — first bit in the MSB
    /// ([428] §6.2; the µC samples at the rising SCK_C edge).
    pub fn spi_frame(&mut self, f: crate::stimulus::Frame, pins: Inputs) -> u64 {
        use crate::stimulus::{Driver, Event, Txn};
        let mut d = Driver::default();
        d.inputs = pins;
        d.start(Txn::Frame(f));
        let mut reply = 0u64;
        let mut out = self.outputs();
        for _ in 0..f.cycles() {
            let (inp, ev) = d.step();
            if let Event::Sample(_) = ev {
                let bit = if out.sdoz_c_oe { out.sdoz_c } else { out.nint_sdo_c };
                reply = reply << 1 | bit as u64;
            }
            out = self.tick(&inp);
        }
        reply
    }

    /// Output pins after the last tick.
    #[inline]
    pub fn outputs(&self) -> Outputs {
        outputs(&self.out)
    }

    /// Probe bundle after the last tick.
    #[inline]
    pub fn probes(&self) -> Probes {
        probes(&self.probes)
    }

    /// Starts Verilator's VCD trace of every RTL signal from the next tick on (only on a model
    /// made by [`Rtl::new_traced`]).
    pub fn trace_open(&mut self, path: &Path, fclk_hz: u64) -> Result<(), String> {
        if !self.traced {
            return Err(format!("{}: this RTL model has no trace code (Rtl::new_traced makes one that has)", path.display()));
        }
        let s = path.to_str().ok_or_else(|| format!("{}: path is not UTF-8", path.display()))?;
        let period = period_ps(fclk_hz);
        if self.sim.pin_mut().trace_open(s, period) {
            Ok(())
        } else {
            Err(format!("{}: cannot open for writing", path.display()))
        }
    }

    pub fn trace_close(&mut self) {
        self.sim.pin_mut().trace_close();
    }
}

/// Without Verilator: the inputs and the expected state, kept as they are (nothing compares them).
#[cfg(tmc429_no_rtl)]
#[derive(Clone, Copy, Debug)]
pub struct Expected {
    out: Outputs,
    probes: Probes,
}

#[cfg(tmc429_no_rtl)]
impl Expected {
    pub fn new(_i: &Inputs, o: &Outputs, p: &Probes) -> Expected {
        Expected { out: *o, probes: *p }
    }

    pub fn model(&self) -> (Outputs, Probes) {
        (self.out, self.probes)
    }
}

/// Without Verilator: no value of this type exists (its field is uninhabited), so every method
/// is unreachable; [`Rtl::try_new`] returns [`MISSING`].
#[cfg(tmc429_no_rtl)]
pub struct Rtl {
    never: std::convert::Infallible,
}

#[cfg(tmc429_no_rtl)]
impl Rtl {
    pub fn try_new(_variant: Variant) -> Result<Rtl, String> {
        Err(MISSING.to_string())
    }

    pub fn try_new_traced(_variant: Variant) -> Result<Rtl, String> {
        Err(MISSING.to_string())
    }

    /// Panics: callers that can report an error use [`Rtl::try_new`].
    pub fn new(_variant: Variant) -> Rtl {
        panic!("{MISSING}")
    }

    /// Panics: callers that can report an error use [`Rtl::try_new_traced`].
    pub fn new_traced(_variant: Variant) -> Rtl {
        panic!("{MISSING}")
    }

    pub fn variant(&self) -> Variant {
        match self.never {}
    }

    pub fn tick(&mut self, _i: &Inputs) -> Outputs {
        match self.never {}
    }

    pub fn tick_agrees(&mut self, _e: &Expected, _compare: crate::signals::Compare) -> bool {
        match self.never {}
    }

    pub fn cycle(&self) -> u64 {
        match self.never {}
    }

    pub fn outputs(&self) -> Outputs {
        match self.never {}
    }

    pub fn probes(&self) -> Probes {
        match self.never {}
    }

    pub fn trace_open(&mut self, _path: &Path, _fclk_hz: u64) -> Result<(), String> {
        match self.never {}
    }

    pub fn trace_close(&mut self) {
        match self.never {}
    }
}

/// One CLK period in picoseconds (the VCD time unit).
pub fn period_ps(fclk_hz: u64) -> u64 {
    (1_000_000_000_000u64 / fclk_hz.max(1)).max(2)
}
