//! `tmc429 tmcl`: the TMCL module layer (crate `tmcl`): serve a virtual TMCM-3110 or
//! TMCM-1311, assemble, disassemble and run TMCL programs.

use std::io::Write;
use std::path::{Path, PathBuf};

use tmcl::asm;
use tmcl::chip::ModelChip;
use tmcl::module::{AppState, Module};
use tmcl::personality::ModuleType;
use tmcl::server::{Options, Server};

use tmc429_model::text::shown;

use crate::{Outcome, UserError};

#[derive(clap::Args)]
pub struct Args {
    #[command(subcommand)]
    pub cmd: Sub,
}

#[derive(clap::Subcommand)]
pub enum Sub {
    /// Serve the virtual module over TCP and/or a pseudo-terminal.
    Serve(ServeArgs),
    /// Assemble a TMCL program: print its listing, or write the binary with -o.
    Asm(AsmArgs),
    /// Disassemble a binary written by `asm -o` (7 bytes per instruction).
    Disasm(DisasmArgs),
    /// Run a TMCL program on a virtual module and report where it ended.
    Run(RunArgs),
}

#[derive(clap::Args)]
pub struct ModuleArgs {
    /// Module type: tmcm-3110 (three axes, TMC429 units) or tmcm-1311 (one axis, pps, pps²).
    #[arg(long = "module", default_value = "tmcm-3110", value_parser = parse_module)]
    pub module: ModuleType,
    /// EEPROM image file (missing: factory defaults, created on the first store).
    #[arg(long)]
    pub eeprom: Option<PathBuf>,
    /// TMC429 clock in Hz (TMCM modules clock their TMC429 at 16 MHz).
    #[arg(long, default_value_t = 16_000_000, value_parser = parse_hz)]
    pub fclk: u64,
    /// Drive a digital input: N=0|1 (N = 0..7); repeatable.
    #[arg(long = "input", value_name = "N=LEVEL")]
    pub inputs: Vec<String>,
    /// Set an analog input: CH=VALUE (CH = 0 or 4, VALUE = 0..4095); repeatable.
    #[arg(long = "analog", value_name = "CH=VALUE")]
    pub analog: Vec<String>,
    /// Supply voltage in 1/10 V (GIO 8, 1).
    #[arg(long, default_value_t = 240)]
    pub supply: u16,
    /// Left end switch of an axis: AXIS=POS (pressed at positions <= POS) or AXIS=FROM:TO
    /// (pressed inside, can be driven through); repeatable.
    #[arg(long = "left-switch", value_name = "AXIS=POS")]
    pub left: Vec<String>,
    /// Right end switch of an axis: AXIS=POS (pressed at positions >= POS) or AXIS=FROM:TO;
    /// repeatable.
    #[arg(long = "right-switch", value_name = "AXIS=POS")]
    pub right: Vec<String>,
    /// Home switch of an axis: AXIS=FROM:TO (active inside the window); repeatable.
    #[arg(long = "home-switch", value_name = "AXIS=FROM:TO")]
    pub home: Vec<String>,
}

#[derive(clap::Args)]
pub struct ServeArgs {
    /// Listen on this TCP address, e.g. 127.0.0.1:2323 (port 0 picks a free port).
    #[arg(long)]
    pub tcp: Option<String>,
    /// Open a pseudo-terminal and print its path.
    #[arg(long)]
    pub pty: bool,
    /// Module time per wall-clock time (2 = twice as fast).
    #[arg(long, default_value_t = 1.0)]
    pub time_scale: f64,
    /// A partial binary frame is dropped after this pause [ms].
    #[arg(long, default_value_t = tmcl::link::DEFAULT_FRAME_TIMEOUT_MS)]
    pub frame_timeout_ms: u64,
    #[command(flatten)]
    pub module: ModuleArgs,
}

#[derive(clap::Args)]
pub struct AsmArgs {
    /// TMCL source file.
    pub file: PathBuf,
    /// Write the binary (7 bytes per instruction) to this file instead of the listing.
    #[arg(short = 'o', long)]
    pub output: Option<PathBuf>,
}

#[derive(clap::Args)]
pub struct DisasmArgs {
    /// Binary file (7 bytes per instruction).
    pub file: PathBuf,
}

#[derive(clap::Args)]
pub struct RunArgs {
    /// TMCL source file.
    pub file: PathBuf,
    /// Module time to run at most [s].
    #[arg(long, default_value_t = 10.0)]
    pub time: f64,
    #[command(flatten)]
    pub module: ModuleArgs,
}

pub fn run(a: Args) -> Result<Outcome, UserError> {
    match a.cmd {
        Sub::Serve(s) => serve(s),
        Sub::Asm(s) => asm_cmd(s),
        Sub::Disasm(s) => disasm(s),
        Sub::Run(s) => run_prog(s),
    }
}

fn parse_module(s: &str) -> Result<ModuleType, String> {
    ModuleType::parse(s).ok_or_else(|| format!("unknown module type '{s}': expected tmcm-3110 or tmcm-1311"))
}

fn parse_hz(s: &str) -> Result<u64, String> {
    let t = s.trim();
    let (n, mult) = match t.strip_suffix("MHz") {
        Some(n) => (n, 1_000_000f64),
        None => (t.strip_suffix("Hz").unwrap_or(t), 1.0),
    };
    let v: f64 = n.trim().parse().map_err(|_| format!("expected a frequency in Hz (e.g. 16000000 or 16MHz), found '{}'", shown(s)))?;
    let hz = v * mult;
    if !(1000.0..=1e9).contains(&hz) {
        return Err(format!("frequency {} out of range (1 kHz .. 1 GHz)", shown(s)));
    }
    Ok(hz.round() as u64)
}

fn kv<'a>(opt: &str, s: &'a str) -> Result<(i64, &'a str), UserError> {
    let (k, v) = s.split_once('=').ok_or_else(|| UserError(format!("--{opt} {}: expected KEY=VALUE", shown(s))))?;
    let k: i64 = k.trim().parse().map_err(|_| UserError(format!("--{opt} {}: '{}' is not a number", shown(s), shown(k))))?;
    Ok((k, v.trim()))
}

fn num(opt: &str, s: &str, v: &str) -> Result<i64, UserError> {
    v.parse().map_err(|_| UserError(format!("--{opt} {}: '{}' is not a number", shown(s), shown(v))))
}

/// A switch position: compared with the axis' actual position, a signed 32-bit axis parameter;
/// a value outside that range is an error, never cut to 32 bits.
fn position(opt: &str, s: &str, v: &str) -> Result<i32, UserError> {
    let x = num(opt, s, v)?;
    i32::try_from(x).map_err(|_| UserError(format!("--{opt} {}: position {x} out of range {}..{}", shown(s), i32::MIN, i32::MAX)))
}

fn axis(kind: ModuleType, opt: &str, s: &str, k: i64) -> Result<usize, UserError> {
    let n = kind.axes() as i64;
    if (0..n).contains(&k) {
        Ok(k as usize)
    } else {
        Err(UserError(format!("--{opt} {}: axis {k} out of range 0..{} of the {}", shown(s), n - 1, kind.name())))
    }
}

/// A switch's span: one position (an end switch to the end of travel: `end`) or FROM:TO.
fn span(opt: &str, s: &str, v: &str, end: fn(i32) -> tmcl::io::Span) -> Result<tmcl::io::Span, UserError> {
    let n = |x: &str| position(opt, s, x.trim());
    match v.split_once(':') {
        Some((a, b)) => {
            let (a, b) = (n(a)?, n(b)?);
            if a > b {
                return Err(UserError(format!("--{opt} {}: FROM {a} is above TO {b}", shown(s))));
            }
            Ok((a, b))
        }
        None => Ok(end(n(v)?)),
    }
}

fn build_module(a: &ModuleArgs) -> Result<Module<ModelChip>, UserError> {
    let chip = ModelChip::new(tmc429_model::Chip::Tmc429, a.fclk);
    let kind = a.module;
    let mut m = match &a.eeprom {
        Some(p) => {
            Module::with_eeprom(chip, kind, p.clone()).map_err(|(_, e)| UserError(format!("{}: {e}; nothing was loaded", p.display())))?
        }
        None => Module::of_type(chip, kind),
    };
    for s in &a.inputs {
        let (k, v) = kv("input", s)?;
        let l = num("input", s, v)?;
        if !(0..8).contains(&k) || !(0..=1).contains(&l) {
            return Err(UserError(format!("--input {}: expected N=LEVEL with N 0..7 and LEVEL 0 or 1", shown(s))));
        }
        m.io.driven[k as usize] = Some(l == 1);
    }
    for s in &a.analog {
        let (k, v) = kv("analog", s)?;
        let x = num("analog", s, v)?;
        let ch = match k {
            0 => 0,
            4 => 1,
            _ => return Err(UserError(format!("--analog {}: channel must be 0 or 4", shown(s)))),
        };
        if !(0..=4095).contains(&x) {
            return Err(UserError(format!("--analog {}: value must be 0..4095", shown(s))));
        }
        m.io.analog[ch] = x as u16;
    }
    m.io.supply_dv = a.supply;
    for s in &a.left {
        let (k, v) = kv("left-switch", s)?;
        m.world.left[axis(kind, "left-switch", s, k)?] = Some(span("left-switch", s, v, tmcl::io::World::left_end)?);
    }
    for s in &a.right {
        let (k, v) = kv("right-switch", s)?;
        m.world.right[axis(kind, "right-switch", s, k)?] = Some(span("right-switch", s, v, tmcl::io::World::right_end)?);
    }
    for s in &a.home {
        let (k, v) = kv("home-switch", s)?;
        if !v.contains(':') {
            return Err(UserError(format!("--home-switch {}: expected AXIS=FROM:TO", shown(s))));
        }
        // FROM:TO (the end-switch form does not apply to a home switch).
        m.world.home[axis(kind, "home-switch", s, k)?] = Some(span("home-switch", s, v, tmcl::io::World::left_end)?);
    }
    m.update_pins();
    Ok(m)
}

fn serve(a: ServeArgs) -> Result<Outcome, UserError> {
    if a.tcp.is_none() && !a.pty {
        return Err(UserError("tmcl serve: give --tcp ADDRESS:PORT and/or --pty".into()));
    }
    let m = build_module(&a.module)?;
    let opt = Options { tcp: a.tcp.clone(), pty: a.pty, time_scale: a.time_scale, frame_timeout_ms: a.frame_timeout_ms };
    let srv = Server::start(m, &opt).map_err(UserError)?;
    {
        let mut o = std::io::stdout().lock();
        if let Some(addr) = srv.tcp_addr {
            let _ = writeln!(o, "tcp: {addr}");
        }
        if let Some(p) = &srv.pty_path {
            let _ = writeln!(o, "pty: {p}");
        }
        let _ = o.flush();
    }
    srv.wait();
    Ok(Outcome::Ok)
}

fn assemble_file(p: &Path) -> Result<asm::Program, UserError> {
    let text = tmc429_model::text::read_file(p).map_err(UserError)?;
    asm::assemble(p, &text, &asm::FileSystem).map_err(|e| UserError(e.to_string()))
}

fn asm_cmd(a: AsmArgs) -> Result<Outcome, UserError> {
    let prog = assemble_file(&a.file)?;
    if let Some(o) = a.output {
        let mut b = Vec::new();
        for i in &prog.code {
            b.extend_from_slice(&i.to_bytes7());
        }
        super::run::write_atomic(&o, &b)?;
        return Ok(Outcome::Ok);
    }
    let names: std::collections::HashMap<usize, &str> = prog.labels.iter().map(|(n, a)| (*a, n.as_str())).collect();
    let label = |v: i32| prog.labels.iter().find(|(_, a)| *a as i32 == v).map(|(n, _)| n.clone()).unwrap_or_else(|| v.to_string());
    let mut out = std::io::stdout().lock();
    for (addr, i) in prog.code.iter().enumerate() {
        let b = i.to_bytes7();
        let hex: Vec<String> = b.iter().map(|x| format!("{x:02X}")).collect();
        let lab = names.get(&addr).map(|n| format!("{n}:")).unwrap_or_default();
        let _ = writeln!(out, "{addr:4}  {}  {lab:<12} {}", hex.join(" "), asm::format_ins(i, &label));
    }
    Ok(Outcome::Ok)
}

fn disasm(a: DisasmArgs) -> Result<Outcome, UserError> {
    let b = std::fs::read(&a.file).map_err(|e| UserError(format!("{}: cannot read: {e}", a.file.display())))?;
    if b.len() % 7 != 0 {
        return Err(UserError(format!("{}: {} bytes is not a whole number of 7-byte instructions", a.file.display(), b.len())));
    }
    let code: Vec<_> = b
        .chunks(7)
        .map(|c| {
            let mut s = [0u8; 7];
            s.copy_from_slice(c);
            tmcl::Instruction::from_bytes7(&s)
        })
        .collect();
    print!("{}", asm::disassemble(&code));
    Ok(Outcome::Ok)
}

fn run_prog(a: RunArgs) -> Result<Outcome, UserError> {
    let limit = run_time_ms(a.time)?;
    let prog = assemble_file(&a.file)?;
    let mut m = build_module(&a.module)?;
    // Every instruction must be one the module runs (as a download would check it).
    for (ins, (file, line)) in prog.code.iter().zip(&prog.lines) {
        if let Err(e) = m.check_instruction(ins) {
            let text = asm::format_ins(ins, &|v| v.to_string());
            return Err(UserError(format!("{file}:{line}: {text}: {e}; the {} cannot run this program", m.kind().name())));
        }
    }
    m.load_program(&prog.code).map_err(|e| UserError(format!("{}: {e}", a.file.display())))?;
    m.vm.state = AppState::Run;
    let mut ms = 0;
    while ms < limit && m.vm.state == AppState::Run {
        m.run_ms(1);
        ms += 1;
    }
    let mut out = std::io::stdout().lock();
    if m.vm.state == AppState::Run {
        let _ = writeln!(out, "still running after {:.3} s at pc {}", ms as f64 / 1000.0, m.vm.pc);
    } else {
        let _ = writeln!(out, "stopped after {:.3} s at pc {}", ms as f64 / 1000.0, m.vm.pc);
    }
    for ax in 0..m.kind().axes() as u8 {
        let ins = |t| tmcl::Instruction::new(tmcl::proto::op::GAP, t, ax, 0);
        let g = |m: &mut Module<ModelChip>, t| m.execute(&ins(t), tmcl::Origin::Direct).1;
        let (x, v, t) = (g(&mut m, 1), g(&mut m, 3), g(&mut m, 0));
        let _ = writeln!(out, "axis {ax}: actual position {x}, target position {t}, actual speed {v}");
    }
    let _ = writeln!(out, "accumulator {}, X register {}, outputs {:08b}", m.vm.accu, m.vm.x, m.io.outputs);
    // A store the program made (STAP, STGP, …) that did not reach the file is lost state: exit 2.
    if let Some(e) = m.eeprom_error.take() {
        return Err(UserError(format!("EEPROM store failed: {e}; the file is unchanged")));
    }
    Ok(Outcome::Ok)
}

/// `--time` in whole module milliseconds (the module runs in 1 ms steps): at least 1 ms, and no
/// more than a 64-bit count of them (never cut silently).
fn run_time_ms(seconds: f64) -> Result<u64, UserError> {
    let ms = (seconds * 1000.0).round();
    if !(1.0..u64::MAX as f64).contains(&ms) {
        return Err(UserError(format!("--time {seconds:e}: expected 0.001 .. 1.8e16 seconds (the module runs in 1 ms steps)")));
    }
    Ok(ms as u64)
}
