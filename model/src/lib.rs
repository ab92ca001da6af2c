//! Cycle-accurate, pin-level golden model of the Trinamic TMC428 / TMC429 / TMC4210.
//!
//! [`Tmc429::tick`] is one rising CLK edge (docs/model-contract.md C1). The model is the
//! executable definition of the chip: the RTL in `rtl/` matches it cycle for cycle, pins and
//! [`Probes`] alike.

pub mod accel;
pub mod chain;
pub mod chip;
pub mod current;
mod drvpins;
pub mod events;
pub mod host;
pub mod microstep;
pub mod motor_regs;
pub mod pins;
pub mod pmulpdiv;
pub mod ports;
pub mod ram;
pub mod ramp;
pub mod refsw;
pub mod regfile;
pub mod regmap;
pub mod regmap_render;
pub mod regmap_sigrok;
pub mod regmap_verilog;
pub mod schedule;
pub mod schedule_verilog;
pub mod script;
pub mod spi_slave;
pub mod stepdir;
pub mod sync;
pub mod text;
pub mod vroot;
pub mod vtarget;

pub use chip::{Chip, Package};
pub use pins::{Bonding, ChainProbe, Inputs, MotorProbe, Outputs, Probes};
pub use regfile::Global;

use motor_regs::*;
use regmap::f;
use spi_slave::{SpiEvent, SpiSlave};
use sync::SyncBank;

pub use schedule::{PHASE_COMMIT, PHASE_PULSE, PHASE_RAMP, PHASE_SNAPSHOT, PRESCALER_BITS};

/// type_version of the TMC429 and TMC4210 (TMC429 §8.2.4.4).
pub const TYPE_VERSION: u32 = 0x429101;

/// The chip.
#[derive(Clone, Debug)]
pub struct Tmc429 {
    chip: Chip,
    package: Package,
    /// The pins `package` lacks (C90): applied to the inputs before and the outputs after an edge.
    bond: Bonding,
    cycle: u64,
    sync: SyncBank,
    spi: SpiSlave,
    /// Pre-divider counter C (C40).
    prescaler: u32,
    power_down: bool,
    pub(crate) motors: [Motor; 3],
    pub(crate) global: Global,
    pub(crate) ram: [u8; 128],
    out: Outputs,
    /// Driver-chain SPI master (C80–C89).
    pub(crate) chain: chain::Chain,
    /// Current-scale selectors (C75–C77).
    pub(crate) cur: [current::CurrentScale; 3],
    /// Step/Dir outputs (C91–C96).
    pub(crate) sd: stepdir::StepDir,
    /// Edges outside power down (C66): the time base of the Step/Dir unit's counters, which
    /// stop in power down like every unit behind the SPI slave.
    run_edges: u64,
    /// Fast path: the last full evaluation of the motion core changed nothing, and neither its
    /// inputs (synchronized pins, multiplexed switches) nor any register has changed since, so
    /// it would change nothing again outside the frame's event phases. Any write to the
    /// registers or to `Global::mux_switches` must clear it (see [`Tmc429::touch`]).
    quiet: bool,
    /// Synchronized pins and multiplexed switches of the last full evaluation.
    quiet_pins: (u16, u8),
    fast_path: bool,
    /// A register was written outside an edge ([`Tmc429::write_register`] called directly):
    /// the next edge drives the driver-side pins from the state (as an executed datagram does).
    pins_stale: bool,
}

impl Tmc429 {
    /// A chip in its power-on state (C2), in the package with every pin of the variant.
    pub fn new(chip: Chip) -> Self {
        Self::in_package(chip, Package::full(chip))
    }

    /// A chip in `package` in its power-on state (C2, C90); an error if the variant does not
    /// come in that package.
    pub fn with_package(chip: Chip, package: Package) -> Result<Self, String> {
        Ok(Self::in_package(chip, package.check(chip)?))
    }

    fn in_package(chip: Chip, package: Package) -> Self {
        let mut t = Tmc429 {
            chip,
            package,
            bond: Bonding::of(chip, package),
            cycle: 0,
            sync: SyncBank::reset(),
            spi: SpiSlave::reset(),
            prescaler: 0,
            power_down: false,
            motors: [Motor::reset(); 3],
            global: Global::reset(),
            ram: ram::power_on(chip),
            quiet: false,
            quiet_pins: (0, 0),
            fast_path: true,
            pins_stale: false,
            out: Outputs::IDLE,
            chain: chain::Chain::reset(),
            cur: [current::CurrentScale::default(); 3],
            sd: stepdir::StepDir::reset(),
            run_edges: 0,
        };
        t.out.poscmp = t.has_poscmp_pin();
        t.driver_pins(0);
        t.bond.outputs(&mut t.out);
        t
    }

    /// Back to the power-on state (the RTL's synchronous `rst`).
    pub fn reset(&mut self) {
        *self = Tmc429::in_package(self.chip, self.package);
    }

    pub fn chip(&self) -> Chip {
        self.chip
    }

    pub fn package(&self) -> Package {
        self.package
    }

    /// CLK edges since power-on.
    pub fn cycle(&self) -> u64 {
        self.cycle
    }

    /// Pin levels after the last edge.
    pub fn outputs(&self) -> Outputs {
        self.out
    }

    pub fn is_powered_down(&self) -> bool {
        self.power_down
    }

    /// Number of motors of the variant (TMC4210: 1).
    pub fn motor_count(&self) -> usize {
        if self.chip == Chip::Tmc4210 {
            1
        } else {
            3
        }
    }

    /// Read-only view of a motor's registers and state.
    pub fn motor(&self, m: usize) -> &Motor {
        &self.motors[m]
    }

    /// Read-only view of the global registers.
    pub fn global(&self) -> &Global {
        &self.global
    }

    /// RAM contents (cells 0..127).
    pub fn ram(&self) -> &[u8; 128] {
        &self.ram
    }

    /// Left and right switch levels of the three motors as bit masks (bit m = motor m) (C60).
    pub fn switches(&self) -> (u8, u8) {
        refsw::levels(self.chip, &self.global, self.sync.s2)
    }

    /// One rising edge of CLK (C1).
    #[inline]
    pub fn tick(&mut self, inp: &Inputs) -> Outputs {
        self.tick_pins(sync::pack(inp))
    }

    /// One rising edge of CLK with the input pins as one word ([`sync::pack`], bit positions
    /// [`sync::bit`]): [`Tmc429::tick`] for a caller that holds the pins packed, e.g. a run
    /// whose inputs stay the same for many edges.
    #[inline]
    pub fn tick_pins(&mut self, pins: u16) -> Outputs {
        self.tick_changes(pins).unwrap_or(self.out)
    }

    /// One rising edge like [`Tmc429::tick_pins`]; `None` for an edge of the fast path, which
    /// changes nothing a watcher of the chip sees: the output pins, INT, the motors' registers
    /// and every register the µC reads stay as after the previous edge (only the cycle count,
    /// the pre-divider and the driver chain's inner counter advance). A run that decodes pin
    /// events or gathers motor statistics can skip such an edge.
    #[inline]
    pub fn tick_changes(&mut self, pins: u16) -> Option<Outputs> {
        let pins = self.die_pins(pins);
        if self.idle_edges(pins) > 0 {
            self.advance_quiet(1);
            return None;
        }
        Some(self.full_tick(pins))
    }

    /// One rising edge like [`Tmc429::tick_pins`], without the fast path's test: for a caller
    /// that has just seen [`Tmc429::skip_quiet`] stop before this edge, which then is not one of
    /// the fast path's.
    #[inline]
    pub fn tick_full(&mut self, pins: u16) -> Outputs {
        let pins = self.die_pins(pins);
        self.full_tick(pins)
    }

    /// Runs the edges of the fast path that come next with the input pins `pins`, at most
    /// `max`, and returns how many it ran: the same as calling [`Tmc429::tick_changes`] until
    /// it returns `Some` (that edge is not run) or `max` edges ran. For a run whose inputs hold
    /// for many edges: the phases between two slots of the frame (C41) are run at once, as
    /// far as the driver units' counters allow.
    pub fn skip_quiet(&mut self, pins: u16, max: u64) -> u64 {
        let pins = self.die_pins(pins);
        let mut ran = 0;
        while ran < max {
            // This edge and those up to the next slot phase are the fast path's, as long as
            // the drivers' counters keep them quiet.
            let quiet = self.idle_edges(pins);
            if quiet == 0 {
                break;
            }
            let to_slot = u64::from(schedule::SLOT_PHASES.rotate_right(schedule::phase(self.prescaler) + 1).trailing_zeros()) + 1;
            let n = to_slot.min(quiet).min(max - ran);
            self.advance_quiet(n);
            ran += n;
        }
        ran
    }

    /// The pins as the die sees them: a package without REFR pins gives their pull-ups (C90).
    #[inline]
    fn die_pins(&self, pins: u16) -> u16 {
        pins | (self.bond.refr_absent as u16) << sync::bit::REFR1
    }

    /// `n` edges of the fast path (at most up to the next slot phase and as far as the drivers'
    /// counters allow, [`Tmc429::idle_edges`]): only the counters advance.
    #[inline]
    fn advance_quiet(&mut self, n: u64) {
        self.cycle += n;
        self.run_edges += n;
        self.prescaler = (self.prescaler + n as u32) & schedule::PRESCALER_MASK;
        self.chain.count_down(n as u16);
    }

    /// Fast path, exactly equivalent to the full edge (tests/fast_path.rs): the pins are settled
    /// in the synchronizers (no SPI edge in flight, no switch change), the motion core is quiet
    /// and has nothing to do in this phase of the frame ([`Tmc429::motion_idle`]), and so have
    /// the driver units. Then the edge only advances the counters. Returns for how many edges
    /// from this one on the driver units stay quiet ([`Tmc429::drivers_quiet_edges`]), 0 when
    /// this edge is not one of the fast path's.
    #[inline]
    fn idle_edges(&self, pins: u16) -> u64 {
        if !(self.fast_path
            && self.quiet
            && !self.power_down
            && self.sync.settled()
            && pins == self.sync.s1
            && (self.sync.s2, self.global.mux_switches) == self.quiet_pins)
        {
            return 0;
        }
        let quiet = self.drivers_quiet_edges();
        if quiet == 0 || self.ramp_tick_drives() || !self.motion_idle() {
            return 0;
        }
        quiet
    }

    /// The motion core's edge at this phase of the frame changes nothing, given that the last
    /// edge changed no motor and its inputs hold (`quiet`, `quiet_pins`): no edge before a
    /// motor's condition slot that takes other conditions than those it holds, no condition
    /// slot whose conditions differ from those its last slot registered, no snapshot that
    /// changes a target, no ramp tick, no pulse tick that adds to an accumulator.
    #[inline]
    fn motion_idle(&self) -> bool {
        let c = self.prescaler;
        let p = schedule::phase(c);
        if schedule::SLOT_PHASES >> p & 1 == 0 {
            return true;
        }
        let n = self.motor_count();
        let ramp = match schedule::lane_of(&PHASE_RAMP, p) {
            Some(i) if i < n => self.motors[i].rm == HOLD_MODE || !schedule::due(c, self.motors[i].ramp_div),
            _ => true,
        };
        if let Some(i) = schedule::lane_of(&PHASE_COMMIT, p).filter(|&i| i < n) {
            if !ramp::settled(&self.motors[i]) {
                return false;
            }
        }
        if let Some(i) = schedule::lane_of(&schedule::PHASE_SAMPLE, p).filter(|&i| i < n) {
            let (left, right) = self.switches();
            let m = &self.motors[i];
            if !ramp::sample_settled(m, m.vt, (left >> i) & 1 != 0, (right >> i) & 1 != 0) {
                return false;
            }
        }
        let pulse = match schedule::lane_of(&PHASE_PULSE, p) {
            Some(i) if i < n => !schedule::due(c, self.motors[i].pulse_div) || self.motors[i].v.unsigned_abs() < 256,
            _ => true,
        };
        ramp && pulse && vtarget::quiet(&self.motors, n, p)
    }

    /// Disables the fast paths of [`Tmc429::tick`] (for the test that proves them equivalent).
    #[doc(hidden)]
    pub fn set_fast_path(&mut self, on: bool) {
        self.fast_path = on;
        self.quiet = false;
    }

    fn full_tick(&mut self, inp_pins: u16) -> Outputs {
        self.cycle += 1;
        // Every unit reads the old state; the synchronizers shift last.
        let pins = self.sync.s2;

        // µC SPI slave (C10–C13).
        let (wake, exec) = self.spi_edge();
        let int_old = self.int();
        let mut events = [0u8; 3];
        let mut pc_event = false;
        let match_old = self.pos_match();
        let mut pins_changed = exec.is_some() || self.pins_stale;
        self.pins_stale = false;
        if !self.power_down {
            self.run_edges += 1;
            pins_changed |= self.drivers(pins);
            let inputs = (pins, self.global.mux_switches);
            // Held inputs and no motor changed in the last edge: the motion core runs only in a
            // slot phase with work (motion_idle is true outside the slot phases).
            let held = self.quiet && inputs == self.quiet_pins && self.fast_path;
            if !(held && self.motion_idle()) {
                let before = self.motors;
                self.motion(pins, &mut events);
                self.quiet = self.motors == before;
                self.quiet_pins = inputs;
            }
            pc_event = self.pos_compare_event();
            self.prescaler = schedule::next(self.prescaler);
        } else {
            // the edge before a condition slot takes its conditions while powered down too
            self.sample_powered_down(pins);
        }
        if self.pos_compare_register(match_old) {
            self.quiet = false;
        }

        if let Some(d) = exec {
            self.execute(d);
            self.pins_stale = false; // this edge drives the pins (pins_changed)
        }
        // C3: events set after the µC's clear, then the mask forces.
        for (m, e) in self.motors.iter_mut().zip(events) {
            m.int_flags = (m.int_flags | e) & m.int_mask;
        }
        self.pos_compare_flag(pc_event);
        // INT changed by something other than the motors (the position compare flag): the
        // next edge registers it on nINT (C11), so it must not take the fast path.
        if self.int() != int_old {
            self.quiet = false;
        }
        if wake {
            self.power_down = false;
        }

        self.sync.shift(inp_pins);

        self.register_outputs(int_old, match_old, pins_changed.then_some(pins));
        self.out
    }

    /// The µC SPI slave's edge (C10–C13) with the register file's part in it: the status byte
    /// loaded at the frame start (which wakes a powered-down chip, C66), the read value loaded
    /// after the address byte; returns (wake, the datagram that executes in this edge).
    #[inline]
    fn spi_edge(&mut self) -> (bool, Option<u32>) {
        match self.spi.step(&self.sync) {
            SpiEvent::Select => {
                let st = self.status();
                self.spi.load_status(st);
                (self.power_down, None)
            }
            SpiEvent::ReadAddress(a7) => {
                let (d, r) = self.read_register_parts(a7);
                self.spi.load_data(d, r);
                (false, None)
            }
            SpiEvent::Execute(d) => (false, Some(d)),
            SpiEvent::Deselect | SpiEvent::None => (false, None),
        }
    }

    /// The output pin registers after an edge: nINT_SDO_C from INT of the old state or the
    /// SPI data (C11), SDOZ_C and POSCMP on the TMC429 (C65), and the driver-side pins when
    /// something they show may have changed (`driver`: the synchronized pins of the edge).
    #[inline]
    fn register_outputs(&mut self, int_old: bool, match_old: bool, driver: Option<u16>) {
        let sdo = self.spi.sdo();
        let data_on_nint = self.spi.active && !(self.has_pos_comp() && self.global.ifc(f::SDO_INT));
        self.out.nint_sdo_c = if data_on_nint { sdo } else { !int_old };
        if self.has_poscmp_pin() {
            self.out.sdoz_c = sdo;
            self.out.sdoz_c_oe = self.spi.active;
            self.out.poscmp = match_old;
        }
        if let Some(pins) = driver {
            self.driver_pins(pins);
        }
        if !self.bond.is_full() {
            self.bond.outputs(&mut self.out);
        }
    }

    /// The motion core for one cycle (C40–C63), from the old state: the frame schedule of the
    /// target velocities (C41) and each motor's ramp and pulse generator ([`ramp::edge`]).
    fn motion(&mut self, pins: u16, events: &mut [u8; 3]) {
        let c = self.prescaler;
        let (left, right) = refsw::levels(self.chip, &self.global, pins);
        let n = self.motor_count();
        for (i, m) in self.motors.iter_mut().enumerate().take(n) {
            // The ramp and pulse generator uses the committed target of the old state (C41).
            let vt = m.vt;
            vtarget::edge(m, i, schedule::phase(c));
            let sample_tick = schedule::sample_tick(schedule::next(c), i);
            let cond_tick = schedule::cond_tick(c, i);
            let ramp_tick = schedule::ramp_tick(c, i, m.ramp_div);
            let pulse_tick = schedule::pulse_tick(c, i, m.pulse_div);
            let (l, r) = ((left >> i) & 1 != 0, (right >> i) & 1 != 0);
            events[i] = ramp::edge(m, vt, sample_tick, cond_tick, ramp_tick, pulse_tick, l, r);
        }
    }

    /// A powered-down edge whose pre-divider stays in a motor's condition slot takes that slot's
    /// conditions from the old state (C52, C66): the slot of the first running edge applies
    /// those of the edge before it.
    fn sample_powered_down(&mut self, pins: u16) {
        let c = self.prescaler;
        let n = self.motor_count();
        if let Some(i) = schedule::lane_of(&PHASE_COMMIT, schedule::phase(c)).filter(|&i| i < n) {
            let (left, right) = refsw::levels(self.chip, &self.global, pins);
            let m = &mut self.motors[i];
            m.cond_next = ramp::evaluate(m, m.vt, (left >> i) & 1 != 0, (right >> i) & 1 != 0);
        }
    }
}
