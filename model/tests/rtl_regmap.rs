//! The RTL's register decode comes from the one register map: `rtl/tmc429_regmap.vh` is the
//! rendering of `model/src/regmap.rs` (`tmc429 regmap --format verilog`), and no RTL source
//! decodes an address or a register field with a number of its own.

mod common;

use common::rtl::{self, starts_with_number};
use tmc429_model::regmap_verilog;

#[test]
fn the_rtl_header_is_the_register_map() {
    let file = rtl::header("tmc429_regmap.vh");
    assert!(file == regmap_verilog::header(), "rtl/tmc429_regmap.vh is stale: run `{}`", regmap_verilog::REGENERATE);
}

/// Signals that carry an address or a register's bits as the map lays them out: a bit-select
/// of one with a number instead of a `TMC429_*` name is a hand-written field position.
const REGISTER_SIGNALS: &[&str] = &[
    "cmd",
    "a7",
    "rd_addr",
    "wdata",
    "cfg_data",
    "widx",
    "jdx",
    "sh_idx",
    "cfg_idx",
    "rq_idx",
    "rsel",
    "if_conf",
    "ifconf",
    "ifconf_nx",
    "gconf",
    "gconf_nx",
    "gconf_wd",
    "drv_m0",
    "drv_m1",
    "drv_m2",
    "ref_conf",
];
/// Signals that hold an IDX or JDX: compared with, or a case over, a number is a register index.
const INDEX_SIGNALS: &[&str] = &["widx", "jdx", "sh_idx", "cfg_idx"];

/// The text after each whole-word occurrence of `name` in `code`.
fn after<'a>(code: &'a str, name: &'a str) -> impl Iterator<Item = &'a str> + 'a {
    let word = |c: char| c.is_ascii_alphanumeric() || c == '_' || c == '`';
    code.match_indices(name).filter_map(move |(i, _)| {
        let before_ok = !code[..i].ends_with(word);
        let rest = &code[i + name.len()..];
        (before_ok && !rest.starts_with(word)).then_some(rest)
    })
}

/// A case label of numbers only (`4'd0:`, `4'd0, 4'd1:`).
fn numeric_label(code: &str) -> bool {
    let t = code.trim_start();
    match t.split_once(':') {
        Some((label, _)) if starts_with_number(t) => {
            label.chars().all(|c| c.is_ascii_hexdigit() || matches!(c, '\'' | 'h' | 'b' | 'o' | '_' | ',' | ' '))
        }
        _ => false,
    }
}

/// The lines of a Verilog source that decode with a hand-written number: `(line, text)`.
fn literal_decodes(source: &str) -> Vec<(usize, String)> {
    let mut found = Vec::new();
    let mut in_index_case = false;
    for (n, line) in source.lines().enumerate() {
        let code = rtl::code_of(line);
        if let Some(sel) = after(code, "case").next() {
            let sel = sel.trim_start().trim_start_matches('(').trim_start();
            let name = sel.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_')).next().unwrap_or("");
            // an IDX signal, or the IDX bits of an address (`a7[...]`, `a[...]` in a function)
            let addr = matches!(name, "a7" | "a") && sel[name.len()..].trim_start().starts_with('[');
            in_index_case = INDEX_SIGNALS.contains(&name) || addr;
        }
        if after(code, "endcase").next().is_some() {
            in_index_case = false;
        }
        let slice =
            REGISTER_SIGNALS.iter().any(|s| after(code, s).any(|r| r.trim_start().strip_prefix('[').is_some_and(starts_with_number)));
        let compare = INDEX_SIGNALS.iter().any(|s| {
            after(code, s).any(|r| {
                let r = r.trim_start();
                (r.starts_with("==") || r.starts_with("!=")) && starts_with_number(&r[2..])
            })
        });
        if slice || compare || (in_index_case && numeric_label(code)) {
            found.push((n + 1, line.trim().to_string()));
        }
    }
    found
}

#[test]
fn the_rtl_decodes_through_the_header_names() {
    let bad = rtl::lines_found(literal_decodes);
    assert!(bad.is_empty(), "register decode with a number instead of a name of rtl/tmc429_regmap.vh:\n{}", bad.join("\n"));
}

/// The forms of the decode the RTL had before the header, each caught.
#[test]
fn hand_written_indices_and_fields_are_found() {
    let old = "\
    wire w_int = we & (widx == 4'd11);   // interrupt
    wire [6:0] a7 = cmd[31:25];
    wire w_pc = wr_g & (jdx != 4'd6);
    .pol_nscs_s(gconf_nx[2]), .inv_ref(ifconf_nx[0]),
    case (widx)
    4'd0:  x_target <= wdata;
    4'd2, 4'd3: v_min <= wdata[10:0];
    endcase
    case (ph)
    5'd29: x <= 1'b1;
    endcase
    assign y = rsel[ 1] & x;
    case (a[3:0])
    4'd9: sh_rst = 24'h429101;
    endcase
";
    let lines: Vec<usize> = literal_decodes(old).into_iter().map(|(n, _)| n).collect();
    assert_eq!(lines, [1, 2, 3, 4, 6, 7, 12, 14]);
    let new = "\
    wire w_int = we & (widx == `TMC429_IDX_INTERRUPT);   // was widx == 4'd11
    wire [6:0] a7 = cmd[`TMC429_DG_A7];
    case (widx)
    `TMC429_IDX_X_TARGET: x_target <= wdata[`TMC429_F_X_TARGET];
    endcase
    wire [11:0] w_v = (wdata[`TMC429_F_V_ACTUAL] == 12'h800) ? 12'h801 : wdata[`TMC429_F_V_ACTUAL];
    wire [3:0] jdx_q = x[3:0];
    case (a)
    6'd0: rom_word = 12'h151;
    endcase
";
    assert_eq!(literal_decodes(new), []);
}
