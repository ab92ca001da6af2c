//! `scripts/motor-check`, the check of iCE40 netlists that `scripts/rtl-check` runs on both flows
//! of every variant: the motors a variant lacks (the TMC4210's 1 and 2) have no flip-flop, and
//! every motor it has has some (docs/rtl.md "Checks"). The netlists here are Yosys JSON written by
//! hand in the shape `synth_ice40 -json` writes, flip-flops named by the nets they drive as
//! there: the TMC4210 netlist of the build before the check has 196 flip-flops on nets of motors
//! 1 and 2.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn motor_check(args: &[&str]) -> Output {
    Command::new(root().join("scripts/motor-check")).args(args).output().unwrap()
}

fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

/// A scratch file `name` with `body` in this test's own directory.
fn file(tag: &str, name: &str, body: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("tmc429-motor-check-{tag}-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    let p = d.join(name);
    std::fs::write(&p, body).unwrap();
    p
}

/// A netlist of one module whose flip-flops (cell type, the name of the net their Q drives) are
/// given; a LUT drives a net of motor 2 as well (not a flip-flop: not counted).
fn netlist(ffs: &[(&str, &str)]) -> String {
    let mut names = vec![r#""u_top.mot[2].u_m.u_ramp.xeqt": {"bits": [99]}"#.to_string()];
    let mut cells = vec![r#""lut": {"type": "SB_LUT4", "connections": {"I0": ["0"], "O": [99]}}"#.to_string()];
    for (i, (ty, net)) in ffs.iter().enumerate() {
        let bit = 10 + i;
        names.push(format!(r#""{net}": {{"bits": [{bit}]}}"#));
        cells.push(format!(r#""ff{i}": {{"type": "{ty}", "connections": {{"C": [2], "D": ["0"], "Q": [{bit}]}}}}"#));
    }
    format!(
        r#"{{"creator": "Yosys", "modules": {{"tmc429_chip": {{"netnames": {{{}}}, "cells": {{{}}}}}}}}}"#,
        names.join(", "),
        cells.join(", ")
    )
}

const M0: (&str, &str) = ("SB_DFFESR", "u_top.mot[0].u_m.u_ramp.x_actual");
const SD0: (&str, &str) = ("SB_DFFSR", "u_top.g_sd[0].g_on.u_sd.backlog");
const M1: (&str, &str) = ("SB_DFFESR", "u_top.mot[1].u_m.u_ramp.x_actual");
const CUR2: (&str, &str) = ("SB_DFFER", "u_top.u_cur2.v0_count");
const SHARED: (&str, &str) = ("SB_DFF", "u_top.u_vt.a_dx");

#[test]
fn a_flip_flop_of_a_motor_the_variant_lacks_fails() {
    let p = file("lacks", "tmc4210.json", &netlist(&[M0, SD0, M1, CUR2, SHARED]));
    let o = motor_check(&["--motors", "1", p.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(1), "stderr: {}", text(&o.stderr));
    assert_eq!(
        text(&o.stdout),
        format!(
            "{}: flip-flops of motors 0, 1, 2: 2, 1, 1\n  \
             motor 1: 1, but the variant has 1 motor(s): its registers were not removed\n  \
             motor 2: 1, but the variant has 1 motor(s): its registers were not removed\n",
            p.display()
        )
    );
}

#[test]
fn the_motors_a_variant_has_each_with_flip_flops_pass() {
    let one = file("pass", "tmc4210.json", &netlist(&[M0, SD0, SHARED]));
    let three = file("pass", "tmc429.json", &netlist(&[M0, M1, CUR2]));
    let o = motor_check(&["--motors", "1", one.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "stderr: {}", text(&o.stderr));
    assert_eq!(text(&o.stdout), format!("{}: flip-flops of motors 0, 1, 2: 2, 0, 0\n", one.display()));
    let o = motor_check(&["--motors", "3", three.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "stderr: {}", text(&o.stderr));
    assert_eq!(text(&o.stdout), format!("{}: flip-flops of motors 0, 1, 2: 1, 1, 1\n", three.display()));
}

#[test]
fn a_motor_the_variant_has_without_a_flip_flop_fails_as_renamed_instances() {
    let p = file("renamed", "tmc429.json", &netlist(&[M0, M1, SHARED]));
    let o = motor_check(&["--motors", "3", p.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(1));
    assert_eq!(
        text(&o.stdout),
        format!(
            "{}: flip-flops of motors 0, 1, 2: 1, 1, 0\n  \
             motor 2: none, but the variant has 3 motor(s): are the instance names those of rtl/tmc429_top.v?\n",
            p.display()
        )
    );
}

#[test]
fn a_bad_argument_an_unreadable_file_or_not_a_netlist_exits_2() {
    let usage = "usage: scripts/motor-check --motors N NETLIST.json...   (N = 1, 2 or 3)\n";
    let p = file("args", "a.json", &netlist(&[M0]));
    for args in [vec![], vec!["--motors", "1"], vec!["--motors", "4", p.to_str().unwrap()], vec![p.to_str().unwrap()]] {
        let o = motor_check(&args);
        assert_eq!((o.status.code(), text(&o.stderr)), (Some(2), usage.to_string()), "{args:?}");
    }
    let missing = std::env::temp_dir().join("tmc429-motor-check-no-such-file.json");
    let o = motor_check(&["--motors", "1", missing.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(text(&o.stderr), format!("motor-check: {}: cannot read: No such file or directory\n", missing.display()));
    let not = file("not", "not.json", "{\"creator\": \"Yosys\"}\n");
    let o = motor_check(&["--motors", "1", not.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    assert!(text(&o.stderr).starts_with(&format!("motor-check: {}: not a Yosys JSON netlist (expected modules with cells)", not.display())));
    assert!(o.stdout.is_empty());
}
