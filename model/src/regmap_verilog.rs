//! The register map as a Verilog header (`rtl/tmc429_regmap.vh`), rendered from
//! [`crate::regmap::REGISTERS`] by `tmc429 regmap --format verilog`; the RTL decodes the
//! datagram through its names, and a test keeps the file in the repository equal to this
//! rendering.
//!
//! Every name is a `define (a header's unused localparams would be lint warnings in every
//! module that includes it). Per register: `TMC429_IDX_*` (motor register, TMC428 Table 7-2),
//! `TMC429_JDX_*` (global register) or `TMC429_ADDR_*` (first RAM word), `TMC429_CHIPS_*` (the
//! variants that have it, bit CHIP), `TMC429_RESET_*` (the power-on read value) and
//! `TMC429_WMASK_*` (the bits a write stores). Per field: `TMC429_F_*` (its bit range, or its bit
//! for a one-bit field), `_LSB`, `_MSB` and `_W`.

use std::collections::HashMap;
use std::fmt::Write;

use crate::regmap::{self, Field, Register, Space, REGISTERS};
use crate::Chip;

/// The command that writes the header.
pub const REGENERATE: &str = "tmc429 regmap --format verilog > rtl/tmc429_regmap.vh";

fn ident(s: &str) -> String {
    s.to_ascii_uppercase()
}

/// The name prefix of a register entry: `TMC429`, or the variant's name for a second layout of
/// a register another entry already describes (the TMC4210's global_parameters).
fn prefix(r: &Register, first: bool) -> String {
    let chips: Vec<Chip> = Chip::ALL.into_iter().filter(|c| r.chips.contains(*c)).collect();
    match (first, chips.as_slice()) {
        (false, [only]) => ident(only.name()),
        _ => "TMC429".to_string(),
    }
}

/// The name of a field after `TMC429_F_`: its own, with the register's for a one-letter name
/// (`POS_COMP_INT_M`) and `RAM_` for the RAM words' cells.
fn field_name(r: &Register, f: &Field) -> String {
    match r.space {
        Space::Ram => format!("RAM_{}", ident(f.name)),
        _ if f.name.len() == 1 => format!("{}_{}", ident(r.name), ident(f.name)),
        _ => ident(f.name),
    }
}

fn chips_text(r: &Register) -> String {
    Chip::ALL.into_iter().filter(|c| r.chips.contains(*c)).map(|c| c.name().to_ascii_uppercase()).collect::<Vec<_>>().join(", ")
}

/// `((chip) == 0 ? V0 : (chip) == 1 ? V1 : V2)` over the variants, the value of each formatted.
fn per_variant(value: impl Fn(Chip) -> String) -> String {
    let mut s = String::from("(");
    for c in &Chip::ALL[..Chip::ALL.len() - 1] {
        let _ = write!(s, "(chip) == {} ? {} : ", c.rtl_param(), value(*c));
    }
    s + &value(Chip::ALL[Chip::ALL.len() - 1]) + ")"
}

/// The IDX (motor registers) or JDX (global registers) a variant has, as a 16-bit mask.
fn present_mask(chip: Chip, space: Space) -> String {
    let mask = (0..16u8)
        .filter(|&i| regmap::lookup(chip, if space == Space::Motor { regmap::motor_a7(0, i) } else { regmap::global_a7(i) }).is_some());
    format!("16'h{:04X}", mask.fold(0u16, |m, i| m | 1 << i))
}

fn motors(chip: Chip) -> usize {
    (0..3).filter(|&m| regmap::lookup(chip, regmap::motor_a7(m, regmap::idx::X_TARGET)).is_some()).count()
}

/// Bit range `msb:lsb` (or the bit) of a mask of contiguous ones.
fn bits(mask: u64) -> String {
    let (lsb, msb) = (mask.trailing_zeros(), 63 - mask.leading_zeros());
    if lsb == msb {
        format!("{lsb}")
    } else {
        format!("{msb}:{lsb}")
    }
}

/// One `` `define NAME VALUE `` line, with its comment after it (also the schedule header's,
/// [`crate::schedule_verilog`]).
pub(crate) fn define(s: &mut String, name: &str, value: &str, comment: &str) {
    let line = format!("`define {name} {value}");
    if comment.is_empty() {
        s.push_str(&line);
    } else {
        let _ = write!(s, "{line:<48} // {comment}");
    }
    s.push('\n');
}

/// The datagram's layout and the address spaces (TMC428 §6.2, §7.1).
fn layout(s: &mut String) {
    let dg = |a7: u8, read: bool, data: u32| u64::from(regmap::datagram(a7, read, data));
    s.push_str("// ---- the datagram (TMC428 §6.2, §7.1): {A7, RW, data}; A7 = {RRS, SMDA, IDX} --------\n");
    define(s, "TMC429_DG_A7", &bits(dg(0x7F, false, 0)), "address A7");
    define(s, "TMC429_DG_RW", &bits(dg(0, true, 0)), "1: read");
    define(s, "TMC429_DG_DATA", &bits(dg(0, false, 0xFF_FFFF)), "data word");
    define(s, "TMC429_A7_RRS", &bits(u64::from(regmap::ram_a7(0))), "1: RAM word (ADDR in TMC429_A7_ADDR)");
    define(s, "TMC429_A7_SMDA", &bits(u64::from(regmap::motor_a7(3, 0))), "motor 0..2, or TMC429_SMDA_GLOBAL");
    define(s, "TMC429_A7_IDX", &bits(u64::from(regmap::motor_a7(0, 15))), "IDX of a motor register, JDX of a global one");
    define(s, "TMC429_A7_REG", &bits(u64::from(regmap::motor_a7(3, 15))), "{SMDA, IDX}: one of the 64 register addresses");
    define(s, "TMC429_A7_ADDR", &bits(u64::from(regmap::ram_a7(0x3F) & 0x3F)), "ADDR of a RAM word");
    let global = regmap::global_a7(0) >> 4;
    define(s, "TMC429_SMDA_GLOBAL", &format!("2'd{global}"), "SMDA of the global registers");
    s.push_str("\n// ---- the variants (CHIP 0 TMC428, 1 TMC429, 2 TMC4210); a register a variant lacks reads 0\n");
    s.push_str("//      and ignores writes (contract C21) ---------------------------------------------------\n");
    define(s, "TMC429_HAS(chips, chip)", "((((chips) >> (chip)) & 3'd1) != 3'd0)", "a TMC429_CHIPS_* set holds CHIP");
    define(s, "TMC429_MOTORS(chip)", &per_variant(|c| motors(c).to_string()), "motors (SMDA 0..)");
    define(s, "TMC429_IDX_PRESENT(chip)", &per_variant(|c| present_mask(c, Space::Motor)), "bit IDX: the variant has it");
    define(s, "TMC429_JDX_PRESENT(chip)", &per_variant(|c| present_mask(c, Space::Global)), "bit JDX: the variant has it");
}

/// One register with its fields; `fields` holds the field names already defined and their bits.
fn register(s: &mut String, r: &Register, first: bool, fields: &mut HashMap<String, (u8, u8)>) {
    let p = prefix(r, first);
    let name = ident(r.name);
    let chips = format!("3'b{:03b}", r.chips.0);
    let _ = writeln!(s, "\n// {} — {} ({})", r.name, r.section, chips_text(r));
    if first {
        match r.space {
            Space::Motor => define(s, &format!("TMC429_IDX_{name}"), &format!("4'd{}", r.index), ""),
            Space::Global => define(s, &format!("TMC429_JDX_{name}"), &format!("4'd{}", r.index), ""),
            Space::Ram => define(s, &format!("TMC429_ADDR_{name}"), &format!("6'd{}", r.a7(0) & 0x3F), ""),
        }
    }
    define(s, &format!("{p}_CHIPS_{name}"), &chips, "");
    define(s, &format!("{p}_RESET_{name}"), &format!("24'h{:06X}", r.reset), "");
    define(s, &format!("{p}_WMASK_{name}"), &format!("24'h{:06X}", r.writable_mask()), "");
    for f in r.fields {
        let mut fname = field_name(r, f);
        match fields.get(&fname) {
            Some(&at) if at == (f.lsb, f.width) => continue,
            Some(_) => fname = format!("{name}_{}", ident(f.name)),
            None => {}
        }
        fields.insert(fname.clone(), (f.lsb, f.width));
        let f_ = format!("TMC429_F_{fname}");
        define(s, &f_, &bits(u64::from(f.mask())), f.doc);
        define(s, &format!("{f_}_LSB"), &f.lsb.to_string(), "");
        define(s, &format!("{f_}_MSB"), &(f.lsb + f.width - 1).to_string(), "");
        define(s, &format!("{f_}_W"), &f.width.to_string(), "");
    }
}

/// The header `rtl/tmc429_regmap.vh`.
pub fn header() -> String {
    let mut s = format!(
        "// TMC428/TMC429/TMC4210 register map for the RTL (TMC428 Table 7-2, §8-§10; TMC429 §8; TMC4210 §5).\n\
         // Generated from model/src/regmap.rs; do not edit. Regenerate with\n\
         //   {REGENERATE}\n\
         // Names: TMC429_IDX_* / TMC429_JDX_* / TMC429_ADDR_* index of a motor register, a global register,\n\
         // the first RAM word; TMC429_CHIPS_* the variants that have it (bit CHIP); TMC429_RESET_* its\n\
         // power-on read value; TMC429_WMASK_* the bits a write stores (TMC4210_*: that variant's own\n\
         // layout). TMC429_F_* a field's bits (msb:lsb, or the bit), with _LSB, _MSB and _W.\n\
         `ifndef TMC429_REGMAP_VH\n`define TMC429_REGMAP_VH\n\n"
    );
    layout(&mut s);
    let mut seen = std::collections::HashSet::new();
    let mut fields = HashMap::new();
    for r in REGISTERS {
        let first = seen.insert((r.name, r.a7(0)));
        register(&mut s, r, first, &mut fields);
    }
    s += "\n`endif // TMC429_REGMAP_VH\n";
    s
}

/// The value of `` `define NAME `` in a rendered header, without its comment.
#[cfg(test)]
pub(crate) fn define_value<'a>(h: &'a str, name: &str) -> Option<&'a str> {
    let key = format!("`define {name} ");
    h.lines().find_map(|l| l.strip_prefix(&key)).map(|v| v.split("//").next().unwrap().trim())
}

#[cfg(test)]
mod tests {
    use super::define_value as value;
    use super::*;

    /// TMC428 Table 7-2, §8.14, §9.7; TMC429 §8.2.4, §8.2.4.4; TMC4210 §5.3.
    #[test]
    fn names_carry_the_datasheet_values() {
        let h = header();
        assert_eq!(value(&h, "TMC429_IDX_CLK_CONFIG"), Some("4'd12"));
        assert_eq!(value(&h, "TMC429_JDX_GLOBAL_PARAMETERS"), Some("4'd15"));
        assert_eq!(value(&h, "TMC429_ADDR_RAM_MICROSTEP_TABLE"), Some("6'd32"));
        assert_eq!(value(&h, "TMC429_F_PULSE_DIV"), Some("15:12"));
        assert_eq!(value(&h, "TMC429_F_PULSE_DIV_LSB"), Some("12"));
        assert_eq!(value(&h, "TMC429_F_PULSE_DIV_MSB"), Some("15"));
        assert_eq!(value(&h, "TMC429_F_PULSE_DIV_W"), Some("4"));
        assert_eq!(value(&h, "TMC429_F_EN_SD"), Some("5"));
        assert_eq!(value(&h, "TMC429_F_POS_COMP_INT_M"), Some("8"));
        assert_eq!(value(&h, "TMC429_F_RAM_ODD"), Some("13:8"));
        assert_eq!(value(&h, "TMC429_RESET_TYPE_VERSION"), Some("24'h429101"));
        assert_eq!(value(&h, "TMC429_CHIPS_CURRENT_SCALING"), Some("3'b011"));
        assert_eq!(value(&h, "TMC429_WMASK_GLOBAL_PARAMETERS"), Some("24'h31FFFF"));
        assert_eq!(value(&h, "TMC4210_WMASK_GLOBAL_PARAMETERS"), Some("24'h200F00"));
        assert_eq!(value(&h, "TMC429_DG_A7"), Some("31:25"));
        assert_eq!(value(&h, "TMC429_DG_RW"), Some("24"));
        assert_eq!(value(&h, "TMC429_A7_SMDA"), Some("5:4"));
        assert_eq!(value(&h, "TMC429_A7_REG"), Some("5:0"));
        assert_eq!(value(&h, "TMC429_SMDA_GLOBAL"), Some("2'd3"));
        assert_eq!(value(&h, "TMC429_MOTORS(chip)"), Some("((chip) == 0 ? 3 : (chip) == 1 ? 3 : 1)"));
        // TMC428: no ustep_count (IDX 15); TMC4210: no current_scaling (IDX 8)
        assert_eq!(value(&h, "TMC429_IDX_PRESENT(chip)"), Some("((chip) == 0 ? 16'h7FFF : (chip) == 1 ? 16'hFFFF : 16'hFEFF)"));
        // TMC428: JDX 0..3, 8, 14, 15; TMC4210: JDX 4..6, 8, 9, 14, 15
        assert_eq!(value(&h, "TMC429_JDX_PRESENT(chip)"), Some("((chip) == 0 ? 16'hC10F : (chip) == 1 ? 16'hC37F : 16'hC370)"));
    }

    /// Every name is defined once, and each field of the map has its name.
    #[test]
    fn every_name_is_defined_once() {
        let h = header();
        let mut names = std::collections::HashSet::new();
        for l in h.lines().filter_map(|l| l.strip_prefix("`define ")) {
            let name = l.split([' ', '(']).next().unwrap();
            assert!(names.insert(name.to_string()), "{name} defined twice");
        }
        for r in REGISTERS {
            for f in r.fields {
                let n = format!("TMC429_F_{}", field_name(r, f));
                assert_eq!(value(&h, &n), Some(bits(u64::from(f.mask())).as_str()), "{} {}", r.name, f.name);
            }
        }
    }
}
