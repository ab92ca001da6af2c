//! `scripts/carry-paths`, the check of iCE40 netlists for register-to-register paths through
//! more than one carry chain that `scripts/rtl-check` runs on both flows of every variant
//! (docs/rtl.md "Checks"). The netlist here is Yosys JSON written by hand in the shape
//! `synth_ice40 -json` writes: flip-flops a and b feed a chain of two carry cells (sum1), a
//! LUT after it feeds a second chain (sum2) into flip-flop e: two chains; f takes sum1 alone
//! and g the LUT: one chain each; h takes a chain that a path leaves through a LUT and enters
//! again (one chain, counted once); a and b take their own outputs: none.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn carry_paths(args: &[&str]) -> Output {
    Command::new(root().join("scripts/carry-paths")).args(args).output().unwrap()
}

fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

/// A scratch file `name` with `body` in this test's own directory.
fn file(tag: &str, name: &str, body: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("tmc429-carry-paths-{tag}-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    let p = d.join(name);
    std::fs::write(&p, body).unwrap();
    p
}

fn ff(name: &str, d: u32, q: u32) -> String {
    format!(
        r#""{name}": {{"type": "SB_DFF", "port_directions": {{"C": "input", "D": "input", "Q": "output"}}, "connections": {{"C": [1], "D": [{d}], "Q": [{q}]}}}}"#
    )
}

fn carry(name: &str, i0: u32, i1: u32, ci: &str, co: u32) -> String {
    format!(r#""{name}": {{"type": "SB_CARRY", "connections": {{"I0": [{i0}], "I1": [{i1}], "CI": [{ci}], "CO": [{co}]}}}}"#)
}

fn lut(name: &str, i0: u32, i1: u32, o: u32) -> String {
    format!(r#""{name}": {{"type": "SB_LUT4", "connections": {{"I0": [{i0}], "I1": [{i1}], "I2": ["0"], "I3": ["0"], "O": [{o}]}}}}"#)
}

/// The netlist of the module comment; nets by number, 1 the clock.
fn netlist() -> String {
    let cells = [
        ff("a_ff", 2, 2),
        ff("b_ff", 3, 3),
        carry("c1", 2, 3, "\"0\"", 10),
        carry("c2", 2, 3, "10", 11),
        lut("l1", 11, 2, 12),
        carry("c3", 12, 3, "\"0\"", 13),
        ff("e_ff", 13, 14),
        ff("f_ff", 11, 15),
        ff("g_ff", 12, 16),
        carry("x1", 2, 3, "\"0\"", 20),
        lut("l2", 20, 3, 22),
        carry("x2", 22, 3, "20", 21),
        ff("h_ff", 21, 23),
    ];
    let nets =
        [("clk", 1), ("a", 2), ("b", 3), ("sum1", 11), ("l1_o", 12), ("sum2", 13), ("e", 14), ("f", 15), ("g", 16), ("x", 21), ("h", 23)];
    let nets: Vec<String> = nets.iter().map(|(n, b)| format!(r#""{n}": {{"bits": [{b}]}}"#)).collect();
    format!(
        r#"{{"creator": "Yosys", "modules": {{"tmc429_chip": {{"attributes": {{"top": "1"}}, "ports": {{"clk": {{"direction": "input", "bits": [1]}}}}, "cells": {{{}}}, "netnames": {{{}}}}}}}}}"#,
        cells.join(", "),
        nets.join(", ")
    )
}

#[test]
fn a_path_through_two_chains_is_listed_and_fails() {
    let p = file("two", "n.json", &netlist());
    let o = carry_paths(&[p.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(1), "stderr: {}", text(&o.stderr));
    assert_eq!(
        text(&o.stdout),
        format!(
            "{}: path ends by the carry chains their worst path crosses: 0: 2, 1: 3, 2: 1\n  2 chains: a -> e (D)\n      through sum1 (2 carry cells) | sum2 (1 carry cell)\n",
            p.display()
        )
    );
}

#[test]
fn an_allowed_path_end_passes_and_is_marked() {
    let p = file("allow", "n.json", &netlist());
    let o = carry_paths(&["--allow", "^e$", p.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "stderr: {}", text(&o.stderr));
    assert!(text(&o.stdout).contains("  2 chains (allowed): a -> e (D)\n"), "{}", text(&o.stdout));
    // a pattern that matches another register does not allow e
    let o = carry_paths(&["--allow", "^f$", p.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(1));
}

#[test]
fn bad_usage_an_unreadable_file_a_loop_or_not_a_netlist_exits_2() {
    let usage = "usage: scripts/carry-paths [--allow REGEX]... NETLIST.json...\n";
    for args in [&[][..], &["--allow"][..], &["--frob", "x.json"][..]] {
        let o = carry_paths(args);
        assert_eq!((o.status.code(), text(&o.stderr)), (Some(2), usage.to_string()), "{args:?}");
    }
    let p = file("bad", "n.json", &netlist());
    let o = carry_paths(&["--allow", "(", p.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    assert!(text(&o.stderr).starts_with("carry-paths: --allow: not a regular expression: "), "{}", text(&o.stderr));
    let missing = std::env::temp_dir().join("tmc429-carry-paths-no-such-file.json");
    let o = carry_paths(&[missing.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(text(&o.stderr), format!("carry-paths: {}: cannot read: No such file or directory\n", missing.display()));
    let not = file("not", "not.json", "{\"creator\": \"Yosys\"}\n");
    let o = carry_paths(&[not.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        text(&o.stderr)
            .starts_with(&format!("carry-paths: {}: not a Yosys JSON netlist (expected a flat module with cells)", not.display())),
        "{}",
        text(&o.stderr)
    );
    assert!(o.stdout.is_empty());
    // a LUT that takes its own output into flip-flop e: no path ends to count
    let looped = netlist().replace(
        r#""I0": [11], "I1": [2], "I2": ["0"], "I3": ["0"], "O": [12]"#,
        r#""I0": [12], "I1": [2], "I2": ["0"], "I3": ["0"], "O": [12]"#,
    );
    let p = file("loop", "n.json", &looped);
    let o = carry_paths(&[p.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(text(&o.stderr), format!("carry-paths: {}: a combinational loop through l1_o: not a synthesized netlist\n", p.display()));
}
