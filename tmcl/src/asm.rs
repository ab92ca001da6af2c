//! TMCL assembler and disassembler: the TMCL-IDE mnemonic language (labels, symbolic
//! constants `Name = value`, `//` and `/* */` comments, `#include`) to binary and back.

use crate::proto::{op, Instruction};
use std::collections::HashMap;
use std::fmt;
use std::path::{Path, PathBuf};

/// An assembly error with its place.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct AsmError {
    pub file: String,
    pub line: usize,
    pub msg: String,
}

impl fmt::Display for AsmError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}: {}", self.file, self.line, self.msg)
    }
}

impl std::error::Error for AsmError {}

/// What an operand slot holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Slot {
    /// Type field, with an optional keyword table.
    Type(&'static [(&'static str, u8)]),
    /// Motor/bank field.
    Motor,
    /// Value field.
    Value,
    /// Value field holding a program address (label).
    Addr,
}

const MVP_T: &[(&str, u8)] = &[("ABS", 0), ("REL", 1), ("COORD", 2)];
const RFS_T: &[(&str, u8)] = &[("START", 0), ("STOP", 1), ("STATUS", 2)];
const CALC_T: &[(&str, u8)] =
    &[("ADD", 0), ("SUB", 1), ("MUL", 2), ("DIV", 3), ("MOD", 4), ("AND", 5), ("OR", 6), ("XOR", 7), ("NOT", 8), ("LOAD", 9)];
const CALCX_T: &[(&str, u8)] =
    &[("ADD", 0), ("SUB", 1), ("MUL", 2), ("DIV", 3), ("MOD", 4), ("AND", 5), ("OR", 6), ("XOR", 7), ("NOT", 8), ("LOAD", 9), ("SWAP", 10)];
const JC_T: &[(&str, u8)] = &[("ZE", 0), ("NZ", 1), ("EQ", 2), ("NE", 3), ("GT", 4), ("GE", 5), ("LT", 6), ("LE", 7), ("ETO", 8)];
const WAIT_T: &[(&str, u8)] = &[("TICKS", 0), ("POS", 1), ("REFSW", 2), ("LIMSW", 3), ("RFS", 4)];
const CLE_T: &[(&str, u8)] = &[("ALL", 0), ("ETO", 1), ("EAL", 2), ("EDV", 3), ("EPO", 4)];
const NUM: &[(&str, u8)] = &[];

use Slot::*;

/// Mnemonic, opcode, operand slots, number of trailing optional slots.
struct Spec {
    name: &'static str,
    op: u8,
    slots: &'static [Slot],
    optional: usize,
}

const SPECS: &[Spec] = &[
    Spec { name: "ROR", op: op::ROR, slots: &[Motor, Value], optional: 0 },
    Spec { name: "ROL", op: op::ROL, slots: &[Motor, Value], optional: 0 },
    Spec { name: "MST", op: op::MST, slots: &[Motor], optional: 0 },
    Spec { name: "MVP", op: op::MVP, slots: &[Type(MVP_T), Motor, Value], optional: 0 },
    Spec { name: "SAP", op: op::SAP, slots: &[Type(NUM), Motor, Value], optional: 0 },
    Spec { name: "GAP", op: op::GAP, slots: &[Type(NUM), Motor, Value], optional: 1 },
    Spec { name: "STAP", op: op::STAP, slots: &[Type(NUM), Motor, Value], optional: 1 },
    Spec { name: "RSAP", op: op::RSAP, slots: &[Type(NUM), Motor, Value], optional: 1 },
    Spec { name: "SGP", op: op::SGP, slots: &[Type(NUM), Motor, Value], optional: 0 },
    Spec { name: "GGP", op: op::GGP, slots: &[Type(NUM), Motor, Value], optional: 1 },
    Spec { name: "STGP", op: op::STGP, slots: &[Type(NUM), Motor, Value], optional: 1 },
    Spec { name: "RSGP", op: op::RSGP, slots: &[Type(NUM), Motor, Value], optional: 1 },
    Spec { name: "RFS", op: op::RFS, slots: &[Type(RFS_T), Motor, Value], optional: 1 },
    Spec { name: "SIO", op: op::SIO, slots: &[Type(NUM), Motor, Value], optional: 0 },
    Spec { name: "GIO", op: op::GIO, slots: &[Type(NUM), Motor, Value], optional: 1 },
    Spec { name: "CALC", op: op::CALC, slots: &[Type(CALC_T), Value], optional: 1 },
    Spec { name: "COMP", op: op::COMP, slots: &[Value], optional: 0 },
    Spec { name: "JC", op: op::JC, slots: &[Type(JC_T), Addr], optional: 0 },
    Spec { name: "JA", op: op::JA, slots: &[Addr], optional: 0 },
    Spec { name: "CSUB", op: op::CSUB, slots: &[Addr], optional: 0 },
    Spec { name: "RSUB", op: op::RSUB, slots: &[], optional: 0 },
    Spec { name: "EI", op: op::EI, slots: &[Type(NUM)], optional: 0 },
    Spec { name: "DI", op: op::DI, slots: &[Type(NUM)], optional: 0 },
    Spec { name: "WAIT", op: op::WAIT, slots: &[Type(WAIT_T), Motor, Value], optional: 0 },
    Spec { name: "STOP", op: op::STOP, slots: &[], optional: 0 },
    Spec { name: "SCO", op: op::SCO, slots: &[Type(NUM), Motor, Value], optional: 0 },
    Spec { name: "GCO", op: op::GCO, slots: &[Type(NUM), Motor, Value], optional: 1 },
    Spec { name: "CCO", op: op::CCO, slots: &[Type(NUM), Motor, Value], optional: 1 },
    Spec { name: "CALCX", op: op::CALCX, slots: &[Type(CALCX_T)], optional: 0 },
    Spec { name: "AAP", op: op::AAP, slots: &[Type(NUM), Motor, Value], optional: 1 },
    Spec { name: "AGP", op: op::AGP, slots: &[Type(NUM), Motor, Value], optional: 1 },
    Spec { name: "CLE", op: op::CLE, slots: &[Type(CLE_T)], optional: 0 },
    Spec { name: "VECT", op: op::VECT, slots: &[Type(NUM), Addr], optional: 0 },
    Spec { name: "RETI", op: op::RETI, slots: &[], optional: 0 },
    Spec { name: "ACO", op: op::ACO, slots: &[Type(NUM), Motor, Value], optional: 1 },
    Spec { name: "UF0", op: 64, slots: &[Type(NUM), Motor, Value], optional: 2 },
    Spec { name: "UF1", op: 65, slots: &[Type(NUM), Motor, Value], optional: 2 },
    Spec { name: "UF2", op: 66, slots: &[Type(NUM), Motor, Value], optional: 2 },
    Spec { name: "UF3", op: 67, slots: &[Type(NUM), Motor, Value], optional: 2 },
    Spec { name: "UF4", op: 68, slots: &[Type(NUM), Motor, Value], optional: 2 },
    Spec { name: "UF5", op: 69, slots: &[Type(NUM), Motor, Value], optional: 2 },
    Spec { name: "UF6", op: 70, slots: &[Type(NUM), Motor, Value], optional: 2 },
    Spec { name: "UF7", op: 71, slots: &[Type(NUM), Motor, Value], optional: 2 },
];

fn spec_by_name(n: &str) -> Option<&'static Spec> {
    SPECS.iter().find(|s| s.name.eq_ignore_ascii_case(n))
}
fn spec_by_op(o: u8) -> Option<&'static Spec> {
    SPECS.iter().find(|s| s.op == o)
}

/// Opcodes a program may hold.
pub fn is_program_opcode(o: u8) -> bool {
    spec_by_op(o).is_some()
}

/// Mnemonic of an opcode, if it has one.
pub fn mnemonic(o: u8) -> Option<&'static str> {
    spec_by_op(o).map(|s| s.name)
}

/// Symbols of the include files the TMCL-IDE ships, as far as this module uses them.
fn builtin_include(name: &str) -> Option<&'static [(&'static str, i64)]> {
    const PARAM: &[(&str, i64)] = &[
        ("APTargetPosition", 0),
        ("APActualPosition", 1),
        ("APTargetSpeed", 2),
        ("APActualSpeed", 3),
        ("APMaxPositioningSpeed", 4),
        ("APMaxAcceleration", 5),
        ("APAbsMaxCurrent", 6),
        ("APStandbyCurrent", 7),
        ("APTargetPosReached", 8),
        ("APRefSwitchStatus", 9),
        ("APRightLimitSwitchStatus", 10),
        ("APLeftLimitSwitchStatus", 11),
        ("APRightLimitSwitchDisable", 12),
        ("APLeftLimitSwitchDisable", 13),
        ("APMinimumSpeed", 130),
        ("APActualAcceleration", 135),
        ("APRampMode", 138),
        ("APMicrostepResolution", 140),
        ("APRefSwitchTolerance", 141),
        ("APSoftStopFlag", 149),
        ("APRampDivisor", 153),
        ("APPulseDivisor", 154),
        ("APReferencingMode", 193),
        ("APReferencingSearchSpeed", 194),
        ("APReferencingSwitchSpeed", 195),
        ("APDistanceEndSwitches", 196),
        ("APBoostCurrent", 200),
        ("APFreewheelingDelay", 204),
        ("APPowerDownDelay", 214),
        ("GPSerialAddress", 66),
        ("GPASCIIMode", 67),
        ("GPSerialHeartbeat", 68),
        ("GPSerialHostAddress", 76),
        ("GPAutoStartMode", 77),
        ("GPEndSwitchPolarity", 79),
        ("GPTickTimer", 132),
        ("GPRandomNumber", 133),
        ("Motor0", 0),
        ("Motor1", 1),
        ("Motor2", 2),
    ];
    const IRQ: &[(&str, i64)] = &[
        ("TI_TIMER0", 0),
        ("TI_TIMER1", 1),
        ("TI_TIMER2", 2),
        ("TI_TARGET0", 3),
        ("TI_TARGET1", 4),
        ("TI_TARGET2", 5),
        ("TI_STOPL0", 27),
        ("TI_STOPR0", 28),
        ("TI_STOPL1", 29),
        ("TI_STOPR1", 30),
        ("TI_STOPL2", 31),
        ("TI_STOPR2", 32),
        ("TI_PIN0", 39),
        ("TI_PIN1", 40),
        ("TI_PIN2", 41),
        ("TI_PIN3", 42),
        ("TI_PIN4", 43),
        ("TI_PIN5", 44),
        ("TI_PIN6", 45),
        ("TI_PIN7", 46),
        ("TI_GLOBAL", 255),
    ];
    if name.eq_ignore_ascii_case("TMCLParam.tmc") {
        Some(PARAM)
    } else if name.eq_ignore_ascii_case("Interrupts.inc") {
        Some(IRQ)
    } else {
        None
    }
}

/// One source line after comments are removed.
struct Line {
    file: String,
    no: usize,
    text: String,
}

fn strip_comments(src: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut in_block = false;
    for raw in src.lines() {
        let mut s = String::new();
        let b = raw.as_bytes();
        let mut i = 0;
        while i < b.len() {
            if in_block {
                if b[i] == b'*' && b.get(i + 1) == Some(&b'/') {
                    in_block = false;
                    i += 2;
                } else {
                    i += 1;
                }
                continue;
            }
            if b[i] == b'/' && b.get(i + 1) == Some(&b'/') {
                break;
            }
            if b[i] == b'/' && b.get(i + 1) == Some(&b'*') {
                in_block = true;
                i += 2;
                continue;
            }
            // Keep the text byte-wise; the source is UTF-8 and '/' and '*' are ASCII.
            let ch_len = raw[i..].chars().next().map(|c| c.len_utf8()).unwrap_or(1);
            s.push_str(&raw[i..i + ch_len]);
            i += ch_len;
        }
        out.push(s);
    }
    out
}

fn is_ident_start(c: char) -> bool {
    c.is_ascii_alphabetic() || c == '_'
}
fn is_ident(c: char) -> bool {
    c.is_ascii_alphanumeric() || c == '_'
}

/// Expression evaluator: integers (decimal, $hex, 0x hex, %binary), symbols, + - * / % & | ^ ~ ( ).
struct Expr<'a> {
    s: &'a [u8],
    i: usize,
    syms: &'a HashMap<String, i64>,
}

impl<'a> Expr<'a> {
    fn ws(&mut self) {
        while self.i < self.s.len() && (self.s[self.i] as char).is_ascii_whitespace() {
            self.i += 1;
        }
    }
    fn parse(s: &str, syms: &HashMap<String, i64>) -> Result<i64, String> {
        let mut e = Expr { s: s.as_bytes(), i: 0, syms };
        let v = e.or()?;
        e.ws();
        if e.i != e.s.len() {
            return Err(format!("unexpected '{}' in expression '{}'", &s[e.i..], s.trim()));
        }
        Ok(v)
    }
    fn or(&mut self) -> Result<i64, String> {
        let mut v = self.and()?;
        loop {
            self.ws();
            match self.s.get(self.i) {
                Some(b'|') => {
                    self.i += 1;
                    v |= self.and()?
                }
                Some(b'^') => {
                    self.i += 1;
                    v ^= self.and()?
                }
                _ => return Ok(v),
            }
        }
    }
    fn and(&mut self) -> Result<i64, String> {
        let mut v = self.add()?;
        loop {
            self.ws();
            if self.s.get(self.i) == Some(&b'&') {
                self.i += 1;
                v &= self.add()?;
            } else {
                return Ok(v);
            }
        }
    }
    fn add(&mut self) -> Result<i64, String> {
        let mut v = self.mul()?;
        loop {
            self.ws();
            match self.s.get(self.i) {
                Some(b'+') => {
                    self.i += 1;
                    v = v.wrapping_add(self.mul()?)
                }
                Some(b'-') => {
                    self.i += 1;
                    v = v.wrapping_sub(self.mul()?)
                }
                _ => return Ok(v),
            }
        }
    }
    fn mul(&mut self) -> Result<i64, String> {
        let mut v = self.unary()?;
        loop {
            self.ws();
            match self.s.get(self.i) {
                Some(&c @ (b'*' | b'/' | b'%')) => {
                    self.i += 1;
                    let r = self.unary()?;
                    if c == b'*' {
                        v = v.wrapping_mul(r);
                    } else if r == 0 {
                        return Err("division by zero in expression".into());
                    } else if c == b'/' {
                        v = v.wrapping_div(r);
                    } else {
                        v = v.wrapping_rem(r);
                    }
                }
                _ => return Ok(v),
            }
        }
    }
    fn unary(&mut self) -> Result<i64, String> {
        self.ws();
        match self.s.get(self.i) {
            Some(b'-') => {
                self.i += 1;
                Ok(self.unary()?.wrapping_neg())
            }
            Some(b'+') => {
                self.i += 1;
                self.unary()
            }
            Some(b'~') => {
                self.i += 1;
                Ok(!self.unary()?)
            }
            Some(b'(') => {
                self.i += 1;
                let v = self.or()?;
                self.ws();
                if self.s.get(self.i) != Some(&b')') {
                    return Err("missing ')' in expression".into());
                }
                self.i += 1;
                Ok(v)
            }
            Some(_) => self.atom(),
            None => Err("missing value".into()),
        }
    }
    fn atom(&mut self) -> Result<i64, String> {
        let start = self.i;
        let c = self.s[self.i] as char;
        let text = |a: usize, b: usize, s: &[u8]| String::from_utf8_lossy(&s[a..b]).into_owned();
        if c == '$' || c == '%' || c.is_ascii_digit() {
            let (radix, skip) = if c == '$' {
                (16, 1)
            } else if c == '%' {
                (2, 1)
            } else if c == '0' && matches!(self.s.get(self.i + 1), Some(b'x' | b'X')) {
                (16, 2)
            } else {
                (10, 0)
            };
            self.i += skip;
            let ds = self.i;
            while self.i < self.s.len() && (self.s[self.i] as char).is_ascii_alphanumeric() {
                self.i += 1;
            }
            let digits = text(ds, self.i, self.s);
            return i64::from_str_radix(&digits, radix).map_err(|_| format!("'{}' is not a number", text(start, self.i, self.s)));
        }
        if is_ident_start(c) {
            while self.i < self.s.len() && is_ident(self.s[self.i] as char) {
                self.i += 1;
            }
            let name = text(start, self.i, self.s);
            return self.syms.get(&name).copied().ok_or_else(|| format!("unknown symbol '{name}'"));
        }
        Err(format!("unexpected '{c}' where a value was expected"))
    }
}

fn split_operands(s: &str) -> Vec<String> {
    let t = s.trim();
    if t.is_empty() {
        return Vec::new();
    }
    t.split(',').map(|x| x.trim().to_string()).collect()
}

/// Parses one instruction line (no label) with the given symbols.
fn parse_ins(text: &str, syms: &HashMap<String, i64>) -> Result<Instruction, String> {
    let t = text.trim();
    let (mn, rest) = match t.find(|c: char| c.is_ascii_whitespace() || c == ',') {
        Some(p) => (&t[..p], &t[p..]),
        None => (t, ""),
    };
    let spec = spec_by_name(mn).ok_or_else(|| format!("unknown command '{mn}'"))?;
    // "EI, 255" (as the manual prints it) is accepted: a comma right after the mnemonic.
    let rest = rest.trim_start();
    let rest = rest.strip_prefix(',').unwrap_or(rest);
    let ops = split_operands(rest);
    let min = spec.slots.len() - spec.optional;
    if ops.len() < min || ops.len() > spec.slots.len() {
        let want = if spec.optional > 0 { format!("{} to {}", min, spec.slots.len()) } else { format!("{}", spec.slots.len()) };
        return Err(format!("{} expects {want} operand(s), found {}", spec.name, ops.len()));
    }
    let mut ins = Instruction::new(spec.op, 0, 0, 0);
    for (k, o) in ops.iter().enumerate() {
        if o.is_empty() {
            return Err(format!("operand {} of {} is empty", k + 1, spec.name));
        }
        match spec.slots[k] {
            Type(kw) => {
                let v = if let Some((_, n)) = kw.iter().find(|(n, _)| n.eq_ignore_ascii_case(o)) {
                    *n as i64
                } else {
                    let v = Expr::parse(o, syms).map_err(|e| {
                        if kw.is_empty() {
                            e
                        } else {
                            let names: Vec<&str> = kw.iter().map(|(n, _)| *n).collect();
                            format!("{e}; expected one of {}", names.join(", "))
                        }
                    })?;
                    v
                };
                ins.typ = u8::try_from(v).map_err(|_| format!("type {v} out of range 0..255"))?;
            }
            Motor => {
                let v = Expr::parse(o, syms)?;
                ins.motor = u8::try_from(v).map_err(|_| format!("motor/bank {v} out of range 0..255"))?;
            }
            Value | Addr => {
                let v = Expr::parse(o, syms)?;
                if v < i32::MIN as i64 || v > u32::MAX as i64 {
                    return Err(format!("value {v} does not fit 32 bits"));
                }
                ins.value = v as i32;
            }
        }
    }
    Ok(ins)
}

/// Parses a direct-mode command line (ASCII interface): keywords and numbers only.
pub fn parse_line(text: &str) -> Result<Instruction, String> {
    parse_ins(text, &HashMap::new())
}

/// A file reader, so that `#include` can be resolved without the file system in tests.
pub trait Source {
    fn read(&self, path: &Path) -> std::io::Result<String>;
}

/// Reads from the file system.
pub struct FileSystem;
impl Source for FileSystem {
    fn read(&self, path: &Path) -> std::io::Result<String> {
        std::fs::read_to_string(path)
    }
}

/// An assembled program and its symbols.
#[derive(Clone, Debug, Default)]
pub struct Program {
    pub code: Vec<Instruction>,
    pub labels: Vec<(String, usize)>,
}

fn gather(
    file: &Path,
    text: &str,
    src: &dyn Source,
    lines: &mut Vec<Line>,
    depth: usize,
    syms: &mut HashMap<String, i64>,
) -> Result<(), AsmError> {
    let fname = file.display().to_string();
    for (i, l) in strip_comments(text).into_iter().enumerate() {
        let t = l.trim();
        if let Some(inc) = t.strip_prefix("#include") {
            let name = inc.trim().trim_matches('"').trim_matches(|c| c == '<' || c == '>');
            let e = |msg: String| AsmError { file: fname.clone(), line: i + 1, msg };
            if name.is_empty() {
                return Err(e("#include needs a file name".into()));
            }
            if let Some(b) = builtin_include(name) {
                for (k, v) in b {
                    syms.insert((*k).to_string(), *v);
                }
                continue;
            }
            if depth > 8 {
                return Err(e("includes nested deeper than 8 levels".into()));
            }
            let p: PathBuf = file.parent().unwrap_or(Path::new(".")).join(name);
            let inner = src.read(&p).map_err(|er| e(format!("cannot read include file {}: {er}", p.display())))?;
            gather(&p, &inner, src, lines, depth + 1, syms)?;
            continue;
        }
        lines.push(Line { file: fname.clone(), no: i + 1, text: l });
    }
    Ok(())
}

/// Splits "Label: rest" into the label and the rest.
fn split_label(t: &str) -> (Option<&str>, &str) {
    let t = t.trim();
    if let Some(p) = t.find(':') {
        let name = t[..p].trim();
        if !name.is_empty() && name.chars().next().is_some_and(is_ident_start) && name.chars().all(is_ident) {
            return (Some(name), &t[p + 1..]);
        }
    }
    (None, t)
}

fn split_const(t: &str) -> Option<(&str, &str)> {
    let p = t.find('=')?;
    let name = t[..p].trim();
    (!name.is_empty() && name.chars().next().is_some_and(is_ident_start) && name.chars().all(is_ident)).then(|| (name, &t[p + 1..]))
}

/// Assembles a source text. `file` names it in errors and anchors `#include`.
pub fn assemble(file: &Path, text: &str, src: &dyn Source) -> Result<Program, AsmError> {
    let mut syms: HashMap<String, i64> = HashMap::new();
    let mut lines = Vec::new();
    gather(file, text, src, &mut lines, 0, &mut syms)?;
    // Pass 1: labels and constants.
    let mut addr = 0usize;
    let mut labels = Vec::new();
    let mut label_names: HashMap<String, usize> = HashMap::new();
    for l in &lines {
        let e = |msg: String| AsmError { file: l.file.clone(), line: l.no, msg };
        let (lab, rest) = split_label(&l.text);
        if let Some(n) = lab {
            if label_names.contains_key(n) || syms.contains_key(n) && !label_names.contains_key(n) && false {
                return Err(e(format!("label '{n}' defined twice")));
            }
            label_names.insert(n.to_string(), addr);
            labels.push((n.to_string(), addr));
        }
        let rest = rest.trim();
        if rest.is_empty() {
            continue;
        }
        if let Some((name, expr)) = split_const(rest) {
            if lab.is_some() {
                return Err(e("a constant definition cannot carry a label".into()));
            }
            let v = Expr::parse(expr, &syms).map_err(|m| e(format!("constant '{name}': {m}")))?;
            syms.insert(name.to_string(), v);
            continue;
        }
        addr += 1;
    }
    for (n, a) in &label_names {
        syms.insert(n.clone(), *a as i64);
    }
    // Pass 2: instructions.
    let mut code = Vec::new();
    for l in &lines {
        let (_, rest) = split_label(&l.text);
        let rest = rest.trim();
        if rest.is_empty() || split_const(rest).is_some() {
            continue;
        }
        let ins = parse_ins(rest, &syms).map_err(|msg| AsmError { file: l.file.clone(), line: l.no, msg })?;
        code.push(ins);
    }
    if code.len() > crate::config::PROGRAM_SIZE {
        return Err(AsmError {
            file: file.display().to_string(),
            line: lines.last().map(|l| l.no).unwrap_or(0),
            msg: format!("program has {} instructions, program memory holds {}", code.len(), crate::config::PROGRAM_SIZE),
        });
    }
    Ok(Program { code, labels })
}

/// Formats one instruction in mnemonic form; `label` names program addresses.
pub fn format_ins(i: &Instruction, label: &dyn Fn(i32) -> String) -> String {
    let Some(spec) = spec_by_op(i.op) else {
        return format!("// unknown command {} (type {}, motor {}, value {})", i.op, i.typ, i.motor, i.value);
    };
    let mut ops = Vec::new();
    for s in spec.slots {
        ops.push(match s {
            Type(kw) => kw.iter().find(|(_, n)| *n == i.typ).map(|(n, _)| n.to_string()).unwrap_or_else(|| i.typ.to_string()),
            Motor => i.motor.to_string(),
            Value => i.value.to_string(),
            Addr => label(i.value),
        });
    }
    if ops.is_empty() {
        spec.name.to_string()
    } else {
        format!("{} {}", spec.name, ops.join(", "))
    }
}

/// Disassembles a program; jump targets get labels `L<address>`.
pub fn disassemble(code: &[Instruction]) -> String {
    let mut targets = std::collections::BTreeSet::new();
    for i in code {
        if let Some(s) = spec_by_op(i.op) {
            if s.slots.contains(&Addr) {
                targets.insert(i.value);
            }
        }
    }
    let label = |v: i32| {
        if v >= 0 && (v as usize) < code.len() {
            format!("L{v}")
        } else {
            v.to_string()
        }
    };
    let mut out = String::new();
    for (a, i) in code.iter().enumerate() {
        if targets.contains(&(a as i32)) {
            out.push_str(&format!("L{a}:\n"));
        }
        out.push_str("    ");
        out.push_str(&format_ins(i, &label));
        out.push('\n');
    }
    out
}

/// Opcode of a mnemonic.
pub fn opcode_of(name: &str) -> Option<u8> {
    spec_by_name(name).map(|s| s.op)
}
