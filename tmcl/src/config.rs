//! Configuration the module keeps per axis and globally, with its factory defaults and ranges.

/// Number of axes of the module (TMCM-3110).
pub const AXES: usize = 3;
/// Coordinates per axis: 0 (RAM only) and 1..20 (manual §5.7.24).
pub const COORDS: usize = 21;
/// User variables kept in EEPROM (bank 2, 0..55; manual §10.3).
pub const STORED_USER_VARS: usize = 56;
/// Program memory size in instructions.
pub const PROGRAM_SIZE: usize = 2048;
/// The value of global parameter 64 that marks a valid EEPROM (manual §10.1).
pub const EEPROM_MAGIC: i32 = 0xE4;

/// Per-axis settings that can be stored (access "E" in the parameter table), in TMC429 units.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct AxisConfig {
    /// 4: maximum positioning speed (v_max, 0..2047).
    pub v_max: i32,
    /// 5: maximum acceleration (a_max, 1..2047).
    pub a_max: i32,
    /// 6: run current (kept, no driver modelled).
    pub i_run: i32,
    /// 7: standby current (kept).
    pub i_standby: i32,
    /// 12: right limit switch disable.
    pub disable_right: i32,
    /// 13: left limit switch disable.
    pub disable_left: i32,
    /// 130: minimum speed (v_min).
    pub v_min: i32,
    /// 138: ramp mode used by MVP (0 position, 1 soft position, 2 velocity).
    pub ramp_mode: i32,
    /// 140: microstep resolution (kept; the driver chip is not modelled).
    pub microsteps: i32,
    /// 141: dx_ref_tolerance.
    pub ref_tolerance: i32,
    /// 149: soft stop flag.
    pub soft_stop: i32,
    /// 153: ramp divisor.
    pub ramp_div: i32,
    /// 154: pulse divisor.
    pub pulse_div: i32,
    /// 193: reference search mode.
    pub rfs_mode: i32,
    /// 194: reference search speed.
    pub rfs_speed: i32,
    /// 195: reference switch speed.
    pub rfs_switch_speed: i32,
    /// 200: boost current (kept).
    pub boost_current: i32,
    /// 204: freewheeling delay [10 ms] (kept).
    pub freewheel_delay: i32,
    /// 214: power down delay [10 ms] (kept).
    pub power_down_delay: i32,
}

impl Default for AxisConfig {
    fn default() -> Self {
        AxisConfig {
            v_max: 1000,
            a_max: 1000,
            i_run: 128,
            i_standby: 8,
            disable_right: 0,
            disable_left: 0,
            v_min: 1,
            ramp_mode: 0,
            microsteps: 8,
            ref_tolerance: 0,
            soft_stop: 0,
            ramp_div: 7,
            pulse_div: 3,
            rfs_mode: 1,
            rfs_speed: 500,
            rfs_switch_speed: 100,
            boost_current: 0,
            freewheel_delay: 0,
            power_down_delay: 200,
        }
    }
}

/// Axis parameter numbers that STAP/RSAP accept, in the order of the EEPROM image.
pub const STORED_AXIS_PARAMS: [u8; 19] = [4, 5, 6, 7, 12, 13, 130, 138, 140, 141, 149, 153, 154, 193, 194, 195, 200, 204, 214];

impl AxisConfig {
    pub fn get(&self, p: u8) -> Option<i32> {
        Some(match p {
            4 => self.v_max,
            5 => self.a_max,
            6 => self.i_run,
            7 => self.i_standby,
            12 => self.disable_right,
            13 => self.disable_left,
            130 => self.v_min,
            138 => self.ramp_mode,
            140 => self.microsteps,
            141 => self.ref_tolerance,
            149 => self.soft_stop,
            153 => self.ramp_div,
            154 => self.pulse_div,
            193 => self.rfs_mode,
            194 => self.rfs_speed,
            195 => self.rfs_switch_speed,
            200 => self.boost_current,
            204 => self.freewheel_delay,
            214 => self.power_down_delay,
            _ => return None,
        })
    }
    pub fn set_raw(&mut self, p: u8, v: i32) -> bool {
        let f = match p {
            4 => &mut self.v_max,
            5 => &mut self.a_max,
            6 => &mut self.i_run,
            7 => &mut self.i_standby,
            12 => &mut self.disable_right,
            13 => &mut self.disable_left,
            130 => &mut self.v_min,
            138 => &mut self.ramp_mode,
            140 => &mut self.microsteps,
            141 => &mut self.ref_tolerance,
            149 => &mut self.soft_stop,
            153 => &mut self.ramp_div,
            154 => &mut self.pulse_div,
            193 => &mut self.rfs_mode,
            194 => &mut self.rfs_speed,
            195 => &mut self.rfs_switch_speed,
            200 => &mut self.boost_current,
            204 => &mut self.freewheel_delay,
            214 => &mut self.power_down_delay,
            _ => return false,
        };
        *f = v;
        true
    }
    /// Range of a stored axis parameter (inclusive).
    pub fn range(p: u8) -> Option<(i32, i32)> {
        Some(match p {
            4 | 130 | 194 | 195 => (0, 2047),
            5 => (1, 2047),
            6 | 7 | 200 => (0, 255),
            12 | 13 | 149 => (0, 1),
            138 => (0, 2),
            140 => (0, 8),
            141 => (0, 4095),
            153 | 154 => (0, 13),
            193 => (1, 136),
            204 => (0, 65535),
            214 => (1, 65535),
            _ => return None,
        })
    }
    pub fn valid_value(p: u8, v: i32) -> bool {
        match Self::range(p) {
            Some((lo, hi)) => v >= lo && v <= hi && (p != 193 || matches!(v & 0x7f, 1..=8) && (v & !0xff) == 0),
            None => false,
        }
    }
    pub fn validate(&self) -> Result<(), String> {
        for p in STORED_AXIS_PARAMS {
            let v = self.get(p).unwrap_or(0);
            if !Self::valid_value(p, v) {
                return Err(format!("axis parameter {p} = {v} is out of range"));
            }
        }
        Ok(())
    }
}

/// Bank 0 settings stored in the EEPROM (manual §10.1, the ones this module has).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct GlobalConfig {
    /// 64: EEPROM magic.
    pub magic: i32,
    /// 65: RS485 baud rate index (kept; a pseudo-terminal or TCP link has no baud rate).
    pub baud_rate: i32,
    /// 66: serial (module) address.
    pub serial_address: i32,
    /// 67: ASCII mode configuration.
    pub ascii_mode: i32,
    /// 68: serial heartbeat [ms], 0 = off.
    pub heartbeat: i32,
    /// 73: configuration EEPROM lock flag (read 1 = locked).
    pub eeprom_locked: i32,
    /// 75: telegram pause time (kept).
    pub telegram_pause: i32,
    /// 76: serial host address.
    pub host_address: i32,
    /// 77: auto start mode.
    pub auto_start: i32,
    /// 79: end switch polarity.
    pub end_switch_polarity: i32,
    /// 84: coordinate storage (0 RAM, 1 EEPROM).
    pub coordinate_storage: i32,
    /// 85: do not restore user variables.
    pub no_restore_user_vars: i32,
}

impl Default for GlobalConfig {
    fn default() -> Self {
        GlobalConfig {
            magic: EEPROM_MAGIC,
            baud_rate: 0,
            serial_address: 1,
            ascii_mode: 0,
            heartbeat: 0,
            eeprom_locked: 0,
            telegram_pause: 0,
            host_address: 2,
            auto_start: 0,
            end_switch_polarity: 0,
            coordinate_storage: 0,
            no_restore_user_vars: 0,
        }
    }
}

/// Bank-0 parameters stored in the EEPROM, in image order.
pub const STORED_GLOBAL_PARAMS: [u8; 12] = [64, 65, 66, 67, 68, 73, 75, 76, 77, 79, 84, 85];

impl GlobalConfig {
    pub fn get(&self, p: u8) -> Option<i32> {
        Some(match p {
            64 => self.magic,
            65 => self.baud_rate,
            66 => self.serial_address,
            67 => self.ascii_mode,
            68 => self.heartbeat,
            73 => self.eeprom_locked,
            75 => self.telegram_pause,
            76 => self.host_address,
            77 => self.auto_start,
            79 => self.end_switch_polarity,
            84 => self.coordinate_storage,
            85 => self.no_restore_user_vars,
            _ => return None,
        })
    }
    pub fn set_raw(&mut self, p: u8, v: i32) -> bool {
        let f = match p {
            64 => &mut self.magic,
            65 => &mut self.baud_rate,
            66 => &mut self.serial_address,
            67 => &mut self.ascii_mode,
            68 => &mut self.heartbeat,
            73 => &mut self.eeprom_locked,
            75 => &mut self.telegram_pause,
            76 => &mut self.host_address,
            77 => &mut self.auto_start,
            79 => &mut self.end_switch_polarity,
            84 => &mut self.coordinate_storage,
            85 => &mut self.no_restore_user_vars,
            _ => return false,
        };
        *f = v;
        true
    }
    pub fn valid_value(p: u8, v: i32) -> bool {
        match p {
            64 | 75 => (0..=255).contains(&v),
            65 => (0..=11).contains(&v),
            66 | 76 => (1..=255).contains(&v),
            67 => v & !0x31 == 0 && v & 0x30 != 0x30,
            68 => v >= 0,
            73 => v == 0 || v == 1,
            77 | 79 | 84 | 85 => v == 0 || v == 1,
            _ => false,
        }
    }
    pub fn validate(&self) -> Result<(), String> {
        for p in STORED_GLOBAL_PARAMS {
            let v = self.get(p).unwrap_or(-1);
            if !Self::valid_value(p, v) {
                return Err(format!("global parameter {p} = {v} is out of range"));
            }
        }
        Ok(())
    }
}
