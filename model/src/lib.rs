//! Cycle-accurate, pin-level golden model of the Trinamic TMC428 / TMC429 / TMC4210.
//!
//! [`Tmc429::tick`] is one rising CLK edge (docs/model-contract.md C1). The model is the
//! executable definition of the chip: the RTL in `rtl/` matches it cycle for cycle, pins and
//! [`Probes`] alike.

pub mod chain;
pub mod chip;
pub mod current;
pub mod events;
pub mod host;
pub mod microstep;
pub mod motor;
pub mod pins;
pub mod pmulpdiv;
pub mod ram;
pub mod regmap;
pub mod regmap_render;
pub mod script;
pub mod spi_slave;
pub mod stepdir;
pub mod switches;
pub mod sync;

pub use chip::Chip;
pub use pins::{ChainProbe, Inputs, MotorProbe, Outputs, Probes};

use motor::*;
use regmap::{f, Addr};
use spi_slave::{SpiEvent, SpiSlave};
use sync::SyncBank;

/// Width of the pre-divider counter C (C40): 5 phase bits + 15 frame bits cover every
/// pulse_div and ramp_div.
pub const PRESCALER_BITS: u32 = 20;
const PRESCALER_MASK: u32 = (1 << PRESCALER_BITS) - 1;

/// Phases of the 32-cycle frame (C41): target snapshot of motor m, commit of all targets.
pub const PHASE_SNAPSHOT: [u32; 3] = [0, 7, 14];
pub const PHASE_COMMIT: u32 = 29;
pub const PHASE_RAMP: u32 = 30;
pub const PHASE_PULSE: u32 = 31;

/// type_version of the TMC429 and TMC4210 (TMC429 §8.2.4.4).
pub const TYPE_VERSION: u32 = 0x429101;

/// Global registers and driver-chain state shared by the motors.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Global {
    /// Global parameter register $7E, as stored (unused bits 0).
    pub gconf: u32,
    /// if_configuration (TMC429/TMC4210).
    pub ifconf: u32,
    pub pos_comp: u32,
    /// pos_comp_int mask M and flag I.
    pub pc_m: bool,
    pub pc_i: bool,
    /// History flop of the position match (C65).
    pub pc_match_prev: bool,
    pub cover_pos: u8,
    pub cover_len: u8,
    pub cover_datagram: u32,
    /// Cover datagram waiting (cw).
    pub cw: bool,
    /// A datagram_low/high_word write waits for the next datagram (C-chain).
    pub dgw: bool,
    /// 48-bit readback shift register of SDI_S.
    pub readback: u64,
    /// Switch levels sampled through the 74HC157 when refmux = 1 (bit 2m = Rm, 2m+1 = Lm).
    pub mux_switches: u8,
}

impl Global {
    fn reset() -> Self {
        Global {
            gconf: f::CLK2_DIV.put(15),
            ifconf: 0,
            pos_comp: 0,
            pc_m: false,
            pc_i: false,
            pc_match_prev: true,
            cover_pos: 0,
            cover_len: 0,
            cover_datagram: 0,
            cw: false,
            dgw: false,
            readback: 0,
            mux_switches: 0,
        }
    }
    #[inline]
    pub fn g(&self, fl: regmap::Field) -> u32 {
        fl.get(self.gconf)
    }
    #[inline]
    pub fn ifc(&self, fl: regmap::Field) -> bool {
        fl.get(self.ifconf) != 0
    }
}

/// The chip.
#[derive(Clone, Debug)]
pub struct Tmc429 {
    chip: Chip,
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
}

impl Tmc429 {
    /// A chip in its power-on state (C2).
    pub fn new(chip: Chip) -> Self {
        let mut t = Tmc429 {
            chip,
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
            out: Outputs::IDLE,
            chain: chain::Chain::reset(),
            cur: [current::CurrentScale::default(); 3],
            sd: stepdir::StepDir::reset(),
            run_edges: 0,
        };
        t.out.poscmp = t.has_pos_comp();
        t.driver_pins(0);
        t
    }

    /// Back to the power-on state (the RTL's synchronous `rst`).
    pub fn reset(&mut self) {
        *self = Tmc429::new(self.chip);
    }

    pub fn chip(&self) -> Chip {
        self.chip
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

    fn has_pos_comp(&self) -> bool {
        self.chip != Chip::Tmc428
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

    /// The status byte `INT CDGW RS3 xEQt3 RS2 xEQt2 RS1 xEQt1` of the current state (C10).
    pub fn status(&self) -> u8 {
        let (l, _) = self.switches();
        let mut s = 0u8;
        for m in 0..3 {
            let mo = &self.motors[m];
            s |= ((mo.x_actual == mo.x_target) as u8) << (2 * m);
            s |= ((l >> m) & 1) << (2 * m + 1);
        }
        s | (self.cdgw() as u8) << 6 | (self.int() as u8) << 7
    }

    fn cdgw(&self) -> bool {
        self.chain.cdgw(&self.global)
    }

    /// INT (C64).
    pub fn int(&self) -> bool {
        self.motors.iter().any(|m| m.int_flags != 0) || (self.global.pc_i && self.global.pc_m)
    }

    /// Left and right switch levels of the three motors as bit masks (bit m = motor m) (C60).
    pub fn switches(&self) -> (u8, u8) {
        switches::levels(self.chip, &self.global, self.sync.s2)
    }

    /// The probe bundle of the current state.
    pub fn probes(&self) -> Probes {
        let mut p = Probes { prescaler: self.prescaler, power_down: self.power_down as u8, status: self.status(), ..Probes::default() };
        for (mp, m) in p.motor.iter_mut().zip(self.motors.iter()) {
            *mp = MotorProbe {
                x_target: m.x_target,
                x_actual: m.x_actual,
                v_internal: m.v,
                v_target: sext12(m.v_target as u32),
                a_actual: m.a_actual,
                ustep: m.ustep as u32,
                step: m.step as u8,
                dir: m.dir as u8,
                pulse_acc: m.acc,
            };
        }
        let c = &self.chain;
        p.chain.state = c.state;
        p.chain.cell = c.cell;
        p.chain.motor = c.motor;
        p.chain.bit_count = c.bits;
        p.chain.pending = c.req as u8;
        p.chain.cover_waiting = c.cw(&self.global) as u8;
        p.chain.readback = self.global.readback;
        p
    }

    /// The µC SPI slave's ports in the current state ([`spi_slave::SpiPorts`]): the slave's
    /// outputs, and the status byte and read data the register file presents to it for the next
    /// edge. This is the boundary of `rtl/tmc429_spi_slave.v` (test vectors, docs/vectors.md).
    pub fn spi_ports(&self) -> spi_slave::SpiPorts {
        let mut p = self.spi.ports(&self.sync);
        p.status = self.status();
        p.rd_data = self.read_register(p.rd_addr) & 0xFF_FFFF;
        p
    }

    /// The inputs motor `m`'s ramp and pulse generator sees before the next edge: the levels of
    /// the current state ([`motor::RampInputs`]). With [`motor::ramp_ports`] of the state after
    /// that edge this is the boundary of `rtl/tmc429_ramp.v` (test vectors, docs/vectors.md).
    pub fn ramp_inputs(&self, m: usize) -> motor::RampInputs {
        let mo = &self.motors[m];
        let phase = self.prescaler & 31;
        let frame = self.prescaler >> 5;
        let due = |div: u8| frame & ((1 << div) - 1) == (1 << div) - 1;
        let (left, right) = self.switches();
        let p = self.spi.ports(&self.sync);
        let a7 = ((p.cmd >> 25) & 0x7F) as u8;
        let write = p.exec && (p.cmd >> 24) & 1 == 0;
        let (we, widx) = match (regmap::lookup(self.chip, a7), Addr::from_a7(a7)) {
            (Some(_), Addr::Motor(mm, idx)) if write && mm as usize == m => (true, idx),
            _ => (false, 0),
        };
        motor::RampInputs {
            run: !self.power_down,
            ramp_tick: phase == PHASE_RAMP && due(mo.ramp_div),
            pulse_tick: phase == PHASE_PULSE && due(mo.pulse_div),
            rm: mo.rm,
            x_target: mo.x_target,
            v_min: mo.v_min,
            a_max: mo.a_max,
            ref_conf: mo.ref_conf,
            usrs: mo.usrs,
            dx_ref_tolerance: mo.dx_ref_tolerance,
            vt: mo.vt,
            sw_l: (left >> m) & 1 != 0,
            sw_r: (right >> m) & 1 != 0,
            we,
            widx: if we { widx } else { 0 },
            wdata: if we { p.cmd & 0xFF_FFFF } else { 0 },
        }
    }

    /// The inputs the driver-chain master sees before the next edge: the levels of the current
    /// state ([`chain::ChainInputs`]). With the chain state after that edge and
    /// [`Tmc429::chain_step`] this is the boundary of `rtl/tmc429_chain.v` (test vectors,
    /// docs/vectors.md; rtl/README.md "Unit ports").
    pub fn chain_inputs(&self) -> chain::ChainInputs {
        let g = &self.global;
        let mut i = chain::ChainInputs {
            run: !self.power_down,
            spi_mode: self.spi_mode(),
            lsmd: g.g(f::LSMD) as u8,
            pol_ph_ab: g.g(f::POL_PH_AB) != 0,
            pol_fd_ab: g.g(f::POL_FD_AB) != 0,
            pol_dac_ab: g.g(f::POL_DAC_AB) != 0,
            cont_update: g.g(f::CONT_UPDATE) != 0,
            cw: g.cw,
            dgw: g.dgw,
            cover_pos: g.cover_pos & 63,
            cover_len: g.cover_len & 31,
            cover_datagram: g.cover_datagram & 0xFF_FFFF,
            sdi_s: (self.sync.s2 >> sync::bit::SDI_S) & 1 != 0,
            clk2_div: g.g(f::CLK2_DIV) as u8,
            ..Default::default()
        };
        if self.prescaler & 31 == PHASE_RAMP {
            let frame = self.prescaler >> 5;
            for (m, mo) in self.motors.iter().enumerate() {
                let mask = (1u32 << mo.ramp_div) - 1;
                i.ramp_tick |= (((frame & mask) == mask) as u8) << m;
            }
        }
        for (m, mo) in self.motors.iter().enumerate() {
            i.step |= (mo.step as u8) << m;
            i.dir |= (mo.dir as u8) << m;
            i.ustep[m] = mo.ustep;
            i.i_scale[m] = self.cur[m].i_scale(mo);
        }
        i
    }

    /// One edge of a copy `c` of the driver chain (with a copy `g` of the global registers) in
    /// the world of the current state: its RAM, motors, current scales, ramp ticks and SDI_S.
    /// This is the chain's edge of [`Tmc429::tick`] (C80–C89); nothing happens when powered
    /// down (C66). Gives the RTL's next-state outputs (`cs_ns`, `take`, ...) for test vectors.
    pub fn chain_step(&self, c: &mut chain::Chain, g: &mut Global) {
        if self.power_down || self.chip == Chip::Tmc4210 {
            return;
        }
        let i = self.chain_inputs();
        c.tick(i.spi_mode, &self.ram, g, &self.motors, &self.cur, i.ramp_tick, i.sdi_s);
    }

    /// One rising edge of CLK (C1).
    #[inline]
    pub fn tick(&mut self, inp: &Inputs) -> Outputs {
        if self.idle_edge(inp) {
            self.cycle += 1;
            self.run_edges += 1;
            self.prescaler = (self.prescaler + 1) & PRESCALER_MASK;
            self.chain.count_down();
            return self.out;
        }
        self.full_tick(inp)
    }

    /// Fast path, exactly equivalent to the full edge (tests/fast_path.rs): the pins are settled
    /// in the synchronizers (no SPI edge in flight, no switch change), the motion core is quiet,
    /// and this phase of the frame has nothing to do: no snapshot that changes a target, no ramp
    /// tick, no pulse tick that adds to an accumulator. Then the edge only advances the counters.
    #[inline]
    fn idle_edge(&self, inp: &Inputs) -> bool {
        if !(self.fast_path
            && self.quiet
            && !self.power_down
            && self.drivers_quiet()
            && self.sync.settled()
            && sync::pack(inp) == self.sync.s1
            && (self.sync.s2, self.global.mux_switches) == self.quiet_pins)
        {
            return false;
        }
        let phase = self.prescaler & 31;
        let frame = self.prescaler >> 5;
        let n = self.motor_count();
        let due = |div: u8| frame & ((1 << div) - 1) == (1 << div) - 1;
        match phase {
            PHASE_RAMP => !self.motors[..n].iter().any(|m| m.rm != HOLD_MODE && due(m.ramp_div)),
            PHASE_PULSE => !self.motors[..n].iter().any(|m| due(m.pulse_div) && m.v.unsigned_abs() >= 256),
            PHASE_COMMIT => self.motors[..n].iter().all(|m| m.vt_next == m.vt),
            p => match PHASE_SNAPSHOT.iter().position(|&s| s == p) {
                Some(i) if i < n => self.motors[i].target_velocity() == self.motors[i].vt_next,
                _ => true,
            },
        }
    }

    /// Disables the fast paths of [`Tmc429::tick`] (for the test that proves them equivalent).
    #[doc(hidden)]
    pub fn set_fast_path(&mut self, on: bool) {
        self.fast_path = on;
        self.quiet = false;
    }

    fn full_tick(&mut self, inp: &Inputs) -> Outputs {
        self.cycle += 1;
        // Every unit reads the old state; the synchronizers shift last.
        let pins = self.sync.s2;

        // µC SPI slave (C10–C13).
        let ev = self.spi.step(&self.sync);
        let mut wake = false;
        let mut exec = None;
        match ev {
            SpiEvent::Select => {
                let st = self.status();
                self.spi.load_status(st);
                wake = self.power_down;
            }
            SpiEvent::ReadAddress(a7) => {
                let d = self.read_register(a7);
                self.spi.load_data(d);
            }
            SpiEvent::Execute(d) => exec = Some(d),
            SpiEvent::Deselect | SpiEvent::None => {}
        }

        let int_old = self.int();
        let mut events = [0u8; 3];
        let mut pc_event = false;
        let match_old = self.pos_match();
        let mut pins_changed = exec.is_some();
        if !self.power_down {
            self.run_edges += 1;
            pins_changed |= self.drivers(pins);
            let phase = self.prescaler & 31;
            let event_phase = PHASE_SNAPSHOT.contains(&phase) || phase >= PHASE_COMMIT;
            let inputs = (pins, self.global.mux_switches);
            if event_phase || !self.quiet || inputs != self.quiet_pins || !self.fast_path {
                let before = self.motors;
                self.motion(pins, &mut events);
                self.quiet = self.motors == before;
                self.quiet_pins = inputs;
            }
            pc_event = match_old && !self.global.pc_match_prev;
            self.global.pc_match_prev = match_old;
            self.prescaler = (self.prescaler + 1) & PRESCALER_MASK;
        }

        if let Some(d) = exec {
            self.execute(d);
        }
        // C3: events set after the µC's clear, then the mask forces.
        for (m, e) in self.motors.iter_mut().zip(events) {
            m.int_flags = (m.int_flags | e) & m.int_mask;
        }
        if pc_event && self.global.pc_m {
            self.global.pc_i = true;
        }
        if !self.global.pc_m {
            self.global.pc_i = false;
        }
        // INT changed by something other than the motors (the position compare flag): the
        // next edge registers it on nINT (C11), so it must not take the fast path.
        if self.int() != int_old {
            self.quiet = false;
        }
        if wake {
            self.power_down = false;
        }

        self.sync.shift(sync::pack(inp));

        // Registered outputs.
        let sdo = self.spi.sdo();
        let data_on_nint = self.spi.active && !(self.has_pos_comp() && self.global.ifc(f::SDO_INT));
        self.out.nint_sdo_c = if data_on_nint { sdo } else { !int_old };
        if self.has_pos_comp() {
            self.out.sdoz_c = sdo;
            self.out.sdoz_c_oe = self.spi.active;
            self.out.poscmp = match_old;
        }
        if pins_changed {
            self.driver_pins(pins);
        }
        self.out
    }

    /// Position compare match of the current state (C65).
    fn pos_match(&self) -> bool {
        if !self.has_pos_comp() {
            return false;
        }
        let sel = (f::POS_COMP_SEL.get(self.global.ifconf) as usize).min(2);
        self.motors[sel].x_actual == self.global.pos_comp
    }

    /// The motion core for one cycle (C40–C63), from the old state.
    fn motion(&mut self, pins: u16, events: &mut [u8; 3]) {
        let phase = self.prescaler & 31;
        let frame = self.prescaler >> 5;
        let (left, right) = switches::levels(self.chip, &self.global, pins);
        let n = self.motor_count();
        for (i, m) in self.motors.iter_mut().enumerate().take(n) {
            // Target snapshot (C41): computed from the old state, in use from the commit on.
            let vt = m.vt;
            if phase == PHASE_SNAPSHOT[i] {
                m.vt_next = m.target_velocity();
            }
            if phase == PHASE_COMMIT {
                m.vt = m.vt_next;
            }
            let l = (left >> i) & 1 != 0;
            let r = (right >> i) & 1 != 0;
            let rnl = m.ref_conf & REF_RNL != 0;
            let sel = if rnl { r } else { l };
            // The tolerance window masks only the REF_RnL-selected switch.
            let (tol_ok, stop) = motor::switch_stop(m.x_actual, m.v, vt, m.ref_conf, m.dx_ref_tolerance, l, r);
            let soft = m.ref_conf & SOFT_STOP != 0;
            let hard_stop = stop && !soft;
            let at_target = m.x_actual == m.x_target;
            let stop_at_target = m.rm <= SOFT_MODE && at_target && (m.v.unsigned_abs() >> 8) <= m.v_min as u32;

            // Interrupt conditions (C63).
            let cond = ((at_target as u8) * INT_POS_END)
                | (((sel && !tol_ok) as u8) * INT_REF_WRONG)
                | (((m.x_actual == 0 && !sel) as u8) * INT_REF_MISS)
                | ((stop as u8) * INT_STOP)
                | ((!l as u8) * INT_STOP_LEFT_LOW)
                | (!r as u8) * INT_STOP_RIGHT_LOW
                | (l as u8) * INT_STOP_LEFT_HIGH
                | (r as u8) * INT_STOP_RIGHT_HIGH;
            events[i] = cond & !m.cond_prev;
            m.cond_prev = cond;

            // Latch (C62).
            if m.lp && m.v != 0 && sel != m.ref_prev {
                m.x_latched = m.x_actual;
                m.lp = false;
            }
            m.ref_prev = sel;

            let v_old = m.v;
            // The stop actions of this cycle are the registered conditions of the last one
            // (C52, C61); the conditions of this cycle act in the next.
            let (stop_hard, stop_soft) = (m.stop_hard, m.stop_soft);
            m.stop_hard = stop_at_target || hard_stop;
            m.stop_soft = stop && soft;
            // Ramp tick (C51).
            if phase == PHASE_RAMP && m.rm != HOLD_MODE && (frame & ((1 << m.ramp_div) - 1)) == (1 << m.ramp_div) - 1 {
                let t = if stop_soft { 0 } else { vt * 256 };
                let v_new = Motor::approach(v_old, t, m.a_max);
                m.a_actual = v_new - v_old;
                m.v = v_new;
                if m.rm <= SOFT_MODE {
                    m.v_target = (vt as u32 & 0xFFF) as u16;
                }
            }
            if stop_hard {
                m.v = 0;
            }
            // Pulse tick (C53): velocity taken as 0 while the hard stop action holds.
            m.step = false;
            if phase == PHASE_PULSE && (frame & ((1 << m.pulse_div) - 1)) == (1 << m.pulse_div) - 1 {
                let v_eff = if stop_hard { 0 } else { v_old };
                let sum = m.acc + (v_eff.unsigned_abs() >> 8) as u16;
                m.acc = sum & 0x7FF;
                if sum > 0x7FF {
                    m.do_step(v_eff < 0);
                }
            }
        }
    }

    /// Register read data (24 bits) of a 7-bit address in the current state (C20–C31).
    pub fn read_register(&self, a7: u8) -> u32 {
        let Some((reg, motor)) = regmap::lookup(self.chip, a7) else {
            return 0;
        };
        let g = &self.global;
        match Addr::from_a7(a7) {
            Addr::Ram(a) => ram::read_word(&self.ram, a),
            Addr::Motor(_, idx) => {
                let m = &self.motors[motor.unwrap_or(0) as usize];
                match idx {
                    0 => m.x_target,
                    1 => m.x_actual,
                    2 => m.v_min as u32,
                    3 => m.v_max as u32,
                    4 => m.v_target as u32,
                    5 => f::V_ACTUAL.put(m.v_actual() as u32),
                    6 => m.a_max as u32,
                    7 => f::A_ACTUAL.put(m.a_actual as u32),
                    8 => {
                        f::IS_AGTAT.put(m.is_agtat as u32)
                            | f::IS_ALEAT.put(m.is_aleat as u32)
                            | f::IS_V0.put(m.is_v0 as u32)
                            | f::A_THRESHOLD.put(m.a_threshold as u32)
                    }
                    9 => f::PMUL.put(0x80 | m.pmul as u32) | f::PDIV.put(m.pdiv as u32),
                    10 => f::LP.put(m.lp as u32) | ((m.ref_conf as u32) << 8) | f::RM.put(m.rm as u32),
                    11 => f::INTERRUPT_MASK.put(m.int_mask as u32) | f::INTERRUPT_FLAGS.put(m.int_flags as u32),
                    12 => f::PULSE_DIV.put(m.pulse_div as u32) | f::RAMP_DIV.put(m.ramp_div as u32) | f::USRS.put(m.usrs as u32),
                    13 => m.dx_ref_tolerance as u32,
                    14 => m.x_latched,
                    15 => m.ustep as u32,
                    _ => 0,
                }
            }
            Addr::Global(jdx) => match jdx {
                0 => (g.readback & 0xFF_FFFF) as u32,
                1 => ((g.readback >> 24) & 0xFF_FFFF) as u32,
                2 => {
                    f::COVER_WAITING.put(self.chain.cw(g) as u32)
                        | f::COVER_POS.put((g.cover_pos as u32 + 1) & 63)
                        | f::COVER_LEN.put(g.cover_len as u32)
                }
                3 => g.cover_datagram,
                4 => g.ifconf,
                5 => g.pos_comp,
                6 => f::POS_COMP_M.put(g.pc_m as u32) | f::POS_COMP_I.put(g.pc_i as u32),
                9 => TYPE_VERSION,
                14 => {
                    let (l, r) = self.switches();
                    let mut w = 0;
                    for m in 0..3 {
                        w |= (((r >> m) & 1) as u32) << (2 * m) | (((l >> m) & 1) as u32) << (2 * m + 1);
                    }
                    w
                }
                15 => g.gconf & reg.writable_mask(),
                _ => 0,
            },
        }
    }

    /// Marks the motion core's inputs as changed (ends the fast path of [`Tmc429::tick`]).
    #[inline]
    pub(crate) fn touch(&mut self) {
        self.quiet = false;
    }

    /// Executes a 32-bit datagram (C12): a register or RAM write; reads have no side effects.
    fn execute(&mut self, d: u32) {
        if (d >> 24) & 1 == 1 {
            return;
        }
        self.write_register(((d >> 25) & 0x7F) as u8, d & 0xFF_FFFF);
    }

    /// A µC write of `data` (24 bits) to a 7-bit address, with every side effect (C20–C31).
    pub fn write_register(&mut self, a7: u8, data: u32) {
        let Some((reg, motor)) = regmap::lookup(self.chip, a7) else {
            return;
        };
        let data = data & 0xFF_FFFF;
        self.touch();
        match Addr::from_a7(a7) {
            Addr::Ram(a) => ram::write_word(&mut self.ram, a, data),
            Addr::Motor(_, idx) => {
                let m = &mut self.motors[motor.unwrap_or(0) as usize];
                match idx {
                    0 => m.x_target = data,
                    1 => m.x_actual = data,
                    2 => m.v_min = f::V_MIN.get(data) as u16,
                    3 => m.v_max = f::V_MAX.get(data) as u16,
                    4 => m.v_target = f::V_TARGET.get(data) as u16,
                    5 => {
                        // C23: V := w·256, −2048 as −2047.
                        let w = (f::V_ACTUAL.value(data) as i32).max(-2047);
                        m.v = w * 256;
                    }
                    6 => m.a_max = f::A_MAX.get(data) as u16,
                    7 => {}
                    8 => {
                        m.is_agtat = f::IS_AGTAT.get(data) as u8;
                        m.is_aleat = f::IS_ALEAT.get(data) as u8;
                        m.is_v0 = f::IS_V0.get(data) as u8;
                        m.a_threshold = f::A_THRESHOLD.get(data) as u16;
                    }
                    9 => {
                        m.pmul = (f::PMUL.get(data) & 0x7F) as u8;
                        m.pdiv = f::PDIV.get(data) as u8;
                    }
                    10 => {
                        m.ref_conf = ((data >> 8) & 0xF) as u8;
                        m.rm = f::RM.get(data) as u8;
                    }
                    11 => {
                        m.int_mask = f::INTERRUPT_MASK.get(data) as u8;
                        m.int_flags &= !(f::INTERRUPT_FLAGS.get(data) as u8);
                        m.int_flags &= m.int_mask;
                    }
                    12 => {
                        m.pulse_div = f::PULSE_DIV.get(data) as u8;
                        m.ramp_div = f::RAMP_DIV.get(data) as u8;
                        m.usrs = f::USRS.get(data) as u8;
                    }
                    13 => m.dx_ref_tolerance = f::DX_REF_TOLERANCE.get(data) as u16,
                    14 => m.lp = true,
                    15 => m.ustep = f::USTEP_COUNT.get(data) as u8,
                    _ => {}
                }
            }
            Addr::Global(jdx) => {
                let g = &mut self.global;
                match jdx {
                    0 | 1 => g.dgw = true,
                    2 => {
                        g.cover_pos = f::COVER_POS.get(data) as u8;
                        g.cover_len = f::COVER_LEN.get(data) as u8;
                    }
                    3 => {
                        g.cover_datagram = data;
                        g.cw = true;
                    }
                    4 => g.ifconf = data & reg.writable_mask(),
                    5 => g.pos_comp = data,
                    6 => {
                        g.pc_m = f::POS_COMP_M.get(data) != 0;
                        if f::POS_COMP_I.get(data) != 0 || !g.pc_m {
                            g.pc_i = false;
                        }
                    }
                    8 => self.power_down = true,
                    15 => g.gconf = data & reg.writable_mask(),
                    _ => {}
                }
            }
        }
    }
}

/// Driver side: microstep unit, current scaling, SPI chain and Step/Dir (C70–C99).
impl Tmc429 {
    /// The driver units would change nothing in this edge (part of the fast path of
    /// [`Tmc429::tick`]): the chain idle without a request, no ramp tick that counts for the
    /// continuous update or the current-scale selector, the Step/Dir unit idle.
    #[inline]
    fn drivers_quiet(&self) -> bool {
        if self.chip != Chip::Tmc4210 {
            let c = &self.chain;
            let spi = self.spi_mode();
            let quiet = if c.state == chain::IDLE {
                !c.req && !c.cs && c.stepped == 0 && !(self.global.cw && spi)
            } else {
                // Counting down inside a state: the edge only decrements (Chain::count_down).
                spi && c.counting_only()
            };
            if !quiet {
                return false;
            }
            if self.prescaler & 31 == PHASE_RAMP {
                let frame = self.prescaler >> 5;
                let cont = self.spi_mode() && self.global.g(f::CONT_UPDATE) != 0;
                for (m, cs) in self.motors.iter().zip(self.cur.iter()) {
                    let mask = (1u32 << m.ramp_div) - 1;
                    if frame & mask == mask && (cont || m.v != 0 || cs.v0_count < current::V0_DELAY_TICKS) {
                        return false;
                    }
                }
            }
        }
        self.chip == Chip::Tmc428 || self.sd.quiet(self.step_dir_mode(), self.run_edges + 1)
    }

    /// Driver interface mode of the current state (C89, C91).
    #[inline]
    fn spi_mode(&self) -> bool {
        match self.chip {
            Chip::Tmc428 => true,
            Chip::Tmc429 => !self.global.ifc(f::EN_SD),
            Chip::Tmc4210 => false,
        }
    }

    #[inline]
    fn step_dir_mode(&self) -> bool {
        self.chip != Chip::Tmc428 && self.global.ifc(f::EN_SD)
    }

    /// One edge of the driver units, from the old state (C1, C70). Runs before the motion core
    /// mutates the motors, so every unit sees the step flags and indices of the previous edge.
    /// Returns true when a driver-side pin may have changed.
    #[inline]
    fn drivers(&mut self, pins: u16) -> bool {
        let mut ramp_ticks = 0u8;
        if self.prescaler & 31 == PHASE_RAMP {
            let frame = self.prescaler >> 5;
            for (i, m) in self.motors.iter().enumerate() {
                let mask = (1u32 << m.ramp_div) - 1;
                ramp_ticks |= (((frame & mask) == mask) as u8) << i;
            }
        }
        let spi = self.spi_mode();
        let mut changed = false;
        if self.chip != Chip::Tmc4210 {
            let sdi = (pins >> sync::bit::SDI_S) & 1 != 0;
            changed = self.chain.tick(spi, &self.ram, &mut self.global, &self.motors, &self.cur, ramp_ticks, sdi);
            if ramp_ticks != 0 {
                for i in 0..3 {
                    if (ramp_ticks >> i) & 1 != 0 {
                        self.cur[i].ramp_tick(&self.motors[i]);
                    }
                }
            }
        }
        if self.chip != Chip::Tmc428 {
            let n = self.motor_count();
            let sd = self.step_dir_mode();
            changed |= self.sd.tick(self.run_edges, sd, n, &self.motors, self.global.g(f::CLK2_DIV), self.global.ifc(f::STEP_HALF));
        }
        changed
    }

    /// Drives the driver-side output pins from the new state and samples the multiplexed
    /// reference switches on nSCS_S edges (C81, C87, C91, C92). `pins`: the synchronized inputs of
    /// the old state.
    fn driver_pins(&mut self, pins: u16) {
        let g = &self.global;
        if self.spi_mode() {
            let (ncs, ncs2, ncs3, sck, sdo) = self.chain.pins(g);
            if g.g(f::REFMUX) != 0 && ncs != self.out.nscs_s {
                // 74HC157 on nSCS_S: left switches while the pin is high, right while low (C87).
                let inv = self.chip != Chip::Tmc428 && g.ifc(f::INV_REF);
                let mut mux = g.mux_switches;
                // The pin was low before this edge → the right switches were presented.
                let right = !self.out.nscs_s;
                for m in 0..3u32 {
                    let lv = ((pins >> (sync::bit::REF1 + m)) & 1 != 0) ^ inv;
                    let b = if right { 2 * m } else { 2 * m + 1 };
                    mux = (mux & !(1 << b)) | ((lv as u8) << b);
                }
                self.global.mux_switches = mux;
            }
            self.out.nscs_s = ncs;
            self.out.nscs2 = ncs2;
            self.out.nscs3 = ncs3;
            self.out.sck_s = sck;
            self.out.sdo_s = sdo;
            self.out.sdi_s_o = false;
            self.out.sdi_s_oe = false;
            return;
        }
        let inv_stp = g.ifc(f::INV_STP);
        let inv_dir = g.ifc(f::INV_DIR);
        let sd = self.step_dir_mode();
        match self.chip {
            Chip::Tmc429 => {
                // S1 = SDO_S, D1 = SCK_S, S2 = nSCS_S, D2 = SDI_S, S3 = nSCS2, D3 = nSCS3.
                let (s1, d1) = self.sd.pins(0, inv_stp, inv_dir);
                let (s2, d2) = self.sd.pins(1, inv_stp, inv_dir);
                let (s3, d3) = self.sd.pins(2, inv_stp, inv_dir);
                self.out.sdo_s = s1;
                self.out.sck_s = d1;
                self.out.nscs_s = s2;
                self.out.sdi_s_o = d2;
                self.out.sdi_s_oe = true;
                self.out.nscs2 = s3;
                self.out.nscs3 = d3;
            }
            _ => {
                // TMC4210: STEP = SDO_S, DIR = SCK_S; logic high until en_sd = 1 (C92).
                let (s, d) = if sd { self.sd.pins(0, inv_stp, inv_dir) } else { (true, true) };
                self.out.sdo_s = s;
                self.out.sck_s = d;
                self.out.nscs_s = true;
                self.out.nscs2 = true;
                self.out.nscs3 = true;
                self.out.sdi_s_o = false;
                self.out.sdi_s_oe = false;
            }
        }
    }

    /// Driver-chain state (read-only).
    pub fn chain(&self) -> &chain::Chain {
        &self.chain
    }

    /// Current-scale selector of motor `m` (read-only).
    pub fn current_scale(&self, m: usize) -> &current::CurrentScale {
        &self.cur[m]
    }

    /// Step/Dir state (read-only).
    pub fn step_dir(&self) -> &stepdir::StepDir {
        &self.sd
    }
}
