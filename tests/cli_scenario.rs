//! `tmc429 run`, `tmc429 demo` and `tmc429 calc` as a user runs them: exact results, exit
//! codes 0 / 1 / 2, and the files they write (VCD read back with wellen, the .gtkw view, plots).

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use wellen::GetItem;

fn tmc429(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_tmc429")).args(args).output().unwrap()
}

fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

fn tmpdir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("tmc429-cli-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn write(dir: &Path, name: &str, body: &str) -> String {
    let p = dir.join(name);
    std::fs::write(&p, body).unwrap();
    p.to_string_lossy().into_owned()
}

fn example(name: &str) -> String {
    format!("{}/examples/scenarios/{name}", env!("CARGO_MANIFEST_DIR"))
}

/// The bundled first scenario: a RAMP_MODE move ends exactly at x_target (TMC429 §8.1.11),
/// every step counted, velocity 0; the register reads over SPI agree.
#[test]
fn ramp_move_reaches_x_target() {
    let o = tmc429(&["run", &example("ramp-move.toml")]);
    let out = text(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{out}{}", text(&o.stderr));
    assert!(out.starts_with("scenario ramp-move (tmc429, 32 MHz, engine model)\ncycles:       1920000 (60 ms)\n"), "{out}");
    // pulse_div 5: R = 32 MHz · 2047 / (2^5 · 2^16) = 31234.7 Hz; a_max 1000, ramp_div 5:
    // ΔR = (32 MHz)² · 1000 / 2^39 = 1862645.1 Hz/s (TMC429 §8.1.13.1)
    assert!(out.contains("motor 0:      1000 steps, x_actual 1000, peak velocity 31234.7 Hz, peak acceleration 1862645.1 Hz/s\n"), "{out}");
    assert!(out.contains("expectations: 4 of 4 passed\n"), "{out}");
    assert!(out.contains("ramp-move.toml:21: motor 0 rests at its target: motor 0 v_actual = 0 (read) at 55 ms\n"), "{out}");
}

/// A failed expectation exits 1 and names it (file:line, name, what was found).
#[test]
fn failed_expectation_exits_1_and_names_it() {
    let d = tmpdir("fail");
    let f = write(
        &d,
        "short.toml",
        "duration = \"20 ms\"\n\
         [[write]]\n\
         motor = 1\n\
         clk_config = { pulse_div = 5, ramp_div = 5 }\n\
         v_min = 1\nv_max = 2047\na_max = 1000\npmul_pdiv = \"auto\"\n\
         x_target = 1000\n\
         \n\
         [[expect]]\n\
         name = \"too soon\"\n\
         at = \"20 ms\"\n\
         probe = { motor = 1, x_actual = 1000 }\n",
    );
    let o = tmc429(&["run", &f]);
    assert_eq!(o.status.code(), Some(1));
    let out = text(&o.stdout);
    let err = text(&o.stderr);
    assert!(out.contains("expectations: 0 of 1 passed\n"), "{out}");
    // 20 ms: 16.7 ms of ramp up from 0 to 2047 at 1862645 Hz/s, then full speed
    assert!(err.contains(&format!("tmc429: expectation failed: {f}:11: too soon (motor1.x_actual is 362)")), "{err}");
}

/// Typos and impossible values: every one with its line, exit 2, nothing runs.
#[test]
fn scenario_errors_exit_2_with_file_and_line() {
    let d = tmpdir("typo");
    let f = write(
        &d,
        "typo.toml",
        "duration = \"10 ms\"\n\
         driver = \"table-11-3\"\n\
         [[write]]\n\
         motor = 0\n\
         v_maks = 100\n\
         v_max = 3000\n\
         clk_config = { pulse_div = 3, ramp_dvi = 3 }\n\
         [[event]]\n\
         at = \"2 ms\"\n\
         switch = { ref9 = 1 }\n\
         [[expect]]\n\
         at = \"1 ms\"\n\
         probe = { motor = 3, x_actual = 1 }\n",
    );
    let o = tmc429(&["run", &f]);
    assert_eq!(o.status.code(), Some(2));
    assert!(o.stdout.is_empty(), "nothing runs before the whole file parses");
    let err = text(&o.stderr);
    for (line, what) in [
        (2, "unknown driver 'table-11-3': expected one of table-11-2, step-dir, power-on, none"),
        (5, "unknown motor register or field 'v_maks': expected one of x_target, x_actual"),
        (6, "v_max = 3000 out of range: expected 0..2047"),
        (7, "clk_config has no field 'ramp_dvi': expected one of pulse_div, ramp_div, usrs"),
        (10, "unknown pin 'ref9': expected one of ref1, ref2, ref3, refr1, refr2, refr3, sdi_s"),
        (13, "motor 3 out of range: expected 0..2"),
    ] {
        assert!(err.contains(&format!("tmc429: error: {f}:{line}: {what}")), "line {line} missing in:\n{err}");
    }
    // TOML syntax errors carry their line too
    let g = write(&d, "syntax.toml", "duration = \"1 ms\"\n[[write]\nmotor = 0\n");
    let o = tmc429(&["run", &g]);
    assert_eq!(o.status.code(), Some(2));
    assert!(text(&o.stderr).contains(&format!("tmc429: error: {g}:2: TOML:")), "{}", text(&o.stderr));
    // a global register with `motor`, a missing duration, an unwritable plot
    let h = write(&d, "misc.toml", "[[write]]\nmotor = 0\nif_configuration = { en_sd = 1 }\n");
    let err = text(&tmc429(&["run", &h]).stderr);
    assert!(err.contains(&format!("{h}:1: missing `duration`")), "{err}");
    assert!(err.contains(&format!("{h}:3: 'if_configuration' is a global register or field: remove `motor`")), "{err}");
    let o = tmc429(&["run", &example("ramp-move.toml"), "--plot", "/nonexistent-dir/x.svg"]);
    assert_eq!(o.status.code(), Some(2));
    let o = tmc429(&["run", &example("ramp-move.toml"), "--plot", "x.txt"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(text(&o.stderr).contains("expected a file name ending in .svg or .png"));
    let o = tmc429(&["run", "/nonexistent/s.toml"]);
    assert_eq!(o.status.code(), Some(2));
}

/// Register writes, reads and probes on every engine: the RTL of today has the register file,
/// so this scenario co-simulates with 0 mismatches.
#[test]
fn registers_on_every_engine() {
    let d = tmpdir("engines");
    let f = write(
        &d,
        "regs.toml",
        "duration = \"1 ms\"\n\
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
         [[expect]]\n\
         at = \"0.8 ms\"\n\
         register = { motor = 1, dx_ref_tolerance = 291, x_target = -5 }\n\
         [[expect]]\n\
         at = \"0.9 ms\"\n\
         register = { pos_comp = 1234, sdo_int = 1, type_version = 0x429101 }\n\
         probe = { motor = 1, x_actual = -5 }\n",
    );
    for engine in ["model", "rtl", "cosim"] {
        let o = tmc429(&["run", &f, "--engine", engine]);
        let out = text(&o.stdout);
        assert_eq!(o.status.code(), Some(0), "{engine}: {out}");
        assert!(out.contains("cycles:       32000 (1 ms)\n"), "{out}");
        assert!(out.contains("expectations: 6 of 6 passed\n"), "{engine}: {out}");
        assert!(out.contains("type_version = 4362497 (read) at 900 µs"), "{out}");
        if engine == "cosim" {
            assert!(out.contains("mismatches:   0\n"), "{out}");
        }
    }
}

/// The plot names the motors and the axes with their units; the PNG is a PNG.
#[test]
fn plots_have_motors_and_axes() {
    let d = tmpdir("plot");
    let svg = d.join("m.svg");
    let png = d.join("m.png");
    for p in [&svg, &png] {
        let o = tmc429(&["run", &example("ramp-move.toml"), "--plot", p.to_str().unwrap()]);
        assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    }
    let s = std::fs::read_to_string(&svg).unwrap();
    assert!(s.starts_with("<svg"), "an SVG document");
    // the text of every <text> element
    let texts: Vec<&str> = s.split("</text>").filter_map(|c| c.rsplit_once('>').map(|(_, t)| t.trim())).collect();
    for label in ["position [microsteps]", "velocity [Hz]", "acceleration [Hz/s]", "motor 0", "motor 1", "motor 2"] {
        assert_eq!(texts.iter().filter(|t| **t == label).count(), if label.starts_with("motor") { 3 } else { 1 }, "{label} in the SVG");
    }
    assert_eq!(texts.iter().filter(|t| **t == "time [ms]").count(), 3, "one time axis per panel");
    assert!(texts.contains(&"ramp-move: tmc429 at 32 MHz, engine model"));
    // time axis ticks up to the run's 60 ms
    assert!(texts.contains(&"60.0"), "{texts:?}");
    let b = std::fs::read(&png).unwrap();
    assert_eq!(&b[..8], b"\x89PNG\r\n\x1a\n");
    // 1000 × 900 pixels (IHDR)
    assert_eq!(u32::from_be_bytes(b[16..20].try_into().unwrap()), 1000);
    assert_eq!(u32::from_be_bytes(b[20..24].try_into().unwrap()), 900);
    // no temporary files left behind
    let left: Vec<_> = std::fs::read_dir(&d).unwrap().map(|e| e.unwrap().file_name()).collect();
    assert_eq!(left.len(), 2, "{left:?}");
}

/// Names of every variable in a VCD, as `scope.sub.name`.
fn vcd_vars(path: &Path) -> Vec<String> {
    let w = wellen::simple::read(path).expect("wellen reads the VCD");
    let h = w.hierarchy();
    h.iter_vars().map(|v| v.full_name(h)).collect()
}

/// The signals a .gtkw names, without bit ranges, and its dumpfile.
fn gtkw_signals(path: &Path) -> (String, Vec<String>) {
    let t = std::fs::read_to_string(path).unwrap();
    let dump = t.lines().find_map(|l| l.strip_prefix("[dumpfile] ")).unwrap().trim_matches('"').to_string();
    let sigs = t
        .lines()
        .filter(|l| !l.is_empty() && !l.starts_with(['[', '*', '@', '-']))
        .map(|l| l.split('[').next().unwrap().to_string())
        .collect();
    (dump, sigs)
}

/// The vector files the demo writes (docs/vectors.md), in the order its summary lists them.
const DEMO_VECTORS: [&str; 6] = [
    "chip-demo-tmc429.hex",
    "chip-demo-tmc429.cols",
    "chip-demo-tmc429.meta",
    "spi-demo-tmc429.csv",
    "ramp-demo-tmc429.csv",
    "chain-demo-tmc429.csv",
];

fn check_demo_outputs(dir: &Path, cosim: bool, stdout: &str) {
    let listed: Vec<&str> = stdout.lines().filter_map(|l| l.strip_prefix("vectors: ")).collect();
    let want: Vec<String> = DEMO_VECTORS.iter().map(|f| dir.join(f).display().to_string()).collect();
    assert_eq!(listed, want, "the summary lists the vector files");
    for f in DEMO_VECTORS {
        assert!(dir.join(f).metadata().unwrap().len() > 200, "{f}");
    }
    // 60 ms at 32 MHz and the reset line
    let meta = std::fs::read_to_string(dir.join("chip-demo-tmc429.meta")).unwrap();
    assert!(meta.contains("\ncycles 1920001\n") && meta.contains("\nscenario demo\n"), "{meta}");
    let vcd = dir.join("demo.vcd");
    let vars = vcd_vars(&vcd);
    let (dump, sigs) = gtkw_signals(&dir.join("demo.gtkw"));
    assert_eq!(dump, "demo.vcd");
    assert!(sigs.len() > 30, "{sigs:?}");
    for s in &sigs {
        assert!(vars.contains(s), "the .gtkw names {s}, which the VCD lacks");
    }
    assert_eq!(sigs.iter().any(|s| s == "cosim.mismatch"), cosim);
    for f in ["demo.svg", "demo.png"] {
        assert!(dir.join(f).metadata().unwrap().len() > 10_000, "{f}");
    }
}

/// The demo on the golden model: every expectation holds, exact figures, the files it names.
#[test]
fn demo_on_the_model() {
    let d = tmpdir("demo-model");
    let o = tmc429(&["demo", "--engine", "model", "--out", d.to_str().unwrap()]);
    let out = text(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{out}{}", text(&o.stderr));
    let want = "scenario demo (tmc429, 32 MHz, engine model)\n\
                cycles:       1920000 (60 ms)\n\
                motor 0:      1018 steps, x_actual -300, peak velocity 31234.7 Hz, peak acceleration 3725290.3 Hz/s\n\
                motor 1:      600 steps, x_actual 600, peak velocity 22888.2 Hz, peak acceleration 2793967.7 Hz/s\n\
                motor 2:      600 steps, x_actual 300, peak velocity 15258.8 Hz, peak acceleration 3725290.3 Hz/s\n";
    assert!(out.starts_with(want), "{out}");
    assert!(out.contains("expectations: 5 of 5 passed\n"), "{out}");
    assert!(out.contains("motor 2 latched the switch position: motor 2 x_latched = -300 (read) at 25 ms\n"), "{out}");
    check_demo_outputs(&d, false, &out);
    // the vectors: the last ramp tick of each motor (cycle, motor, mode, x_target, x_actual,
    // v_internal …) at rest on its target, in the motor's ramp phase 16 + 7m (C41: the cycle
    // after an edge of phase p is 32·k + p + 1), and one CSV row per driver-chain datagram counted
    let ramp = std::fs::read_to_string(d.join("ramp-demo-tmc429.csv")).unwrap();
    for (m, want) in
        [(0, "1919985,0,RAMP,-300,-300,0,0,0,0,0"), (1, "1919992,1,SOFT,600,600,0,0,0,0,0"), (2, "1919999,2,RAMP,300,300,0,0,0,0,0")]
    {
        let last = ramp.lines().filter(|l| l.split(',').nth(1) == Some(&m.to_string())).last().unwrap();
        assert_eq!(last, want);
    }
    let chain = std::fs::read_to_string(d.join("chain-demo-tmc429.csv")).unwrap();
    assert!(out.contains("datagrams:    1175 (driver chain)\n"), "{out}");
    assert_eq!(chain.lines().count(), 1 + 1175);
    // the model-side VCD: motor 2's latch is armed and REF3 closes at the latched position
    let mut w = wellen::simple::read(d.join("demo.vcd")).unwrap();
    let h = w.hierarchy();
    let var = h.lookup_var(&["top"], &"ref3").unwrap();
    let sig = h.get(var).signal_ref();
    w.load_signals(&[sig]);
    let n = w.get_signal(sig).unwrap().iter_changes().count();
    assert_eq!(n, 3, "REF3: initial 0, closes, opens");
}

/// The README's main command: the demo co-simulated (golden model and RTL), 0 mismatches.
#[test]
fn demo_cosim_has_no_mismatch() {
    let d = tmpdir("demo-cosim");
    let o = tmc429(&["demo", "--out", d.to_str().unwrap()]);
    let out = text(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{out}{}", text(&o.stderr));
    assert!(out.contains("engine cosim"), "{out}");
    assert!(out.contains("mismatches:   0\n"), "{out}");
    assert!(out.contains("expectations: 5 of 5 passed\n"), "{out}");
    check_demo_outputs(&d, true, &out);
}

#[test]
fn demo_print_is_the_bundled_file() {
    let o = tmc429(&["demo", "--print"]);
    assert_eq!(o.status.code(), Some(0));
    assert_eq!(text(&o.stdout), std::fs::read_to_string(example("demo.toml")).unwrap());
}

/// `tmc429 calc` from registers: TMC429 §8.1.13 (R, ΔR, S at 16 MHz) and §8.1.10.2.3 (pmulpdiv.c).
#[test]
fn calc_from_registers_reproduces_the_datasheet() {
    let o = tmc429(&[
        "calc",
        "--fclk",
        "16MHz",
        "--pulse-div",
        "7",
        "--ramp-div",
        "7",
        "--v-max",
        "1000",
        "--a-max",
        "100",
        "--p-reduction",
        "0.05",
    ]);
    let out = text(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    assert!(out.contains("step rate     1907.35 Hz microsteps, 1907.35 Hz full steps\n"), "{out}");
    assert!(out.contains("braking       625 microsteps (625 full steps) from v_max to 0"), "{out}");
    assert!(out.contains("pmul_pdiv     p_mul 189, p_div 5 (register $00BD05); p = 0.738281 (ideal 0.781250,"), "{out}");
    assert!(out.contains("check         ok\n"), "{out}");
    // ΔR at a_max 1000, pd = rd = 7: 29103.83 Hz/s; pd = rd = 0: 476837158.2 Hz/s
    let o = tmc429(&["calc", "--fclk", "16MHz", "--pulse-div", "7", "--ramp-div", "7", "--v-max", "1000", "--a-max", "1000"]);
    assert!(text(&o.stdout).contains("acceleration  29103.83 Hz/s microsteps"), "{}", text(&o.stdout));
    let o = tmc429(&["calc", "--fclk", "16MHz", "--pulse-div", "0", "--ramp-div", "0", "--v-max", "2047", "--a-max", "1000"]);
    let out = text(&o.stdout);
    assert!(out.contains("acceleration  476837158.20 Hz/s microsteps"), "{out}");
    assert!(out.contains("step rate     499755.86 Hz microsteps"), "{out}");
    // pmulpdiv.c results ([429] §8.1.10.2.3): a_max, ramp_div, pulse_div, p_reduction -> p_mul, p_div, lower, upper
    for (a, rd, pd, red, pm, pdv, lo, hi) in [
        ("10", "3", "3", "0.05", 151, 8, 1, 4095),
        ("1000", "3", "3", "0.05", 237, 2, 1, 4095),
        ("1000", "7", "7", "0", 250, 2, 1, 4095),
        ("1000", "7", "7", "0.01", 247, 2, 1, 4095),
        ("2047", "0", "0", "0.05", 243, 1, 1, 4095),
        ("1000", "6", "3", "0.05", 237, 5, 4, 32767),
        ("16", "5", "0", "0.05", 243, 13, 16, 131071),
        ("1023", "0", "0", "0", 255, 2, 1, 4095),
    ] {
        let o = tmc429(&["calc", "--pulse-div", pd, "--ramp-div", rd, "--v-max", "2047", "--a-max", a, "--p-reduction", red]);
        let out = text(&o.stdout);
        assert!(out.contains(&format!("pmul_pdiv     p_mul {pm}, p_div {pdv} ")), "a_max {a} rd {rd} pd {pd}: {out}");
        assert!(out.contains(&format!("a_max limits  {lo} .. {hi} ")), "a_max {a} rd {rd} pd {pd}: {out}");
    }
    // unrepresentable p: a_max 1000, rd 3, pd 6 (p = 62.5 > 31.9)
    let o = tmc429(&["calc", "--pulse-div", "6", "--ramp-div", "3", "--v-max", "2047", "--a-max", "1000", "--p-reduction", "0.05"]);
    let out = text(&o.stdout);
    assert!(out.contains("pmul_pdiv     none: p = 62.500000 is not representable"), "{out}");
    assert!(out.contains("warning       a_max 1000 is above A_MAX_UPPER_LIMIT 511"), "{out}");
}

/// `tmc429 calc` from a speed and an acceleration: the registers, and back the same units.
#[test]
fn calc_from_units() {
    // 300 rpm of a 200-step motor at 16 microsteps = 16000 Hz; 5000 full steps/s²
    let o = tmc429(&["calc", "--fclk", "16MHz", "--usrs", "4", "--rpm", "300", "--steps-per-rev", "200", "--accel", "5000"]);
    let out = text(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    for l in [
        "pulse_div     4\n",
        "ramp_div      9\n",
        "v_max         1049\n",
        "a_max         1374\n",
        "step rate     16006.47 Hz microsteps, 1000.40 Hz full steps\n",
        "speed         300.12 rpm at 200 full steps per revolution\n",
        "check         ok\n",
    ] {
        assert!(out.contains(l), "{l} missing in {out}");
    }
    // faster than fCLK/32: exit 2
    let o = tmc429(&["calc", "--fclk", "16MHz", "--speed", "600000", "--accel", "1000"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(text(&o.stderr).contains("faster than the chip can step"), "{}", text(&o.stderr));
    let o = tmc429(&["calc", "--speed", "100"]);
    assert_eq!(o.status.code(), Some(2));
    let o = tmc429(&["calc", "--pulse-div", "14", "--ramp-div", "0", "--v-max", "1", "--a-max", "1"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(text(&o.stderr).contains("pulse_div 14 out of range 0..13"));
}
