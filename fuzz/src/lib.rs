//! The fuzz targets: every parser a user reaches, each a function of arbitrary bytes that panics
//! when the parser breaks a rule of the project. scripts/fuzz builds them with coverage
//! instrumentation and runs them under libFuzzer (docs/testplan.md, "Fuzzing").
//!
//! Rules checked on every input, beyond "no panic, no hang, no stack overflow":
//! - an error names a line inside the input (1-based), and its message carries no control
//!   character and stays short ([`MESSAGE_MAX`]): input is quoted escaped and shortened;
//! - what is accepted means what it says: an assembled program disassembles and assembles back to
//!   the same code, a disassembly is a fixed point, a decoded EEPROM image encodes and decodes to
//!   itself, a TMCL link answers in whole checksummed frames, `calc` prints finite numbers.

use std::path::Path;

use tmc429_model::{script, text, Chip, Inputs, Tmc429};
use tmc429_scenario::calc::{self, Request};
use tmcl::asm;
use tmcl::chip::{sext, Spi429};
use tmcl::eeprom::Image;
use tmcl::link::{Link, Mode};
use tmcl::{Module, Reply};

/// Longest error message a parser may produce, in bytes (the longest lists every register name of
/// a variant).
pub const MESSAGE_MAX: usize = 2000;

fn check_message(m: &str) {
    assert!(!m.chars().any(char::is_control), "control character in the message {m:?}");
    assert!(m.len() <= MESSAGE_MAX, "message of {} bytes: {}", m.len(), &m[..200]);
}

/// The input as UTF-8 text, or `None` after checking the error that reports why it is not.
fn utf8(data: &[u8]) -> Option<String> {
    match text::utf8(data.to_vec()) {
        Ok(t) => Some(t),
        Err(e) => {
            check_message(&e);
            None
        }
    }
}

/// Lines an error may name: 1 ..= the lines of the text (one more for an error at its very end).
fn lines(text: &str) -> usize {
    text.bytes().filter(|&b| b == b'\n').count() + 1
}

fn check_line(line: usize, lines: usize) {
    assert!((1..=lines).contains(&line), "line {line} of {lines}");
}

/// A datagram script of `tmc429 spi` and `tmc429 vectors --scenario FILE`.
pub fn script(data: &[u8]) {
    let Some(t) = utf8(data) else { return };
    match script::parse(&t, "fuzz.spi") {
        Ok(ls) => ls.iter().for_each(|l| check_line(l.line, lines(&t))),
        Err(errs) => {
            assert!(!errs.is_empty());
            let n = lines(&t);
            for e in errs {
                check_line(e.line, n);
                check_message(&e.message);
            }
        }
    }
}

/// A scenario file of `tmc429 run`, `tmc429 vectors --scenario FILE.toml`.
pub fn scenario(data: &[u8]) {
    let Some(t) = utf8(data) else { return };
    match tmc429_scenario::parse(&t, "fuzz.toml") {
        Ok(sc) => assert!(sc.duration > 0 && sc.sck_half >= 3),
        Err(errs) => {
            assert!(!errs.is_empty());
            let n = lines(&t);
            for e in errs {
                check_line(e.line, n);
                check_message(&e.msg);
            }
        }
    }
}

/// The golden model behind its register interface: each datagram executes at once, without the
/// 264 CLK of its SPI frame (the SPI port has its own tests), so that a module powers up in
/// microseconds and the TMCL targets run thousands of inputs per second.
struct RegChip {
    chip: Tmc429,
    pins: Inputs,
}

impl Spi429 for RegChip {
    fn write(&mut self, a7: u8, data: u32) -> u8 {
        self.chip.write_register(a7, data);
        self.chip.status()
    }
    fn read(&mut self, a7: u8) -> u32 {
        self.chip.read_register(a7)
    }
    fn wait(&mut self, cycles: u64) {
        for _ in 0..cycles {
            self.chip.tick(&self.pins);
        }
    }
    fn cycle(&self) -> u64 {
        self.chip.cycle()
    }
    fn fclk(&self) -> u64 {
        16_000_000
    }
    fn set_ref_pins(&mut self, left: [bool; 3], right: [bool; 3]) {
        [self.pins.ref1, self.pins.ref2, self.pins.ref3] = left;
        [self.pins.refr1, self.pins.refr2, self.pins.refr3] = right;
    }
    fn mechanical_position(&self, m: usize) -> i32 {
        self.chip.probes().motor.get(m).map(|p| sext(p.x_actual, 24)).unwrap_or(0)
    }
}

fn module() -> Module<RegChip> {
    Module::new(RegChip { chip: Tmc429::new(Chip::Tmc429), pins: Inputs::default() })
}

/// The binary TMCL stream of a host link (`tmcl serve`): 9-byte commands in, 9-byte replies out,
/// each with a valid checksum (or the version string of command 136 type 0), until the link
/// switches to ASCII (command 139).
pub fn tmcl_binary(data: &[u8]) {
    let mut m = module();
    let mut link = Link::new(false);
    for frame in data.chunks(9) {
        let binary = link.mode == Mode::Binary;
        let out = link.feed(&mut m, frame, 0);
        if !binary {
            continue;
        }
        assert_eq!(out.len() % 9, 0, "a partial reply frame: {out:02x?}");
        for r in out.chunks(9) {
            let r: &[u8; 9] = r.try_into().unwrap();
            assert!(Reply::from_bytes(r).is_ok() || &r[1..] == b"3110V100", "a bad reply frame {r:02x?}");
        }
    }
    let _ = link.poll(&mut m, 1_000);
}

/// The ASCII TMCL stream of a host link (manual §4.4): command lines in, answers out.
pub fn tmcl_ascii(data: &[u8]) {
    let mut m = module();
    let mut link = Link::new(true);
    let out = link.feed(&mut m, data, 0);
    // at most the echo of every byte and one answer (≤ 16 bytes) per byte
    assert!(out.len() <= 17 * data.len(), "{} bytes out for {} in", out.len(), data.len());
}

/// `#include "inc.tmc"` reads the input itself (so includes nest until the limit).
struct Itself<'a>(&'a str);

impl asm::Source for Itself<'_> {
    fn read(&self, path: &Path) -> std::io::Result<String> {
        match path.file_name().and_then(|n| n.to_str()) {
            Some("inc.tmc") => Ok(self.0.to_string()),
            _ => Err(std::io::ErrorKind::NotFound.into()),
        }
    }
}

/// The TMCL assembler (`tmcl asm`, `tmcl run`): an accepted program disassembles and assembles
/// back to the same code.
pub fn asm(data: &[u8]) {
    let Some(t) = utf8(data) else { return };
    match asm::assemble(Path::new("fuzz.tmc"), &t, &Itself(&t)) {
        Ok(p) => {
            let listing = asm::disassemble(&p.code);
            let q = asm::assemble(Path::new("listing.tmc"), &listing, &Itself(""))
                .unwrap_or_else(|e| panic!("the disassembly does not assemble: {e}\n{listing}"));
            assert_eq!(p.code, q.code, "{listing}");
        }
        Err(e) => {
            assert!(e.line >= 1);
            check_message(&e.msg);
        }
    }
}

/// The TMCL disassembler (`tmcl disasm`): 7 bytes per instruction; a listing of known opcodes
/// assembles back to code whose listing is the same.
pub fn disasm(data: &[u8]) {
    let code: Vec<tmcl::Instruction> =
        data.chunks_exact(7).take(tmcl::config::PROGRAM_SIZE).map(|c| tmcl::Instruction::from_bytes7(c.try_into().unwrap())).collect();
    let listing = asm::disassemble(&code);
    if code.iter().all(|i| asm::mnemonic(i.op).is_some()) {
        let q = asm::assemble(Path::new("listing.tmc"), &listing, &Itself(""))
            .unwrap_or_else(|e| panic!("the disassembly does not assemble: {e}\n{listing}"));
        assert_eq!(asm::disassemble(&q.code), listing);
    }
}

/// An EEPROM image (`--eeprom FILE`): a decoded image encodes and decodes to itself; a rejected
/// one says why. An input whose first byte is odd is the rest with its length field and CRC-32
/// made right, so that the checks behind the CRC are reached too.
pub fn eeprom(data: &[u8]) {
    let bytes = match data.split_first() {
        Some((&mode, rest)) if mode & 1 == 1 && rest.len() >= 16 => {
            let mut b = rest.to_vec();
            let n = b.len() - 16;
            b[8..12].copy_from_slice(&(n as u32).to_le_bytes());
            let crc = tmcl::eeprom::crc32(&b[..12 + n]);
            b[12 + n..].copy_from_slice(&crc.to_le_bytes());
            b
        }
        _ => data.to_vec(),
    };
    match Image::decode(&bytes) {
        Ok(img) => assert_eq!(Image::decode(&img.encode()).expect("an encoded image decodes"), img),
        Err(e) => check_message(&e.to_string()),
    }
}

/// The arguments of `tmc429 calc` (`--option value` pairs, values as the command line parses
/// them): an answer prints finite numbers only.
pub fn calc(data: &[u8]) {
    let t = String::from_utf8_lossy(data);
    let mut r = Request { fclk: 32e6, microsteps: 1, p_reduction: 0.01, ..Default::default() };
    let toks: Vec<&str> = t.split_whitespace().collect();
    for pair in toks.chunks(2) {
        let [opt, val] = pair else { return };
        let ok = match *opt {
            "--fclk" => val.parse().ok().filter(|f| (1.0..=1e9).contains(f)).map(|f| r.fclk = f).is_some(),
            "--microsteps" => val.parse().map(|v| r.microsteps = v).is_ok(),
            "--usrs" => val.parse().map(|v| r.usrs = Some(v)).is_ok(),
            "--speed" => val.parse().map(|v| r.speed = Some(v)).is_ok(),
            "--rpm" => val.parse().map(|v| r.rpm = Some(v)).is_ok(),
            "--steps-per-rev" => val.parse().map(|v| r.steps_per_rev = Some(v)).is_ok(),
            "--accel" => val.parse().map(|v| r.accel = Some(v)).is_ok(),
            "--p-reduction" => val.parse().map(|v| r.p_reduction = v).is_ok(),
            "--pulse-div" => val.parse().map(|v| r.pulse_div = Some(v)).is_ok(),
            "--ramp-div" => val.parse().map(|v| r.ramp_div = Some(v)).is_ok(),
            "--v-max" => val.parse().map(|v| r.v_max = Some(v)).is_ok(),
            "--a-max" => val.parse().map(|v| r.a_max = Some(v)).is_ok(),
            _ => false,
        };
        if !ok {
            return; // the command line would refuse it before calc runs
        }
    }
    match calc::answer(&r) {
        Ok(s) => assert!(!s.contains("NaN") && !s.contains("inf"), "{r:?}\n{s}"),
        Err(e) => check_message(&e),
    }
}
