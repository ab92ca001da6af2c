//! The module firmware: a TMCM-3110-compatible TMCL interpreter that drives a TMC429 through
//! its SPI registers only (as a real module's processor does).

use crate::chip::{reg, sext, Spi429};
use crate::config::*;
use crate::eeprom::{EepromError, Image};
use crate::io::{Io, World};
use crate::proto::{op, Command, Instruction, Reply, Response, Status};
use std::path::PathBuf;

/// Module type reported by command 136.
pub const MODULE_TYPE: u16 = 3110;
/// Firmware version reported by command 136: major, minor.
pub const VERSION: (u8, u8) = (1, 0);

/// Where a command comes from: the host (direct mode) or the stored program.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Origin {
    Direct,
    Program,
}

/// Application status (global parameter 128, command 135).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AppState {
    Stop = 0,
    Run = 1,
    Step = 2,
    Reset = 3,
}

/// Condition a WAIT command blocks on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Wait {
    pub kind: u8,
    pub motor: u8,
    /// Millisecond at which the wait ends (TICKS) or times out (others); `None` = no timeout.
    pub deadline: Option<u64>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Saved {
    pc: u16,
    accu: i32,
    x: i32,
    cmp: i8,
    eto: bool,
    wait: Option<Wait>,
}

/// Interrupt numbers this module has (manual §5.6.3 for a three-axis module).
pub fn interrupt_exists(n: u8) -> bool {
    matches!(n, 0..=5 | 27..=32 | 39..=46 | 255)
}

/// The TMCL virtual machine: accumulator, X register, flags, stack, interrupts.
#[derive(Clone, Debug)]
pub struct Vm {
    pub state: AppState,
    pub pc: u16,
    pub accu: i32,
    pub x: i32,
    /// Result of the last comparison or load: sign of (accu − operand).
    pub cmp: i8,
    /// Timeout flag (ETO).
    pub eto: bool,
    pub stack: Vec<u16>,
    pub wait: Option<Wait>,
    pub vectors: [Option<u16>; 256],
    pub enabled: [bool; 256],
    pub global_enable: bool,
    pub pending: [bool; 256],
    saved: Option<Saved>,
    timer_next: [u64; 3],
}

impl Default for Vm {
    fn default() -> Self {
        Vm {
            state: AppState::Stop,
            pc: 0,
            accu: 0,
            x: 0,
            cmp: 0,
            eto: false,
            stack: Vec::new(),
            wait: None,
            vectors: [None; 256],
            enabled: [false; 256],
            global_enable: false,
            pending: [false; 256],
            saved: None,
            timer_next: [0; 3],
        }
    }
}

/// Reference search state of one axis.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum RfsPhase {
    Idle,
    /// Looking for the switch at search speed in direction `dir`; reverse at the end switch on `rev`.
    Find {
        sw: Sw,
        dir: i32,
        rev: Option<Sw>,
        reversed: bool,
    },
    /// Moving back out of the switch at switch speed; `armed` once the switch was seen active
    /// while moving in direction `dir`.
    Leave {
        sw: Sw,
        dir: i32,
        armed: bool,
    },
    /// Re-entering the switch at switch speed; `p1` = where it was left.
    Enter {
        sw: Sw,
        dir: i32,
        p1: i32,
    },
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Sw {
    Left,
    Right,
    Home,
}

#[derive(Clone, Copy, Debug)]
struct Rfs {
    phase: RfsPhase,
    /// Mode 2/3: after the right switch was found, search the left one; the right switch position.
    then_left: bool,
    right_pos: Option<i32>,
    distance: i32,
    last_switch_pos: i32,
}

impl Default for Rfs {
    fn default() -> Self {
        Rfs { phase: RfsPhase::Idle, then_left: false, right_pos: None, distance: 0, last_switch_pos: 0 }
    }
}

/// The module.
pub struct Module<C: Spi429> {
    pub chip: C,
    eeprom: Image,
    eeprom_path: Option<PathBuf>,
    /// Last error writing the EEPROM file (reported by the server).
    pub eeprom_error: Option<String>,
    axes: [AxisConfig; AXES],
    global: GlobalConfig,
    user_vars: [i32; 256],
    coords: [[i32; COORDS]; AXES],
    /// Bank 3: timer periods (0..2), stop switch transitions (27..32), input edges (39..46).
    irq_cfg: [i32; 256],
    pub io: Io,
    pub world: World,
    program: Vec<Instruction>,
    prog_len: usize,
    pub vm: Vm,
    download: Option<usize>,
    speed_changed: [bool; AXES],
    rfs: [Rfs; AXES],
    tick_offset: u32,
    rng: u64,
    last_cmd_ms: u64,
    heartbeat_tripped: bool,
    prev_switches: u8,
    prev_inputs: u8,
    prev_reached: u8,
    /// Instructions the interpreter runs per millisecond at most.
    pub instructions_per_ms: u32,
}

fn ok(v: i32) -> (u8, i32) {
    (Status::Ok.code(), v)
}
fn err(s: Status, v: i32) -> (u8, i32) {
    (s.code(), v)
}

impl<C: Spi429> Module<C> {
    /// Powers the module up with factory defaults (no EEPROM file).
    pub fn new(chip: C) -> Self {
        Self::with_image(chip, Image::default(), None)
    }

    /// Powers the module up from an EEPROM file: missing = factory defaults (and the file is
    /// created on the first store); corrupt = error, nothing applied.
    pub fn with_eeprom(chip: C, path: PathBuf) -> Result<Self, (C, EepromError)> {
        match Image::load(&path) {
            Ok(img) => Ok(Self::with_image(chip, img.unwrap_or_default(), Some(path))),
            Err(e) => Err((chip, e)),
        }
    }

    fn with_image(chip: C, mut img: Image, path: Option<PathBuf>) -> Self {
        if img.global.magic != EEPROM_MAGIC {
            // Manual §10.1, parameter 64: a different magic re-initialises to factory defaults.
            img = Image::default();
        }
        let mut m = Module {
            chip,
            eeprom: img.clone(),
            eeprom_path: path,
            eeprom_error: None,
            axes: img.axes,
            global: img.global,
            user_vars: [0; 256],
            coords: [[0; COORDS]; AXES],
            irq_cfg: [0; 256],
            io: Io::default(),
            world: World::default(),
            program: vec![Instruction::default(); PROGRAM_SIZE],
            prog_len: img.program.len(),
            vm: Vm::default(),
            download: None,
            speed_changed: [false; AXES],
            rfs: [Rfs::default(); AXES],
            tick_offset: 0,
            rng: 0x2545_f491_4f6c_dd1d,
            last_cmd_ms: 0,
            heartbeat_tripped: false,
            prev_switches: 0,
            prev_inputs: 0,
            prev_reached: 0,
            instructions_per_ms: 16,
        };
        if img.global.no_restore_user_vars == 0 {
            m.user_vars[..STORED_USER_VARS].copy_from_slice(&img.user_vars);
        }
        for a in 0..AXES {
            for c in 1..COORDS {
                m.coords[a][c] = img.coords[a][c];
            }
        }
        for (i, ins) in img.program.iter().enumerate() {
            m.program[i] = *ins;
        }
        m.init_chip();
        m.prev_inputs = m.io.inputs();
        if m.global.auto_start == 1 && m.prog_len > 0 {
            m.vm.state = AppState::Run;
        }
        m
    }

    // ----- time -----

    /// Milliseconds since power-on (from the chip's clock).
    pub fn now_ms(&self) -> u64 {
        let f = self.chip.fclk().max(1000);
        self.chip.cycle() / (f / 1000)
    }

    fn cycles_per_ms(&self) -> u64 {
        (self.chip.fclk() / 1000).max(1)
    }

    /// Runs the module for `ms` milliseconds of module time: the chip runs, and once per
    /// millisecond the firmware services switches, reference searches, the heartbeat,
    /// interrupts and the program.
    pub fn run_ms(&mut self, ms: u64) {
        for _ in 0..ms {
            let target = (self.now_ms() + 1) * self.cycles_per_ms();
            let now = self.chip.cycle();
            if target > now {
                self.chip.wait(target - now);
            }
            self.service();
        }
    }

    /// Advances to the given chip cycle (used by the server to follow wall-clock time).
    pub fn run_until_cycle(&mut self, cycle: u64) {
        let cpm = self.cycles_per_ms();
        while self.chip.cycle() < cycle {
            let next_ms = (self.chip.cycle() / cpm + 1) * cpm;
            let step = next_ms.min(cycle) - self.chip.cycle();
            self.chip.wait(step.max(1));
            if self.chip.cycle() >= next_ms {
                self.service();
            }
        }
    }

    // ----- chip access -----

    fn wr(&mut self, a7: u8, data: u32) -> u8 {
        self.chip.write(a7, data & 0x00ff_ffff)
    }
    fn rd(&mut self, a7: u8) -> u32 {
        self.chip.read(a7) & 0x00ff_ffff
    }
    fn rd_motor(&mut self, m: usize, idx: u8) -> u32 {
        self.rd(reg::motor(m, idx))
    }
    fn wr_motor(&mut self, m: usize, idx: u8, data: u32) {
        self.wr(reg::motor(m, idx), data);
    }

    fn if_configuration(&self) -> u32 {
        reg::IF_EN_SD | reg::IF_EN_REFR | if self.global.end_switch_polarity != 0 { reg::IF_INV_REF } else { 0 }
    }

    fn ref_conf_bits(&self, m: usize) -> u32 {
        let a = &self.axes[m];
        let mut r = 0;
        if a.disable_left != 0 {
            r |= reg::DISABLE_STOP_L;
        }
        if a.disable_right != 0 {
            r |= reg::DISABLE_STOP_R;
        }
        if a.soft_stop != 0 {
            r |= reg::SOFT_STOP;
        }
        r
    }

    /// Writes the whole configuration to the chip (power-on, factory reset).
    fn init_chip(&mut self) {
        self.update_pins();
        // Step/Dir outputs for the driver stages, right switches on REFR1..3, STPDIV = 0.
        let ifc = self.if_configuration();
        self.wr(reg::IF_CONFIGURATION, ifc);
        self.wr(reg::GLOBAL_PARAMETERS, 0);
        for m in 0..AXES {
            self.apply_axis(m);
            self.wr_motor(m, reg::INT_MASK_FLAGS, 0x00ff);
            self.wr_motor(m, reg::V_TARGET, 0);
            self.wr_motor(m, reg::V_ACTUAL, 0);
            self.wr_motor(m, reg::X_TARGET, 0);
            self.wr_motor(m, reg::X_ACTUAL, 0);
            let rm = self.position_rm(m);
            self.set_rm(m, rm);
        }
    }

    /// Writes an axis's ramp configuration (v_min, v_max, a_max, pmul/pdiv, dividers, ref_conf).
    fn apply_axis(&mut self, m: usize) {
        let a = self.axes[m];
        self.wr_motor(m, reg::V_MIN, a.v_min as u32);
        self.wr_motor(m, reg::V_MAX, a.v_max as u32);
        self.speed_changed[m] = false;
        self.wr_motor(m, reg::PULSEDIV_RAMPDIV, ((a.pulse_div as u32) << 12) | ((a.ramp_div as u32) << 8));
        self.wr_motor(m, reg::A_MAX, a.a_max as u32);
        if let Some((pm, pd)) = crate::calc::pmul_pdiv(a.a_max, a.ramp_div, a.pulse_div) {
            self.wr_motor(m, reg::PMUL_PDIV, ((pm as u32) << 8) | pd as u32);
        }
        self.wr_motor(m, reg::DX_REF_TOLERANCE, a.ref_tolerance as u32);
        let rc = self.rd_motor(m, reg::REFCONF_RM);
        let rfs_active = self.rfs[m].phase != RfsPhase::Idle;
        let mut bits = self.ref_conf_bits(m);
        if rfs_active {
            bits |= reg::DISABLE_STOP_L | reg::DISABLE_STOP_R;
        }
        self.wr_motor(m, reg::REFCONF_RM, bits | (rc & 3));
    }

    fn set_rm(&mut self, m: usize, rm: u32) {
        let rc = self.rd_motor(m, reg::REFCONF_RM);
        self.wr_motor(m, reg::REFCONF_RM, (rc & 0x0f00) | (rm & 3));
    }

    fn rm(&mut self, m: usize) -> u32 {
        self.rd_motor(m, reg::REFCONF_RM) & 3
    }

    fn position_rm(&self, m: usize) -> u32 {
        if self.axes[m].ramp_mode == 1 {
            reg::RM_SOFT
        } else if self.axes[m].ramp_mode == 2 {
            reg::RM_VELOCITY
        } else {
            reg::RM_RAMP
        }
    }

    fn x_actual(&mut self, m: usize) -> i32 {
        sext(self.rd_motor(m, reg::X_ACTUAL), 24)
    }
    fn x_target(&mut self, m: usize) -> i32 {
        sext(self.rd_motor(m, reg::X_TARGET), 24)
    }

    /// Position reached flag of every motor (bit m), from x_actual = x_target.
    pub fn reached_mask(&mut self) -> u8 {
        let mut mask = 0;
        for m in 0..AXES {
            if self.x_actual(m) == self.x_target(m) {
                mask |= 1 << m;
            }
        }
        mask
    }

    /// Switch states from the chip's reference switch register: bit 2m right, 2m+1 left.
    fn switch_register(&mut self) -> u8 {
        (self.rd(reg::REF_SWITCHES) & 0x3f) as u8
    }

    fn home_switch(&self, m: usize) -> bool {
        let x = self.chip.mechanical_position(m);
        let h = self.world.home(m, x);
        // Mode + 128 reverses the home switch polarity (manual §9, parameter 193).
        h ^ (self.axes[m].rfs_mode & 0x80 != 0)
    }

    /// Drives the switch pins from the world model: pin high = switch pressed.
    pub fn update_pins(&mut self) {
        let mut l = [false; 3];
        let mut r = [false; 3];
        for m in 0..AXES {
            let x = self.chip.mechanical_position(m);
            l[m] = self.world.left(m, x);
            r[m] = self.world.right(m, x);
        }
        self.chip.set_ref_pins(l, r);
    }

    // ----- motion -----

    fn rotate(&mut self, m: usize, v: i32) -> (u8, i32) {
        if !(-2047..=2047).contains(&v) {
            return err(Status::InvalidValue, v);
        }
        self.cancel_rfs(m);
        self.set_rm(m, reg::RM_VELOCITY);
        // In velocity mode v_max limits the target; the configured maximum returns with MVP.
        self.wr_motor(m, reg::V_MAX, 2047);
        self.speed_changed[m] = true;
        self.wr_motor(m, reg::V_TARGET, v as u32 & 0xfff);
        ok(v)
    }

    fn stop_motor(&mut self, m: usize) {
        self.cancel_rfs(m);
        self.set_rm(m, reg::RM_VELOCITY);
        self.wr_motor(m, reg::V_TARGET, 0);
    }

    fn move_to(&mut self, m: usize, target: i64) -> (u8, i32) {
        if !(-(1 << 23)..(1 << 23)).contains(&target) {
            return err(Status::InvalidValue, target as i32);
        }
        self.cancel_rfs(m);
        if self.speed_changed[m] {
            let v = self.axes[m].v_max as u32;
            self.wr_motor(m, reg::V_MAX, v);
            self.speed_changed[m] = false;
        }
        self.wr_motor(m, reg::X_TARGET, target as u32 & 0xff_ffff);
        let rm = if self.axes[m].ramp_mode == 1 { reg::RM_SOFT } else { reg::RM_RAMP };
        self.set_rm(m, rm);
        ok(target as i32)
    }

    fn mvp(&mut self, typ: u8, m: usize, v: i32) -> (u8, i32) {
        match typ {
            0 => self.move_to(m, v as i64),
            1 => {
                let base = self.x_actual(m) as i64;
                let r = self.move_to(m, base + v as i64);
                (r.0, v)
            }
            2 => {
                if !(0..COORDS as i32).contains(&v) {
                    return err(Status::InvalidValue, v);
                }
                let c = self.coords[m][v as usize] as i64;
                let r = self.move_to(m, c);
                (r.0, v)
            }
            _ => err(Status::WrongType, v),
        }
    }

    // ----- reference search -----

    fn cancel_rfs(&mut self, m: usize) {
        if self.rfs[m].phase != RfsPhase::Idle {
            self.rfs[m].phase = RfsPhase::Idle;
            let rc = self.rd_motor(m, reg::REFCONF_RM);
            let bits = self.ref_conf_bits(m);
            self.wr_motor(m, reg::REFCONF_RM, bits | (rc & 3));
        }
    }

    fn rfs_drive(&mut self, m: usize, dir: i32, fast: bool) {
        let s = if fast { self.axes[m].rfs_speed } else { self.axes[m].rfs_switch_speed };
        self.set_rm(m, reg::RM_VELOCITY);
        self.wr_motor(m, reg::V_MAX, 2047);
        self.speed_changed[m] = true;
        self.wr_motor(m, reg::V_TARGET, (dir * s) as u32 & 0xfff);
    }

    fn rfs_start(&mut self, m: usize) {
        let mode = self.axes[m].rfs_mode & 0x7f;
        let rc = self.rd_motor(m, reg::REFCONF_RM);
        // The stop functions of the end switches play no part in the search (manual §9).
        self.wr_motor(m, reg::REFCONF_RM, (rc & !0x0300) | reg::DISABLE_STOP_L | reg::DISABLE_STOP_R);
        let r = &mut self.rfs[m];
        r.then_left = false;
        r.right_pos = None;
        r.phase = match mode {
            2 | 3 => {
                r.then_left = true;
                RfsPhase::Find { sw: Sw::Right, dir: 1, rev: None, reversed: false }
            }
            5 => RfsPhase::Find { sw: Sw::Home, dir: -1, rev: Some(Sw::Left), reversed: false },
            6 => RfsPhase::Find { sw: Sw::Home, dir: 1, rev: Some(Sw::Right), reversed: false },
            7 => RfsPhase::Find { sw: Sw::Home, dir: 1, rev: None, reversed: false },
            8 => RfsPhase::Find { sw: Sw::Home, dir: -1, rev: None, reversed: false },
            _ => RfsPhase::Find { sw: Sw::Left, dir: -1, rev: None, reversed: false },
        };
        let (dir, fast) = (if matches!(mode, 2 | 3 | 6 | 7) { 1 } else { -1 }, true);
        self.rfs_drive(m, dir, fast);
    }

    fn sw_active(&mut self, m: usize, sw: Sw, regv: u8) -> bool {
        match sw {
            Sw::Left => regv & (2 << (2 * m)) != 0,
            Sw::Right => regv & (1 << (2 * m)) != 0,
            Sw::Home => self.home_switch(m),
        }
    }

    fn rfs_service(&mut self, m: usize) {
        let phase = self.rfs[m].phase;
        if phase == RfsPhase::Idle {
            return;
        }
        let regv = self.switch_register();
        match phase {
            RfsPhase::Idle => {}
            RfsPhase::Find { sw, dir, rev, reversed } => {
                if self.sw_active(m, sw, regv) {
                    let x = self.x_actual(m);
                    self.rfs[m].last_switch_pos = x;
                    if sw == Sw::Right && self.rfs[m].then_left {
                        self.rfs[m].right_pos = Some(x);
                        self.rfs[m].phase = RfsPhase::Find { sw: Sw::Left, dir: -1, rev: None, reversed: false };
                        self.rfs_drive(m, -1, true);
                    } else {
                        self.rfs[m].phase = RfsPhase::Leave { sw, dir: -dir, armed: false };
                        self.rfs_drive(m, -dir, false);
                    }
                } else if let (Some(r), false) = (rev, reversed) {
                    if self.sw_active(m, r, regv) {
                        self.rfs[m].phase = RfsPhase::Find { sw, dir: -dir, rev, reversed: true };
                        self.rfs_drive(m, -dir, true);
                    }
                }
            }
            RfsPhase::Leave { sw, dir, armed } => {
                // Only count the release once the axis moves in the leaving direction inside
                // the switch (it may brake through a narrow switch first).
                let v = sext(self.rd_motor(m, reg::V_ACTUAL), 12);
                let active = self.sw_active(m, sw, regv);
                let moving = v.signum() == dir.signum();
                if moving && active && !armed {
                    self.rfs[m].phase = RfsPhase::Leave { sw, dir, armed: true };
                } else if moving && armed && !active {
                    let p1 = self.x_actual(m);
                    self.rfs[m].phase = RfsPhase::Enter { sw, dir: -dir, p1 };
                    self.rfs_drive(m, -dir, false);
                }
            }
            RfsPhase::Enter { sw, p1, dir } => {
                let v = sext(self.rd_motor(m, reg::V_ACTUAL), 12);
                if v.signum() == dir.signum() && self.sw_active(m, sw, regv) {
                    let p2 = self.x_actual(m);
                    self.rfs[m].last_switch_pos = p2;
                    // Stop at once, make the centre of the two switching points position 0.
                    self.wr_motor(m, reg::V_TARGET, 0);
                    self.wr_motor(m, reg::V_ACTUAL, 0);
                    let zero = ((p1 as i64 + p2 as i64) / 2) as i32;
                    let x = self.x_actual(m);
                    let nx = (x - zero) as u32 & 0xff_ffff;
                    self.wr_motor(m, reg::X_TARGET, nx);
                    self.wr_motor(m, reg::X_ACTUAL, nx);
                    if let Some(rp) = self.rfs[m].right_pos {
                        self.rfs[m].distance = rp - zero;
                    }
                    self.rfs[m].phase = RfsPhase::Idle;
                    let bits = self.ref_conf_bits(m);
                    let rm = self.position_rm(m);
                    self.wr_motor(m, reg::REFCONF_RM, bits | rm);
                    if self.speed_changed[m] {
                        let v = self.axes[m].v_max as u32;
                        self.wr_motor(m, reg::V_MAX, v);
                        self.speed_changed[m] = false;
                    }
                }
            }
        }
    }

    fn rfs_status(&self, m: usize) -> i32 {
        match self.rfs[m].phase {
            RfsPhase::Idle => 0,
            RfsPhase::Find { .. } => 1,
            RfsPhase::Leave { .. } => 2,
            RfsPhase::Enter { .. } => 3,
        }
    }

    // ----- parameters -----

    fn save_eeprom(&mut self) {
        if let Some(p) = self.eeprom_path.clone() {
            self.eeprom.program = self.program[..self.prog_len].to_vec();
            if let Err(e) = self.eeprom.save(&p) {
                self.eeprom_error = Some(format!("{}: {e}", p.display()));
            }
        }
    }

    fn eeprom_locked(&self) -> bool {
        self.global.eeprom_locked != 0
    }

    fn sap(&mut self, p: u8, m: usize, v: i32) -> (u8, i32) {
        match p {
            0 => return self.set_position_reg(m, reg::X_TARGET, v),
            1 => {
                let r = self.set_position_reg(m, reg::X_ACTUAL, v);
                if r.0 == Status::Ok.code() {
                    // At rest in a positioning mode the target follows, so setting the
                    // position does not start a move.
                    let rm = self.rm(m);
                    let vact = sext(self.rd_motor(m, reg::V_ACTUAL), 12);
                    if rm != reg::RM_VELOCITY && vact == 0 {
                        self.wr_motor(m, reg::X_TARGET, v as u32 & 0xff_ffff);
                    }
                }
                return r;
            }
            2 | 3 => {
                if !(-2047..=2047).contains(&v) {
                    return err(Status::InvalidValue, v);
                }
                let idx = if p == 2 { reg::V_TARGET } else { reg::V_ACTUAL };
                self.wr_motor(m, idx, v as u32 & 0xfff);
                return ok(v);
            }
            _ => {}
        }
        if AxisConfig::range(p).is_none() {
            return err(Status::WrongType, v);
        }
        if !AxisConfig::valid_value(p, v) {
            return err(Status::InvalidValue, v);
        }
        let mut a = self.axes[m];
        a.set_raw(p, v);
        if matches!(p, 5 | 153 | 154) && crate::calc::pmul_pdiv(a.a_max, a.ramp_div, a.pulse_div).is_none() {
            // pmul/pdiv cannot represent this a_max with these dividers (TMC429 §8.7.1 limits).
            return err(Status::InvalidValue, v);
        }
        self.axes[m] = a;
        match p {
            4 => {
                if !self.speed_changed[m] {
                    self.wr_motor(m, reg::V_MAX, v as u32);
                }
            }
            130 => self.wr_motor(m, reg::V_MIN, v as u32),
            5 | 153 | 154 => {
                let a = self.axes[m];
                self.wr_motor(m, reg::PULSEDIV_RAMPDIV, ((a.pulse_div as u32) << 12) | ((a.ramp_div as u32) << 8));
                self.wr_motor(m, reg::A_MAX, a.a_max as u32);
                if let Some((pm, pd)) = crate::calc::pmul_pdiv(a.a_max, a.ramp_div, a.pulse_div) {
                    self.wr_motor(m, reg::PMUL_PDIV, ((pm as u32) << 8) | pd as u32);
                }
            }
            12 | 13 | 149 => {
                if self.rfs[m].phase == RfsPhase::Idle {
                    let rc = self.rd_motor(m, reg::REFCONF_RM);
                    let bits = self.ref_conf_bits(m);
                    self.wr_motor(m, reg::REFCONF_RM, bits | (rc & 3));
                }
            }
            138 => {
                let rm = self.position_rm(m);
                self.set_rm(m, rm);
            }
            141 => self.wr_motor(m, reg::DX_REF_TOLERANCE, v as u32),
            _ => {}
        }
        ok(v)
    }

    fn set_position_reg(&mut self, m: usize, idx: u8, v: i32) -> (u8, i32) {
        if !(-(1 << 23)..(1 << 23)).contains(&v) {
            return err(Status::InvalidValue, v);
        }
        self.wr_motor(m, idx, v as u32 & 0xff_ffff);
        ok(v)
    }

    fn gap(&mut self, p: u8, m: usize) -> (u8, i32) {
        let v = match p {
            0 => self.x_target(m),
            1 => self.x_actual(m),
            2 => sext(self.rd_motor(m, reg::V_TARGET), 12),
            3 => sext(self.rd_motor(m, reg::V_ACTUAL), 12),
            8 => (self.x_actual(m) == self.x_target(m)) as i32,
            9 => self.home_switch(m) as i32,
            10 => (self.switch_register() & (1 << (2 * m)) != 0) as i32,
            11 => (self.switch_register() & (2 << (2 * m)) != 0) as i32,
            135 => sext(self.rd_motor(m, reg::A_ACTUAL), 12),
            138 => self.rm(m) as i32,
            196 => self.rfs[m].distance,
            197 => self.rfs[m].last_switch_pos,
            _ => match self.axes[m].get(p) {
                Some(v) => v,
                None => return err(Status::WrongType, 0),
            },
        };
        ok(v)
    }

    fn stap(&mut self, p: u8, m: usize) -> (u8, i32) {
        let Some(v) = self.axes[m].get(p) else { return err(Status::WrongType, 0) };
        if self.eeprom_locked() {
            return err(Status::EepromLocked, 0);
        }
        self.eeprom.axes[m].set_raw(p, v);
        self.save_eeprom();
        ok(v)
    }

    fn rsap(&mut self, p: u8, m: usize) -> (u8, i32) {
        let Some(v) = self.eeprom.axes[m].get(p) else { return err(Status::WrongType, 0) };
        self.sap(p, m, v)
    }

    fn sgp(&mut self, p: u8, bank: u8, v: i32) -> (u8, i32) {
        match bank {
            0 => match p {
                73 => {
                    // Manual §10.1: write 1234 to lock, 4321 to unlock.
                    let l = match v {
                        1234 => 1,
                        4321 => 0,
                        _ => return err(Status::InvalidValue, v),
                    };
                    self.global.eeprom_locked = l;
                    self.eeprom.global.eeprom_locked = l;
                    self.save_eeprom();
                    ok(v)
                }
                132 => {
                    self.tick_offset = (self.now_ms() as u32).wrapping_sub(v as u32);
                    ok(v)
                }
                128..=131 | 133 => err(Status::WrongType, v),
                _ if GlobalConfig::valid_value(p, 0) || self.global.get(p).is_some() => {
                    if !GlobalConfig::valid_value(p, v) {
                        return err(Status::InvalidValue, v);
                    }
                    if self.eeprom_locked() {
                        return err(Status::EepromLocked, v);
                    }
                    // Parameters 64..128 are stored in EEPROM by SGP itself (manual §10.1).
                    self.global.set_raw(p, v);
                    self.eeprom.global.set_raw(p, v);
                    if p == 79 {
                        let ifc = self.if_configuration();
                        self.wr(reg::IF_CONFIGURATION, ifc);
                    }
                    self.save_eeprom();
                    ok(v)
                }
                _ => err(Status::WrongType, v),
            },
            2 => {
                self.user_vars[p as usize] = v;
                ok(v)
            }
            3 => {
                let valid = match p {
                    0..=2 => v >= 0,
                    27..=32 | 39..=46 => (0..=3).contains(&v),
                    _ => return err(Status::WrongType, v),
                };
                if !valid {
                    return err(Status::InvalidValue, v);
                }
                self.irq_cfg[p as usize] = v;
                if p <= 2 {
                    self.vm.timer_next[p as usize] = self.now_ms() + v as u64;
                }
                ok(v)
            }
            _ => err(Status::InvalidValue, v),
        }
    }

    fn ggp(&mut self, p: u8, bank: u8) -> (u8, i32) {
        match bank {
            0 => {
                let v = match p {
                    128 => self.vm.state as i32,
                    129 => self.download.is_some() as i32,
                    130 => self.vm.pc as i32,
                    132 => (self.now_ms() as u32).wrapping_sub(self.tick_offset) as i32,
                    133 => {
                        // xorshift64*
                        self.rng ^= self.rng >> 12;
                        self.rng ^= self.rng << 25;
                        self.rng ^= self.rng >> 27;
                        ((self.rng.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 33) & 0x7fff_ffff) as i32
                    }
                    _ => match self.global.get(p) {
                        Some(v) => v,
                        None => return err(Status::WrongType, 0),
                    },
                };
                ok(v)
            }
            2 => ok(self.user_vars[p as usize]),
            3 => match p {
                0..=2 | 27..=32 | 39..=46 => ok(self.irq_cfg[p as usize]),
                _ => err(Status::WrongType, 0),
            },
            _ => err(Status::InvalidValue, 0),
        }
    }

    fn stgp(&mut self, p: u8, bank: u8) -> (u8, i32) {
        match bank {
            0 => match self.global.get(p) {
                // Bank-0 settings are already in EEPROM (SGP stores them).
                Some(v) => {
                    if self.eeprom_locked() && p != 73 {
                        return err(Status::EepromLocked, v);
                    }
                    ok(v)
                }
                None => err(Status::WrongType, 0),
            },
            2 => {
                if (p as usize) >= STORED_USER_VARS {
                    return err(Status::WrongType, 0);
                }
                if self.eeprom_locked() {
                    return err(Status::EepromLocked, 0);
                }
                let v = self.user_vars[p as usize];
                self.eeprom.user_vars[p as usize] = v;
                self.save_eeprom();
                ok(v)
            }
            3 => err(Status::WrongType, 0),
            _ => err(Status::InvalidValue, 0),
        }
    }

    fn rsgp(&mut self, p: u8, bank: u8) -> (u8, i32) {
        match bank {
            0 => match self.eeprom.global.get(p) {
                Some(v) => {
                    self.global.set_raw(p, v);
                    ok(v)
                }
                None => err(Status::WrongType, 0),
            },
            2 => {
                if (p as usize) >= STORED_USER_VARS {
                    return err(Status::WrongType, 0);
                }
                let v = self.eeprom.user_vars[p as usize];
                self.user_vars[p as usize] = v;
                ok(v)
            }
            3 => err(Status::WrongType, 0),
            _ => err(Status::InvalidValue, 0),
        }
    }

    // ----- I/O -----

    fn sio(&mut self, port: u8, bank: u8, v: i32) -> (u8, i32) {
        let val = if v == -1 { self.vm.accu } else { v };
        match (bank, port) {
            (0, 0..=7) | (2, 0..=7) => {
                if val != 0 && val != 1 {
                    return err(Status::InvalidValue, v);
                }
                let bit = 1u8 << port;
                let r = if bank == 0 { &mut self.io.pullups } else { &mut self.io.outputs };
                if val == 1 {
                    *r |= bit
                } else {
                    *r &= !bit
                }
                ok(v)
            }
            (0, 255) | (2, 255) => {
                // Value -1: the low 8 bits of the accumulator (manual §5.7.14).
                if v != -1 && !(0..=255).contains(&v) {
                    return err(Status::InvalidValue, v);
                }
                let r = if bank == 0 { &mut self.io.pullups } else { &mut self.io.outputs };
                *r = val as u8;
                ok(v)
            }
            (0 | 2, _) => err(Status::WrongType, v),
            _ => err(Status::InvalidValue, v),
        }
    }

    fn gio(&mut self, port: u8, bank: u8) -> (u8, i32) {
        match (bank, port) {
            (0, 0..=7) => ok(self.io.input(port as usize) as i32),
            (0, 255) => ok(self.io.inputs() as i32),
            (1, 0) | (1, 4) => ok(self.io.analog(port as usize) as i32),
            (1, 8) => ok(self.io.supply_dv as i32),
            (2, 0..=7) => ok(((self.io.outputs >> port) & 1) as i32),
            (2, 255) => ok(self.io.outputs as i32),
            (0..=2, _) => err(Status::WrongType, 0),
            _ => err(Status::InvalidValue, 0),
        }
    }

    // ----- coordinates -----

    fn sco(&mut self, n: u8, motor: u8, v: i32) -> (u8, i32) {
        if motor == 255 {
            // SCO n, 255, 0: copy one (n = 1..20) or all (n = 0) coordinates to EEPROM.
            if self.eeprom_locked() {
                return err(Status::EepromLocked, v);
            }
            match n {
                0 => {
                    for a in 0..AXES {
                        for c in 1..COORDS {
                            self.eeprom.coords[a][c] = self.coords[a][c];
                        }
                    }
                }
                1..=20 => {
                    for a in 0..AXES {
                        self.eeprom.coords[a][n as usize] = self.coords[a][n as usize];
                    }
                }
                _ => return err(Status::WrongType, v),
            }
            self.save_eeprom();
            return ok(v);
        }
        let Some(m) = self.axis(motor) else { return err(Status::InvalidValue, v) };
        if n as usize >= COORDS {
            return err(Status::WrongType, v);
        }
        self.set_coord(m, n as usize, v);
        ok(v)
    }

    fn set_coord(&mut self, m: usize, n: usize, v: i32) {
        self.coords[m][n] = v;
        if n > 0 && self.global.coordinate_storage == 1 && !self.eeprom_locked() {
            self.eeprom.coords[m][n] = v;
            self.save_eeprom();
        }
    }

    fn gco(&mut self, n: u8, motor: u8) -> (u8, i32) {
        if motor == 255 {
            match n {
                0 => {
                    for a in 0..AXES {
                        for c in 1..COORDS {
                            self.coords[a][c] = self.eeprom.coords[a][c];
                        }
                    }
                }
                1..=20 => {
                    for a in 0..AXES {
                        self.coords[a][n as usize] = self.eeprom.coords[a][n as usize];
                    }
                }
                _ => return err(Status::WrongType, 0),
            }
            return ok(0);
        }
        let Some(m) = self.axis(motor) else { return err(Status::InvalidValue, 0) };
        if n as usize >= COORDS {
            return err(Status::WrongType, 0);
        }
        ok(self.coords[m][n as usize])
    }

    fn axis(&self, motor: u8) -> Option<usize> {
        ((motor as usize) < AXES).then_some(motor as usize)
    }

    // ----- calculation -----

    fn calc(a: i32, opn: u8, b: i32) -> Option<i32> {
        Some(match opn {
            0 => a.wrapping_add(b),
            1 => a.wrapping_sub(b),
            2 => a.wrapping_mul(b),
            3 => {
                if b == 0 {
                    return None;
                }
                a.wrapping_div(b)
            }
            4 => {
                if b == 0 {
                    return None;
                }
                a.wrapping_rem(b)
            }
            5 => a & b,
            6 => a | b,
            7 => a ^ b,
            8 => !a,
            9 => b,
            _ => return None,
        })
    }

    fn set_accu(&mut self, v: i32) {
        self.vm.accu = v;
        self.vm.cmp = v.signum() as i8;
    }

    // ----- command execution -----

    /// Executes one instruction; returns status code and reply value. The reply value is the
    /// command's value unless the command reads something (as TMCL firmware does).
    pub fn execute(&mut self, ins: &Instruction, origin: Origin) -> (u8, i32) {
        let (o, t, mo, v) = (ins.op, ins.typ, ins.motor, ins.value);
        let axis = self.axis(mo);
        let need_axis = |f: &mut dyn FnMut(usize) -> (u8, i32)| match axis {
            Some(m) => f(m),
            None => err(Status::InvalidValue, v),
        };
        let program = origin == Origin::Program;
        let r = match o {
            op::ROR => need_axis(&mut |m| self.rotate(m, v)),
            op::ROL => need_axis(&mut |m| {
                let r = self.rotate(m, v.wrapping_neg());
                (r.0, v)
            }),
            op::MST => need_axis(&mut |m| {
                self.stop_motor(m);
                ok(v)
            }),
            op::MVP => need_axis(&mut |m| self.mvp(t, m, v)),
            op::SAP => need_axis(&mut |m| self.sap(t, m, v)),
            op::GAP => need_axis(&mut |m| self.gap(t, m)),
            op::STAP => need_axis(&mut |m| self.stap(t, m)),
            op::RSAP => need_axis(&mut |m| self.rsap(t, m)),
            op::SGP => self.sgp(t, mo, v),
            op::GGP => self.ggp(t, mo),
            op::STGP => self.stgp(t, mo),
            op::RSGP => self.rsgp(t, mo),
            op::RFS => need_axis(&mut |m| match t {
                0 => {
                    self.rfs_start(m);
                    ok(v)
                }
                1 => {
                    if self.rfs[m].phase != RfsPhase::Idle {
                        self.stop_motor(m);
                    }
                    ok(v)
                }
                2 => ok(self.rfs_status(m)),
                _ => err(Status::WrongType, v),
            }),
            op::SIO => self.sio(t, mo, v),
            op::GIO => self.gio(t, mo),
            op::SCO => self.sco(t, mo, v),
            op::GCO => self.gco(t, mo),
            op::CCO => need_axis(&mut |m| {
                if t as usize >= COORDS {
                    return err(Status::WrongType, v);
                }
                let x = self.x_actual(m);
                self.set_coord(m, t as usize, x);
                ok(v)
            }),
            op::ACO => need_axis(&mut |m| {
                if t as usize >= COORDS {
                    return err(Status::WrongType, v);
                }
                let a = self.vm.accu;
                self.set_coord(m, t as usize, a);
                ok(v)
            }),
            op::CALC => match Self::calc(self.vm.accu, t, v) {
                Some(r) if t <= 9 => {
                    self.set_accu(r);
                    ok(v)
                }
                _ if t > 9 => err(Status::WrongType, v),
                _ => err(Status::InvalidValue, v),
            },
            op::CALCX => match t {
                8 => {
                    self.vm.x = !self.vm.x;
                    ok(v)
                }
                9 => {
                    self.vm.x = self.vm.accu;
                    ok(v)
                }
                10 => {
                    std::mem::swap(&mut self.vm.x, &mut self.vm.accu);
                    let a = self.vm.accu;
                    self.set_accu(a);
                    ok(v)
                }
                0..=7 => match Self::calc(self.vm.accu, t, self.vm.x) {
                    Some(r) => {
                        self.set_accu(r);
                        ok(v)
                    }
                    None => err(Status::InvalidValue, v),
                },
                _ => err(Status::WrongType, v),
            },
            op::COMP => {
                self.vm.cmp = (self.vm.accu as i64 - v as i64).signum() as i8;
                ok(v)
            }
            op::AAP => need_axis(&mut |m| {
                let a = self.vm.accu;
                let r = self.sap(t, m, a);
                (r.0, v)
            }),
            op::AGP => {
                let a = self.vm.accu;
                let r = self.sgp(t, mo, a);
                (r.0, v)
            }
            op::CLE => match t {
                0 | 1 => {
                    self.vm.eto = false;
                    ok(v)
                }
                2..=4 => ok(v),
                _ => err(Status::WrongType, v),
            },
            op::VECT => {
                if !interrupt_exists(t) || t == 255 {
                    return err(Status::WrongType, v);
                }
                if !(0..PROGRAM_SIZE as i32).contains(&v) {
                    return err(Status::InvalidValue, v);
                }
                self.vm.vectors[t as usize] = Some(v as u16);
                ok(v)
            }
            op::EI | op::DI => {
                if !interrupt_exists(t) {
                    return err(Status::WrongType, v);
                }
                let on = o == op::EI;
                if t == 255 {
                    self.vm.global_enable = on;
                } else {
                    self.vm.enabled[t as usize] = on;
                    if !on {
                        self.vm.pending[t as usize] = false;
                    }
                    if on && t <= 2 {
                        let p = self.irq_cfg[t as usize] as u64;
                        self.vm.timer_next[t as usize] = self.now_ms() + p;
                    }
                }
                ok(v)
            }
            op::JA | op::JC | op::CSUB | op::RSUB | op::WAIT | op::STOP | op::RETI => {
                // Program flow commands are for standalone programs (manual §5.3).
                err(Status::NotAvailable, v)
            }
            op::UF0..=op::UF7 => err(Status::NotAvailable, v),
            _ => err(Status::InvalidCommand, v),
        };
        if program && r.0 == Status::Ok.code() && matches!(o, op::GAP | op::GGP | op::GIO | op::GCO) {
            self.set_accu(r.1);
        }
        if program && o == op::RFS && t == 2 && r.0 == Status::Ok.code() {
            self.set_accu(r.1);
        }
        r
    }

    /// Handles one frame from the host (9-byte form) and returns what the module sends back.
    pub fn handle_bytes(&mut self, b: &[u8; 9]) -> Response {
        if b[0] != self.global.serial_address as u8 {
            return Response::None;
        }
        match Command::from_bytes(b) {
            Ok(c) => self.handle_instruction(&c.ins),
            Err(_) => {
                self.last_cmd_ms = self.now_ms();
                // Wrong checksum: status 1, command and value 0 (as TMCL firmware replies).
                Response::Normal(self.reply(Status::WrongChecksum.code(), 0, 0))
            }
        }
    }

    pub fn reply(&self, status: u8, op: u8, value: i32) -> Reply {
        Reply { host: self.global.host_address as u8, module: self.global.serial_address as u8, status, op, value }
    }

    /// Module address (global parameter 66) and host address (76).
    pub fn addresses(&self) -> (u8, u8) {
        (self.global.serial_address as u8, self.global.host_address as u8)
    }

    /// Global parameter 67 (ASCII interface configuration).
    pub fn ascii_config(&self) -> i32 {
        self.global.ascii_mode
    }

    /// Handles one command in direct mode (with download mode and the control commands).
    pub fn handle_instruction(&mut self, ins: &Instruction) -> Response {
        self.last_cmd_ms = self.now_ms();
        self.heartbeat_tripped = false;
        let o = ins.op;
        if let Some(addr) = self.download {
            if o < 128 {
                if !crate::asm::is_program_opcode(o) {
                    return Response::Normal(self.reply(Status::InvalidCommand.code(), o, ins.value));
                }
                if addr >= PROGRAM_SIZE {
                    return Response::Normal(self.reply(Status::InvalidValue.code(), o, ins.value));
                }
                self.program[addr] = *ins;
                self.download = Some(addr + 1);
                self.prog_len = self.prog_len.max(addr + 1);
                return Response::Normal(self.reply(Status::Loaded.code(), o, ins.value));
            }
        }
        let (st, val) = match o {
            op::APP_STOP => {
                self.vm.state = AppState::Stop;
                ok(ins.value)
            }
            op::APP_RUN => {
                if ins.typ == 1 {
                    if !(0..PROGRAM_SIZE as i32).contains(&ins.value) {
                        return Response::Normal(self.reply(Status::InvalidValue.code(), o, ins.value));
                    }
                    self.vm.pc = ins.value as u16;
                    self.vm.wait = None;
                }
                self.vm.state = AppState::Run;
                ok(ins.value)
            }
            op::APP_STEP => {
                self.vm.state = AppState::Step;
                self.step_program();
                if self.vm.state == AppState::Run {
                    self.vm.state = AppState::Step;
                }
                ok(ins.value)
            }
            op::APP_RESET => {
                self.reset_vm();
                self.vm.state = AppState::Reset;
                ok(ins.value)
            }
            op::DOWNLOAD_START => {
                if self.eeprom_locked() {
                    err(Status::EepromLocked, ins.value)
                } else if !(0..PROGRAM_SIZE as i32).contains(&ins.value) {
                    err(Status::InvalidValue, ins.value)
                } else {
                    self.vm.state = AppState::Stop;
                    self.download = Some(ins.value as usize);
                    ok(ins.value)
                }
            }
            op::DOWNLOAD_END => {
                if self.download.take().is_some() {
                    self.save_eeprom();
                }
                ok(ins.value)
            }
            op::READ_MEMORY => {
                if !(0..PROGRAM_SIZE as i32).contains(&ins.value) {
                    err(Status::InvalidValue, ins.value)
                } else {
                    let p = self.program[ins.value as usize];
                    match ins.typ {
                        0 => ok(((p.op as i32) << 24) | ((p.typ as i32) << 16) | ((p.motor as i32) << 8)),
                        1 => ok(p.value),
                        _ => err(Status::WrongType, ins.value),
                    }
                }
            }
            op::APP_STATUS => ok(self.vm.state as i32),
            op::FIRMWARE_VERSION => match ins.typ {
                0 => {
                    let s = format!("{:04}V{}{:02}", MODULE_TYPE, VERSION.0, VERSION.1);
                    let mut text = [b'0'; 8];
                    text.copy_from_slice(&s.as_bytes()[..8]);
                    return Response::Version { host: self.global.host_address as u8, text };
                }
                1 => ok(((MODULE_TYPE as i32) << 16) | ((VERSION.0 as i32) << 8) | VERSION.1 as i32),
                _ => err(Status::WrongType, ins.value),
            },
            op::FACTORY_DEFAULTS => {
                if ins.value == 1234 && !self.eeprom_locked() {
                    self.factory_reset();
                }
                // This command sends no reply (manual §5.7.39).
                return Response::None;
            }
            op::TARGET_REACHED_EVENT => {
                // The event reply itself is sent by the link that asked (see server).
                ok(Self::event_mask(ins.value) as i32)
            }
            op::ASCII_MODE => ok(ins.value),
            _ => self.execute(ins, Origin::Direct),
        };
        Response::Normal(self.reply(st, o, val))
    }

    /// Motors selected by the value of command 138: a bit mask; 0 means motor 0.
    pub fn event_mask(v: i32) -> u8 {
        let m = (v & 0x07) as u8;
        if m == 0 {
            1
        } else {
            m
        }
    }

    /// Command 137: all settings and the program back to factory defaults, in EEPROM and RAM.
    pub fn factory_reset(&mut self) {
        self.eeprom = Image::default();
        self.axes = self.eeprom.axes;
        self.global = self.eeprom.global;
        self.user_vars = [0; 256];
        self.coords = [[0; COORDS]; AXES];
        self.irq_cfg = [0; 256];
        self.program = vec![Instruction::default(); PROGRAM_SIZE];
        self.prog_len = 0;
        self.download = None;
        self.vm = Vm::default();
        self.rfs = [Rfs::default(); AXES];
        self.save_eeprom();
        self.init_chip();
    }

    fn reset_vm(&mut self) {
        let vectors = self.vm.vectors;
        self.vm = Vm { vectors, ..Vm::default() };
    }

    /// The program currently in memory (up to the highest address written).
    pub fn program(&self) -> &[Instruction] {
        &self.program[..self.prog_len]
    }

    /// Loads a program as a download would (addresses 0..), without the EEPROM write.
    pub fn load_program(&mut self, prog: &[Instruction]) -> Result<(), String> {
        if prog.len() > PROGRAM_SIZE {
            return Err(format!("program has {} instructions, memory holds {PROGRAM_SIZE}", prog.len()));
        }
        self.program = vec![Instruction::default(); PROGRAM_SIZE];
        self.program[..prog.len()].copy_from_slice(prog);
        self.prog_len = prog.len();
        self.reset_vm();
        Ok(())
    }

    // ----- periodic service -----

    fn service(&mut self) {
        self.update_pins();
        let now = self.now_ms();
        let hb = self.global.heartbeat;
        if hb > 0 && !self.heartbeat_tripped && now.saturating_sub(self.last_cmd_ms) > hb as u64 {
            // Serial heartbeat expired: stop all motors (manual §10.1, parameter 68).
            self.heartbeat_tripped = true;
            for m in 0..AXES {
                self.stop_motor(m);
            }
        }
        for m in 0..AXES {
            self.rfs_service(m);
        }
        let running = matches!(self.vm.state, AppState::Run);
        if running {
            self.detect_interrupts(now);
            for _ in 0..self.instructions_per_ms {
                if !self.step_program() {
                    break;
                }
            }
        }
    }

    fn detect_interrupts(&mut self, now: u64) {
        let vm = &mut self.vm;
        for t in 0..3 {
            let p = self.irq_cfg[t] as u64;
            if p > 0 && vm.enabled[t] && now >= vm.timer_next[t] {
                vm.pending[t] = true;
                vm.timer_next[t] = now + p;
            }
        }
        let want_sw = (27..=32).any(|n| self.vm.enabled[n]);
        if want_sw {
            let s = self.switch_register();
            let changed = s ^ self.prev_switches;
            for m in 0..AXES {
                for (side, bit) in [(0usize, 2u8 << (2 * m)), (1, 1u8 << (2 * m))] {
                    let n = 27 + 2 * m + side;
                    let rising = changed & bit != 0 && s & bit != 0;
                    let falling = changed & bit != 0 && s & bit == 0;
                    let cfg = self.irq_cfg[n];
                    if self.vm.enabled[n] && ((rising && cfg & 1 != 0) || (falling && cfg & 2 != 0)) {
                        self.vm.pending[n] = true;
                    }
                }
            }
            self.prev_switches = s;
        }
        let inp = self.io.inputs();
        let changed = inp ^ self.prev_inputs;
        for i in 0..8 {
            let n = 39 + i;
            let bit = 1u8 << i;
            let cfg = self.irq_cfg[n];
            if changed & bit != 0 && self.vm.enabled[n] {
                let rising = inp & bit != 0;
                if (rising && cfg & 1 != 0) || (!rising && cfg & 2 != 0) {
                    self.vm.pending[n] = true;
                }
            }
        }
        self.prev_inputs = inp;
        if (3..=5).any(|n| self.vm.enabled[n]) {
            let r = self.reached_mask();
            let rising = r & !self.prev_reached;
            for m in 0..AXES {
                if rising & (1 << m) != 0 && self.vm.enabled[3 + m] {
                    self.vm.pending[3 + m] = true;
                }
            }
            self.prev_reached = r;
        }
    }

    fn dispatch_interrupt(&mut self) -> bool {
        if !self.vm.global_enable || self.vm.saved.is_some() {
            return false;
        }
        for n in 0..255usize {
            if self.vm.pending[n] && self.vm.enabled[n] {
                if let Some(addr) = self.vm.vectors[n] {
                    self.vm.pending[n] = false;
                    self.vm.saved = Some(Saved {
                        pc: self.vm.pc,
                        accu: self.vm.accu,
                        x: self.vm.x,
                        cmp: self.vm.cmp,
                        eto: self.vm.eto,
                        wait: self.vm.wait.take(),
                    });
                    self.vm.pc = addr;
                    return true;
                }
            }
        }
        false
    }

    fn wait_done(&mut self, w: &Wait, now: u64) -> Option<bool> {
        let m = w.motor as usize;
        let cond = match w.kind {
            0 => return Some(w.deadline.is_some_and(|d| now >= d)),
            1 => {
                let (xa, xt) = (self.x_actual(m), self.x_target(m));
                xa == xt
            }
            2 => self.home_switch(m),
            3 => {
                let s = self.switch_register();
                s & (3 << (2 * m)) != 0
            }
            4 => self.rfs[m].phase == RfsPhase::Idle,
            _ => true,
        };
        if cond {
            Some(true)
        } else if w.deadline.is_some_and(|d| now >= d) {
            // Timeout: ETO flag (manual §5.7.22).
            self.vm.eto = true;
            Some(true)
        } else {
            Some(false)
        }
    }

    /// Executes one program step. Returns false when the program cannot proceed this
    /// millisecond (stopped or waiting).
    pub fn step_program(&mut self) -> bool {
        if !matches!(self.vm.state, AppState::Run | AppState::Step) {
            return false;
        }
        self.dispatch_interrupt();
        let now = self.now_ms();
        if let Some(w) = self.vm.wait {
            match self.wait_done(&w, now) {
                Some(true) => {
                    self.vm.wait = None;
                    self.vm.pc = self.vm.pc.wrapping_add(1);
                    return true;
                }
                _ => return false,
            }
        }
        let pc = self.vm.pc as usize;
        if pc >= PROGRAM_SIZE {
            self.vm.state = AppState::Stop;
            return false;
        }
        let ins = self.program[pc];
        let mut next = self.vm.pc.wrapping_add(1);
        match ins.op {
            op::JA => next = ins.value as u16,
            op::JC => {
                let c = self.vm.cmp;
                let take = match ins.typ {
                    0 | 2 => c == 0,
                    1 | 3 => c != 0,
                    4 => c > 0,
                    5 => c >= 0,
                    6 => c < 0,
                    7 => c <= 0,
                    8 => self.vm.eto,
                    _ => false,
                };
                if take {
                    next = ins.value as u16;
                }
            }
            op::CSUB => {
                // Eight levels; a call with a full stack is ignored (manual §5.7.20).
                if self.vm.stack.len() < 8 {
                    self.vm.stack.push(next);
                    next = ins.value as u16;
                }
            }
            op::RSUB => {
                if let Some(r) = self.vm.stack.pop() {
                    next = r;
                }
            }
            op::WAIT => {
                let w = Wait {
                    kind: ins.typ,
                    motor: ins.motor.min(AXES as u8 - 1),
                    deadline: if ins.typ == 0 || ins.value > 0 { Some(now + 10 * (ins.value.max(0) as u64)) } else { None },
                };
                if ins.typ > 4 || (ins.typ > 0 && ins.motor as usize >= AXES) {
                    self.vm.state = AppState::Stop;
                    return false;
                }
                if let Some(true) = self.wait_done(&w, now) {
                    // Already satisfied.
                } else {
                    self.vm.wait = Some(w);
                    return false;
                }
            }
            op::STOP => {
                self.vm.state = AppState::Stop;
                return false;
            }
            op::RETI => {
                if let Some(s) = self.vm.saved.take() {
                    self.vm.accu = s.accu;
                    self.vm.x = s.x;
                    self.vm.cmp = s.cmp;
                    self.vm.eto = s.eto;
                    self.vm.wait = s.wait;
                    self.vm.pc = s.pc;
                    return true;
                }
            }
            o if crate::asm::is_program_opcode(o) => {
                self.execute(&ins, Origin::Program);
            }
            _ => {
                // An empty or invalid cell ends the program.
                self.vm.state = AppState::Stop;
                return false;
            }
        }
        self.vm.pc = next;
        self.vm.state != AppState::Stop
    }

    // ----- test-side access -----

    pub fn user_var(&self, n: u8) -> i32 {
        self.user_vars[n as usize]
    }
    pub fn axis_config(&self, m: usize) -> Option<AxisConfig> {
        self.axes.get(m).copied()
    }
    pub fn eeprom_image(&self) -> &Image {
        &self.eeprom
    }
    pub fn download_address(&self) -> Option<usize> {
        self.download
    }
}
