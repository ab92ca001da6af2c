//! The disassembler: instructions back to TMCL-IDE mnemonics (the assembler's inverse).

use crate::asm::{spec_by_op, Slot::*};
use crate::proto::Instruction;

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
