//! `tmc429 capture compare` without a chip: captures made from the RTL's own simulation
//! (`tmc429 capture export --engine rtl`), sampled at logic-analyzer rates (24 MHz and 100 MHz)
//! with a random phase, trigger point and jitter, of a 32 MHz and a 16 MHz chip, compare clean;
//! a planted difference (a changed reply bit, a missing step, a different datagram) is found and
//! named; bad captures (truncated, wrong sample rate, missing channels) exit 2 with a clear error.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use tmc429_scenario::capture;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn scratch(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("tmc429-capture-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn tmc429(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_tmc429")).args(args).current_dir(root()).output().unwrap()
}

fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

/// Exports a capture of `scenario`'s pins from the RTL; returns its stdout.
fn export(scenario: &str, out: &Path, rate: &str, seed: u64, plant: Option<&str>) -> String {
    let out_s = out.to_str().unwrap();
    let seed_s = seed.to_string();
    let mut args = vec!["capture", "export", scenario, "-o", out_s, "--rate", rate, "--engine", "rtl", "--seed", &seed_s, "--jitter", "2"];
    if let Some(p) = plant {
        args.extend(["--plant", p]);
    }
    let o = tmc429(&args);
    assert!(o.status.success(), "export failed: {}{}", text(&o.stdout), text(&o.stderr));
    text(&o.stdout)
}

/// `tmc429 capture compare` of a file: (exit code, stdout, stderr).
fn compare(file: &Path, extra: &[&str]) -> (i32, String, String) {
    let mut args = vec!["capture", "compare", file.to_str().unwrap()];
    args.extend(extra);
    let o = tmc429(&args);
    (o.status.code().unwrap_or(-1), text(&o.stdout), text(&o.stderr))
}

/// `name: N compared, N agree` with N > 0.
fn all_agree(report: &str, name: &str) {
    let line = report.lines().find(|l| l.starts_with(&format!("{name}:"))).unwrap_or_else(|| panic!("no '{name}' line:\n{report}"));
    let counts = line.split_once(':').unwrap().1;
    let nums: Vec<u64> = counts.split(|c: char| !c.is_ascii_digit()).filter_map(|t| t.parse().ok()).collect();
    assert!(line.contains("compared") && nums.len() >= 2 && nums[0] > 0 && nums[0] == nums[1], "{line}\n{report}");
}

fn clean(scenario: &str, chip: &str, fclk: &str, rate: &str, seed: u64, streams: &[&str]) {
    let dir = scratch(&format!("clean-{chip}-{rate}-{seed}"));
    let f = dir.join("c.sr");
    export(scenario, &f, rate, seed, None);
    let (code, out, err) = compare(&f, &["--chip", chip, "--fclk", fclk]);
    assert_eq!(code, 0, "{scenario} at {rate}: {out}{err}");
    assert!(out.ends_with("result: the chip agrees with the model\n"), "{out}");
    for s in ["µC frames", "status bytes", "read data"].iter().chain(streams) {
        all_agree(&out, s);
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_32_mhz_chain_at_24_mhz_compares_clean() {
    clean("examples/scenarios/demo.toml", "tmc429", "32MHz", "24MHz", 11, &["chain datagrams", "nINT edges"]);
}

#[test]
fn a_32_mhz_chain_at_100_mhz_compares_clean() {
    clean("examples/scenarios/demo.toml", "tmc429", "32MHz", "100MHz", 12, &["chain datagrams", "nINT edges"]);
}

#[test]
fn a_16_mhz_step_dir_chip_at_24_and_100_mhz_compares_clean() {
    let steps = ["steps motor 0", "steps motor 1", "steps motor 2", "nINT edges"];
    clean("examples/scenarios/bench-stepdir.toml", "tmc429", "16MHz", "24MHz", 13, &steps);
    clean("examples/scenarios/bench-stepdir.toml", "tmc429", "16MHz", "100MHz", 14, &steps);
}

#[test]
fn a_16_mhz_tmc428_chain_with_readback_at_24_and_100_mhz_compares_clean() {
    clean("examples/scenarios/bench-chain.toml", "tmc428", "16MHz", "24MHz", 15, &["chain datagrams"]);
    clean("examples/scenarios/bench-chain.toml", "tmc428", "16MHz", "100MHz", 16, &["chain datagrams"]);
}

/// The number after `word` in `s` (`frame 77` → 77).
fn number_after(s: &str, word: &str) -> u64 {
    let rest = &s[s.find(word).unwrap_or_else(|| panic!("'{word}' not in: {s}")) + word.len()..];
    rest.trim_start().split(|c: char| !c.is_ascii_digit()).next().unwrap().parse().unwrap()
}

/// Exports with a planted difference and compares: exactly one difference, the one planted.
fn planted(scenario: &str, chip: &str, fclk: &str, rate: &str, plant: &str) -> (String, String) {
    let dir = scratch(&format!("plant-{plant}"));
    let f = dir.join("p.sr");
    let out = export(scenario, &f, rate, 21, Some(plant));
    let line = out.lines().find(|l| l.starts_with("planted: ")).unwrap_or_else(|| panic!("no 'planted:' line: {out}")).to_string();
    let (code, report, err) = compare(&f, &["--chip", chip, "--fclk", fclk]);
    assert_eq!(code, 1, "{line}\n{report}{err}");
    assert!(report.ends_with("result: 1 difference\n"), "{line}\n{report}");
    let diff = report.lines().find(|l| l.starts_with("difference 1 at ")).unwrap().to_string();
    std::fs::remove_dir_all(&dir).unwrap();
    (line, diff)
}

#[test]
fn a_changed_reply_bit_is_found_and_named() {
    let (p, d) = planted("examples/scenarios/demo.toml", "tmc429", "32MHz", "24MHz", "reply-bit");
    let frame = number_after(&p, "µC frame");
    assert!(p.starts_with(&format!("planted: reply bit 0 of µC frame {frame} flipped at ")), "{p}");
    assert!(d.contains(&format!("µC frame {frame} (R ")), "{p}\n{d}");
    assert!(d.contains("reply bit 0 (x_actual bit 0) is "), "{p}\n{d}");
}

#[test]
fn a_missing_step_is_found_and_named() {
    let (p, d) = planted("examples/scenarios/bench-stepdir.toml", "tmc429", "16MHz", "24MHz", "missing-step");
    let step = number_after(&p, "step");
    assert!(p.starts_with(&format!("planted: step {step} of motor 0 removed at ")), "{p}");
    assert!(d.contains(&format!("motor 0 step {step} (")) && d.ends_with("): in the model, missing on the chip"), "{p}\n{d}");
}

#[test]
fn a_different_datagram_is_found_and_named() {
    let (p, d) = planted("examples/scenarios/bench-chain.toml", "tmc428", "16MHz", "100MHz", "datagram");
    let k = number_after(&p, "chain datagram");
    assert!(p.starts_with(&format!("planted: position 5 of chain datagram {k} flipped at ")), "{p}");
    assert!(d.contains(&format!("chain datagram {k}: position 5 differs: chip 36 bits $")), "{p}\n{d}");
}

/// A clean capture of the Step/Dir bench scenario from the golden model, as a library value.
fn model_capture(dir: &Path) -> (PathBuf, capture::Capture) {
    let f = dir.join("m.sr");
    let o = tmc429(&[
        "capture",
        "export",
        "examples/scenarios/bench-stepdir.toml",
        "-o",
        f.to_str().unwrap(),
        "--rate",
        "24MHz",
        "--seed",
        "3",
    ]);
    assert!(o.status.success(), "{}", text(&o.stderr));
    let cap = capture::read(&f).unwrap();
    (f, cap)
}

fn expect_error(file: &Path, extra: &[&str], want: &str) {
    let (code, out, err) = compare(file, extra);
    assert_eq!(code, 2, "{out}{err}");
    assert!(out.is_empty(), "a bad capture prints no report: {out}");
    assert!(err.starts_with(&format!("tmc429: error: {}: ", file.display())) && err.contains(want), "expected '{want}' in:\n{err}");
}

#[test]
fn truncated_captures_exit_2() {
    let dir = scratch("truncated");
    let (f, _) = model_capture(&dir);
    let bytes = std::fs::read(&f).unwrap();
    let half = dir.join("half.sr");
    std::fs::write(&half, &bytes[..bytes.len() / 2]).unwrap();
    expect_error(&half, &["--fclk", "16MHz"], "not a readable sigrok session file (a zip archive)");
    // a VCD cut in the middle of a line, and one cut at a line inside a µC frame
    let v = dir.join("m.vcd");
    let o = tmc429(&["capture", "export", "examples/scenarios/bench-stepdir.toml", "-o", v.to_str().unwrap(), "--rate", "100MHz"]);
    assert!(o.status.success());
    let vcd = std::fs::read_to_string(&v).unwrap();
    let cut = dir.join("cut.vcd");
    let mid = vcd.len() / 2;
    let mid = (mid..vcd.len()).find(|&i| vcd.as_bytes()[i - 1] != b'\n' && vcd.is_char_boundary(i)).unwrap();
    std::fs::write(&cut, &vcd[..mid]).unwrap();
    expect_error(&cut, &["--fclk", "16MHz"], "the last line is incomplete: the VCD is truncated");
    // nSCS_C is the first channel (`!`): cut after it falls for the third time
    let lines: Vec<&str> = vcd.lines().collect();
    let falls: Vec<usize> = (0..lines.len()).filter(|&i| lines[i] == "0!" && i > 30).collect();
    let inside = dir.join("inside.vcd");
    std::fs::write(&inside, lines[..falls[2] + 3].join("\n") + "\n").unwrap();
    expect_error(&inside, &["--fclk", "16MHz"], "the capture ends inside a µC frame (nSCS_C low since ");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_wrong_sample_rate_or_fclk_exits_2() {
    let dir = scratch("rate");
    let (_, cap) = model_capture(&dir);
    for (factor, want) in [
        (10.0, "below the 3 CLK of TMC428 Table 6-1: is the sample rate (240 MHz) or --fclk (16 MHz) wrong?"),
        (0.1, "times as long as the model's: is the sample rate (2.4 MHz) or --fclk (16 MHz) wrong?"),
    ] {
        let mut c = cap.clone();
        c.samplerate = (c.samplerate as f64 * factor) as u64;
        let f = dir.join(format!("x{factor}.sr"));
        capture::write(&f, &c).unwrap();
        expect_error(&f, &["--fclk", "16MHz"], want);
    }
    let f = dir.join("x1.sr");
    capture::write(&f, &cap).unwrap();
    expect_error(&f, &["--fclk", "4MHz"], "is the sample rate (24 MHz) or --fclk (4 MHz) wrong?");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn missing_channels_exit_2_and_the_pin_map_finds_them() {
    let dir = scratch("channels");
    let (_, cap) = model_capture(&dir);
    let mut c = cap.clone();
    for (k, ch) in c.channels.iter_mut().enumerate() {
        ch.name = format!("D{k}");
    }
    let f = dir.join("renamed.sr");
    capture::write(&f, &c).unwrap();
    expect_error(
        &f,
        &["--fclk", "16MHz"],
        "no channel for nSCS_C, SCK_C, SDI_C, nINT_SDO_C or SDOZ_C: a comparison needs the µC's bus (channels: D0, D1, D2",
    );
    let map: Vec<String> = cap.channels.iter().enumerate().map(|(k, ch)| format!("{}=D{k}", ch.name)).collect();
    let (code, out, err) = compare(&f, &["--fclk", "16MHz", "--pin", &map.join(",")]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(out.contains("pins: nSCS_C=D0 SCK_C=D1 SDI_C=D2 "), "{out}");
    expect_error(&f, &["--fclk", "16MHz", "--pin", "SCK_C=D99"], "--pin SCK_C=D99: the capture has no channel 'D99'");
    let mut c = cap.clone();
    c.channels.retain(|ch| ch.name != "SDI_C");
    let f = dir.join("no-sdi.sr");
    capture::write(&f, &c).unwrap();
    expect_error(&f, &["--fclk", "16MHz"], "no channel for SDI_C:");
    std::fs::remove_dir_all(&dir).unwrap();
}
