//! `tmc429 spi` and `tmc429 regmap` as a user runs them.

use std::io::Write;
use std::process::{Command, Output, Stdio};

fn tmc429(args: &[&str], stdin: &str) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_tmc429"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    child.stdin.take().unwrap().write_all(stdin.as_bytes()).unwrap();
    child.wait_with_output().unwrap()
}

fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

/// The README's datasheet example: the bundled example script (TMC428 §6.5 / TMC429 §6.2.3 examples).
#[test]
fn bundled_example() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/examples/spi/datasheet.spi");
    let o = tmc429(&["spi", path], "");
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    assert_eq!(text(&o.stdout), "15000000\n15000123\n15000000\n15002321\n15429101\n15\n");
}

#[test]
fn stdin_timestamps_and_decode() {
    let o = tmc429(&["spi", "--timestamps", "--decode", "--chip", "tmc428"], "0x1A000123\n$1B000000 # read back\nwait 10\nbits 4 0x0\n");
    assert_eq!(o.status.code(), Some(0));
    let out = text(&o.stdout);
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(lines.len(), 3);
    // 4 CLK hold + 32 bits × 8 CLK: nSCS_C rises at edge 260; each frame takes 264 edges with
    // its final hold; then 10 waited and 4 + 4 × 8 for the 4-bit frame.
    assert!(lines[0].starts_with("260 15000000  # W dx_ref_tolerance[0] dx_ref_tolerance=291 ($123) | status $15"), "{}", lines[0]);
    assert!(lines[1].starts_with("524 15000123  # R dx_ref_tolerance[0]"), "{}", lines[1]);
    assert!(lines[2].starts_with("574 1  # short frame"), "{}", lines[2]);
}

#[test]
fn script_errors_name_every_line_and_exit_2() {
    let o = tmc429(&["spi"], "0x1A000123\n0x1A00012\nbits 40 1\nwait x\npin REF9=1\npin REF1=2\nfoo\n");
    assert_eq!(o.status.code(), Some(2));
    assert!(o.stdout.is_empty(), "nothing runs before the whole script parses");
    let err = text(&o.stderr);
    for (line, what) in [
        (2, "a datagram has exactly 8 hex digits, found '0x1A00012'"),
        (3, "expected a bit count 1..31, found '40'"),
        (4, "expected a decimal cycle count, found 'x'"),
        (5, "unknown pin 'REF9'"),
        (6, "pin REF1: expected 0 or 1, found '2'"),
        (7, "expected a datagram (8 hex digits), 'bits', 'wait' or 'pin', found 'foo'"),
    ] {
        assert!(err.contains(&format!("tmc429: error: <stdin>:{line}: {what}")), "line {line} missing in:\n{err}");
    }
}

#[test]
fn bad_options_exit_2() {
    let o = tmc429(&["spi", "--sck-half", "2"], "0x1A000123\n");
    assert_eq!(o.status.code(), Some(2));
    assert!(text(&o.stderr).contains("below the minimum of 3 CLK"));
    let o = tmc429(&["spi", "--chip", "tmc999"], "");
    assert_eq!(o.status.code(), Some(2));
    assert!(text(&o.stderr).contains("expected tmc428, tmc429 or tmc4210"));
    let o = tmc429(&["spi", "/nonexistent/script.spi"], "");
    assert_eq!(o.status.code(), Some(2));
    assert!(text(&o.stderr).contains("/nonexistent/script.spi: cannot read"));
    let o = tmc429(&["spi", "--package", "dil20"], "");
    assert_eq!(o.status.code(), Some(2));
    assert!(text(&o.stderr).contains("--package: tmc429 has no dil20 package: expected qfn32 or sop24 or ssop16"), "{}", text(&o.stderr));
    let o = tmc429(&["spi", "--package", "soic8"], "");
    assert_eq!(o.status.code(), Some(2));
    assert!(text(&o.stderr).contains("unknown package 'soic8'"));
}

/// `--package` (C90): REFR3 low with en_refr = 1 reads r3 = 0 on the QFN32 and 1 on the SOP24,
/// whose r3 "always reads as high level (internal pull-ups)" ([429] §8.2.4.5).
#[test]
fn package_option() {
    let script = "pin REFR1=0 REFR2=0 REFR3=0\n0x68000100\n0x7D000000\n";
    for (package, r3) in [("qfn32", "15000000"), ("sop24", "15000010")] {
        let o = tmc429(&["spi", "--package", package], script);
        assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
        assert_eq!(text(&o.stdout).lines().last(), Some(r3), "{package}");
    }
}

/// docs/regmap.md is the generated Markdown, byte for byte.
#[test]
fn regmap_doc_is_generated() {
    let o = tmc429(&["regmap", "--format", "md"], "");
    assert_eq!(o.status.code(), Some(0));
    let doc = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/docs/regmap.md")).unwrap();
    assert!(text(&o.stdout) == doc, "docs/regmap.md is stale: run `tmc429 regmap --format md > docs/regmap.md`");
}

/// rtl/tmc429_regmap.vh is the generated Verilog header, byte for byte, and names the datasheet's
/// values (TMC428 Table 7-2: clk_config is IDX 12; §8.14: pulse_div is bits 15..12).
#[test]
fn regmap_verilog_is_the_rtl_header() {
    let o = tmc429(&["regmap", "--format", "verilog"], "");
    assert!(o.status.success());
    let vh = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/rtl/tmc429_regmap.vh")).unwrap();
    assert!(text(&o.stdout) == vh, "rtl/tmc429_regmap.vh is stale: run `tmc429 regmap --format verilog > rtl/tmc429_regmap.vh`");
    assert!(vh.contains("\n`define TMC429_IDX_CLK_CONFIG 4'd12\n"));
    assert!(vh.contains("\n`define TMC429_F_PULSE_DIV 15:12 "));
}

/// rtl/tmc429_schedule.vh is the generated frame schedule header, byte for byte, with the
/// contract's lanes (C41: motor 1's ramp tick at phase 23, motor 2's commit at 28).
#[test]
fn regmap_verilog_schedule_is_the_rtl_header() {
    let o = tmc429(&["regmap", "--format", "verilog-schedule"], "");
    assert!(o.status.success());
    let vh = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/rtl/tmc429_schedule.vh")).unwrap();
    assert!(
        text(&o.stdout) == vh,
        "rtl/tmc429_schedule.vh is stale: run `tmc429 regmap --format verilog-schedule > rtl/tmc429_schedule.vh`"
    );
    assert!(vh.contains("\n`define TMC429_PH_RAMP(m) ((m) == 0 ? 5'd16 : (m) == 1 ? 5'd23 : 5'd30) "));
    assert!(vh.contains("\n`define TMC429_PH_COMMIT(m) ((m) == 0 ? 5'd14 : (m) == 1 ? 5'd21 : 5'd28) "));
}

#[test]
fn regmap_c_and_json() {
    let c = text(&tmc429(&["regmap", "--format", "c"], "").stdout);
    assert!(c.contains("#define TMC429_A7_TYPE_VERSION 0x39u"));
    assert!(c.contains("#define TMC429_PMUL_PDIV_PMUL_SHIFT 8u"));
    assert!(c.contains("#define TMC429_CURRENT_SCALING_IS_AGTAT_MASK 0x700000ul"));
    let j = text(&tmc429(&["regmap", "--format", "json"], "").stdout);
    assert!(j.contains("{\"name\":\"v_max\",\"lsb\":0,\"width\":11,\"signed\":false,\"access\":\"RW\""));
    assert!(j.trim_start().starts_with('[') && j.trim_end().ends_with(']'));
}

/// `--events`: continuous-update datagrams of the TMC429's power-on chain configuration
/// ($87F87F87F, TMC429 §11.4.2) and INT changes, in cycle order between the frame lines.
#[test]
fn events_in_cycle_order() {
    let script = "0x7E010F02\nwait 25000\n0x16000100\n0x00000005\n0x00000000\n0x16000101\n";
    let o = tmc429(&["spi", "--events", "--timestamps"], script);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let out = text(&o.stdout);
    let lines: Vec<&str> = out.lines().collect();
    // Motor 2's request, then motor 1's 341 ramp ticks later, in its ramp phase 7 cycles earlier
    // (C41, C83): 341 · 32 − 7 = 10905 CLK.
    assert_eq!(&lines[..3], ["260 15000000", "chain 12479 36 87F87F87F", "chain 23384 36 87F87F87F"], "{out}");
    // POS_END unmasked, x_target away and back: INT rises after the frame that returns, and falls
    // after the frame that clears the flag.
    let int_lines: Vec<&str> = lines.iter().copied().filter(|l| l.starts_with("int ")).collect();
    assert_eq!(int_lines.len(), 2, "{out}");
    assert!(int_lines[0].ends_with(" 1") && int_lines[1].ends_with(" 0"), "{out}");
    let cycles: Vec<u64> = lines
        .iter()
        .map(|l| l.split_whitespace().nth(if l.starts_with(char::is_numeric) { 0 } else { 1 }).unwrap().parse().unwrap())
        .collect();
    assert!(cycles.windows(2).all(|w| w[0] <= w[1]), "cycle order: {out}");
}
