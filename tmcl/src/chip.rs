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

/// Register addresses and bits of the TMC429, from the model's register map.
pub mod reg {
    use tmc429_model::motor_regs;
    pub use tmc429_model::regmap::idx::{
        A_ACTUAL, A_MAX, CLK_CONFIG as PULSEDIV_RAMPDIV, DX_REF_TOLERANCE, INTERRUPT as INT_MASK_FLAGS, PMUL_PDIV,
        REF_CONF_RM as REFCONF_RM, V_ACTUAL, V_MAX, V_MIN, V_TARGET, X_ACTUAL, X_TARGET,
    };
    use tmc429_model::regmap::{f, global_a7, jdx};
    /// Motor register address: `SMDA = m`, `IDX = idx`.
    pub fn motor(m: usize, idx: u8) -> u8 {
        tmc429_model::regmap::motor_a7(m as u8, idx)
    }
    pub const IF_CONFIGURATION: u8 = global_a7(jdx::IF_CONFIGURATION);
    pub const REF_SWITCHES: u8 = global_a7(jdx::REF_SWITCHES);
    pub const GLOBAL_PARAMETERS: u8 = global_a7(jdx::GLOBAL_PARAMETERS);

    /// if_configuration bits (TMC429 §8.2.4).
    pub const IF_INV_REF: u32 = f::INV_REF.mask();
    pub const IF_EN_SD: u32 = f::EN_SD.mask();
    pub const IF_EN_REFR: u32 = f::EN_REFR.mask();
    /// ref_conf bits in register 10.
    pub const DISABLE_STOP_L: u32 = f::DISABLE_STOP_L.mask();
    pub const DISABLE_STOP_R: u32 = f::DISABLE_STOP_R.mask();
    pub const SOFT_STOP: u32 = f::SOFT_STOP.mask();
    /// Ramp modes (rm).
    pub const RM_RAMP: u32 = motor_regs::RAMP_MODE as u32;
    pub const RM_SOFT: u32 = motor_regs::SOFT_MODE as u32;
    pub const RM_VELOCITY: u32 = motor_regs::VELOCITY_MODE as u32;
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
