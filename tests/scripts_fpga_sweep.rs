//! The place-and-route sweeps of `scripts/fpga` and `scripts/rtl-report` (docs/fpga.md,
//! docs/rtl.md). They bound each nextpnr run (`--pnr-timeout`): nextpnr's router does not give up
//! on a placement it cannot route, so a run past its time is stopped, its seed's entry says so,
//! and no bitstream is left behind; those tests synthesize the TMC4210 (Yosys, about 20 s) and
//! give nextpnr one second, far less than its placement takes. `scripts/fpga` goes on after a
//! place and route that fails as after one past its time; with `--until-met` it places the seeds
//! in order and stops at the first placement that meets the CLK; `scripts/rtl-report` ends with
//! the worst path of each placement it lists and its path ends' slack at 48 MHz, whose Fmax is
//! nextpnr's to the SDF's whole picoseconds (one TMC4210 placement, under a minute).

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn scratch(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("tmc429-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn script(name: &str, args: &[&str]) -> Output {
    Command::new(root().join("scripts").join(name)).args(args).output().unwrap()
}

fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

#[test]
fn fpga_stops_a_place_and_route_past_its_time_and_keeps_no_bitstream() {
    let out = scratch("fpga-timeout");
    // a bitstream of an earlier run in the same directory
    std::fs::write(out.join("icebreaker-tmc4210.bin"), b"old").unwrap();
    let o = script("fpga", &["--chip", "tmc4210", "--seeds", "1 2", "--pnr-timeout", "1", "--out", out.to_str().unwrap()]);
    let stdout = text(&o.stdout);
    assert_eq!(o.status.code(), Some(1), "stdout:\n{stdout}\nstderr:\n{}", text(&o.stderr));
    assert!(stdout.contains("1: stopped after 1 s, 2: stopped after 1 s (no placement finished in time)"), "stdout:\n{stdout}");
    assert!(!out.join("icebreaker-tmc4210.bin").exists(), "the earlier bitstream is removed");
    std::fs::remove_dir_all(&out).ok();
}

/// A seed whose place and route ends with an error (here a `nextpnr-ice40` ahead of the real one
/// on PATH that fails seed 1 and runs the real one for the others) is listed as failed, its log
/// named on stderr, and the sweep goes on: seed 2 runs, and is stopped past its one second.
#[test]
fn fpga_goes_on_after_a_place_and_route_that_fails() {
    let out = scratch("fpga-failed");
    let bin = out.join("bin");
    std::fs::create_dir_all(&bin).unwrap();
    let which = Command::new("sh").args(["-c", "command -v nextpnr-ice40"]).output().unwrap();
    let real = text(&which.stdout).trim().to_string();
    assert!(!real.is_empty(), "nextpnr-ice40 is on PATH (scripts/setup)");
    let fake = bin.join("nextpnr-ice40");
    std::fs::write(
        &fake,
        format!("#!/bin/sh\ncase \" $* \" in *\" --seed 1 \"*) echo 'ERROR: not routed' >&2; exit 1 ;; esac\nexec {real} \"$@\"\n"),
    )
    .unwrap();
    use std::os::unix::fs::PermissionsExt;
    std::fs::set_permissions(&fake, std::fs::Permissions::from_mode(0o755)).unwrap();
    let path = format!("{}:{}", bin.display(), std::env::var("PATH").unwrap_or_default());
    let o = Command::new(root().join("scripts/fpga"))
        .args(["--chip", "tmc4210", "--seeds", "1 2", "--pnr-timeout", "1", "--out", out.to_str().unwrap()])
        .env("PATH", path)
        .output()
        .unwrap();
    let (stdout, stderr) = (text(&o.stdout), text(&o.stderr));
    assert_eq!(o.status.code(), Some(1), "stdout:\n{stdout}\nstderr:\n{stderr}");
    assert!(stdout.contains("1: place and route failed, 2: stopped after 1 s (no placement routed)"), "stdout:\n{stdout}");
    let log = out.join("ice40-tmc4210.seed1.log");
    assert!(stderr.contains(&format!("fpga: place and route failed for ice40 tmc4210 seed 1, see {}", log.display())), "stderr:\n{stderr}");
    assert!(!out.join("icebreaker-tmc4210.bin").exists(), "no bitstream without a routed placement");
    std::fs::remove_dir_all(&out).ok();
}

#[test]
fn rtl_report_stops_a_place_and_route_past_its_time() {
    let o = script("rtl-report", &["--flow", "plain", "--chip", "tmc4210", "--seeds", "1", "--pnr-timeout", "1"]);
    let stdout = text(&o.stdout);
    assert_eq!(o.status.code(), Some(1), "stdout:\n{stdout}\nstderr:\n{}", text(&o.stderr));
    assert!(stdout.contains("stopped after 1 s; no placement finished in time"), "stdout:\n{stdout}");
}

#[test]
fn a_timeout_that_is_not_a_number_of_seconds_is_refused() {
    for name in ["fpga", "rtl-report"] {
        for bad in ["0", "10m", ""] {
            let o = script(name, &["--pnr-timeout", bad]);
            assert_eq!(o.status.code(), Some(2), "{name} --pnr-timeout '{bad}'");
            let err = text(&o.stderr);
            assert!(err.contains(&format!("{name}: --pnr-timeout takes a number of seconds above 0, not '{bad}'")), "{name}: {err}");
        }
    }
}

/// The seeds' entries of a result line: "... 32 1: 30.12, 2: 36.16 (best ..." gives
/// [(1, 30.12), (2, 36.16)].
fn seed_entries(line: &str) -> Vec<(u32, f64)> {
    let list = line.split(" (best").next().unwrap();
    list.split(',')
        .filter_map(|e| {
            let mut words = e.split_whitespace().rev();
            let (mhz, seed) = (words.next()?, words.next()?);
            Some((seed.trim_end_matches(':').parse().ok()?, mhz.parse().ok()?))
        })
        .collect()
}

#[test]
fn fpga_until_met_stops_at_the_first_placement_that_meets_the_clk() {
    let out = scratch("fpga-until-met");
    let o = script("fpga", &["--chip", "tmc4210", "--seeds", "1 2 3", "--until-met", "--out", out.to_str().unwrap()]);
    let stdout = text(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "stdout:\n{stdout}\nstderr:\n{}", text(&o.stderr));
    let line = stdout.lines().find(|l| l.contains(" tmc4210 ")).expect("the TMC4210's line");
    let placed = seed_entries(line);
    // the TMC4210's CLK is 32 MHz: every seed placed before the last misses it, the last meets it
    let (last, mhz) = *placed.last().expect("a seed placed");
    assert!(mhz >= 32.0, "{line}");
    assert!(placed[..placed.len() - 1].iter().all(|&(_, m)| m < 32.0), "{line}");
    assert_eq!(placed.iter().map(|&(s, _)| s).collect::<Vec<_>>(), (1..=last).collect::<Vec<_>>(), "{line}");
    assert!(line.contains(&format!("seed {last}: meets 32 MHz")), "{line}");
    assert!(out.join("icebreaker-tmc4210.bin").exists(), "the bitstream of the placement that meets");
    std::fs::remove_dir_all(&out).ok();
}

#[test]
fn rtl_report_prints_the_worst_path_of_each_placement_it_lists() {
    let out = scratch("rtl-report-paths");
    let o = script("rtl-report", &["--flow", "plain", "--chip", "tmc4210", "--seeds", "1", "--out", out.to_str().unwrap()]);
    let stdout = text(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "stdout:\n{stdout}\nstderr:\n{}", text(&o.stderr));
    // the table's line: "plain    TMC4210 ... 1: F; F, F" (one seed: best and worst are it)
    let line = stdout.lines().find(|l| l.starts_with("plain ") && l.contains("TMC4210")).expect("the TMC4210's line");
    let mhz = line.rsplit(", ").next().unwrap().trim();
    let lines: Vec<&str> = stdout.lines().collect();
    let head = lines
        .iter()
        .position(|l| *l == "The worst path of each placement (scripts/pnr-paths on the place-and-route logs, which --out keeps):")
        .expect("the paths' section");
    // the entry of the log the run kept, with the Fmax of the table, and its two registers
    assert!(lines[head + 1].starts_with(&format!("plain-tmc4210.seed1.nextpnr.log: {mhz} MHz; worst path ")), "{stdout}");
    assert!(lines[head + 2].starts_with("  from u_top."), "{stdout}");
    assert!(lines[head + 3].starts_with("  to   u_top."), "{stdout}");
    // then the placement's path ends below zero slack at 48 MHz (scripts/pnr-slack), whose
    // Fmax, computed from the delays nextpnr wrote (whole picoseconds), is nextpnr's within the
    // 0.01 MHz that rounding moves it
    assert_eq!(
        lines[head + 4..head + 7],
        [
            "",
            "Path ends below zero slack at 48 MHz, the chip's 32 MHz with 50 % margin (scripts/pnr-slack on the delays",
            "nextpnr wrote for each placement, which --out keeps: FLOW-CHIP.seedS.sdf and .routed.json), by unit:"
        ],
        "{stdout}"
    );
    let slack = lines[head + 7];
    let computed: f64 = slack
        .strip_prefix("plain-tmc4210.seed1: ")
        .and_then(|r| r.split(" MHz; ").next())
        .and_then(|f| f.parse().ok())
        .expect("the placement's name and Fmax");
    let logged: f64 = mhz.parse().expect("the table's Fmax");
    assert!((computed - logged).abs() < 0.0101, "{computed} against {logged}:\n{stdout}");
    assert!(slack.contains(" path ends below zero slack at 48 MHz ("), "{stdout}");
    // then the netlist's carry cells with one net on both operands: none (docs/rtl.md "Checks")
    assert_eq!(
        lines[head + 8..],
        [
            "",
            "Carry cells with one net on both operands (scripts/carry-check; docs/rtl.md \"Checks\"):",
            "plain-tmc4210.json: carry cells with one net on both operands: 0"
        ],
        "{stdout}"
    );
    for kept in ["plain-tmc4210.seed1.nextpnr.log", "plain-tmc4210.seed1.sdf", "plain-tmc4210.seed1.routed.json"] {
        assert!(out.join(kept).exists(), "{kept}");
    }
    std::fs::remove_dir_all(&out).ok();
}
