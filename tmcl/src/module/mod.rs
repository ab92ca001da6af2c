//! The module firmware: a TMCL interpreter that drives a TMC429 through its SPI registers only
//! (as a real module's processor does), as a TMCM-3110 or as the TMCM-1311 of the TMCL firmware
//! manual (`crate::personality`).
//!
//! Units: `control` (frames, download, commands 128..139), `execute` (one instruction),
//! `motion` (ROR, ROL, MST, MVP), `axis_params` and `axis1311` (SAP, GAP, STAP, RSAP),
//! `global_params` (SGP, GGP, STGP, RSGP), `io_coords` (SIO, GIO, SCO, GCO, CCO, ACO), `rfs`
//! (reference search), `vm` and `service` (the program interpreter and the millisecond
//! service), `chip_io` (the TMC429 registers), `scale` (the TMCM-1311's units on the TMC429).

use crate::chip::{reg, sext, Spi429};
use crate::config::*;
use crate::eeprom::{EepromError, Image};
use crate::io::{Io, World};
use crate::personality::ModuleType;
use crate::proto::{op, Command, Instruction, Reply, Response, Status};
use std::path::PathBuf;

mod axis1311;
mod axis_params;
mod check;
mod chip_io;
mod control;
mod execute;
mod global_params;
mod io_coords;
mod motion;
mod rfs;
mod scale;
mod service;
mod vm;

pub use check::Refusal;
use rfs::Rfs;
pub use vm::{AppState, Vm, Wait};

/// Firmware version reported by command 136 for every module type: major, minor.
pub const VERSION: (u8, u8) = (1, 0);

/// Where a command comes from: the host (direct mode) or the stored program.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Origin {
    Direct,
    Program,
}

/// Firmware state of one axis besides its settings.
#[derive(Clone, Copy, Debug, Default)]
struct AxisState {
    /// v_max holds 2047 (velocity mode) instead of the configured maximum.
    speed_changed: bool,
    rfs: Rfs,
    /// Steps issued since power-on, accumulated from x_actual (`scale::track`).
    steps: i64,
    last_x: u32,
    /// TMCM-1311: the 32-bit position is `steps + pos_offset` (wrapping).
    pos_offset: i64,
    /// TMCM-1311: target position (32 bits) and commanded target speed [pps].
    target: i32,
    target_speed: i32,
    /// TMCM-1311: the TMC429 dividers and a_max in use.
    pulse_div: u8,
    ramp_div: u8,
    a_max: i32,
    /// TMCM-1311 encoder: counter = raw + offset; revolution of the last null channel check.
    enc_offset: i64,
    enc_rev: i64,
    /// Encoder deviation flag (axis parameter 207, CLE EDV).
    deviation: bool,
}

/// Levels the interrupt sources had at the last millisecond (edges are seen whether or not
/// an interrupt is enabled, so enabling one never fires on an older edge).
#[derive(Clone, Copy, Debug, Default)]
struct Edges {
    switches: u8,
    inputs: u8,
    reached: u8,
    deviation: bool,
}

/// The module.
pub struct Module<C: Spi429> {
    pub chip: C,
    kind: ModuleType,
    eeprom: Image,
    eeprom_path: Option<PathBuf>,
    /// Last error writing the EEPROM file (reported by the server).
    pub eeprom_error: Option<String>,
    axes: [AxisConfig; AXES],
    global: GlobalConfig,
    st: [AxisState; AXES],
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
    tick_offset: u32,
    rng: u64,
    last_cmd_ms: u64,
    heartbeat_tripped: bool,
    edges: Edges,
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
    /// Powers a TMCM-3110 up with factory defaults (no EEPROM file).
    pub fn new(chip: C) -> Self {
        Self::of_type(chip, ModuleType::Tmcm3110)
    }

    /// Powers a module of the given type up with factory defaults (no EEPROM file).
    pub fn of_type(chip: C, kind: ModuleType) -> Self {
        Self::with_image(chip, Image::factory(kind), None)
    }

    /// Powers the module up from an EEPROM file: missing = factory defaults (and the file is
    /// created on the first store); corrupt or of another module type = error, nothing applied.
    pub fn with_eeprom(chip: C, kind: ModuleType, path: PathBuf) -> Result<Self, (C, EepromError)> {
        match Image::load(&path) {
            Ok(Some(img)) if img.global.kind() != kind => {
                let e = format!("the image is of a {}, this module is a {}", img.global.kind().name(), kind.name());
                Err((chip, EepromError::Corrupt(e)))
            }
            Ok(img) => {
                let m = Self::with_image(chip, img.unwrap_or_else(|| Image::factory(kind)), Some(path));
                // A stored program holds only instructions this module runs (as downloads check).
                let bad = m.program().iter().enumerate().find_map(|(a, ins)| m.check_instruction(ins).err().map(|e| (a, e)));
                match bad {
                    Some((a, e)) => Err((m.chip, EepromError::Corrupt(format!("program instruction {a}: {e}")))),
                    None => Ok(m),
                }
            }
            Err(e) => Err((chip, e)),
        }
    }

    fn with_image(chip: C, mut img: Image, path: Option<PathBuf>) -> Self {
        let kind = img.global.kind();
        if img.global.get(64) != Some(EEPROM_MAGIC) {
            // [TMCL] §10.1, parameter 64: a different magic re-initialises to factory defaults.
            img = Image::factory(kind);
        }
        let mut m = Module {
            chip,
            kind,
            eeprom: img.clone(),
            eeprom_path: path,
            eeprom_error: None,
            axes: img.axes,
            global: img.global,
            st: [AxisState::default(); AXES],
            user_vars: [0; 256],
            coords: [[0; COORDS]; AXES],
            irq_cfg: [0; 256],
            // The TMCM-1311's inputs have no pull-ups ([TMCL] §5.7.14: SIO bank 2 only).
            io: Io { pullups: if kind == ModuleType::Tmcm3110 { 0xff } else { 0 }, ..Io::default() },
            world: World::default(),
            program: vec![Instruction::default(); PROGRAM_SIZE],
            prog_len: img.program.len(),
            vm: Vm::default(),
            download: None,
            tick_offset: 0,
            rng: 0x2545_f491_4f6c_dd1d,
            last_cmd_ms: 0,
            heartbeat_tripped: false,
            edges: Edges::default(),
            instructions_per_ms: 16,
        };
        if m.gp(85) == 0 {
            m.user_vars[..STORED_USER_VARS].copy_from_slice(&img.user_vars);
        }
        for a in 0..AXES {
            m.coords[a][1..].copy_from_slice(&img.coords[a][1..]);
        }
        m.program[..img.program.len()].copy_from_slice(&img.program);
        m.init_chip();
        if m.gp(77) == 1 && m.prog_len > 0 {
            m.vm.state = AppState::Run;
        }
        m
    }

    /// The module type.
    pub fn kind(&self) -> ModuleType {
        self.kind
    }

    /// A bank-0 setting (0 if this module type has no such setting).
    fn gp(&self, p: u8) -> i32 {
        self.global.get(p).unwrap_or(0)
    }
    /// An axis setting (0 if this module type has no such setting).
    fn ap(&self, m: usize, p: u8) -> i32 {
        self.axes[m].get(p).unwrap_or(0)
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

    /// The axis of a motor number, if this module has it.
    fn axis(&self, motor: u8) -> Option<usize> {
        ((motor as usize) < self.kind.axes()).then_some(motor as usize)
    }

    /// Command 137: all settings and the program back to factory defaults, in EEPROM and RAM.
    pub fn factory_reset(&mut self) {
        self.eeprom = Image::factory(self.kind);
        self.axes = self.eeprom.axes;
        self.global = self.eeprom.global;
        self.user_vars = [0; 256];
        self.coords = [[0; COORDS]; AXES];
        self.irq_cfg = [0; 256];
        self.program = vec![Instruction::default(); PROGRAM_SIZE];
        self.prog_len = 0;
        self.download = None;
        self.vm = Vm::default();
        self.st = [AxisState::default(); AXES];
        self.save_eeprom();
        self.init_chip();
    }

    /// The program currently in memory (up to the highest address written).
    pub fn program(&self) -> &[Instruction] {
        &self.program[..self.prog_len]
    }

    /// Loads a program as a download would (addresses 0..), without the EEPROM write. Every
    /// instruction must be one this module can execute ([`Module::check_instruction`]).
    pub fn load_program(&mut self, prog: &[Instruction]) -> Result<(), String> {
        if prog.len() > PROGRAM_SIZE {
            return Err(format!("program has {} instructions, memory holds {PROGRAM_SIZE}", prog.len()));
        }
        for (a, ins) in prog.iter().enumerate() {
            if let Err(e) = self.check_instruction(ins) {
                return Err(format!("instruction {a} ({}): {e}", crate::asm::format_ins(ins, &|v| v.to_string())));
            }
        }
        self.program = vec![Instruction::default(); PROGRAM_SIZE];
        self.program[..prog.len()].copy_from_slice(prog);
        self.prog_len = prog.len();
        self.reset_vm();
        Ok(())
    }

    fn save_eeprom(&mut self) {
        if let Some(p) = self.eeprom_path.clone() {
            self.eeprom.program = self.program[..self.prog_len].to_vec();
            if let Err(e) = self.eeprom.save(&p) {
                self.eeprom_error = Some(format!("{}: {e}", p.display()));
            }
        }
    }

    fn eeprom_locked(&self) -> bool {
        self.gp(73) != 0
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
