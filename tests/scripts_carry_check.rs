//! `scripts/carry-check`, the check of iCE40 netlists for carry cells with one net on both
//! operands that `scripts/rtl-check` runs on both flows of every variant (docs/rtl.md "Checks").
//! The netlists here are Yosys JSON written by hand in the shape `synth_ice40 -json` writes: the
//! cell of the build before the check, `SB_CARRY` with I0 = I1 = v_mc and a carry-in of 0, a
//! carry of two different nets, and one with a constant on both operands (not a net: no arc to
//! route).

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn carry_check(args: &[&Path]) -> Output {
    Command::new(root().join("scripts/carry-check")).args(args).output().unwrap()
}

fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

/// A scratch file `name` with `body` in this test's own directory.
fn file(tag: &str, name: &str, body: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("tmc429-carry-check-{tag}-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    let p = d.join(name);
    std::fs::write(&p, body).unwrap();
    p
}

/// A netlist of one module with the carry cells given as (name, I0, I1), nets by number
/// (2 = v_mc, 3 = v_mx[0]) or constants ("0", "1").
fn netlist(cells: &[(&str, &str, &str)]) -> String {
    let cells: Vec<String> = cells
        .iter()
        .map(|(n, i0, i1)| {
            format!(r#""{n}": {{"type": "SB_CARRY", "connections": {{"CI": ["0"], "CO": [9], "I0": [{i0}], "I1": [{i1}]}}}}"#)
        })
        .collect();
    format!(
        r#"{{"creator": "Yosys", "modules": {{"tmc429_chip": {{"netnames": {{"u_top.mot[0].u_m.u_ramp.v_mc": {{"bits": [2]}}, "u_top.mot[0].u_m.u_ramp.v_mx": {{"bits": [3]}}}}, "cells": {{{}}}}}}}}}"#,
        cells.join(", ")
    )
}

#[test]
fn a_carry_with_one_net_on_both_operands_is_listed_and_fails() {
    let bad = "u_top.mot[0].u_m.u_ramp.p_t_SB_LUT4_O_2_I3_SB_CARRY_CO";
    let p = file("bad", "bad.json", &netlist(&[(bad, "2", "2"), ("ok", "2", "3"), ("const", "\"1\"", "\"1\"")]));
    let o = carry_check(&[&p]);
    assert_eq!(o.status.code(), Some(1), "stderr: {}", text(&o.stderr));
    assert_eq!(
        text(&o.stdout),
        format!("{}: carry cells with one net on both operands: 1\n  {bad}  (I0 = I1 = u_top.mot[0].u_m.u_ramp.v_mc)\n", p.display())
    );
}

#[test]
fn a_netlist_without_one_passes() {
    let a = file("good", "a.json", &netlist(&[("ok", "2", "3"), ("const", "\"0\"", "\"0\"")]));
    let b = file("good", "b.json", &netlist(&[]));
    let o = carry_check(&[&a, &b]);
    assert_eq!(o.status.code(), Some(0), "stderr: {}", text(&o.stderr));
    assert_eq!(
        text(&o.stdout),
        format!(
            "{}: carry cells with one net on both operands: 0\n{}: carry cells with one net on both operands: 0\n",
            a.display(),
            b.display()
        )
    );
}

#[test]
fn no_argument_an_unreadable_file_or_not_a_netlist_exits_2() {
    let o = carry_check(&[]);
    assert_eq!((o.status.code(), text(&o.stderr)), (Some(2), "usage: scripts/carry-check NETLIST.json...\n".to_string()));
    let missing = std::env::temp_dir().join("tmc429-carry-check-no-such-file.json");
    let o = carry_check(&[&missing]);
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(text(&o.stderr), format!("carry-check: {}: cannot read: No such file or directory\n", missing.display()));
    let not = file("not", "not.json", "{\"creator\": \"Yosys\"}\n");
    let o = carry_check(&[&not]);
    assert_eq!(o.status.code(), Some(2));
    assert!(text(&o.stderr).starts_with(&format!("carry-check: {}: not a Yosys JSON netlist (expected modules with cells)", not.display())));
    assert!(o.stdout.is_empty());
}
