//! Bad and hostile input on every path a user reaches, and outputs on a full disk: a clear error
//! naming the file and line (or byte offset) and exit 2, never a crash, a half-written file or
//! lost state. A full disk is a file-size limit (`ulimit -f`, SIGXFSZ ignored): writes past it
//! fail with EFBIG as they would with ENOSPC.

use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

const BIN: &str = env!("CARGO_BIN_EXE_tmc429");

fn tmc429(args: &[&str]) -> Output {
    Command::new(BIN).args(args).stdin(Stdio::null()).output().unwrap()
}

/// `tmc429 ARGS` with files limited to `kib` KiB.
fn tmc429_full_disk(kib: u32, args: &[&str]) -> Output {
    let script = format!("trap '' XFSZ; ulimit -f {kib}; exec \"$0\" \"$@\"");
    Command::new("bash").arg("-c").arg(script).arg(BIN).args(args).stdin(Stdio::null()).output().unwrap()
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

fn tmpdir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("tmc429-robust-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn write(dir: &Path, name: &str, body: impl AsRef<[u8]>) -> String {
    let p = dir.join(name);
    std::fs::write(&p, body).unwrap();
    p.to_string_lossy().into_owned()
}

fn names(d: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(d).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    v.sort();
    v
}

/// Exit 2 and exactly these stderr lines.
fn fails_with(o: &Output, lines: &[&str]) {
    assert_eq!(o.status.code(), Some(2), "{}", stderr(o));
    assert_eq!(stderr(o).lines().collect::<Vec<_>>(), lines);
}

/// 20 000 nested parentheses or 50 000 unary operators: an error, not a stack overflow.
#[test]
fn deep_tmcl_expressions_are_an_error() {
    let d = tmpdir("asm-depth");
    let parens = write(&d, "p.tmc", format!("ROR 0, {}1{}\n", "(".repeat(20_000), ")".repeat(20_000)));
    let minus = write(&d, "m.tmc", format!("STOP\nROR 0, {}1\n", "-~".repeat(25_000)));
    let deep = "expression nested deeper than 64 levels of parentheses and unary operators";
    fails_with(&tmc429(&["tmcl", "asm", &parens]), &[&format!("tmc429: error: {parens}:1: {deep}")]);
    fails_with(&tmc429(&["tmcl", "run", &minus]), &[&format!("tmc429: error: {minus}:2: {deep}")]);
    // 64 levels are fine
    let ok = write(&d, "ok.tmc", format!("ROR 0, {}1{}\n", "(".repeat(63), ")".repeat(63)));
    assert_eq!(tmc429(&["tmcl", "asm", &ok]).status.code(), Some(0));
    std::fs::remove_dir_all(&d).unwrap();
}

/// A store of the program that fails (full disk): exit 2 with the file named, the old image
/// intact, no `.tmp` left; without a file before, none after.
#[test]
fn a_failed_eeprom_store_is_reported_and_loses_nothing() {
    let d = tmpdir("eeprom");
    let eep = d.join("m.eep").to_string_lossy().into_owned();
    let prog = |v: i32| format!("SAP 4, 0, {v}\nSTAP 4, 0\n{}STOP\n", "WAIT TICKS, 0, 1\n".repeat(200));
    let p1 = write(&d, "a.tmc", prog(1234));
    let p2 = write(&d, "b.tmc", prog(1321));
    let failed = format!("tmc429: error: EEPROM store failed: {eep}: File too large (os error 27); the file is unchanged");
    let o = tmc429_full_disk(1, &["tmcl", "run", &p1, "--time", "0.05", "--eeprom", &eep]);
    fails_with(&o, &[&failed]);
    assert_eq!(names(&d), ["a.tmc", "b.tmc"]);
    assert_eq!(tmc429(&["tmcl", "run", &p1, "--time", "0.05", "--eeprom", &eep]).status.code(), Some(0));
    let before = std::fs::read(&eep).unwrap();
    fails_with(&tmc429_full_disk(1, &["tmcl", "run", &p2, "--time", "0.05", "--eeprom", &eep]), &[&failed]);
    assert_eq!(std::fs::read(&eep).unwrap(), before);
    assert_eq!(names(&d), ["a.tmc", "b.tmc", "m.eep"]);
    std::fs::remove_dir_all(&d).unwrap();
}

/// `run --vcd` and `tmcl asm -o` on a full disk: the error names the file, nothing is left.
#[test]
fn outputs_on_a_full_disk_leave_nothing() {
    let d = tmpdir("full");
    let out = d.join("out");
    std::fs::create_dir(&out).unwrap();
    let vcd = out.join("r.vcd").to_string_lossy().into_owned();
    let scenario = format!("{}/examples/scenarios/ramp-move.toml", env!("CARGO_MANIFEST_DIR"));
    let o = tmc429_full_disk(64, &["run", &scenario, "--vcd", &vcd]);
    fails_with(&o, &[&format!("tmc429: error: {vcd}: cannot write: File too large (os error 27)")]);
    let src = write(&d, "big.tmc", (0..1500).map(|i| format!("ROR 0, {i}\n")).collect::<String>());
    let bin = out.join("big.bin").to_string_lossy().into_owned();
    let o = tmc429_full_disk(8, &["tmcl", "asm", &src, "-o", &bin]);
    fails_with(&o, &[&format!("tmc429: error: {bin}: cannot write: File too large (os error 27)")]);
    assert!(names(&out).is_empty(), "{:?}", names(&out));
    std::fs::remove_dir_all(&d).unwrap();
}

/// A set of vectors whose last name is taken by a directory: exit 2 and no file of the set.
#[test]
fn a_vector_set_appears_whole_or_not_at_all() {
    let d = tmpdir("vecset");
    std::fs::create_dir(d.join("chip-chip-hold-tmc429.meta")).unwrap();
    let o = tmc429(&["vectors", "--unit", "chip", "--scenario", "chip-hold", "--out", &d.to_string_lossy()]);
    let meta = d.join("chip-chip-hold-tmc429.meta");
    fails_with(&o, &[&format!("tmc429: error: {}: cannot write: a directory of that name is in the way", meta.display())]);
    assert_eq!(names(&d), ["chip-chip-hold-tmc429.meta"]);
    std::fs::remove_dir_all(&d).unwrap();
}

/// Switch positions are checked against the 32-bit position, never cut to it.
#[test]
fn switch_positions_beyond_32_bits_are_rejected() {
    let d = tmpdir("switch");
    let p = write(&d, "p.tmc", "STOP\n");
    fails_with(
        &tmc429(&["tmcl", "run", &p, "--right-switch", "0=4294967296"]),
        &["tmc429: error: --right-switch 0=4294967296: position 4294967296 out of range -2147483648..2147483647"],
    );
    fails_with(
        &tmc429(&["tmcl", "run", &p, "--home-switch", "1=-2147483649:0"]),
        &["tmc429: error: --home-switch 1=-2147483649:0: position -2147483649 out of range -2147483648..2147483647"],
    );
    fails_with(&tmc429(&["tmcl", "run", &p, "--home-switch", "1=5:4"]), &["tmc429: error: --home-switch 1=5:4: FROM 5 is above TO 4"]);
    fails_with(
        &tmc429(&["tmcl", "run", &p, "--time", "1e300"]),
        &["tmc429: error: --time 1e300: expected 0.001 .. 1.8e16 seconds (the module runs in 1 ms steps)"],
    );
    std::fs::remove_dir_all(&d).unwrap();
}

/// `calc` prints finite numbers only: 0 steps per revolution is an error, a_max = 0 has no
/// braking ramp.
#[test]
fn calc_never_prints_inf_or_nan() {
    let regs = ["calc", "--pulse-div", "0", "--ramp-div", "0", "--v-max", "0", "--a-max", "0"];
    fails_with(
        &tmc429(&[&regs[..], &["--steps-per-rev", "0"]].concat()),
        &["tmc429: error: --steps-per-rev 0: expected at least 1 full step per revolution"],
    );
    let o = tmc429(&regs);
    assert_eq!(o.status.code(), Some(0));
    let out = String::from_utf8(o.stdout).unwrap();
    assert!(!out.contains("NaN") && !out.contains("inf"), "{out}");
    assert!(out.contains("braking       none: a_max = 0 never changes the velocity\n"), "{out}");
}

/// Input that is not UTF-8: the line and byte offset of the first bad byte.
#[test]
fn non_utf8_input_names_line_and_offset() {
    let d = tmpdir("utf8");
    let spi = write(&d, "a.spi", b"0x1A000123\n\xff\n");
    let toml = write(&d, "a.toml", b"duration = \"1 ms\"\nname = \"\xc3\x28\"\n");
    let tmc = write(&d, "a.tmc", b"STOP\nSTOP\nSTOP // \xfe\n");
    let tail = "is not UTF-8 (the file must be UTF-8 text)";
    fails_with(&tmc429(&["spi", &spi]), &[&format!("tmc429: error: {spi}:2: byte offset 11: \\xff {tail}")]);
    fails_with(&tmc429(&["run", &toml]), &[&format!("tmc429: error: {toml}:2: byte offset 26: \\xc3 {tail}")]);
    fails_with(&tmc429(&["tmcl", "asm", &tmc]), &[&format!("tmc429: error: {tmc}:3: byte offset 18: \\xfe {tail}")]);
    let o = Command::new(BIN).args(["spi"]).stdin(std::fs::File::open(&spi).unwrap()).output().unwrap();
    fails_with(&o, &[&format!("tmc429: error: <stdin>:2: byte offset 11: \\xff {tail}")]);
    std::fs::remove_dir_all(&d).unwrap();
}

/// NUL and ESC from the input are escaped; a 100 kB token and a 300-digit number are cut to 40
/// characters and `…`.
#[test]
fn errors_escape_and_shorten_what_they_quote() {
    let d = tmpdir("quote");
    let spi = write(&d, "a.spi", format!("x\x1b[2J\0y\n{}\nbits {} 1\n", "A".repeat(100_000), "9".repeat(300)));
    let o = tmc429(&["spi", &spi]);
    let a40 = "A".repeat(40);
    let n40 = "9".repeat(40);
    fails_with(
        &o,
        &[
            &format!("tmc429: error: {spi}:1: expected a datagram (8 hex digits), 'bits', 'wait' or 'pin', found 'x\\x1b[2J\\0y'"),
            &format!("tmc429: error: {spi}:2: expected a datagram (8 hex digits), 'bits', 'wait' or 'pin', found '{a40}…'"),
            &format!("tmc429: error: {spi}:3: expected a bit count 1..31, found '{n40}…'"),
        ],
    );
    let toml = write(&d, "a.toml", format!("duration = \"1 ms\"\ndriver = \"\\u001b]0;x\\u0007\"\nlut = \"{}\"\n", "s".repeat(5000)));
    let s40 = "s".repeat(40);
    fails_with(
        &tmc429(&["run", &toml]),
        &[
            &format!("tmc429: error: {toml}:2: unknown driver '\\x1b]0;x\\x07': expected one of table-11-2, step-dir, power-on, none"),
            &format!("tmc429: error: {toml}:3: unknown lut '{s40}…': expected sine or none"),
        ],
    );
    let tmc = write(&d, "a.tmc", format!("ROR 0, {}\nMVP\x1b ABS, 0, 1\n", "7".repeat(300)));
    let s40 = "7".repeat(40);
    fails_with(&tmc429(&["tmcl", "asm", &tmc]), &[&format!("tmc429: error: {tmc}:1: '{s40}…' is not a number")]);
    // an include file's name (found by the asm fuzz target: NUL bytes were echoed raw)
    let inc = write(&d, "inc.tmc", "#include \"x\0\x1b.inc\"\n");
    fails_with(
        &tmc429(&["tmcl", "asm", &inc]),
        &[&format!(
            "tmc429: error: {inc}:1: cannot read include file {}/x\\0\\x1b.inc: file name contained an unexpected NUL byte",
            d.display()
        )],
    );
    std::fs::remove_dir_all(&d).unwrap();
}

/// A TOML error without a place of its own (the parser's recursion limit on dotted keys) is
/// reported on the line that nests deepest; a time beyond a 64-bit cycle count is rejected.
#[test]
fn scenario_nesting_and_huge_times() {
    let d = tmpdir("toml");
    let deep = write(&d, "deep.toml", format!("duration = \"1 ms\"\n\n\nx{} = 1\n", ".x".repeat(300)));
    let o = tmc429(&["run", &deep]);
    assert_eq!(o.status.code(), Some(2));
    let e = stderr(&o);
    assert!(e.starts_with(&format!("tmc429: error: {deep}:4: TOML: ")), "{e}");
    assert!(e.trim_end().ends_with("(keys, arrays or inline tables nested too deeply)"), "{e}");
    let huge = write(&d, "huge.toml", "duration = \"1e300 s\"\n");
    fails_with(
        &tmc429(&["run", &huge]),
        &[&format!("tmc429: error: {huge}:1: duration: time \"1e300 s\" is 3.2e307 CLK cycles, more than a 64-bit cycle count holds")],
    );
    std::fs::remove_dir_all(&d).unwrap();
}
