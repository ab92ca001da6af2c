//! `scripts/pnr-slack`, every path end's slack in a placed and routed iCE40 design by unit, which
//! `scripts/rtl-report` prints for each placement (docs/rtl.md "Checks"). `tests/pnr/slack/` is a
//! hand-made design in the forms nextpnr and Yosys write (`--sdf`, `--write`, `synth_ice40
//! -json`): registers a (clock to output 1390 ps), c and d, a LUT b between a and c, a block RAM
//! whose read data also enters b and whose write data comes from c. Its arrivals, by hand:
//! c's input 1390 + 600 + 1000 + 700 = 3690 ps (a through b; the RAM's 1178 + 400 + 1100 = 2678
//! is earlier), with its setup 1234 ps: 4924 ps, the worst path, 203.09 MHz; d's 1390 + 500 +
//! 1181 = 3071 ps; the RAM's write data 1390 + 900 + 100 = 2390 ps. At 250 MHz (4000 ps) c has
//! -924 ps of slack, d 929, the RAM 1610. That the Fmax is nextpnr's (to its rounding) on a real placement:
//! tests/scripts_fpga_sweep.rs (`scripts/rtl-report`).

use std::path::Path;
use std::process::{Command, Output};

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn pnr_slack(args: &[&str]) -> Output {
    Command::new(root().join("scripts/pnr-slack")).current_dir(root()).args(args).output().unwrap()
}

fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

const SDF: &str = "tests/pnr/slack/small.sdf";
const ROUTED: &str = "tests/pnr/slack/small.routed.json";
const SYNTH: &str = "tests/pnr/slack/small.synth.json";

#[test]
fn each_path_end_s_slack_by_its_register_and_unit() {
    let o = pnr_slack(&["--mhz", "250", "--worst", "3", SDF, ROUTED, SYNTH]);
    assert_eq!(o.status.code(), Some(0), "stderr: {}", text(&o.stderr));
    // c's flip-flop is named by its register in the synthesized netlist (u_top.u_c.q), not by
    // the top's net (u_top.c_q) the routed netlist names; d's by its own bit of u_top.u_d.r
    let want = "tests/pnr/slack/small.sdf: Fmax 203.09 MHz (worst path 4.92 ns)\n\
                path ends below zero slack at 250 MHz: 1 of 3 (1 register)\n\
                unit                         registers below 0    of  least slack ns\n\
                u_c                                          1     1           -0.92\n\
                \n\
                the 3 path ends of least slack (slack ns, register, its worst path's start):\n    \
                -0.92  u_top.u_c.q  <-  u_top.u_a.q\n     \
                0.93  u_top.u_d.r[1]  <-  u_top.u_a.q\n     \
                1.61  u_top.u_b.mem.0.0_RAM.WDATA_0  <-  u_top.u_c.q\n";
    assert_eq!(text(&o.stdout), want);
}

#[test]
fn the_worst_path_into_a_register_step_by_step() {
    let o = pnr_slack(&["--mhz", "250", "--path", "u_top.u_c.q", SDF, ROUTED, SYNTH]);
    assert_eq!(o.status.code(), Some(0), "stderr: {}", text(&o.stderr));
    // a's clock to output, the LUT b (the net it drives) reached at 1390 + 600 + 1000 ps, c's
    // input 700 ps later with its setup
    let want = "\nthe worst path into u_top.u_c.q (slack -0.92 ns at 250 MHz):\n    \
                1.39  u_top.u_a.q  (clock to output)\n    \
                2.99  u_top.u_b.sum  (I0 to O)\n    \
                4.92  u_top.u_c.q  (I0 and its setup)\n";
    assert!(text(&o.stdout).ends_with(want), "{}", text(&o.stdout));
    // a name no path end has: nothing printed
    let o = pnr_slack(&["--path", "u_top.u_a.q", SDF, ROUTED, SYNTH]);
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(text(&o.stderr), "pnr-slack: --path: no path end loads a register named 'u_top.u_a.q' (the names --worst prints)\n");
    assert!(o.stdout.is_empty());
}

#[test]
fn the_summary_is_one_line_and_48_mhz_is_the_default() {
    let o = pnr_slack(&["--summary", "--mhz", "250", SDF, ROUTED, SYNTH]);
    assert_eq!(o.status.code(), Some(0), "stderr: {}", text(&o.stderr));
    assert_eq!(text(&o.stdout), "small: 203.09 MHz; 1 of 3 path ends below zero slack at 250 MHz (1 register): u_c 1\n");
    // at 48 MHz (20833 ps) every path end has slack
    let o = pnr_slack(&["--summary", SDF, ROUTED, SYNTH]);
    assert_eq!(text(&o.stdout), "small: 203.09 MHz; 0 of 3 path ends below zero slack at 48 MHz (0 registers)\n");
}

#[test]
fn bad_usage_and_bad_files_are_named_with_exit_status_2() {
    let usage =
        "pnr-slack: usage: scripts/pnr-slack [--mhz F] [--worst N] [--path REG] [--log LOG] [--summary] SDF ROUTED.json SYNTH.json\n";
    let o = pnr_slack(&[SDF, ROUTED]);
    assert_eq!((o.status.code(), text(&o.stderr)), (Some(2), usage.to_string()));
    let o = pnr_slack(&["--mhz", "0", SDF, ROUTED, SYNTH]);
    assert_eq!(o.status.code(), Some(2));
    assert!(text(&o.stderr).starts_with("pnr-slack: --mhz: bad value '0'\n"), "{}", text(&o.stderr));
    let o = pnr_slack(&["tests/pnr/slack/no-such.sdf", ROUTED, SYNTH]);
    assert_eq!(
        (o.status.code(), text(&o.stderr)),
        (Some(2), "pnr-slack: tests/pnr/slack/no-such.sdf: No such file or directory\n".to_string())
    );
    // a netlist where the SDF should be, and the SDF where a netlist should be
    let o = pnr_slack(&[ROUTED, ROUTED, SYNTH]);
    assert_eq!((o.status.code(), text(&o.stderr)), (Some(2), format!("pnr-slack: {ROUTED}: not an SDF file (no DELAYFILE)\n")));
    let o = pnr_slack(&[SDF, SDF, SYNTH]);
    assert_eq!((o.status.code(), text(&o.stderr)), (Some(2), format!("pnr-slack: {SDF}: not a flat JSON netlist of Yosys or nextpnr\n")));
    assert!(o.stdout.is_empty());
}

#[test]
fn a_broken_sdf_is_named_by_file_and_line() {
    let dir = std::env::temp_dir().join(format!("tmc429-pnr-slack-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let sdf = std::fs::read_to_string(root().join(SDF)).unwrap();
    // line 26: a's clock to output (the first), its delay broken; then the file cut before its end
    let bad_delay = dir.join("bad-delay.sdf");
    std::fs::write(&bad_delay, sdf.replacen("(IOPATH CLK O (1390:1390:1390)", "(IOPATH CLK O (1390:x:1390)", 1)).unwrap();
    let p = bad_delay.to_str().unwrap();
    let o = pnr_slack(&[p, ROUTED, SYNTH]);
    assert_eq!(
        (o.status.code(), text(&o.stderr)),
        (Some(2), format!("pnr-slack: {p}:26: expected a delay (min:typ:max in ps), found (1390:x:1390)\n"))
    );
    // bytes that are no text
    let binary = dir.join("binary.sdf");
    std::fs::write(&binary, [0x7f, b'E', b'L', b'F', 0xff, 0xfe, 0x00, 0x80]).unwrap();
    let p = binary.to_str().unwrap();
    let o = pnr_slack(&[p, ROUTED, SYNTH]);
    assert_eq!((o.status.code(), text(&o.stderr)), (Some(2), format!("pnr-slack: {p}: not an SDF file (not UTF-8 text)\n")));
    let cut = dir.join("cut.sdf");
    std::fs::write(&cut, &sdf[..sdf.find("  (CELL\n    (CELLTYPE \"ICESTORM_RAM\")").unwrap()]).unwrap();
    let p = cut.to_str().unwrap();
    let o = pnr_slack(&[p, ROUTED, SYNTH]);
    assert_eq!((o.status.code(), text(&o.stderr)), (Some(2), format!("pnr-slack: {p}:1: a '(' without its ')'\n")));
    assert!(o.stdout.is_empty());
    std::fs::remove_dir_all(&dir).ok();
}
