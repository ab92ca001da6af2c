//! TMCL assembler and disassembler: the TMCL-IDE mnemonic language (labels, symbolic
//! constants `Name = value`, `//` and `/* */` comments, `#include`) to binary and back.

pub use crate::asm_expr::MAX_EXPR_DEPTH;
use crate::asm_expr::{is_ident, is_ident_start, Expr};
use crate::proto::{op, Instruction};
use std::collections::HashMap;
use std::fmt;
use std::path::{Path, PathBuf};
use tmc429_model::text::shown;

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
pub(crate) enum Slot {
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

pub use crate::disasm::{disassemble, format_ins};

/// Mnemonic, opcode, operand slots, number of trailing optional slots.
pub(crate) struct Spec {
    pub(crate) name: &'static str,
    op: u8,
    pub(crate) slots: &'static [Slot],
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
pub(crate) fn spec_by_op(o: u8) -> Option<&'static Spec> {
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
    let spec = spec_by_name(mn).ok_or_else(|| format!("unknown command '{}'", shown(mn)))?;
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
    /// A file that is not UTF-8 is `InvalidData` with the line and byte offset of the first bad
    /// byte ([`tmc429_model::text::utf8`]).
    fn read(&self, path: &Path) -> std::io::Result<String> {
        tmc429_model::text::utf8(std::fs::read(path)?).map_err(|e| std::io::Error::new(std::io::ErrorKind::InvalidData, e))
    }
}

/// An assembled program and its symbols.
#[derive(Clone, Debug, Default)]
pub struct Program {
    pub code: Vec<Instruction>,
    pub labels: Vec<(String, usize)>,
    /// File and line of each instruction of `code`.
    pub lines: Vec<(String, usize)>,
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
            if let Some(b) = crate::asm_symbols::builtin_include(name) {
                for (k, v) in b {
                    syms.insert((*k).to_string(), *v);
                }
                continue;
            }
            if depth > 8 {
                return Err(e("includes nested deeper than 8 levels".into()));
            }
            let p: PathBuf = file.parent().unwrap_or(Path::new(".")).join(name);
            let shown_p = shown(&p.display().to_string());
            let inner = src.read(&p).map_err(|er| match er.kind() {
                std::io::ErrorKind::InvalidData => e(format!("include file {shown_p}:{er}")),
                _ => e(format!("cannot read include file {shown_p}: {er}")),
            })?;
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
            if label_names.contains_key(n) {
                return Err(e(format!("label '{}' defined twice", shown(n))));
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
            let v = Expr::parse(expr, &syms).map_err(|m| e(format!("constant '{}': {m}", shown(name))))?;
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
    let mut places = Vec::new();
    for l in &lines {
        let (_, rest) = split_label(&l.text);
        let rest = rest.trim();
        if rest.is_empty() || split_const(rest).is_some() {
            continue;
        }
        let ins = parse_ins(rest, &syms).map_err(|msg| AsmError { file: l.file.clone(), line: l.no, msg })?;
        code.push(ins);
        places.push((l.file.clone(), l.no));
    }
    if code.len() > crate::config::PROGRAM_SIZE {
        return Err(AsmError {
            file: file.display().to_string(),
            line: lines.last().map(|l| l.no).unwrap_or(0),
            msg: format!("program has {} instructions, program memory holds {}", code.len(), crate::config::PROGRAM_SIZE),
        });
    }
    Ok(Program { code, labels, lines: places })
}

/// Opcode of a mnemonic.
pub fn opcode_of(name: &str) -> Option<u8> {
    spec_by_name(name).map(|s| s.op)
}
