//! The register file (`rtl/tmc429_regfile.v`, the same unit): the global registers, the µC's
//! register and RAM reads and writes with their side effects, the status byte, INT and the
//! position compare (TMC428 §7–§10, TMC429 §8, TMC4210 §5; docs/model-contract.md C20–C31,
//! C64, C65, C87, C88).

use crate::motor_regs::Motor;
use crate::regmap::{self, f, idx, jdx, Addr, Register};
use crate::{ram, Chip, Tmc429, TYPE_VERSION};

/// Global registers, with the cover and datagram-word flags the driver chain takes and returns.
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
    /// The position match registered in every edge (C65: the POSCMP level).
    pub pc_match_q: bool,
    /// History flop of the registered match, in the running edges (C65).
    pub pc_match_prev: bool,
    /// Cover position (the register holds it + 1 mod 64, which is what reads back, C29).
    pub cover_pos: u8,
    pub cover_len: u8,
    pub cover_datagram: u32,
    /// Cover datagram waiting (cw).
    pub cw: bool,
    /// A datagram_low/high_word write waits for the next datagram (C88).
    pub dgw: bool,
    /// Switch levels sampled through the 74HC157 when refmux = 1 (bit 2m = Rm, 2m+1 = Lm).
    pub mux_switches: u8,
}

impl Global {
    /// The register file's side of the chain's take/return handshake (C85, C88, C89): a
    /// datagram start clears cw and the datagram-word flag, an en_sd abort sets back the ones
    /// the datagram had taken.
    #[inline]
    pub(crate) fn handshake(&mut self, hs: &crate::chain::Handshake) {
        if hs.take {
            self.cw = false;
            self.dgw = false;
        }
        self.cw |= hs.ret_cw;
        self.dgw |= hs.ret_dgw;
    }

    pub(crate) fn reset() -> Self {
        Global {
            gconf: f::CLK2_DIV.put(15),
            ifconf: 0,
            pos_comp: 0,
            pc_m: false,
            pc_i: false,
            pc_match_q: true,
            pc_match_prev: true,
            // The register stores COVER_POS + 1 and resets to 0 (C29): position 63.
            cover_pos: 63,
            cover_len: 0,
            cover_datagram: 0,
            cw: false,
            dgw: false,
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

impl Tmc429 {
    /// The variant has the position compare registers (C65): the TMC429 and the TMC4210.
    #[inline]
    pub(crate) fn has_pos_comp(&self) -> bool {
        self.chip != Chip::Tmc428
    }

    /// The variant has the SDOZ_C and POSCMP pins (C90): the TMC429 (its SSOP16 package
    /// excepted, [`crate::Bonding`]); the TMC4210 has the registers, not the pins ([4210] §3.2).
    #[inline]
    pub(crate) fn has_poscmp_pin(&self) -> bool {
        self.chip == Chip::Tmc429
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
    #[inline]
    pub fn int(&self) -> bool {
        self.motors.iter().any(|m| m.int_flags != 0) || (self.global.pc_i && self.global.pc_m)
    }

    /// Position compare match of the current state (C65).
    #[inline]
    pub(crate) fn pos_match(&self) -> bool {
        if !self.has_pos_comp() {
            return false;
        }
        let sel = (f::POS_COMP_SEL.get(self.global.ifconf) as usize).min(2);
        self.motors[sel].x_actual == self.global.pos_comp
    }

    /// The position compare's event in a running edge (C65): the registered match (the POSCMP
    /// level) rose since the last running edge.
    #[inline]
    pub(crate) fn pos_compare_event(&mut self) -> bool {
        let event = self.global.pc_match_q && !self.global.pc_match_prev;
        self.global.pc_match_prev = self.global.pc_match_q;
        event
    }

    /// The match of the old state registered in every edge (the POSCMP level, C65); whether it
    /// changed.
    #[inline]
    pub(crate) fn pos_compare_register(&mut self, match_old: bool) -> bool {
        let changed = self.global.pc_match_q != match_old;
        self.global.pc_match_q = match_old;
        changed
    }

    /// The flag I after this edge's µC write (C3, C65): set by the event while the mask M is
    /// set, cleared while it is not.
    #[inline]
    pub(crate) fn pos_compare_flag(&mut self, event: bool) {
        if event && self.global.pc_m {
            self.global.pc_i = true;
        }
        if !self.global.pc_m {
            self.global.pc_i = false;
        }
    }

    /// The read value of a 7-bit address as the register file presents it to the SPI slave
    /// (`rtl/tmc429_regfile.v`): v_actual as V >> 8 rounded down, with its rounding toward 0
    /// (C42: 1 for a negative V with a nonzero low byte) apart, which the slave adds to bits
    /// 11..0 in the edge after the load; every other register as [`Tmc429::read_register`].
    pub fn read_register_parts(&self, a7: u8) -> (u32, bool) {
        if let (Some((_, Some(m))), Addr::Motor(_, idx::V_ACTUAL)) = (regmap::lookup(self.chip, a7), Addr::from_a7(a7)) {
            let mo = &self.motors[m as usize];
            return (f::V_ACTUAL.put((mo.v >> 8) as u32), mo.v_round());
        }
        (self.read_register(a7), false)
    }

    /// Register read data (24 bits) of a 7-bit address in the current state (C20–C31).
    pub fn read_register(&self, a7: u8) -> u32 {
        let Some((reg, motor)) = regmap::lookup(self.chip, a7) else {
            return 0;
        };
        match Addr::from_a7(a7) {
            Addr::Ram(a) => ram::read_word(&self.ram, a),
            Addr::Motor(_, i) => motor_read(&self.motors[motor.unwrap_or(0) as usize], i),
            Addr::Global(j) => self.global_read(j, reg),
        }
    }

    /// Marks the motion core's inputs as changed (ends the fast path of [`Tmc429::tick`]).
    #[inline]
    pub(crate) fn touch(&mut self) {
        self.quiet = false;
    }

    /// Executes a 32-bit datagram (C12): a register or RAM write; reads have no side effects.
    pub(crate) fn execute(&mut self, d: u32) {
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
        self.pins_stale = true;
        match Addr::from_a7(a7) {
            Addr::Ram(a) => ram::write_word(&mut self.ram, a, data),
            Addr::Motor(_, i) => motor_write(&mut self.motors[motor.unwrap_or(0) as usize], i, data),
            Addr::Global(j) => self.global_write(j, data, reg),
        }
    }

    /// The read value of global register JDX `j` (C29–C31, C64, C87).
    fn global_read(&self, j: u8, reg: &Register) -> u32 {
        let g = &self.global;
        match j {
            jdx::DATAGRAM_LOW_WORD => (self.chain.readback & 0xFF_FFFF) as u32,
            jdx::DATAGRAM_HIGH_WORD => ((self.chain.readback >> 24) & 0xFF_FFFF) as u32,
            jdx::COVER_POS_LEN => {
                f::COVER_WAITING.put(self.chain.cw(g) as u32)
                    | f::COVER_POS.put((g.cover_pos as u32 + 1) & 63)
                    | f::COVER_LEN.put(g.cover_len as u32)
            }
            jdx::COVER_DATAGRAM => g.cover_datagram,
            jdx::IF_CONFIGURATION => g.ifconf,
            jdx::POS_COMP => g.pos_comp,
            jdx::POS_COMP_INT => f::POS_COMP_M.put(g.pc_m as u32) | f::POS_COMP_I.put(g.pc_i as u32),
            jdx::TYPE_VERSION => TYPE_VERSION,
            jdx::REF_SWITCHES => {
                let (l, r) = self.switches();
                let mut w = 0;
                for m in 0..3 {
                    w |= (((r >> m) & 1) as u32) << (2 * m) | (((l >> m) & 1) as u32) << (2 * m + 1);
                }
                w
            }
            jdx::GLOBAL_PARAMETERS => g.gconf & reg.writable_mask(),
            _ => 0,
        }
    }

    /// A µC write of `data` to global register JDX `j`, with its side effects (C29–C31, C64,
    /// C66, C87, C88).
    fn global_write(&mut self, j: u8, data: u32, reg: &Register) {
        let g = &mut self.global;
        match j {
            jdx::DATAGRAM_LOW_WORD | jdx::DATAGRAM_HIGH_WORD => {
                // "A write to one of these read-only registers initializes them" (C87).
                self.chain.clear_readback();
                g.dgw = true;
            }
            jdx::COVER_POS_LEN => {
                g.cover_pos = f::COVER_POS.get(data) as u8;
                g.cover_len = f::COVER_LEN.get(data) as u8;
            }
            jdx::COVER_DATAGRAM => {
                g.cover_datagram = data;
                g.cw = true;
            }
            jdx::IF_CONFIGURATION => g.ifconf = data & reg.writable_mask(),
            jdx::POS_COMP => g.pos_comp = data,
            jdx::POS_COMP_INT => {
                g.pc_m = f::POS_COMP_M.get(data) != 0;
                if f::POS_COMP_I.get(data) != 0 || !g.pc_m {
                    g.pc_i = false;
                }
            }
            jdx::POWER_DOWN => self.power_down = true,
            jdx::GLOBAL_PARAMETERS => g.gconf = data & reg.writable_mask(),
            _ => {}
        }
    }
}

/// The read value of motor register IDX `i` of motor `m` (C21–C28).
fn motor_read(m: &Motor, i: u8) -> u32 {
    match i {
        idx::X_TARGET => m.x_target,
        idx::X_ACTUAL => m.x_actual,
        idx::V_MIN => m.v_min as u32,
        idx::V_MAX => m.v_max as u32,
        idx::V_TARGET => m.v_target as u32,
        idx::V_ACTUAL => f::V_ACTUAL.put(m.v_actual() as u32),
        idx::A_MAX => m.a_max as u32,
        idx::A_ACTUAL => f::A_ACTUAL.put(m.a_actual as u32),
        idx::CURRENT_SCALING => {
            f::IS_AGTAT.put(m.is_agtat as u32)
                | f::IS_ALEAT.put(m.is_aleat as u32)
                | f::IS_V0.put(m.is_v0 as u32)
                | f::A_THRESHOLD.put(m.a_threshold as u32)
        }
        idx::PMUL_PDIV => f::PMUL.put(0x80 | m.pmul as u32) | f::PDIV.put(m.pdiv as u32),
        idx::REF_CONF_RM => f::LP.put(m.lp as u32) | (m.ref_conf as u32) << f::DISABLE_STOP_L.lsb | f::RM.put(m.rm as u32),
        idx::INTERRUPT => f::INTERRUPT_MASK.put(m.int_mask as u32) | f::INTERRUPT_FLAGS.put(m.int_flags as u32),
        idx::CLK_CONFIG => f::PULSE_DIV.put(m.pulse_div as u32) | f::RAMP_DIV.put(m.ramp_div as u32) | f::USRS.put(m.usrs as u32),
        idx::DX_REF_TOLERANCE => m.dx_ref_tolerance as u32,
        idx::X_LATCHED => m.x_latched,
        idx::USTEP_COUNT => m.ustep as u32,
        _ => 0,
    }
}

/// A µC write of `data` to motor register IDX `i` of motor `m`, with its side effects (C21–C28).
fn motor_write(m: &mut Motor, i: u8, data: u32) {
    match i {
        idx::X_TARGET => m.x_target = data,
        idx::X_ACTUAL => m.x_actual = data,
        idx::V_MIN => m.v_min = f::V_MIN.get(data) as u16,
        idx::V_MAX => m.v_max = f::V_MAX.get(data) as u16,
        idx::V_TARGET => m.v_target = f::V_TARGET.get(data) as u16,
        idx::V_ACTUAL => {
            // C23: V := w·256, −2048 as −2047.
            let w = (f::V_ACTUAL.value(data) as i32).max(-2047);
            m.v = w * 256;
            // the write wins over a ramp tick's V not yet stored (C3, C51)
            m.v_due = None;
        }
        idx::A_MAX => m.a_max = f::A_MAX.get(data) as u16,
        idx::A_ACTUAL => {}
        idx::CURRENT_SCALING => {
            m.is_agtat = f::IS_AGTAT.get(data) as u8;
            m.is_aleat = f::IS_ALEAT.get(data) as u8;
            m.is_v0 = f::IS_V0.get(data) as u8;
            m.a_threshold = f::A_THRESHOLD.get(data) as u16;
        }
        idx::PMUL_PDIV => {
            m.pmul = (f::PMUL.get(data) & 0x7F) as u8;
            m.pdiv = f::PDIV.get(data) as u8;
        }
        idx::REF_CONF_RM => {
            // the four ref_conf bits, disable_stop_l .. ref_rnl
            m.ref_conf = ((data >> f::DISABLE_STOP_L.lsb) & 0xF) as u8;
            m.rm = f::RM.get(data) as u8;
        }
        idx::INTERRUPT => {
            m.int_mask = f::INTERRUPT_MASK.get(data) as u8;
            m.int_flags &= !(f::INTERRUPT_FLAGS.get(data) as u8);
            m.int_flags &= m.int_mask;
        }
        idx::CLK_CONFIG => {
            m.pulse_div = f::PULSE_DIV.get(data) as u8;
            m.ramp_div = f::RAMP_DIV.get(data) as u8;
            m.usrs = f::USRS.get(data) as u8;
        }
        idx::DX_REF_TOLERANCE => m.dx_ref_tolerance = f::DX_REF_TOLERANCE.get(data) as u16,
        idx::X_LATCHED => m.lp = true,
        idx::USTEP_COUNT => m.ustep = f::USTEP_COUNT.get(data) as u8,
        _ => {}
    }
}
