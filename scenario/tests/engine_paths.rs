//! The scenario engine's shortcuts change nothing (docs/performance.md, "The scenario engine on
//! the model"): a run with a VCD reads the probes and runs the checks in every edge and never takes
//! the idle stretch; a run without it takes both shortcuts. Everything the run reports — motor
//! statistics, datagrams, Step/Dir pulses, expectations with their times, plot samples — is equal.

use tmc429_scenario::run::{run, Engine, Options, Report};
use tmc429_scenario::scenario::parse;

fn report(file: &str, vcd: Option<&std::path::Path>) -> Report {
    let path = format!("{}/../examples/scenarios/{file}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap();
    let mut sc = parse(&text, &path).unwrap_or_else(|e| panic!("{path}: {e:?}"));
    // long enough for every event and check of the files used here
    sc.duration = sc.duration.min(3_000_000);
    let mut opt = Options::new(Engine::Model);
    opt.vcd = vcd.map(|p| p.to_path_buf());
    run(&sc, &opt, &mut |_, _| {}).unwrap()
}

fn same_report(file: &str) {
    let dir = std::env::temp_dir().join(format!("tmc429-engine-paths-{}-{file}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let full = report(file, Some(&dir.join("run.vcd")));
    let fast = report(file, None);
    std::fs::remove_dir_all(&dir).unwrap();
    assert_eq!(fast.cycles, full.cycles, "{file}");
    assert_eq!(format!("{:?}", fast.motors), format!("{:?}", full.motors), "{file}");
    assert_eq!(fast.datagrams, full.datagrams, "{file}");
    assert_eq!(fast.step_pulses, full.step_pulses, "{file}");
    assert_eq!(fast.expects, full.expects, "{file}");
    assert_eq!(format!("{:?}", fast.samples), format!("{:?}", full.samples), "{file}");
    assert!(full.expects.iter().all(|e| e.passed), "{file}: {:?}", full.expects);
}

/// The demo: cycle events, a `when` trigger, register reads, `at` probes and a `reached` check.
#[test]
fn demo_reports_the_same_either_way() {
    same_report("demo.toml");
}

/// The driver chain with readback and a cover datagram (TMC428, 16 MHz).
#[test]
fn chain_bench_reports_the_same_either_way() {
    same_report("bench-chain.toml");
}

/// Step/Dir pulses decoded from the pins.
#[test]
fn step_dir_bench_reports_the_same_either_way() {
    same_report("bench-stepdir.toml");
}
