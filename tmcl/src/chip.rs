//! The motion controller as the module firmware sees it: a TMC429 behind its µC SPI port,
//! plus the module's wiring of the reference-switch pins.
//!
//! The firmware only ever uses [`Spi429::write`] and [`Spi429::read`] (32-bit datagrams, as a
//! real module's processor does); the other methods belong to the simulation around the chip
//! (time, pins, and the mechanical position the switches are mounted against).

/// A TMC429 reachable through its µC SPI port.
pub trait Spi429 {
    /// One write datagram to address `a7` (7-bit `RRS SMDA IDX`); returns the status byte.
    fn write(&mut self, a7: u8, data: u32) -> u8;
    /// One read datagram; returns the 24 data bits.
    fn read(&mut self, a7: u8) -> u32;
    /// Lets the chip run for `cycles` CLK cycles with the bus idle.
    fn wait(&mut self, cycles: u64);
    /// CLK cycles since power-on.
    fn cycle(&self) -> u64;
    /// Clock frequency in Hz.
    fn fclk(&self) -> u64;
    /// Levels of the reference inputs REF1..3 (left switches) and REFR1..3 (right switches).
    fn set_ref_pins(&mut self, left: [bool; 3], right: [bool; 3]);
    /// Mechanical position of motor `m` in steps (the steps the chip has issued; no step loss is
    /// modelled). Used only to place switches along the axis, never by the firmware.
    fn mechanical_position(&self, m: usize) -> i32;
}

/// Register addresses (A7) of the TMC429 (spec digest §1.2, §2).
pub mod reg {
    pub const X_TARGET: u8 = 0;
    pub const X_ACTUAL: u8 = 1;
    pub const V_MIN: u8 = 2;
    pub const V_MAX: u8 = 3;
    pub const V_TARGET: u8 = 4;
    pub const V_ACTUAL: u8 = 5;
    pub const A_MAX: u8 = 6;
    pub const A_ACTUAL: u8 = 7;
    pub const PMUL_PDIV: u8 = 9;
    pub const REFCONF_RM: u8 = 10;
    pub const INT_MASK_FLAGS: u8 = 11;
    pub const PULSEDIV_RAMPDIV: u8 = 12;
    pub const DX_REF_TOLERANCE: u8 = 13;
    /// Motor register address: `SMDA = m`, `IDX = idx`.
    pub fn motor(m: usize, idx: u8) -> u8 {
        ((m as u8) << 4) | (idx & 0x0f)
    }
    pub const IF_CONFIGURATION: u8 = 0x34;
    pub const REF_SWITCHES: u8 = 0x3e;
    pub const GLOBAL_PARAMETERS: u8 = 0x3f;

    /// if_configuration bits (TMC429 §8.2.4).
    pub const IF_INV_REF: u32 = 1 << 0;
    pub const IF_EN_SD: u32 = 1 << 5;
    pub const IF_EN_REFR: u32 = 1 << 8;
    /// ref_conf bits in register 10.
    pub const DISABLE_STOP_L: u32 = 1 << 8;
    pub const DISABLE_STOP_R: u32 = 1 << 9;
    pub const SOFT_STOP: u32 = 1 << 10;
    /// Ramp modes (rm).
    pub const RM_RAMP: u32 = 0;
    pub const RM_SOFT: u32 = 1;
    pub const RM_VELOCITY: u32 = 2;
}

/// Sign-extends the low `bits` bits.
pub fn sext(v: u32, bits: u32) -> i32 {
    let s = 32 - bits;
    ((v << s) as i32) >> s
}

/// The golden model behind its virtual µC ([`tmc429_model::host::Host`]).
pub struct ModelChip {
    host: tmc429_model::host::Host,
    fclk: u64,
    /// Mechanical position minus x_actual per motor: x_actual writes move the register, not
    /// the axis.
    offset: [i64; 3],
}

impl ModelChip {
    pub fn new(chip: tmc429_model::Chip, fclk: u64) -> Self {
        let mut host = tmc429_model::host::Host::new(chip);
        // Switches open, REFR inputs driven (the module wires them to its end switches).
        let p = host.pins_mut();
        p.ref1 = false;
        p.ref2 = false;
        p.ref3 = false;
        p.refr1 = false;
        p.refr2 = false;
        p.refr3 = false;
        ModelChip { host, fclk, offset: [0; 3] }
    }
    pub fn host(&self) -> &tmc429_model::host::Host {
        &self.host
    }
    fn x_actual_probe(&self, m: usize) -> i32 {
        let pr = self.host.chip().probes();
        pr.motor.get(m).map(|p| sext(p.x_actual, 24)).unwrap_or(0)
    }
    /// Mechanical position of motor `m` (see [`Spi429::mechanical_position`]).
    pub fn mechanical_position_of(&self, m: usize) -> i32 {
        Spi429::mechanical_position(self, m)
    }
}

impl Spi429 for ModelChip {
    fn write(&mut self, a7: u8, data: u32) -> u8 {
        let m = (a7 >> 4) as usize;
        if a7 & 0x4f == reg::X_ACTUAL && m < 3 {
            let before = self.x_actual_probe(m);
            let st = self.host.write(a7, data);
            let after = self.x_actual_probe(m);
            self.offset[m] += before as i64 - after as i64;
            return st;
        }
        self.host.write(a7, data)
    }
    fn read(&mut self, a7: u8) -> u32 {
        self.host.read(a7)
    }
    fn wait(&mut self, cycles: u64) {
        self.host.wait(cycles)
    }
    fn cycle(&self) -> u64 {
        self.host.cycle()
    }
    fn fclk(&self) -> u64 {
        self.fclk
    }
    fn set_ref_pins(&mut self, left: [bool; 3], right: [bool; 3]) {
        let p = self.host.pins_mut();
        p.ref1 = left[0];
        p.ref2 = left[1];
        p.ref3 = left[2];
        p.refr1 = right[0];
        p.refr2 = right[1];
        p.refr3 = right[2];
    }
    fn mechanical_position(&self, m: usize) -> i32 {
        (self.x_actual_probe(m) as i64 + self.offset.get(m).copied().unwrap_or(0)) as i32
    }
}
