//! The co-simulation VCDs read back with wellen: scopes, signals and exact values.
#![cfg(not(tmc429_no_rtl))] // needs Verilator (testbench/build.rs)

use std::path::PathBuf;

use tmc429_model::Chip;
use tmc429_testbench::{run, Config};
use wellen::GetItem;

fn value_at_end(w: &mut wellen::simple::Waveform, path: &[&str], name: &str) -> String {
    let h = w.hierarchy();
    let var = h.lookup_var(path, &name).unwrap_or_else(|| panic!("{path:?}.{name} missing"));
    let sig = h.get(var).signal_ref();
    w.load_signals(&[sig]);
    let s = w.get_signal(sig).expect("signal loaded");
    let (_, v) = s.iter_changes().last().expect("signal has values");
    v.to_string()
}

fn changes(w: &mut wellen::simple::Waveform, path: &[&str], name: &str) -> Vec<(u64, String)> {
    let h = w.hierarchy();
    let var = h.lookup_var(path, &name).unwrap_or_else(|| panic!("{path:?}.{name} missing"));
    let sig = h.get(var).signal_ref();
    w.load_signals(&[sig]);
    let times = w.time_table().to_vec();
    let s = w.get_signal(sig).expect("signal loaded");
    s.iter_changes().map(|(t, v)| (times[t as usize], v.to_string())).collect()
}

#[test]
fn vcd_has_model_and_rtl_side_by_side() {
    let dir = std::env::temp_dir().join(format!("tmc429-vcd-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path: PathBuf = dir.join("cosim.vcd");
    let mut cfg = Config::new(Chip::Tmc429, 1, 30_000);
    cfg.vcd = Some(path.clone());
    let out = run(&cfg).expect("co-simulation runs");
    assert!(out.mismatch.is_none());
    assert_eq!(out.vcd_files, vec![path.clone(), dir.join("cosim.rtl.vcd")]);

    let mut w = wellen::simple::read(&path).expect("wellen reads the VCD");
    let h = w.hierarchy();
    let top: Vec<String> = h.scopes().map(|s| h.get(s).name(h).to_string()).collect();
    for s in ["top", "motor0", "motor1", "motor2", "chain", "spi", "rtl", "cosim"] {
        assert!(top.iter().any(|t| t == s), "scope {s} missing in {top:?}");
    }
    // timescale from fclk: 32 MHz = 31 250 ps per CLK; 20 000 cycles traced
    let t = w.time_table();
    assert_eq!(t[0], 31_250 / 2);
    assert_eq!(*t.last().unwrap(), 20_000 * 31_250);
    // the prologue's first write puts motor 1 in HOLD_MODE; decoded as a string
    let txn = changes(&mut w, &["spi"], "transaction");
    assert_eq!(txn[0].1, "W_ref_conf_rm[1]=$000003");
    // model and RTL pins agree over the whole window
    assert_eq!(changes(&mut w, &["top"], "nint_sdo_c"), changes(&mut w, &["rtl", "top"], "nint_sdo_c"));
    assert_eq!(changes(&mut w, &["top"], "status"), changes(&mut w, &["rtl", "top"], "status"));
    assert_eq!(value_at_end(&mut w, &["cosim"], "mismatch"), "0");
    // the prescaler counts every CLK edge outside power down: at most 20 000 after 20 000
    let pre = u64::from_str_radix(&value_at_end(&mut w, &["top"], "prescaler"), 2).unwrap();
    assert!(pre <= 20_000 && pre > 10_000, "prescaler {pre}");

    // Verilator's trace of the RTL: every RTL signal, the same time base
    let mut r = wellen::simple::read(dir.join("cosim.rtl.vcd")).expect("wellen reads the RTL VCD");
    let st = changes(&mut r, &["rtl"], "probe_status");
    assert!(!st.is_empty());
    let model_status = changes(&mut w, &["top"], "status");
    // same first value: status $15 after reset
    assert_eq!(u64::from_str_radix(&st[0].1, 2).unwrap(), 0x15);
    assert_eq!(u64::from_str_radix(&model_status[0].1, 2).unwrap(), 0x15);
    assert!(r.hierarchy().lookup_var(&["rtl", "tmc429_top", "u_spi"], &"cnt").is_some());
    std::fs::remove_dir_all(&dir).ok();
}
