//! The register map: the one description of every register and field of the family.
//!
//! Everything else is derived from [`REGISTERS`]: the model's field decoding (through the
//! [`f`] field constants), `tmc429 regmap --format md|c|json`, `docs/regmap.md`, the C header and
//! the decoded register names of traces. Sources: TMC428 datasheet Table 7-2 and §8–§10,
//! TMC429 datasheet §7.3 and §8, TMC4210 datasheet §5.

use crate::Chip;

/// How the µC may access a field.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Access {
    /// Read and write.
    Rw,
    /// Read only; writes are ignored.
    R,
    /// Write only (a write is a command); reads 0.
    W,
    /// Reads the flag; writing 1 clears it, 0 keeps it.
    W1c,
}

impl Access {
    pub fn as_str(self) -> &'static str {
        match self {
            Access::Rw => "RW",
            Access::R => "R",
            Access::W => "W",
            Access::W1c => "W1C",
        }
    }
}

/// One field of a 24-bit register data word.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Field {
    pub name: &'static str,
    pub lsb: u8,
    pub width: u8,
    pub signed: bool,
    pub access: Access,
    pub doc: &'static str,
}

impl Field {
    pub const fn mask(&self) -> u32 {
        (((1u64 << self.width) - 1) as u32) << self.lsb
    }
    /// The field's raw (unsigned) value in a data word.
    #[inline]
    pub const fn get(&self, word: u32) -> u32 {
        (word >> self.lsb) & (((1u64 << self.width) - 1) as u32)
    }
    /// The field's value, sign-extended when the field is signed.
    #[inline]
    pub const fn value(&self, word: u32) -> i64 {
        let raw = self.get(word) as i64;
        if self.signed && (raw >> (self.width - 1)) & 1 == 1 {
            raw - (1i64 << self.width)
        } else {
            raw
        }
    }
    /// `v` placed at the field's position (truncated to its width).
    #[inline]
    pub const fn put(&self, v: u32) -> u32 {
        (v << self.lsb) & self.mask()
    }
}

/// Address space of a register (the RRS bit and SMDA of the datagram, TMC428 §7.1).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Space {
    /// Per-motor register: A7 = SMDA·16 + IDX, SMDA 0..2.
    Motor,
    /// Global register: A7 = $30 + JDX.
    Global,
    /// RAM word (RRS = 1): A7 = $40 + ADDR; `index` 0 = driver configuration (ADDR 0..31),
    /// 1 = microstep table (ADDR 32..63).
    Ram,
}

/// Set of chip variants a register exists on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ChipSet(pub u8);

impl ChipSet {
    pub const ALL: ChipSet = ChipSet(0b111);
    pub const SPI_CHAIN: ChipSet = ChipSet(0b011);
    pub const TMC428: ChipSet = ChipSet(0b001);
    pub const TMC429_4210: ChipSet = ChipSet(0b110);
    pub const TMC4210: ChipSet = ChipSet(0b100);
    pub const NOT_4210: ChipSet = ChipSet(0b011);
    pub fn contains(self, chip: Chip) -> bool {
        self.0 & chip.bit() != 0
    }
}

/// One register: a (space, index) with its fields.
#[derive(Debug)]
pub struct Register {
    pub name: &'static str,
    pub space: Space,
    /// IDX (motor), JDX (global) or RAM half.
    pub index: u8,
    pub chips: ChipSet,
    pub fields: &'static [Field],
    /// Value read after power-on (motor 1 for per-motor registers).
    pub reset: u32,
    /// Side effects of a write or read, in words.
    pub effect: &'static str,
    /// Datasheet section the register is described in.
    pub section: &'static str,
}

impl Register {
    /// The 7-bit address (RRS, SMDA/ADDR, IDX) of this register for `motor` (0..2; ignored for
    /// global registers; for RAM the first word of the half).
    pub fn a7(&self, motor: u8) -> u8 {
        match self.space {
            Space::Motor => (motor << 4) | self.index,
            Space::Global => 0x30 | self.index,
            Space::Ram => 0x40 | (self.index << 5),
        }
    }
    pub fn field(&self, name: &str) -> Option<&'static Field> {
        self.fields.iter().find(|f| f.name.eq_ignore_ascii_case(name))
    }
    /// Bits a write stores (not R, not W1C).
    pub fn writable_mask(&self) -> u32 {
        self.fields.iter().filter(|f| matches!(f.access, Access::Rw)).fold(0, |m, f| m | f.mask())
    }
}

const fn fld(name: &'static str, lsb: u8, width: u8, signed: bool, access: Access, doc: &'static str) -> Field {
    Field { name, lsb, width, signed, access, doc }
}

/// Every field of the family, as constants the model decodes with.
pub mod f {
    use super::{fld, Access::*, Field};
    // Per-motor (TMC428 §8, TMC429 §8.1).
    pub const X_TARGET: Field = fld("x_target", 0, 24, true, Rw, "target position");
    pub const X_ACTUAL: Field = fld("x_actual", 0, 24, true, Rw, "actual position");
    pub const V_MIN: Field = fld("v_min", 0, 11, false, Rw, "minimum velocity (RAMP, SOFT)");
    pub const V_MAX: Field = fld("v_max", 0, 11, false, Rw, "maximum velocity");
    pub const V_TARGET: Field = fld("v_target", 0, 12, true, Rw, "target velocity (VELOCITY mode input; computed in RAMP, SOFT)");
    pub const V_ACTUAL: Field = fld("v_actual", 0, 12, true, Rw, "actual velocity: sign and 11 MSBs of the internal velocity");
    pub const A_MAX: Field = fld("a_max", 0, 11, false, Rw, "maximum acceleration");
    pub const A_ACTUAL: Field = fld("a_actual", 0, 12, true, R, "velocity change of the last ramp tick");
    pub const IS_AGTAT: Field = fld("is_agtat", 20, 3, false, Rw, "current scale while |a| > a_threshold");
    pub const IS_ALEAT: Field = fld("is_aleat", 16, 3, false, Rw, "current scale while |a| <= a_threshold");
    pub const IS_V0: Field = fld("is_v0", 12, 3, false, Rw, "current scale at rest");
    pub const A_THRESHOLD: Field = fld("a_threshold", 0, 11, false, Rw, "acceleration threshold of current scaling");
    pub const PMUL: Field = fld("pmul", 8, 8, false, Rw, "p_mul = 128 + bits 14..8; bit 15 reads 1");
    pub const PDIV: Field = fld("pdiv", 0, 4, false, Rw, "p_div exponent (valid 0..13)");
    pub const LP: Field = fld("lp", 16, 1, false, R, "latch pending");
    pub const REF_RNL: Field = fld("ref_rnl", 11, 1, false, Rw, "1: right switch is the reference switch");
    pub const SOFT_STOP: Field = fld("soft_stop", 10, 1, false, Rw, "1: switch stop with a linear ramp");
    pub const DISABLE_STOP_R: Field = fld("disable_stop_r", 9, 1, false, Rw, "1: right switch does not stop");
    pub const DISABLE_STOP_L: Field = fld("disable_stop_l", 8, 1, false, Rw, "1: left switch does not stop");
    pub const RM: Field = fld("rm", 0, 2, false, Rw, "ramp mode: 0 RAMP, 1 SOFT, 2 VELOCITY, 3 HOLD");
    pub const INTERRUPT_MASK: Field = fld("interrupt_mask", 8, 8, false, Rw, "interrupt mask");
    pub const INTERRUPT_FLAGS: Field = fld("interrupt_flags", 0, 8, false, W1c, "interrupt flags (write 1 to clear)");
    pub const PULSE_DIV: Field = fld("pulse_div", 12, 4, false, Rw, "pulse clock divider exponent");
    pub const RAMP_DIV: Field = fld("ramp_div", 8, 4, false, Rw, "ramp clock divider exponent");
    pub const USRS: Field = fld("usrs", 0, 3, false, Rw, "microstep resolution: 2^usrs per full step");
    pub const DX_REF_TOLERANCE: Field = fld("dx_ref_tolerance", 0, 12, false, Rw, "reference switch tolerance window");
    pub const X_LATCHED: Field = fld("x_latched", 0, 24, true, R, "latched position; a write arms the latch");
    pub const USTEP_COUNT: Field = fld("ustep_count", 0, 8, false, Rw, "full-wave microstep index");
    // Global (TMC428 §9, TMC429 §8.2).
    pub const DATAGRAM_LOW: Field = fld("datagram_low_word", 0, 24, false, R, "bits 23..0 of the driver-chain readback; a write arms CDGW");
    pub const DATAGRAM_HIGH: Field =
        fld("datagram_high_word", 0, 24, false, R, "bits 47..24 of the driver-chain readback; a write arms CDGW");
    pub const COVER_WAITING: Field = fld("cw", 23, 1, false, R, "cover datagram waiting");
    pub const COVER_POS: Field = fld("cover_pos", 8, 6, false, Rw, "first bit position of the cover datagram (reads back +1)");
    pub const COVER_LEN: Field = fld("cover_len", 0, 5, false, Rw, "cover datagram length (0..24)");
    pub const COVER_DATAGRAM: Field = fld("cover_datagram", 0, 24, false, Rw, "cover datagram; a write requests it");
    pub const INV_REF: Field = fld("inv_ref", 0, 1, false, Rw, "invert all reference inputs");
    pub const SDO_INT: Field = fld("sdo_int", 1, 1, false, Rw, "nINT_SDO_C is a plain nINT output");
    pub const STEP_HALF: Field = fld("step_half", 2, 1, false, Rw, "STEP toggles once per step");
    pub const INV_STP: Field = fld("inv_stp", 3, 1, false, Rw, "invert STEP");
    pub const INV_DIR: Field = fld("inv_dir", 4, 1, false, Rw, "invert DIR");
    pub const EN_SD: Field = fld("en_sd", 5, 1, false, Rw, "Step/Dir mode");
    pub const POS_COMP_SEL: Field = fld("pos_comp_sel", 6, 2, false, Rw, "motor compared with pos_comp");
    pub const EN_REFR: Field = fld("en_refr", 8, 1, false, Rw, "enable REFR1..3");
    pub const POS_COMP: Field = fld("pos_comp", 0, 24, true, Rw, "position compared with x_actual of the selected motor");
    pub const POS_COMP_M: Field = fld("m", 8, 1, false, Rw, "position compare interrupt mask");
    pub const POS_COMP_I: Field = fld("i", 0, 1, false, W1c, "position compare interrupt flag");
    pub const POWER_DOWN: Field = fld("power_down", 0, 24, false, W, "a write powers down until nSCS_C falls");
    pub const TYPE_VERSION: Field = fld("type_version", 0, 24, false, R, "$429101");
    pub const R1: Field = fld("r1", 0, 1, false, R, "right switch motor 1 (TMC4210: REF_R)");
    pub const L1: Field = fld("l1", 1, 1, false, R, "left switch motor 1 (TMC4210: REF_L)");
    pub const R2: Field = fld("r2", 2, 1, false, R, "right switch motor 2");
    pub const L2: Field = fld("l2", 3, 1, false, R, "left switch motor 2 (TMC4210: GP_IN)");
    pub const R3: Field = fld("r3", 4, 1, false, R, "right switch motor 3");
    pub const L3: Field = fld("l3", 5, 1, false, R, "left switch motor 3");
    pub const LSMD: Field = fld("lsmd", 0, 2, false, Rw, "last stepper motor driver (0..2)");
    pub const POL_NSCS_S: Field = fld("polarity_nscs_s", 2, 1, false, Rw, "nSCS_S high active");
    pub const POL_SCK_S: Field = fld("polarity_sck_s", 3, 1, false, Rw, "invert SCK_S");
    pub const POL_PH_AB: Field = fld("polarity_ph_ab", 4, 1, false, Rw, "invert PH_A, PH_B");
    pub const POL_FD_AB: Field = fld("polarity_fd_ab", 5, 1, false, Rw, "FD low active");
    pub const POL_DAC_AB: Field = fld("polarity_dac_ab", 6, 1, false, Rw, "invert all DAC bits");
    pub const CS_COM_IND: Field = fld("cs_com_ind", 7, 1, false, Rw, "individual nSCS_S, nSCS2, nSCS3");
    pub const CLK2_DIV: Field = fld("clk2_div", 8, 8, false, Rw, "SCK_S divider: f = fCLK/(2(clk2_div+1)); Step/Dir: bits 11..8 = STPDIV");
    pub const STPDIV: Field = fld("stpdiv", 8, 4, false, Rw, "step pulse length 16(1+STPDIV) CLK");
    pub const CONT_UPDATE: Field = fld("cont_update", 16, 1, false, Rw, "periodic driver-chain datagrams");
    pub const REFMUX: Field = fld("refmux", 20, 1, false, Rw, "reference switches multiplexed by a 74HC157 on nSCS_S");
    pub const MOT1R: Field = fld("mot1r", 21, 1, false, Rw, "REF3 is the right switch of motor 1");
    // RAM word (TMC428 Table 10-1).
    pub const RAM_ODD: Field = fld("odd", 8, 6, false, Rw, "cell 2*ADDR+1");
    pub const RAM_EVEN: Field = fld("even", 0, 6, false, Rw, "cell 2*ADDR");
}

/// IDX of the per-motor registers (TMC428 Table 7-2); the table below uses these.
pub mod idx {
    pub const X_TARGET: u8 = 0;
    pub const X_ACTUAL: u8 = 1;
    pub const V_MIN: u8 = 2;
    pub const V_MAX: u8 = 3;
    pub const V_TARGET: u8 = 4;
    pub const V_ACTUAL: u8 = 5;
    pub const A_MAX: u8 = 6;
    pub const A_ACTUAL: u8 = 7;
    pub const CURRENT_SCALING: u8 = 8;
    pub const PMUL_PDIV: u8 = 9;
    pub const REF_CONF_RM: u8 = 10;
    pub const INTERRUPT: u8 = 11;
    pub const CLK_CONFIG: u8 = 12;
    pub const DX_REF_TOLERANCE: u8 = 13;
    pub const X_LATCHED: u8 = 14;
    pub const USTEP_COUNT: u8 = 15;
}

/// JDX of the global registers (TMC428 §9, TMC429 §8.2); the table below uses these.
pub mod jdx {
    pub const DATAGRAM_LOW_WORD: u8 = 0;
    pub const DATAGRAM_HIGH_WORD: u8 = 1;
    pub const COVER_POS_LEN: u8 = 2;
    pub const COVER_DATAGRAM: u8 = 3;
    pub const IF_CONFIGURATION: u8 = 4;
    pub const POS_COMP: u8 = 5;
    pub const POS_COMP_INT: u8 = 6;
    pub const POWER_DOWN: u8 = 8;
    pub const TYPE_VERSION: u8 = 9;
    pub const REF_SWITCHES: u8 = 14;
    pub const GLOBAL_PARAMETERS: u8 = 15;
}

use f::*;
use Space::*;

const fn reg(
    name: &'static str,
    space: Space,
    index: u8,
    chips: ChipSet,
    fields: &'static [Field],
    reset: u32,
    effect: &'static str,
    section: &'static str,
) -> Register {
    Register { name, space, index, chips, fields, reset, effect, section }
}

/// The register map of the family.
#[rustfmt::skip] // one register per line: the table reads like the datasheets' maps
pub static REGISTERS: &[Register] = &[
    reg("x_target", Motor, idx::X_TARGET, ChipSet::ALL, &[X_TARGET], 0, "", "TMC428 §8.1"),
    reg("x_actual", Motor, idx::X_ACTUAL, ChipSet::ALL, &[X_ACTUAL], 0, "in RAMP and SOFT mode the motor then drives to x_target", "TMC428 §8.2"),
    reg("v_min", Motor, idx::V_MIN, ChipSet::ALL, &[V_MIN], 0, "", "TMC428 §8.3"),
    reg("v_max", Motor, idx::V_MAX, ChipSet::ALL, &[V_MAX], 0, "", "TMC428 §8.4"),
    reg("v_target", Motor, idx::V_TARGET, ChipSet::ALL, &[V_TARGET], 0, "overwritten by the ramp generator at each ramp tick in RAMP and SOFT mode (contract C24)", "TMC428 §8.5"),
    reg("v_actual", Motor, idx::V_ACTUAL, ChipSet::ALL, &[V_ACTUAL], 0, "a write sets the internal velocity and clears its 8 fraction bits (contract C23)", "TMC428 §8.6"),
    reg("a_max", Motor, idx::A_MAX, ChipSet::ALL, &[A_MAX], 0, "", "TMC428 §8.7"),
    reg("a_actual", Motor, idx::A_ACTUAL, ChipSet::ALL, &[A_ACTUAL], 0, "", "TMC428 §8.8"),
    reg("current_scaling", Motor, idx::CURRENT_SCALING, ChipSet::NOT_4210, &[IS_AGTAT, IS_ALEAT, IS_V0, A_THRESHOLD], 0, "", "TMC428 §8.9"),
    reg("pmul_pdiv", Motor, idx::PMUL_PDIV, ChipSet::ALL, &[PMUL, PDIV], 0x8000, "bit 15 reads 1 (contract C22)", "TMC428 §8.10"),
    reg("ref_conf_rm", Motor, idx::REF_CONF_RM, ChipSet::ALL, &[LP, REF_RNL, SOFT_STOP, DISABLE_STOP_R, DISABLE_STOP_L, RM], 0, "", "TMC428 §8.11, §8.12"),
    reg("interrupt", Motor, idx::INTERRUPT, ChipSet::ALL, &[INTERRUPT_MASK, INTERRUPT_FLAGS], 0, "flags clear where 1 is written and are forced 0 where masked", "TMC428 §8.13"),
    reg("clk_config", Motor, idx::CLK_CONFIG, ChipSet::ALL, &[PULSE_DIV, RAMP_DIV, USRS], 0, "", "TMC428 §8.14, §8.15"),
    reg("dx_ref_tolerance", Motor, idx::DX_REF_TOLERANCE, ChipSet::ALL, &[DX_REF_TOLERANCE], 0, "", "TMC428 §8.15"),
    reg("x_latched", Motor, idx::X_LATCHED, ChipSet::ALL, &[X_LATCHED], 0, "a write (any data) arms the latch: lp := 1", "TMC428 §8.16"),
    reg("ustep_count", Motor, idx::USTEP_COUNT, ChipSet::TMC429_4210, &[USTEP_COUNT], 0, "", "TMC429 §8.1.16"),
    reg("datagram_low_word", Global, jdx::DATAGRAM_LOW_WORD, ChipSet::SPI_CHAIN, &[DATAGRAM_LOW], 0, "a write arms CDGW until the next datagram completes", "TMC428 §9.1"),
    reg("datagram_high_word", Global, jdx::DATAGRAM_HIGH_WORD, ChipSet::SPI_CHAIN, &[DATAGRAM_HIGH], 0, "a write arms CDGW until the next datagram completes", "TMC428 §9.1"),
    reg("cover_pos_len", Global, jdx::COVER_POS_LEN, ChipSet::SPI_CHAIN, &[COVER_WAITING, COVER_POS, COVER_LEN], 0, "the register stores cover_pos + 1 and reads it back: 0 after power-on (contract C29)", "TMC428 §9.2"),
    reg("cover_datagram", Global, jdx::COVER_DATAGRAM, ChipSet::SPI_CHAIN, &[COVER_DATAGRAM], 0, "a write sets cw and requests a datagram", "TMC428 §9.3"),
    reg("if_configuration", Global, jdx::IF_CONFIGURATION, ChipSet::TMC429_4210, &[INV_REF, SDO_INT, STEP_HALF, INV_STP, INV_DIR, EN_SD, POS_COMP_SEL, EN_REFR], 0, "", "TMC429 §8.2.4"),
    reg("pos_comp", Global, jdx::POS_COMP, ChipSet::TMC429_4210, &[POS_COMP], 0, "", "TMC429 §8.2.4.1"),
    reg("pos_comp_int", Global, jdx::POS_COMP_INT, ChipSet::TMC429_4210, &[POS_COMP_M, POS_COMP_I], 0, "I clears where 1 is written and is forced 0 while M = 0", "TMC429 §8.2.4.2"),
    reg("power_down", Global, jdx::POWER_DOWN, ChipSet::ALL, &[POWER_DOWN], 0, "a write stops all clocks until nSCS_C falls", "TMC428 §9.5"),
    reg("type_version", Global, jdx::TYPE_VERSION, ChipSet::TMC429_4210, &[TYPE_VERSION], 0x429101, "", "TMC429 §8.2.4.4"),
    reg("ref_switches", Global, jdx::REF_SWITCHES, ChipSet::ALL, &[R1, L1, R2, L2, R3, L3], 0, "", "TMC428 §9.6, TMC429 §8.2.4.5"),
    reg("global_parameters", Global, jdx::GLOBAL_PARAMETERS, ChipSet::NOT_4210, &[LSMD, POL_NSCS_S, POL_SCK_S, POL_PH_AB, POL_FD_AB, POL_DAC_AB, CS_COM_IND, CLK2_DIV, CONT_UPDATE, REFMUX, MOT1R], 0x000F00, "", "TMC428 §9.7, TMC429 §8.2.5"),
    reg("global_parameters", Global, jdx::GLOBAL_PARAMETERS, ChipSet::TMC4210, &[STPDIV, MOT1R], 0x000F00, "", "TMC4210 §5.3"),
    reg("ram_driver_config", Ram, 0, ChipSet::ALL, &[RAM_ODD, RAM_EVEN], 0, "two 6-bit cells per word: bit 5 NxM, bits 4..0 primary signal code (the TMC4210 stores them, it has no driver chain)", "TMC428 §10, §11; TMC4210 §1.3, §5.2.3"),
    reg("ram_microstep_table", Ram, 1, ChipSet::ALL, &[RAM_ODD, RAM_EVEN], 0, "two 6-bit quarter-sine entries per word (the TMC4210 stores them, it has no microstep unit)", "TMC428 §10, §12; TMC4210 §1.3, §5.2.3"),
];

/// A decoded 7-bit address.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Addr {
    /// Motor register: (motor 0..2, IDX).
    Motor(u8, u8),
    /// Global register JDX.
    Global(u8),
    /// RAM word ADDR 0..63.
    Ram(u8),
}

impl Addr {
    pub fn from_a7(a7: u8) -> Addr {
        let a7 = a7 & 0x7F;
        if a7 & 0x40 != 0 {
            Addr::Ram(a7 & 0x3F)
        } else if a7 >> 4 == 3 {
            Addr::Global(a7 & 0xF)
        } else {
            Addr::Motor(a7 >> 4, a7 & 0xF)
        }
    }
    pub fn a7(self) -> u8 {
        match self {
            Addr::Motor(m, i) => (m << 4) | i,
            Addr::Global(j) => 0x30 | j,
            Addr::Ram(a) => 0x40 | a,
        }
    }
}

/// The register at a 7-bit address on a chip, with the motor it belongs to. `None` for an address
/// the variant does not have (it reads 0 and ignores writes, contract C21).
pub fn lookup(chip: Chip, a7: u8) -> Option<(&'static Register, Option<u8>)> {
    let (space, index, motor) = match Addr::from_a7(a7) {
        Addr::Motor(m, i) => {
            if chip == Chip::Tmc4210 && m != 0 {
                return None;
            }
            (Motor, i, Some(m))
        }
        Addr::Global(j) => (Global, j, None),
        Addr::Ram(a) => (Ram, a >> 5, None),
    };
    REGISTERS.iter().find(|r| r.space == space && r.index == index && r.chips.contains(chip)).map(|r| (r, motor))
}

/// Find a register by name on a chip (case-insensitive). Motor registers are found for motor 0.
pub fn by_name(chip: Chip, name: &str) -> Option<&'static Register> {
    REGISTERS.iter().find(|r| r.name.eq_ignore_ascii_case(name) && r.chips.contains(chip))
}

/// Address of a motor register (motor 0..2, IDX 0..15).
pub const fn motor_a7(motor: u8, idx: u8) -> u8 {
    ((motor & 3) << 4) | (idx & 0xF)
}

/// Address of a global register (JDX 0..15).
pub const fn global_a7(jdx: u8) -> u8 {
    0x30 | (jdx & 0xF)
}

/// Address of a RAM word (ADDR 0..63).
pub const fn ram_a7(addr: u8) -> u8 {
    0x40 | (addr & 0x3F)
}

/// First byte of a datagram: A7 and the RW bit (TMC428 §6.2: W byte = A7·2, R byte = A7·2+1).
pub const fn datagram(a7: u8, read: bool, data: u32) -> u32 {
    ((a7 as u32 & 0x7F) << 25) | ((read as u32) << 24) | (data & 0xFF_FFFF)
}

/// A register's name for traces: `x_target[1]` for motor registers, `ram[12]` for RAM words,
/// `unused` for addresses the chip lacks.
pub fn display_name(chip: Chip, a7: u8) -> String {
    match (lookup(chip, a7), Addr::from_a7(a7)) {
        (Some((r, Some(m))), _) => format!("{}[{}]", r.name, m),
        (Some(_), Addr::Ram(a)) => format!("ram[{a}]"),
        (Some((r, None)), _) => r.name.to_string(),
        (None, Addr::Motor(m, i)) => format!("unused[m{m}.{i}]"),
        (None, Addr::Global(j)) => format!("unused[g{j}]"),
        (None, Addr::Ram(a)) => format!("unused[ram{a}]"),
    }
}

/// The fields of a data word decoded for humans: `v_max=2047`, signed fields as signed numbers.
pub fn decode_fields(reg: &Register, data: u32) -> String {
    let mut out = Vec::new();
    for fl in reg.fields {
        let v = fl.value(data);
        if fl.width >= 8 && !fl.signed {
            out.push(format!("{}={} (${:X})", fl.name, v, v));
        } else {
            out.push(format!("{}={}", fl.name, v));
        }
    }
    out.join(" ")
}
