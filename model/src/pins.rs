//! The pin list shared by all variants, and the probe bundle of internal state.
//!
//! One [`crate::Tmc429::tick`] equals one rising edge of CLK: the [`Inputs`] are the pin levels
//! just before the edge, the [`Outputs`] the levels just after it (docs/model-contract.md C1).
//! Every output is a register output (no combinational path from an input to an output).

/// Input pins. Names are the TMC429 datasheet's (§1.5); the TMC4210 uses REF1 as REF_L,
/// REF2 as GP_IN and REF3 as REF_R (TMC4210 §1.5).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Inputs {
    /// µC chip select, low active (asynchronous to CLK).
    pub nscs_c: bool,
    /// µC serial clock (asynchronous to CLK); idles high.
    pub sck_c: bool,
    /// µC serial data in.
    pub sdi_c: bool,
    /// Serial data returned by the driver chain (input in SPI mode).
    pub sdi_s: bool,
    pub ref1: bool,
    pub ref2: bool,
    pub ref3: bool,
    /// TMC429 right reference inputs (internal pull-ups: an open input reads 1).
    pub refr1: bool,
    pub refr2: bool,
    pub refr3: bool,
}

impl Default for Inputs {
    /// Idle bus (nSCS_C = SCK_C = 1), switches open, REFR pulled up.
    fn default() -> Self {
        Inputs {
            nscs_c: true,
            sck_c: true,
            sdi_c: false,
            sdi_s: false,
            ref1: false,
            ref2: false,
            ref3: false,
            refr1: true,
            refr2: true,
            refr3: true,
        }
    }
}

/// Output pins. In Step/Dir mode (TMC429 `en_sd` = 1, TMC4210) the driver-chain pins carry
/// STEP/DIR (TMC429 §10: S1 = SDO_S, D1 = SCK_S, S2 = nSCS_S, D2 = SDI_S, S3 = nSCS2, D3 = nSCS3).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Outputs {
    /// nINT_SDO_C: serial data while nSCS_C is low, nINT while high (TMC428 §6.2);
    /// permanently nINT with `sdo_int` = 1 (TMC429 §8.2.4).
    pub nint_sdo_c: bool,
    /// SDOZ_C data (TMC429): serial data, valid when `sdoz_c_oe`.
    pub sdoz_c: bool,
    /// SDOZ_C output enable: 1 while nSCS_C is low (tri-state otherwise).
    pub sdoz_c_oe: bool,
    pub nscs_s: bool,
    pub sck_s: bool,
    pub sdo_s: bool,
    /// Driver on the SDI_S pin (D2 in Step/Dir mode), valid when `sdi_s_oe`.
    pub sdi_s_o: bool,
    pub sdi_s_oe: bool,
    pub nscs2: bool,
    pub nscs3: bool,
    /// Position compare output (TMC429 §8.2.4.1), high while positions match.
    pub poscmp: bool,
}

impl Outputs {
    /// The levels with nothing selected: nINT inactive (high), SDOZ_C and SDI_S not driven,
    /// the chip selects inactive, SCK_S and SDO_S high ([429] §8.2.4 note, Fig. 11.1), POSCMP
    /// low; a chip's power-on pins start from these (`Tmc429::new` then applies its variant's
    /// driver pins and pos_comp).
    pub const IDLE: Outputs = Outputs {
        nint_sdo_c: true,
        sdoz_c: false,
        sdoz_c_oe: false,
        nscs_s: true,
        sck_s: true,
        sdo_s: true,
        sdi_s_o: false,
        sdi_s_oe: false,
        nscs2: true,
        nscs3: true,
        poscmp: false,
    };
}

/// Per-motor internal state exposed for comparison and tracing (the probes, docs/cosim.md).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct MotorProbe {
    /// 24-bit register value, zero-extended.
    pub x_target: u32,
    /// 24-bit register value, zero-extended.
    pub x_actual: u32,
    /// Internal velocity: sign + 11 integer + 8 fraction bits (TMC428 §8.6), as i32.
    pub v_internal: i32,
    /// v_target register (12-bit signed), as i32.
    pub v_target: i32,
    /// a_actual register (12-bit signed), as i32.
    pub a_actual: i32,
    /// Full-wave microstep index (0..255).
    pub ustep: u32,
    /// 1 in the cycle in which the motor made a (micro)step.
    pub step: u8,
    /// Direction of the last step: 1 = negative (code $12, TMC428 Table 11-1).
    pub dir: u8,
    /// Pulse accumulator (11 bit).
    pub pulse_acc: u16,
}

/// Driver-chain (SPI master / Step/Dir) state.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct ChainProbe {
    /// Sequencer state (see docs/model-contract.md, driver chain).
    pub state: u8,
    /// Configuration RAM cell being sent.
    pub cell: u8,
    /// Motor whose signals are being sent.
    pub motor: u8,
    /// Bits sent so far in this datagram.
    pub bit_count: u8,
    /// A datagram is requested and not yet started.
    pub pending: u8,
    /// cover datagram waiting (cw).
    pub cover_waiting: u8,
    /// 48-bit readback shift register.
    pub readback: u64,
}

/// Everything the co-simulation compares besides the pins.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Probes {
    pub motor: [MotorProbe; 3],
    pub chain: ChainProbe,
    /// Free-running CLK counter behind the clk/32 pre-divider (stops in power-down).
    pub prescaler: u32,
    /// 1 while powered down.
    pub power_down: u8,
    /// Status byte as it would be sent now.
    pub status: u8,
}

/// The pins a package lacks beyond its variant's (contract C90): absent REFR inputs read 1
/// (their internal pull-ups, TMC429 §4.2), absent outputs are tied off (nSCS2, nSCS3 = 1;
/// POSCMP = 0; SDOZ_C not driven).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Bonding {
    /// Bit n − 1: REFRn is not bonded.
    pub refr_absent: u8,
    /// nSCS2 and nSCS3 are not bonded.
    pub no_nscs23: bool,
    /// POSCMP and SDOZ_C are not bonded.
    pub no_poscmp_sdoz: bool,
}

impl Bonding {
    /// The pins `package` lacks on `chip` (a package `chip` does not come in lacks nothing).
    pub fn of(chip: crate::Chip, package: crate::chip::Package) -> Bonding {
        use crate::chip::Package;
        match (chip, package) {
            (crate::Chip::Tmc429, Package::Sop24) => Bonding { refr_absent: 0b100, ..Bonding::default() },
            (crate::Chip::Tmc429, Package::Ssop16) => Bonding { refr_absent: 0b111, no_nscs23: true, no_poscmp_sdoz: true },
            (crate::Chip::Tmc428, Package::Ssop16) => Bonding { no_nscs23: true, ..Bonding::default() },
            _ => Bonding::default(),
        }
    }

    /// Every pin of the variant is bonded.
    pub fn is_full(&self) -> bool {
        *self == Bonding::default()
    }

    /// Ties off the outputs the package lacks.
    #[inline]
    pub fn outputs(&self, o: &mut Outputs) {
        if self.no_nscs23 {
            o.nscs2 = true;
            o.nscs3 = true;
        }
        if self.no_poscmp_sdoz {
            o.poscmp = false;
            o.sdoz_c = false;
            o.sdoz_c_oe = false;
        }
    }
}
