//! `scripts/pnr-paths`, the worst path of nextpnr logs that `scripts/rtl-report` prints after
//! its tables (docs/rtl.md "Synthesis: iCE40 UP5K"). `tests/pnr/plain-tmc429.seed2.nextpnr.log`
//! is the timing part of a real log (the TMC429, plain flow, seed 2; its "Defined in" source
//! lines left out): a placement estimate of 36.05 MHz, the routed clock's critical path report,
//! two cross-domain reports (pins to and from the clock, which are not the clock's path) and
//! the routed Fmax of 34.98 MHz.

use std::path::Path;
use std::process::{Command, Output};

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn pnr_paths(args: &[&str]) -> Output {
    Command::new(root().join("scripts/pnr-paths")).current_dir(root()).args(args).output().unwrap()
}

fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

const LOG: &str = "tests/pnr/plain-tmc429.seed2.nextpnr.log";

#[test]
fn the_routed_clock_path_is_summarized_with_its_registers() {
    let o = pnr_paths(&[LOG]);
    assert_eq!(o.status.code(), Some(0), "stderr: {}", text(&o.stderr));
    // the routed Fmax (not the placement estimate), the clock-to-clock report's total 28.6 ns
    // = 10.1 logic + 18.5 routing; the LUTs after the launching register: the xeqt chain's carry
    // out, v_mx, p_step and the two LUTs of x_actual's clock enable; p_t's 11 carry cells
    let want = format!(
        "{LOG}: 34.98 MHz; worst path 28.6 ns (10.1 ns logic, 18.5 ns routing), 5 LUTs and 11 carry cells\n  \
         from u_top.u_regs.mot[2].u_m.u_ramp.v\n  to   u_top.u_regs.mot[2].u_m.u_ramp.x_actual (CEN)\n"
    );
    assert_eq!(text(&o.stdout), want);
}

#[test]
fn a_log_without_a_routed_path_says_so_and_fails() {
    let dir = std::env::temp_dir().join(format!("tmc429-pnr-paths-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    // a placement stopped before routing: the log ends in the placer
    let stopped = dir.join("plain-tmc429.seed3.nextpnr.log");
    std::fs::write(&stopped, "Info: Placed 5031 cells based on constraints.\nInfo: Running simulated annealing placer.\n").unwrap();
    let s = stopped.to_str().unwrap();
    let o = pnr_paths(&[LOG, s]);
    assert_eq!(o.status.code(), Some(1));
    let out = text(&o.stdout);
    assert!(out.starts_with(&format!("{LOG}: 34.98 MHz;")), "{out}");
    assert!(out.ends_with(&format!("{s}: no routed critical path (the placement did not finish)\n")), "{out}");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn no_log_or_an_unreadable_one_is_a_usage_error() {
    let o = pnr_paths(&[]);
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(text(&o.stderr), "usage: scripts/pnr-paths LOG...\n");
    let o = pnr_paths(&["tests/pnr/no-such.log"]);
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(text(&o.stderr), "pnr-paths: tests/pnr/no-such.log: cannot read it: No such file or directory\n");
    assert!(o.stdout.is_empty());
}
