//! What the vector tests share: the CLI, temporary directories, CSV reading, and the Icarus
//! Verilog build and replay of the chip testbench.
#![allow(dead_code)] // each test file uses a part

use std::path::{Path, PathBuf};
use std::process::Command;

pub fn tmc429() -> Command {
    Command::new(env!("CARGO_BIN_EXE_tmc429"))
}

pub fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

pub fn tmpdir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("tmc429-vectors-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

pub fn export(dir: &Path, args: &[&str]) -> String {
    let out = tmc429().args(["vectors", "--out"]).arg(dir).args(args).output().unwrap();
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    String::from_utf8(out.stdout).unwrap()
}

pub fn csv(path: &Path) -> Vec<Vec<String>> {
    let text = std::fs::read_to_string(path).unwrap();
    text.lines().skip(1).map(|l| split_csv(l)).collect()
}

pub fn split_csv(l: &str) -> Vec<String> {
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
pub fn build_chip_tb(dir: &Path, define: Option<&str>) -> PathBuf {
    let vvp = dir.join(format!("tb_chip{}.vvp", define.map(|d| format!("_{d}")).unwrap_or_default()));
    let mut rtl: Vec<PathBuf> = std::fs::read_dir(root().join("rtl"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "v"))
        .collect();
    rtl.sort();
    build_tb(&vvp, "tb_chip", define, &rtl)
}

/// Icarus Verilog build of a unit's replay testbench `vectors/tb/TB.v` with the RTL files it
/// wires (names under rtl/), for the TMC429 (CHIP = 1): `DIR/TB.vvp`.
pub fn build_unit_tb(dir: &Path, tb: &str, rtl: &[&str]) -> PathBuf {
    let rtl: Vec<PathBuf> = rtl.iter().map(|f| root().join("rtl").join(f)).collect();
    build_tb(&dir.join(format!("{tb}.vvp")), tb, None, &rtl)
}

/// `iverilog` of `vectors/tb/TB.v` with CHIP = 1, an optional define and the RTL files, into `vvp`.
fn build_tb(vvp: &Path, tb: &str, define: Option<&str>, rtl: &[PathBuf]) -> PathBuf {
    let mut c = Command::new("iverilog");
    c.args(["-g2005", "-P", &format!("{tb}.CHIP=1"), "-I"]).arg(root().join("vectors/tb")).arg("-I").arg(root().join("rtl"));
    c.arg("-o").arg(vvp);
    if let Some(d) = define {
        c.arg(format!("-D{d}"));
    }
    c.arg(root().join(format!("vectors/tb/{tb}.v")));
    c.args(rtl);
    let o = c.output().expect("iverilog (scripts/setup installs it)");
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    vvp.to_path_buf()
}

pub fn replay(vvp: &Path, stem: &Path, hex: Option<&Path>) -> Vec<String> {
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

pub fn meta(stem: &Path, key: &str) -> String {
    let t = std::fs::read_to_string(stem.with_extension("meta")).unwrap();
    t.lines().find_map(|l| l.strip_prefix(&format!("{key} ")).map(str::to_string)).unwrap_or_else(|| panic!("no {key} in .meta"))
}
