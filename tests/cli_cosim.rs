//! `tmc429 cosim`: summary, exit status 0 / 1 / 2, mismatch report and VCD files.

use std::process::Command;

fn tmc429() -> Command {
    Command::new(env!("CARGO_BIN_EXE_tmc429"))
}

#[test]
fn clean_run_exits_0_with_summary_and_coverage() {
    let out = tmc429().args(["cosim", "--chip", "tmc4210", "--seed", "3", "--cycles", "50000", "--coverage"]).output().unwrap();
    let s = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(0), "{s}");
    assert!(s.starts_with("cosim tmc4210: seed 3\ncycles:       50000\n"), "{s}");
    assert!(s.contains("mismatches:   0\n"));
    // TMC4210: registers, the RAM words (C30), no POSCMP or SDOZ_C pin bins (C90)
    assert!(s.contains("coverage: 227 bins,"), "{s}");
    assert!(s.contains("bins never hit"));
}

#[test]
fn planted_bug_exits_1_with_report_and_vcd() {
    let dir = std::env::temp_dir().join(format!("tmc429-cli-cosim-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let vcd = dir.join("bug.vcd");
    let out = tmc429()
        .args(["cosim", "--chip", "tmc429", "--seed", "1", "--cycles", "10000000", "--plant-bug", "status"])
        .arg("--vcd")
        .arg(&vcd)
        .output()
        .unwrap();
    let s = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(1), "{s}");
    assert!(s.contains("mismatches:   1\n"));
    assert!(s.contains("MISMATCH at cycle "));
    assert!(s.contains("  top.status "));
    assert!(s.contains(" SPI transactions (oldest first):"));
    assert!(s.contains("W datagram_"));
    assert!(vcd.exists() && dir.join("bug.rtl.vcd").exists());
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn bad_usage_exits_2() {
    for args in [
        vec!["cosim", "--chip", "tmc999"],
        vec!["cosim", "--cycles", "0"],
        vec!["cosim", "--seed", "x"],
        vec!["cosim", "--chip", "tmc428", "--plant-bug", "status"],
        vec!["cosim", "--vcd", "/nonexistent-dir/x.vcd", "--cycles", "10"],
    ] {
        let out = tmc429().args(&args).output().unwrap();
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        assert!(!out.stderr.is_empty(), "{args:?}: an error message");
    }
}
