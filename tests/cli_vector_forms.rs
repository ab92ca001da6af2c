//! `tmc429 vectors --format stil|evcd|vcd`: the chip-level vectors in the forms testers and
//! simulators read, checked with readers written elsewhere (docs/vectors.md, "Tester forms"):
//! every chip-level set of vectors/golden/SETS is written as STIL, parsed by Semi_ATE.STIL's
//! dump compiler (PyPI) and compared vector by vector with the pin-level form of the same set
//! (tests/formats/stil_roundtrip.py); its EVCD is converted by GTKWave's evcd2vcd and the
//! result equals its pin VCD (tests/formats/evcd_equal.py). scripts/setup installs both readers.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn tmpdir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("tmc429-forms-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn run(c: &mut Command) -> Output {
    c.output().unwrap_or_else(|e| panic!("{c:?}: {e} (scripts/setup installs it)"))
}

fn export(dir: &Path, scenario: &str, chip: &str, format: &str) -> PathBuf {
    let o = run(Command::new(env!("CARGO_BIN_EXE_tmc429"))
        .args(["vectors", "--unit", "chip", "--scenario", scenario, "--chip", chip, "--format", format, "--out"])
        .arg(dir));
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    // the first file it names: the .stil, .evcd, .vcd or .hex
    let f = PathBuf::from(String::from_utf8(o.stdout).unwrap().lines().next().unwrap());
    assert!(f.is_file(), "{}", f.display());
    f
}

/// The chip-level sets of vectors/golden/SETS: (scenario, chip).
fn chip_sets() -> Vec<(String, String)> {
    let text = std::fs::read_to_string(root().join("vectors/golden/SETS")).unwrap();
    let sets: Vec<(String, String)> = text
        .lines()
        .map(|l| l.split_whitespace().collect::<Vec<_>>())
        .filter(|w| w.first() == Some(&"chip"))
        .map(|w| (w[1].to_string(), w[2].to_string()))
        .collect();
    assert!(!sets.is_empty(), "SETS lists chip-level sets");
    sets
}

fn python(script: &str, args: &[&Path]) -> Output {
    run(Command::new("python3").arg(root().join("tests/formats").join(script)).args(args))
}

fn evcd2vcd(evcd: &Path, out: &Path) {
    let o = run(Command::new("evcd2vcd").arg(evcd));
    assert!(o.status.success(), "evcd2vcd {}: {}", evcd.display(), String::from_utf8_lossy(&o.stderr));
    std::fs::write(out, o.stdout).unwrap();
}

/// Runs `f` on every chip-level set, two at a time.
fn each_set(tag: &str, f: impl Fn(&Path, &str, &str) + Sync) {
    let sets = chip_sets();
    let dir = tmpdir(tag);
    std::thread::scope(|s| {
        for half in sets.chunks(sets.len().div_ceil(2)) {
            let (f, dir) = (&f, &dir);
            s.spawn(move || {
                for (scenario, chip) in half {
                    let d = dir.join(format!("{scenario}-{chip}"));
                    std::fs::create_dir_all(&d).unwrap();
                    f(&d, scenario, chip);
                }
            });
        }
    });
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn stil_of_every_chip_set_parses_and_round_trips() {
    each_set("stil", |d, scenario, chip| {
        let stil = export(d, scenario, chip, "stil");
        let hex = export(d, scenario, chip, "pins");
        let o = python("stil_roundtrip.py", &[&stil, &hex.with_extension("")]);
        assert!(o.status.success(), "{scenario} {chip}: {}{}", String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr));
        let cycles = std::fs::read_to_string(hex.with_extension("meta"))
            .unwrap()
            .lines()
            .find_map(|l| l.strip_prefix("cycles ").map(str::to_string))
            .unwrap();
        assert!(
            String::from_utf8_lossy(&o.stdout).contains(&format!(": {cycles} vectors equal")),
            "{}",
            String::from_utf8_lossy(&o.stdout)
        );
    });
}

#[test]
fn evcd_of_every_chip_set_converts_to_the_pin_vcd() {
    each_set("evcd", |d, scenario, chip| {
        let evcd = export(d, scenario, chip, "evcd");
        let vcd = export(d, scenario, chip, "vcd");
        let conv = d.join("converted.vcd");
        evcd2vcd(&evcd, &conv);
        let o = python("evcd_equal.py", &[&conv, &vcd]);
        assert!(o.status.success(), "{scenario} {chip}: {}{}", String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr));
    });
}

/// The checkers fail on a changed vector, a changed pin level and a changed timing.
#[test]
fn the_checkers_find_a_difference() {
    let d = tmpdir("negative");
    let stil = export(&d, "datasheet", "tmc429", "stil");
    let stem = export(&d, "datasheet", "tmc429", "pins").with_extension("");
    let text = std::fs::read_to_string(&stil).unwrap();
    // vector 0 is the reset edge: POSCMP is 1 after it on the TMC429 (C2), its last character
    let v0 = text.find("    V { all = ").unwrap();
    let end = v0 + text[v0..].find(';').unwrap();
    assert_eq!(&text[end - 1..end], "H", "{}", &text[v0..end]);
    for (what, bad) in [
        ("vector", format!("{}L{}", &text[..end - 1], &text[end..])),
        ("timing", text.replacen("'15.625ns' U", "'15ns' U", 1)),
        ("pattern", text.replacen("    V { all = ", "", 1)),
    ] {
        assert_ne!(bad, text, "{what}");
        let f = d.join(format!("bad-{what}.stil"));
        std::fs::write(&f, bad).unwrap();
        let o = python("stil_roundtrip.py", &[&f, &stem]);
        assert_eq!(o.status.code(), Some(1), "{what}: {}", String::from_utf8_lossy(&o.stdout));
    }
    let evcd = export(&d, "datasheet", "tmc429", "evcd");
    let vcd = export(&d, "datasheet", "tmc429", "vcd");
    let conv = d.join("converted.vcd");
    evcd2vcd(&evcd, &conv);
    let text = std::fs::read_to_string(&vcd).unwrap();
    let last = text.rfind("\n#").unwrap();
    let bad = d.join("bad.vcd");
    // the dump ends with CLK falling at n·T: move it one picosecond
    let t: u64 = text[last + 2..].lines().next().unwrap().parse().unwrap();
    std::fs::write(&bad, format!("{}\n#{}{}", &text[..last], t + 1, &text[last + 2 + t.to_string().len()..])).unwrap();
    let o = python("evcd_equal.py", &[&conv, &bad]);
    assert_eq!(o.status.code(), Some(1), "{}", String::from_utf8_lossy(&o.stdout));
    std::fs::remove_dir_all(&d).ok();
}

/// The header states the timing of the set's fclk (each variant's default, docs/vectors.md):
/// 31.25 ns at 32 MHz (TMC429), 62.5 ns at 16 MHz (TMC428); CLK rises at the half period,
/// outputs are strobed at 7/8 of it.
#[test]
fn stil_timing_follows_fclk() {
    let d = tmpdir("timing");
    let s429 = std::fs::read_to_string(export(&d, "datasheet", "tmc429", "stil")).unwrap();
    assert!(s429.contains("Period '31.25ns';"), "{s429}");
    assert!(s429.contains("clk { P { '0ns' D; '15.625ns' U; } }"), "{s429}");
    assert!(s429.contains("outputs { LHX { '27.343ns' L/H/X; } }"), "{s429}");
    let s428 = std::fs::read_to_string(export(&d, "registers", "tmc428", "stil")).unwrap();
    assert!(s428.contains("Period '62.5ns';"), "{s428}");
    assert!(s428.contains("clk { P { '0ns' D; '31.25ns' U; } }"), "{s428}");
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn tester_forms_are_of_the_chip_only() {
    let d = tmpdir("usage");
    for unit in ["spi", "ramp", "chain"] {
        let o = run(Command::new(env!("CARGO_BIN_EXE_tmc429"))
            .args(["vectors", "--unit", unit, "--scenario", "datasheet", "--format", "stil", "--out"])
            .arg(&d));
        assert_eq!(o.status.code(), Some(2), "{unit}");
        let e = String::from_utf8_lossy(&o.stderr);
        assert!(e.contains("STIL, EVCD and pin VCD are forms of the chip's pins: use --unit chip"), "{e}");
    }
    assert_eq!(std::fs::read_dir(&d).unwrap().count(), 0, "no file left behind");
    std::fs::remove_dir_all(&d).ok();
}
