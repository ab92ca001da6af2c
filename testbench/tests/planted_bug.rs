//! The harness provably fails: the RTL built with PLANT_BUG_STATUS (the CDGW status bit
//! forgets a datagram_low/high write) must be caught, with the full report.
#![cfg(not(tmc429_no_rtl))] // needs Verilator (testbench/build.rs)

use tmc429_model::Chip;
use tmc429_testbench::{run, Config, Variant};

#[test]
fn planted_status_bug_is_caught_with_report() {
    let dir = std::env::temp_dir().join(format!("tmc429-planted-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let vcd = dir.join("planted.vcd");
    let mut cfg = Config::new(Chip::Tmc429, 1, 2_000_000);
    cfg.variant = Variant::PlantedStatusBug;
    cfg.vcd = Some(vcd.clone());
    let out = run(&cfg).expect("co-simulation runs");
    let m = out.mismatch.as_ref().expect("the planted bug is caught");
    // the first difference is the status probe: CDGW (bit 6) set in the model only
    let d = m.diffs.iter().find(|d| d.signal.name == "status").expect("status differs");
    assert_eq!(d.model & 0x40, 0x40);
    assert_eq!(d.rtl & 0x40, 0);
    assert_eq!(d.model ^ d.rtl, 0x40);
    // it shows right after a datagram_low/high write executes
    let last = m.history.last().expect("transactions recorded");
    let name = tmc429_testbench::coverage::reg_name(Chip::Tmc429, last.frame.a7());
    assert!(name.starts_with("datagram_"), "last transaction {name}");
    assert!(!last.frame.is_read());
    assert!(m.history.len() <= 16 && !m.history.is_empty());
    let report = out.report(m);
    assert!(report.contains(&format!("MISMATCH at cycle {}", m.cycle)));
    assert!(report.contains("top.status"));
    assert!(report.contains("W datagram_"));
    assert_eq!(out.mismatches(), 1);
    assert_eq!(out.cycles, m.cycle);
    for f in &out.vcd_files {
        assert!(std::fs::metadata(f).map(|md| md.len() > 0).unwrap_or(false), "{}", f.display());
    }
    std::fs::remove_dir_all(&dir).ok();
}
