//! The RTL's coding rules that a tool can hold (docs/rtl.md, "Checks"): every `rtl/*.v` is one
//! module between `default_nettype none` and `default_nettype wire`, every process is clocked
//! by the rising edge of `clk` or is combinational (the reset is synchronous: no `negedge`, no
//! reset in a sensitivity list), and a next state has one suffix, `_nx`. Active-low pins keep
//! the datasheets' leading `n` (nSCS_C: `nscs_c`), so no name ends in `_n`, nor in another
//! next-state suffix (`_ns`, `_next`, `_d`).

mod common;

use common::rtl;

/// Suffixes a name in rtl/ does not end in: `_nx` is the one next-state suffix.
const OTHER_SUFFIXES: &[&str] = &["_n", "_ns", "_next", "_d"];

/// The names of `text` (identifiers outside `//` comments and strings) that end in one of
/// [`OTHER_SUFFIXES`]: (line number from 1, the name).
fn other_suffixes(text: &str) -> Vec<(usize, String)> {
    let mut found = Vec::new();
    for (n, line) in text.lines().enumerate() {
        let code: String = rtl::code_of(line).split('"').step_by(2).collect::<Vec<_>>().join(" ");
        for name in code.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_' || c == '$' || c == '\'')) {
            let plain = !name.contains('\'') && !name.starts_with(|c: char| c.is_ascii_digit() || c == '$');
            if plain && OTHER_SUFFIXES.iter().any(|s| name.len() > s.len() && name.ends_with(s)) {
                found.push((n + 1, name.to_string()));
            }
        }
    }
    found
}

/// The lines of `text` that break the file rules: a second module, no `default_nettype none`
/// before the module or no `default_nettype wire` as the last line, or a sensitivity list
/// other than `posedge clk` and `*`.
fn file_rules(text: &str) -> Vec<(usize, String)> {
    let mut found = Vec::new();
    let lines: Vec<&str> = text.lines().collect();
    let code: Vec<&str> = lines.iter().map(|l| rtl::code_of(l).trim()).collect();
    let module = code.iter().position(|t| t.starts_with("module "));
    let none = code.iter().position(|&t| t == "`default_nettype none");
    match (none, module) {
        (Some(a), Some(b)) if a < b => {}
        _ => found.push((module.map_or(1, |b| b + 1), "`default_nettype none` before the module".into())),
    }
    if lines.last().map(|l| l.trim()) != Some("`default_nettype wire") {
        found.push((lines.len(), "`default_nettype wire` as the last line".into()));
    }
    for (n, &code) in code.iter().enumerate() {
        if module.is_some_and(|b| n > b) && code.starts_with("module ") {
            found.push((n + 1, "one module per file".into()));
        }
        for (i, _) in code.match_indices('@') {
            let list: String = code[i + 1..].chars().take_while(|&c| c != ')').filter(|c| !c.is_whitespace()).collect();
            if list != "(posedgeclk" && list != "(*" {
                found.push((n + 1, format!("sensitivity `{}` (only `posedge clk` and `*`)", code[i..].trim())));
            }
        }
    }
    found
}

#[test]
fn every_next_state_ends_in_nx() {
    let bad = rtl::lines_found(other_suffixes);
    assert!(bad.is_empty(), "names with another next-state suffix than `_nx` ({OTHER_SUFFIXES:?}):\n{}", bad.join("\n"));
}

#[test]
fn every_source_is_one_module_with_no_implicit_nets_and_one_clock_edge() {
    let bad = rtl::lines_found(file_rules);
    assert!(bad.is_empty(), "rtl/ file rules broken:\n{}", bad.join("\n"));
}

#[test]
fn the_rules_find_what_they_forbid() {
    let old = "`default_nettype none\nmodule a (input wire clk);\n    reg [2:0] state, state_n; // state_n in a comment\n\
               wire x_next = \"y_n\" == 0;\n    wire [3:0] v = 4'd0; reg q_nx, q_d;\n\
               always @(posedge clk or posedge rst) q_nx <= 1'b0;\n    always @(negedge clk) q_d <= 1'b0;\nendmodule\n\
               module b; endmodule\n";
    assert_eq!(
        other_suffixes(old),
        [(3, "state_n".to_string()), (4, "x_next".to_string()), (5, "q_d".to_string()), (7, "q_d".to_string())]
    );
    let rules: Vec<usize> = file_rules(old).into_iter().map(|(n, _)| n).collect();
    assert_eq!(rules, [9, 6, 7, 9]);
    let new = "`default_nettype none\nmodule a (input wire clk);\n    reg [2:0] state, state_nx;\n\
               always @(posedge clk) state <= state_nx;\n    always @(*) state_nx = state;\nendmodule\n\n`default_nettype wire\n";
    assert_eq!(other_suffixes(new), []);
    assert_eq!(file_rules(new), []);
}
