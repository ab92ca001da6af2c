//! `tmc429 vectors`: exported files, exact values from the datasheets and the contract, replay on
//! the RTL under Icarus Verilog (clean, planted bug, corrupt files), usage errors.

use std::path::{Path, PathBuf};
use std::process::Command;

fn tmc429() -> Command {
    Command::new(env!("CARGO_BIN_EXE_tmc429"))
}

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn tmpdir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("tmc429-vectors-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn export(dir: &Path, args: &[&str]) -> String {
    let out = tmc429().args(["vectors", "--out"]).arg(dir).args(args).output().unwrap();
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    String::from_utf8(out.stdout).unwrap()
}

fn csv(path: &Path) -> Vec<Vec<String>> {
    let text = std::fs::read_to_string(path).unwrap();
    text.lines().skip(1).map(|l| split_csv(l)).collect()
}

fn split_csv(l: &str) -> Vec<String> {
    let mut out = vec![String::new()];
    let mut quoted = false;
    for c in l.chars() {
        match c {
            '"' => quoted = !quoted,
            ',' if !quoted => out.push(String::new()),
            _ => out.last_mut().unwrap().push(c),
        }
    }
    out
}

/// Builds tb_chip (CHIP = 1) with Icarus, optionally with a define; returns the vvp file.
fn build_chip_tb(dir: &Path, define: Option<&str>) -> PathBuf {
    let vvp = dir.join(format!("tb_chip{}.vvp", define.map(|d| format!("_{d}")).unwrap_or_default()));
    let mut c = Command::new("iverilog");
    c.args(["-g2005", "-P", "tb_chip.CHIP=1", "-I"]).arg(root().join("vectors/tb")).arg("-o").arg(&vvp);
    if let Some(d) = define {
        c.arg(format!("-D{d}"));
    }
    c.arg(root().join("vectors/tb/tb_chip.v"));
    let mut rtl: Vec<PathBuf> = std::fs::read_dir(root().join("rtl"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "v"))
        .collect();
    rtl.sort();
    c.args(&rtl);
    let o = c.output().expect("iverilog (scripts/setup installs it)");
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    vvp
}

fn replay(vvp: &Path, stem: &Path, hex: Option<&Path>) -> Vec<String> {
    let hex = hex.map(Path::to_path_buf).unwrap_or_else(|| stem.with_extension("hex"));
    let o = Command::new("vvp")
        .arg("-n")
        .arg(vvp)
        .arg(format!("+hex={}", hex.display()))
        .arg(format!("+cols={}", stem.with_extension("cols").display()))
        .arg(format!("+meta={}", stem.with_extension("meta").display()))
        .output()
        .unwrap();
    String::from_utf8(o.stdout).unwrap().lines().map(str::to_string).collect()
}

fn meta(stem: &Path, key: &str) -> String {
    let t = std::fs::read_to_string(stem.with_extension("meta")).unwrap();
    t.lines()
        .find_map(|l| l.strip_prefix(&format!("{key} ")).map(str::to_string))
        .unwrap_or_else(|| panic!("no {key} in .meta"))
}

/// The chip-hold vectors replay clean; with PLANT_BUG_STATUS (CDGW ignores the datagram-word
/// flag) the first mismatch is the status byte's bit 30 on the data pins, in the 8-bit status
/// frame after the datagram_low_word write: frame start + setup (3) + bit 0 (2·3) = SCK_C falls
/// for bit 1, acted on 2 edges later (C4, C11).
#[test]
fn planted_bug_fails_at_the_right_cycle_and_column() {
    let dir = tmpdir("bug");
    export(&dir, &["--unit", "chip", "--scenario", "chip-hold"]);
    export(&dir, &["--unit", "spi", "--scenario", "chip-hold", "--format", "csv"]);
    let stem = dir.join("chip-chip-hold-tmc429");
    let cycles: u64 = meta(&stem, "cycles").parse().unwrap();

    let clean = build_chip_tb(&dir, None);
    let out = replay(&clean, &stem, None);
    assert_eq!(out.last().unwrap(), &format!("{cycles} passed, 0 failed"), "{out:?}");

    // the status frame after the datagram_low_word write
    let rows = csv(&dir.join("spi-chip-hold-tmc429.csv"));
    let w = rows.iter().position(|r| r[6] == "datagram_low_word" && r[5] == "write").unwrap();
    let st = &rows[w + 1];
    assert_eq!((st[5].as_str(), st[4].as_str()), ("short", "55"), "CDGW set in the model: {st:?}");
    let start: u64 = st[0].parse().unwrap();
    let expected = start + 3 + 2 * 3 + 2;

    let bug = build_chip_tb(&dir, Some("PLANT_BUG_STATUS"));
    let out = replay(&bug, &stem, None);
    let first: Vec<&String> = out.iter().filter(|l| l.starts_with("MISMATCH")).take(2).collect();
    assert_eq!(
        first,
        [
            &format!("MISMATCH cycle {expected} column nint_sdo_c: expected 1 got 0"),
            &format!("MISMATCH cycle {expected} column sdoz_c: expected 1 got 0"),
        ]
    );
    let last = out.last().unwrap();
    assert!(last.ends_with(" failed") && !last.ends_with(" 0 failed"), "{last}");
    std::fs::remove_dir_all(&dir).ok();
}

/// A truncated line, a line of the wrong width, a changed digit and a missing line are reported
/// as corrupt, never replayed as a pass.
#[test]
fn corrupt_vector_files_are_reported() {
    let dir = tmpdir("corrupt");
    export(&dir, &["--unit", "chip", "--scenario", "datasheet"]);
    let stem = dir.join("chip-datasheet-tmc429");
    let cycles: u64 = meta(&stem, "cycles").parse().unwrap();
    let good = std::fs::read_to_string(stem.with_extension("hex")).unwrap();
    let lines: Vec<&str> = good.lines().collect();
    assert_eq!(lines.len() as u64, cycles);
    assert!(lines.iter().all(|l| l.len() == 8 && l.starts_with('A')));
    let vvp = build_chip_tb(&dir, None);
    let write = |name: &str, f: &dyn Fn(&mut Vec<String>)| {
        let mut v: Vec<String> = lines.iter().map(|s| s.to_string()).collect();
        f(&mut v);
        let p = dir.join(name);
        std::fs::write(&p, v.join("\n") + "\n").unwrap();
        p
    };
    let cases: [(&str, &dyn Fn(&mut Vec<String>), String); 4] = [
        ("trunc.hex", &|v| { v[99].pop(); }, "line 100: 7 characters, expected 8 hex digits".into()),
        ("wide.hex", &|v| v[9].push('0'), "line 10: 9 characters, expected 8 hex digits".into()),
        ("digit.hex", &|v| {
            let d = if &v[499][3..4] == "0" { "1" } else { "0" };
            v[499].replace_range(3..4, d)
        }, "line 500: check digit wrong".into()),
        ("short.hex", &|v| { v.pop(); }, format!("has {} lines", cycles - 1)),
    ];
    for (name, f, msg) in cases {
        let p = write(name, f);
        let out = replay(&vvp, &stem, Some(&p));
        assert!(out.iter().any(|l| l.starts_with("CORRUPT") && l.contains(&msg)), "{name}: {out:?}");
        assert_eq!(out.last().unwrap(), &format!("0 passed, {cycles} failed"), "{name}");
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// [428] §6.5 examples (errata E1, E2: INT clear, the 32-bit RAM datagram) in spi.csv.
#[test]
fn spi_csv_has_the_datasheet_examples() {
    let dir = tmpdir("spi");
    export(&dir, &["--unit", "spi", "--scenario", "datasheet", "--format", "csv"]);
    let rows = csv(&dir.join("spi-datasheet-tmc429.csv"));
    let got: Vec<(&str, &str, &str, &str)> =
        rows.iter().map(|r| (r[3].as_str(), r[4].as_str(), r[5].as_str(), r[6].as_str())).collect();
    assert_eq!(
        got,
        [
            ("1A000123", "15000000", "write", "dx_ref_tolerance[0]"),
            ("1B000000", "15000123", "read", "dx_ref_tolerance[0]"),
            ("FE002321", "15000000", "write", "ram[63]"),
            ("FF000000", "15002321", "read", "ram[63]"),
            ("00", "15", "short", ""),
            ("73000000", "15429101", "read", "type_version"),
        ]
    );
    // a 32-bit frame at SCK_C half period 3: 3 + 64·3 + 3 cycles from first to last edge
    assert_eq!((rows[0][0].as_str(), rows[0][1].as_str(), rows[0][2].as_str()), ("1", "196", "32"));
    assert_eq!(rows[2][7], "cell127=35 cell126=33");
    std::fs::remove_dir_all(&dir).ok();
}

/// Digest §5.2: the datagrams of the Table 11-2 configuration with the Table 12-2 LUT, and the
/// cover example, with the decoded signals of each motor.
#[test]
fn chain_csv_has_the_table_11_2_datagrams_and_the_cover() {
    let dir = tmpdir("chain");
    export(&dir, &["--unit", "chain", "--scenario", "chain-datasheet"]);
    let rows = csv(&dir.join("chain-chain-datasheet-tmc429.csv"));
    let bits: Vec<(&str, &str)> = rows.iter().map(|r| (r[2].as_str(), r[3].as_str())).collect();
    assert_eq!(
        bits,
        [("36", "05F05F07F"), ("36", "35D35D37D"), ("36", "1CF1CF1EF"), ("36", "55805F07F"), ("36", "ABC05F07F")]
    );
    // w = 16: DAC_A = sin LUT[16] = 24, DAC_B = LUT[48] = 59 (Table 12-2); i_scale %100 halves them
    assert_eq!(&rows[1][6..12], ["24", "1", "0", "59", "1", "1"]);
    assert_eq!(&rows[2][6..12], ["12", "1", "0", "29", "1", "1"]);
    // every datagram carried three motors (LSMD = 2); the cover datagram is flagged
    assert!(rows.iter().all(|r| r[5] == "3" && r[4] == "1"));
    // the cycle of the end is after the start: 36 bits, SCK_S period 16 CLK at clk2_div 7
    let (s, e): (u64, u64) = (rows[0][0].parse().unwrap(), rows[0][1].parse().unwrap());
    assert_eq!(e - s, (36 + 2) * 16 + 2 * 16, "C82: SETUP, 36 bits, 2 NxM gaps, HOLD");
    std::fs::remove_dir_all(&dir).ok();
}

/// lut.csv: [428] Table 12-4 rows (with the %101 row corrected, C71, E5), Table 12-3 phase bits,
/// Table 8-1 scaling, the rhomb shape of §12.3.
#[test]
fn lut_csv_complete_tables() {
    let dir = tmpdir("lut");
    export(&dir, &["--unit", "lut", "--scenario", "tables"]);
    let rows = csv(&dir.join("lut-tables-tmc429.csv"));
    // 2 LUTs × 2 directions × 8 i_scale × Σ over usrs of 256/2^(6-usrs) (usrs 7 as 6)
    assert_eq!(rows.len(), 2 * 2 * 8 * (4 + 8 + 16 + 32 + 64 + 128 + 256 + 256));
    let sel = |lut: &str, usrs: &str, dir: &str, is: &str| -> Vec<Vec<String>> {
        rows.iter().filter(|r| r[0] == lut && r[1] == usrs && r[2] == dir && r[3] == is).cloned().collect()
    };
    // usrs %101 (increment 2): second quadrant sin indices 63, 62, 60, 58 (Table 12-4 corrected);
    // the rhomb LUT (y(i) = i) shows the indices as DAC values
    let r = sel("rhomb", "5", "+", "0");
    assert_eq!(r.len(), 128);
    let q2: Vec<&str> = r[32..36].iter().map(|x| x[6].as_str()).collect();
    assert_eq!(q2, ["63", "62", "60", "58"]);
    let cos: Vec<&str> = r[32..36].iter().map(|x| x[7].as_str()).collect();
    assert_eq!(cos, ["0", "2", "4", "6"]);
    // full step: DAC 0/63, 63/0 with the phase bits of Table 12-3
    let fs = sel("sine", "0", "+", "0");
    let v: Vec<(&str, &str, &str, &str)> = fs.iter().map(|x| (x[5].as_str(), x[6].as_str(), x[7].as_str(), x[8].as_str())).collect();
    assert_eq!(v, [("0", "0", "63", "1"), ("64", "63", "0", "1"), ("128", "0", "63", "0"), ("192", "63", "0", "0")]);
    // negative direction walks 0, 255, 254 …
    let n = sel("sine", "6", "-", "0");
    assert_eq!((n[1][5].as_str(), n[2][5].as_str()), ("255", "254"));
    // Table 8-1: i_scale %100 → (63·4)>>3 = 31
    assert_eq!(sel("sine", "0", "+", "4")[1][6], "31");
    // rhomb: y(i) = i
    assert_eq!(sel("rhomb", "6", "+", "0")[37][6], "37");
    std::fs::remove_dir_all(&dir).ok();
}

/// ramp.csv: every ramp tick; each move of the p examples ends on its target and never passes
/// it (C50–C53), the steps column adds up to the distance.
#[test]
fn ramp_csv_moves_end_on_target() {
    let dir = tmpdir("ramp");
    export(&dir, &["--unit", "ramp", "--scenario", "ramp-p-examples"]);
    let rows = csv(&dir.join("ramp-ramp-p-examples-tmc429.csv"));
    for (m, target) in [(0, 60i64), (1, 400), (2, 150)] {
        let r: Vec<&Vec<String>> = rows.iter().filter(|r| r[1] == m.to_string()).collect();
        let last = r.last().unwrap();
        assert_eq!((last[3].parse::<i64>().unwrap(), last[4].parse::<i64>().unwrap(), last[5].as_str()), (target, target, "0"));
        assert!(r.iter().all(|x| x[4].parse::<i64>().unwrap() <= target), "motor {m} passed its target");
        let steps: i64 = r.iter().map(|x| x[9].parse::<i64>().unwrap()).sum();
        assert_eq!(steps, target, "motor {m}");
        // ramp_div 3 for motor 0: a tick every 256 CLK at phase 30 (C40)
        if m == 0 {
            let c: Vec<u64> = r.iter().rev().take(3).map(|x| x[0].parse().unwrap()).collect();
            assert_eq!((c[0] - c[1], c[1] - c[2], c[0] % 256), (256, 256, 255));
        }
    }
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn pins_files_are_consistent() {
    let dir = tmpdir("pins");
    let printed = export(&dir, &["--unit", "spi", "--scenario", "datasheet", "--format", "pins"]);
    let stem = dir.join("spi-datasheet-tmc429");
    assert_eq!(printed.lines().count(), 3);
    let cols = std::fs::read_to_string(stem.with_extension("cols")).unwrap();
    assert!(cols.starts_with("_sentinel 4 in\nrst 1 in\nnscs_c 1 in\nsck_c 1 in\nsdi_c 1 in\nstatus 8 in\nrd_data 24 in\nrd_addr 7 out\n"));
    assert!(cols.ends_with("sdo 1 out\n_check 5 out\n"));
    assert_eq!(meta(&stem, "width"), "88");
    assert_eq!(meta(&stem, "cycles"), "1045");
    assert_eq!(meta(&stem, "replay"), "ready");
    let hex = std::fs::read_to_string(stem.with_extension("hex")).unwrap();
    assert_eq!(hex.lines().count(), 1045);
    assert!(hex.lines().all(|l| l.len() == 22));
    // no temporary files left behind
    assert!(std::fs::read_dir(&dir).unwrap().all(|e| !e.unwrap().file_name().to_string_lossy().starts_with('.')));
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn bad_usage_exits_2_without_files() {
    let dir = tmpdir("usage");
    let script = dir.join("bad.txt");
    std::fs::write(&script, "0x1A000123\nwait x\n").unwrap();
    let s = script.to_str().unwrap();
    let d = dir.to_str().unwrap();
    for (args, msg) in [
        (vec!["--unit", "motor", "--scenario", "datasheet", "--out", d], "unknown unit"),
        (vec!["--unit", "spi", "--scenario", "nope", "--out", d], "neither a built-in scenario"),
        (vec!["--unit", "ramp", "--scenario", "ramp-modes", "--format", "pins", "--out", d], "need its RTL module"),
        (vec!["--unit", "chip", "--scenario", "datasheet", "--format", "csv", "--out", d], "pin-level vectors only"),
        (vec!["--unit", "lut", "--scenario", "datasheet", "--out", d], "use --scenario tables"),
        (vec!["--unit", "spi", "--scenario", s, "--out", d], "bad.txt:2: expected a decimal cycle count"),
        (vec!["--unit", "spi", "--scenario", "datasheet", "--out", "/proc/nonexistent/x"], "cannot create"),
    ] {
        let out = tmc429().arg("vectors").args(&args).output().unwrap();
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let e = String::from_utf8_lossy(&out.stderr);
        assert!(e.contains(msg), "{args:?}: {e}");
    }
    let left: Vec<_> = std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().file_name()).collect();
    assert_eq!(left, [std::ffi::OsString::from("bad.txt")]);
    std::fs::remove_dir_all(&dir).ok();
}

/// A scenario file in the `tmc429 spi` script format gives the same frames as `tmc429 spi`.
#[test]
fn script_file_scenario() {
    let dir = tmpdir("script");
    let script = dir.join("s.txt");
    std::fs::write(&script, "# status then a read\nbits 8 0\n0x73000000\npin REF1=1\nwait 10\n0x7D000000\n").unwrap();
    export(&dir, &["--unit", "spi", "--scenario", script.to_str().unwrap(), "--sck-half", "4"]);
    let rows = csv(&dir.join("spi-s-tmc429.csv"));
    assert_eq!(rows.len(), 3);
    assert_eq!(rows[1][4], "15429101");
    // ref_switches ($7C) with REF1 high: L1 = bit 1
    assert_eq!((rows[2][6].as_str(), &rows[2][4][6..]), ("ref_switches", "02"));
    assert_eq!(rows[2][8], "status $17: xEQt3 xEQt2 RS1 xEQt1");
    std::fs::remove_dir_all(&dir).ok();
}
