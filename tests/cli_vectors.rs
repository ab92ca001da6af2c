//! `tmc429 vectors`: exported files, exact values from the datasheets and the contract, the
//! scenario forms, usage errors (the replays on the RTL: tests/cli_vector_replay.rs).

mod vectors_common;
use vectors_common::*;

/// [428] §6.5 examples (errata E1, E2: INT clear, the 32-bit RAM datagram) in spi.csv.
#[test]
fn spi_csv_has_the_datasheet_examples() {
    let dir = tmpdir("spi");
    export(&dir, &["--unit", "spi", "--scenario", "datasheet", "--format", "csv"]);
    let rows = csv(&dir.join("spi-datasheet-tmc429.csv"));
    let got: Vec<(&str, &str, &str, &str)> = rows.iter().map(|r| (r[3].as_str(), r[4].as_str(), r[5].as_str(), r[6].as_str())).collect();
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

/// TMC428 §11.2: the datagrams of the Table 11-2 configuration with the Table 12-2 LUT, and the
/// cover example, with the decoded signals of each motor.
#[test]
fn chain_csv_has_the_table_11_2_datagrams_and_the_cover() {
    let dir = tmpdir("chain");
    export(&dir, &["--unit", "chain", "--scenario", "chain-datasheet"]);
    let rows = csv(&dir.join("chain-chain-datasheet-tmc429.csv"));
    let bits: Vec<(&str, &str)> = rows.iter().map(|r| (r[2].as_str(), r[3].as_str())).collect();
    assert_eq!(bits, [("36", "05F05F07F"), ("36", "35D35D37D"), ("36", "1CF1CF1EF"), ("36", "55805F07F"), ("36", "ABC05F07F")]);
    // w = 16: DAC_A = sin LUT[16] = 24, DAC_B = LUT[48] = 59 (Table 12-2); i_scale %100 halves them
    assert_eq!(&rows[1][6..12], ["24", "1", "0", "59", "1", "1"]);
    assert_eq!(&rows[2][6..12], ["12", "1", "0", "29", "1", "1"]);
    // every datagram carried three motors (LSMD = 2); the cover datagram is flagged
    assert!(rows.iter().all(|r| r[5] == "3" && r[4] == "1"));
    // the cycle of the end is after the start: 36 bits, SCK_S period 16 CLK at clk2_div 7
    let (s, e): (u64, u64) = (rows[0][0].parse().unwrap(), rows[0][1].parse().unwrap());
    assert_eq!(e - s, 8 + 36 * 16 + 2 * 16 + 8, "C82: SETUP (t_HDSCSdrv 8), 36 bits, 2 NxM gaps, HOLD 8");
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
    export(&dir, &["--unit", "ramp", "--scenario", "ramp-p-examples", "--format", "csv"]);
    let rows = csv(&dir.join("ramp-ramp-p-examples-tmc429.csv"));
    for (m, target) in [(0, 60i64), (1, 400), (2, 150)] {
        let r: Vec<&Vec<String>> = rows.iter().filter(|r| r[1] == m.to_string()).collect();
        let last = r.last().unwrap();
        assert_eq!((last[3].parse::<i64>().unwrap(), last[4].parse::<i64>().unwrap(), last[5].as_str()), (target, target, "0"));
        assert!(r.iter().all(|x| x[4].parse::<i64>().unwrap() <= target), "motor {m} passed its target");
        let steps: i64 = r.iter().map(|x| x[9].parse::<i64>().unwrap()).sum();
        assert_eq!(steps, target, "motor {m}");
        // ramp_div 3 for motor 0: a tick every 256 CLK at its ramp phase 16 (C40, C41)
        if m == 0 {
            let c: Vec<u64> = r.iter().rev().take(3).map(|x| x[0].parse().unwrap()).collect();
            assert_eq!((c[0] - c[1], c[1] - c[2], c[0] % 256), (256, 256, 7 * 32 + 16 + 1));
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
    assert!(cols.starts_with(
        "_sentinel 4 in\nrst 1 in\nnscs_c 1 in\nsck_c 1 in\nsdi_c 1 in\nstatus 8 in\nrd_data 24 in\nrd_round 1 in\nrd_addr 7 out\n"
    ));
    assert!(cols.ends_with("sdo 1 out\n_check 4 out\n"));
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
        (vec!["--unit", "chip", "--scenario", "datasheet", "--format", "csv", "--out", d], "unit chip has no CSV form"),
        (vec!["--unit", "lut", "--scenario", "datasheet", "--out", d], "use --scenario tables"),
        (vec!["--unit", "spi", "--scenario", s, "--out", d], "bad.txt:2: expected a decimal cycle count"),
        (vec!["--unit", "spi", "--scenario", "datasheet", "--out", "/proc/nonexistent/x"], "cannot create"),
        (
            vec!["--unit", "chip", "--scenario", "datasheet", "--chip", "tmc4210", "--package", "qfn32", "--out", d],
            "tmc4210 has no qfn32 package",
        ),
        (vec!["--unit", "chip", "--scenario", "x.toml", "--package", "sop24", "--out", d], "runs in its variant's full package"),
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

fn example(name: &str) -> String {
    root().join("examples/scenarios").join(name).to_string_lossy().into_owned()
}

/// A TOML scenario file (docs/scenarios.md) as a vector scenario: the RAMP_MODE move of
/// examples/scenarios/ramp-move.toml ends at its x_target 1000 with velocity 0, every step
/// counted (TMC429 §8.1.11).
#[test]
fn toml_scenario_ramp_vectors() {
    let dir = tmpdir("toml-ramp");
    let f = example("ramp-move.toml");
    let printed = export(&dir, &["--unit", "ramp", "--scenario", &f, "--format", "csv"]);
    assert_eq!(printed, format!("{}\n", dir.join("ramp-ramp-move-tmc429.csv").display()));
    let rows = csv(&dir.join("ramp-ramp-move-tmc429.csv"));
    let m0: Vec<&Vec<String>> = rows.iter().filter(|r| r[1] == "0").collect();
    let last = m0.last().unwrap();
    // cycle, motor, mode, x_target, x_actual, v_internal, v_actual, v_target, a_actual, steps
    assert_eq!(last[2..9], ["RAMP", "1000", "1000", "0", "0", "0", "0"]);
    assert!(m0.iter().all(|r| r[4].parse::<i64>().unwrap() <= 1000), "never past the target");
    assert_eq!(m0.iter().map(|r| r[9].parse::<i64>().unwrap()).sum::<i64>(), 1000);
    // ramp_div 5: a tick every 2^5 · 32 CLK, at motor 0's ramp phase 16 of the last frame (C40,
    // C41); 60 ms run
    let c: Vec<u64> = m0.iter().rev().take(2).map(|r| r[0].parse().unwrap()).collect();
    assert_eq!((c[0], c[0] - c[1]), (1_919_985, 1024));
    std::fs::remove_dir_all(&dir).ok();
}

/// The µC's frames of the TOML scenario: the file's writes by name, in file order, and the two
/// reads of its expectation at 55 ms (the frame starts on the edge after 1 760 000).
#[test]
fn toml_scenario_spi_vectors() {
    let dir = tmpdir("toml-spi");
    let f = example("ramp-move.toml");
    export(&dir, &["--unit", "spi", "--format", "csv", "--scenario", &f]);
    let rows = csv(&dir.join("spi-ramp-move-tmc429.csv"));
    let got: Vec<[&str; 5]> = rows.iter().map(|r| [r[0].as_str(), r[3].as_str(), r[4].as_str(), r[5].as_str(), r[6].as_str()]).collect();
    assert_eq!(
        got,
        [
            // sck_half 4 (the scenario default): 4 + 64·4 + 4 CLK from the first edge with nSCS_C
            // low to the first with it high, then 4 high
            ["1", "18005500", "15000000", "write", "clk_config[0]"],
            ["269", "04000001", "15000000", "write", "v_min[0]"],
            ["537", "060007FF", "15000000", "write", "v_max[0]"],
            ["805", "0C0003E8", "15000000", "write", "a_max[0]"],
            // pmulpdiv.c, a_max 1000, ramp_div = pulse_div, 1 %: p_mul 247, p_div 2 (TMC429 §8.1.10.2.3)
            ["1073", "1200F702", "15000000", "write", "pmul_pdiv[0]"],
            ["1341", "000003E8", "15000000", "write", "x_target[0]"],
            ["1760001", "03000000", "150003E8", "read", "x_actual[0]"],
            ["1760269", "0B000000", "15000000", "read", "v_actual[0]"],
        ]
    );
    assert_eq!(rows[0][1], "265");
    std::fs::remove_dir_all(&dir).ok();
}

/// The chip's pins of the TOML scenario: its length, clock and replay state in the meta file,
/// one hex line per CLK edge.
#[test]
fn toml_scenario_chip_vectors() {
    let dir = tmpdir("toml-chip");
    export(&dir, &["--unit", "chip", "--scenario", &example("ramp-move.toml")]);
    let stem = dir.join("chip-ramp-move-tmc429");
    for (k, v) in [
        ("cycles", "1920001"),
        ("fclk", "32000000"),
        ("scenario", "ramp-move"),
        ("chip", "tmc429"),
        ("replay", "ready"),
        ("mask", "7FF"),
        ("not_compared", "-"),
    ] {
        assert_eq!(meta(&stem, k), v, "{k}");
    }
    assert_eq!(std::fs::read_to_string(stem.with_extension("hex")).unwrap().lines().count(), 1_920_001);
    std::fs::remove_dir_all(&dir).ok();
}

/// The scenario file names its chip, fclk and sck_half: an option that contradicts them is an
/// error, one that agrees is accepted; a scenario error names file and line, exits 2 and leaves
/// no files; a unit without a scenario form (lut) is a usage error.
#[test]
fn toml_scenario_option_and_file_errors() {
    let dir = tmpdir("toml-err");
    let f = example("ramp-move.toml");
    for (opt, val, msg) in [
        ("--chip", "tmc428", "--chip tmc428: the scenario file"),
        ("--fclk", "16MHz", "--fclk 16000000: the scenario file"),
        ("--sck-half", "3", "--sck-half 3: the scenario file"),
    ] {
        let o = tmc429().args(["vectors", "--unit", "spi", "--scenario", &f, "--out"]).arg(&dir).args([opt, val]).output().unwrap();
        assert_eq!(o.status.code(), Some(2), "{opt}");
        assert!(String::from_utf8_lossy(&o.stderr).contains(msg), "{}", String::from_utf8_lossy(&o.stderr));
    }
    export(&dir, &["--unit", "spi", "--format", "csv", "--scenario", &f, "--chip", "tmc429", "--fclk", "32MHz", "--sck-half", "4"]);
    let bad = dir.join("bad.toml");
    std::fs::write(&bad, "duration = \"1 ms\"\n[[write]]\nmotor = 0\nv_maks = 1\n").unwrap();
    let o = tmc429().args(["vectors", "--unit", "chip", "--scenario"]).arg(&bad).arg("--out").arg(dir.join("bad")).output().unwrap();
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains(&format!("{}:4: unknown motor register or field 'v_maks'", bad.display())));
    assert!(!dir.join("bad").exists());
    let o = tmc429().args(["vectors", "--unit", "lut", "--scenario", &f, "--out"]).arg(&dir).output().unwrap();
    assert_eq!(o.status.code(), Some(2));
    std::fs::remove_dir_all(&dir).ok();
}

/// The register-only scenario of the `tmc429 run --vectors` tests, written into `dir`.
fn regs_scenario(dir: &std::path::Path) -> std::path::PathBuf {
    let sc = dir.join("regs.toml");
    std::fs::create_dir_all(dir).unwrap();
    std::fs::write(
        &sc,
        "name = \"regs\"\n\
         duration = \"1 ms\"\n\
         driver = \"table-11-2\"\n\
         lut = \"sine\"\n\
         [[write]]\n\
         motor = 1\n\
         dx_ref_tolerance = 291\n\
         x_target = -5\n\
         x_actual = -5\n\
         [[write]]\n\
         pos_comp = 1234\n\
         if_configuration = { sdo_int = 1 }\n\
         [[event]]\n\
         at = \"0.5 ms\"\n\
         switch = { ref1 = true }\n\
         [[expect]]\n\
         at = \"0.9 ms\"\n\
         register = { pos_comp = 1234, type_version = 0x429101 }\n",
    )
    .unwrap();
    sc
}

/// The six files `tmc429 run --vectors` writes for the regs scenario, in the order it lists them.
const RUN_FILES: [&str; 6] = [
    "chip-regs-tmc429.hex",
    "chip-regs-tmc429.cols",
    "chip-regs-tmc429.meta",
    "spi-regs-tmc429.csv",
    "ramp-regs-tmc429.csv",
    "chain-regs-tmc429.csv",
];

/// `tmc429 run FILE --vectors DIR` (the golden model's vectors whatever the engine) into `out`.
fn run_vectors(sc: &std::path::Path, engine: &str, out: &std::path::Path) -> String {
    let o = tmc429().arg("run").arg(sc).args(["--engine", engine, "--vectors"]).arg(out).output().unwrap();
    let stdout = String::from_utf8_lossy(&o.stdout).into_owned();
    assert_eq!(o.status.code(), Some(0), "{stdout}{}", String::from_utf8_lossy(&o.stderr));
    stdout
}

/// `tmc429 run FILE --vectors DIR`: the chip pins and the spi, ramp and chain CSV, listed, no
/// other file; the SPI frames are the driver table's, the LUT's, the writes' and the
/// expectation's reads; the same files as `tmc429 vectors --scenario FILE` per unit.
#[test]
fn run_writes_the_vectors_of_a_scenario() {
    let dir = tmpdir("run");
    let sc = regs_scenario(&dir);
    let model = dir.join("model");
    let out = run_vectors(&sc, "model", &model);
    let listed: Vec<&str> = out.lines().filter_map(|l| l.strip_prefix("vectors: ")).collect();
    let want: Vec<String> = RUN_FILES.iter().map(|n| model.join(n).display().to_string()).collect();
    assert_eq!(listed, want);
    let mut files: Vec<String> =
        std::fs::read_dir(&model).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    files.sort();
    let mut sorted = RUN_FILES.to_vec();
    sorted.sort();
    assert_eq!(files, sorted, "exactly these, no temporary files");
    // the 18 words of Table 11-2 and LSMD, the 32 words of the sine table, the five register
    // writes, and the two reads of the expectation
    let spi = csv(&model.join("spi-regs-tmc429.csv"));
    assert_eq!(spi.len(), 18 + 1 + 32 + 3 + 2 + 2, "{spi:?}");
    assert_eq!((spi[spi.len() - 1][6].as_str(), &spi[spi.len() - 1][4][2..]), ("type_version", "429101"));
    assert_eq!((spi[spi.len() - 2][6].as_str(), &spi[spi.len() - 2][4][2..]), ("pos_comp", "0004D2"));

    // the same files from `tmc429 vectors --scenario FILE.toml`, one unit at a time
    let one = dir.join("one");
    for (unit, stem) in
        [("chip", "chip-regs-tmc429"), ("spi", "spi-regs-tmc429"), ("ramp", "ramp-regs-tmc429"), ("chain", "chain-regs-tmc429")]
    {
        let fmt = if unit == "chip" { "pins" } else { "csv" };
        export(&one, &["--unit", unit, "--format", fmt, "--scenario", sc.to_str().unwrap()]);
        for ext in ["hex", "cols", "meta", "csv"] {
            let a = model.join(stem).with_extension(ext);
            if a.exists() {
                assert_eq!(std::fs::read(&a).unwrap(), std::fs::read(one.join(stem).with_extension(ext)).unwrap(), "{stem}.{ext}");
            }
        }
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// `tmc429 run --engine cosim --vectors DIR` writes the golden model's vectors, byte for byte
/// those of `--engine model`; the chip vectors of the register-only scenario replay on the RTL
/// under Icarus Verilog with 0 failed (the RTL has the SPI slave and the register file).
#[test]
fn run_vectors_of_cosim_are_the_models_and_replay_on_the_rtl() {
    let dir = tmpdir("run-cosim");
    let sc = regs_scenario(&dir);
    let (model, cosim) = (dir.join("model"), dir.join("cosim"));
    run_vectors(&sc, "model", &model);
    run_vectors(&sc, "cosim", &cosim);
    for n in RUN_FILES {
        assert_eq!(std::fs::read(model.join(n)).unwrap(), std::fs::read(cosim.join(n)).unwrap(), "{n}");
    }
    // every pin the chip drives, every cycle
    let stem = model.join("chip-regs-tmc429");
    let cycles: u64 = meta(&stem, "cycles").parse().unwrap();
    assert_eq!(cycles, 32_001);
    let vvp = build_chip_tb(&dir, None);
    let replayed = replay(&vvp, &stem, None);
    assert_eq!(replayed.last().unwrap(), &format!("{cycles} passed, 0 failed"), "{replayed:?}");
    std::fs::remove_dir_all(&dir).ok();
}

/// `tmc429 run --vectors DIR` with a DIR that cannot be made: exit 2 before running, the path
/// and the reason on stderr, nothing on stdout.
#[test]
fn run_vectors_into_an_uncreatable_directory_exits_2() {
    let dir = tmpdir("run-bad");
    let sc = regs_scenario(&dir);
    let o = tmc429().arg("run").arg(&sc).args(["--vectors", "/proc/nonexistent/v"]).output().unwrap();
    assert_eq!(o.status.code(), Some(2));
    assert!(o.stdout.is_empty());
    assert!(String::from_utf8_lossy(&o.stderr).contains("--vectors /proc/nonexistent/v: cannot create"));
    std::fs::remove_dir_all(&dir).ok();
}
