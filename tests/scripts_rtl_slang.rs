//! `scripts/rtl-slang`, the elaboration of the RTL by slang (a strict IEEE 1800 front end, from
//! PyPI) with every warning enabled, which `scripts/rtl-check` runs for every variant and package
//! (docs/rtl.md "Checks"): the RTL as it is has none, alone and compiled with the SystemVerilog
//! DPI-C example; a copy of it with one implicit truncation, or with a module without the
//! `timescale the others have (IEEE 1800-2017 §3.14.2.3), fails with the file and line of it;
//! bad arguments exit 2.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn rtl_slang(args: &[&str]) -> Output {
    Command::new(root().join("scripts/rtl-slang")).args(args).output().unwrap()
}

fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

/// A copy of rtl/ in this test's own directory, with `edit` applied to one file's text.
fn rtl_copy(tag: &str, file: &str, edit: impl Fn(&str) -> String) -> PathBuf {
    let d = std::env::temp_dir().join(format!("tmc429-rtl-slang-{tag}-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    for e in std::fs::read_dir(root().join("rtl")).unwrap() {
        let p = e.unwrap().path();
        if matches!(p.extension().and_then(|x| x.to_str()), Some("v" | "vh")) {
            let body = std::fs::read_to_string(&p).unwrap();
            let name = p.file_name().unwrap();
            let body = if name == file { edit(&body) } else { body };
            std::fs::write(d.join(name), body).unwrap();
        }
    }
    d
}

#[test]
fn the_rtl_elaborates_without_a_warning_for_every_variant() {
    for chip in ["0", "1", "2"] {
        let o = rtl_slang(&[chip]);
        assert_eq!(o.status.code(), Some(0), "CHIP={chip}: {}{}", text(&o.stdout), text(&o.stderr));
        assert_eq!(text(&o.stdout), "", "CHIP={chip}");
    }
}

#[test]
fn the_dpi_example_with_the_rtl_elaborates_without_a_warning() {
    let o = rtl_slang(&["--dpi"]);
    assert_eq!(o.status.code(), Some(0), "{}{}", text(&o.stdout), text(&o.stderr));
    assert_eq!(text(&o.stdout), "");
}

#[test]
fn a_module_without_the_timescale_fails_beside_the_timescaled_testbench() {
    let d = rtl_copy("timescale", "tmc429_sync.v", |s| {
        assert!(s.contains("`timescale 1ns / 1ps\n"));
        s.replacen("`timescale 1ns / 1ps\n", "", 1)
    });
    let o = rtl_slang(&["--rtl", d.to_str().unwrap(), "--dpi"]);
    let out = text(&o.stdout);
    assert_eq!(o.status.code(), Some(1), "{out}{}", text(&o.stderr));
    assert!(out.contains("tmc429_sync.v:"), "{out}");
    assert!(out.contains("does not have a time scale defined but others in the design do"), "{out}");
}

#[test]
fn an_implicit_truncation_fails_with_its_file_and_line() {
    let anchor = "    reg [1:0] sel;\n";
    let d = rtl_copy("trunc", "tmc429_current.v", |s| {
        assert!(s.contains(anchor));
        s.replacen(anchor, &format!("{anchor}    wire [3:0] trunc = a_actual;\n"), 1)
    });
    let line =
        std::fs::read_to_string(d.join("tmc429_current.v")).unwrap().lines().position(|l| l.contains("wire [3:0] trunc")).unwrap() + 1;
    let o = rtl_slang(&["--rtl", d.to_str().unwrap(), "1"]);
    let out = text(&o.stdout);
    assert_eq!(o.status.code(), Some(1), "{out}{}", text(&o.stderr));
    assert!(out.contains(&format!("tmc429_current.v:{line}:")), "{out}");
    assert!(out.contains("[-Wwidth-trunc]"), "{out}");
    assert!(out.contains("0 errors, 1 warning"), "{out}");
}

/// The packages the script takes for each variant (its own list, PACKAGES) are the model's
/// (`Package::of`, C90) and 0: a package the model lacks exits 2, one it has elaborates.
#[test]
fn the_packages_taken_are_the_models() {
    use tmc429_model::{Chip, Package};
    for (code, chip) in [(0, Chip::Tmc428), (1, Chip::Tmc429), (2, Chip::Tmc4210)] {
        let has: Vec<u32> = Package::of(chip).iter().map(|p| p.pins()).collect();
        for pins in [0, 16, 20, 24, 32] {
            let o = rtl_slang(&[&code.to_string(), &pins.to_string()]);
            let want = if pins == 0 || has.contains(&pins) { 0 } else { 2 };
            assert_eq!(o.status.code(), Some(want), "CHIP={code} PINS={pins}: {}", text(&o.stderr));
        }
    }
}

#[test]
fn bad_arguments_exit_2_with_the_usage() {
    for args in [&[][..], &["3"], &["x"], &["1", "24", "9"], &["--rtl", "/nonexistent", "1"], &["--dpi", "1"], &["1", "99"], &["2", "24"]] {
        let o = rtl_slang(args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        let err = text(&o.stderr);
        assert!(err.contains("usage: scripts/rtl-slang [--rtl DIR] CHIP [PINS] | --dpi"), "{args:?}: {err}");
    }
}
