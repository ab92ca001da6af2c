//! Every command the user guide shows runs: the ```sh blocks of README.md, docs/scenarios.md,
//! docs/tmcl.md, docs/vectors.md and docs/fpga.md, with `cargo run --release --`,
//! `target/release/tmc429` and a leading `tmc429` standing for the binary under test, each block
//! as one bash script (`set -e`) in a scratch directory that sees the repository's `examples/`,
//! `rtl/`, `vectors/`, `fpga/`, `scripts/` and `tests/`. docs/bench.md's blocks run the same way,
//! with the decoders of `sigrok/` at hand. docs/fpga.md's blocks synthesize and place and route
//! for minutes: that test is `#[ignore]`d and scripts/test runs it on its own
//! (`cargo test --workspace --release --test docs_commands -- --ignored`). ```text blocks are synopses and
//! the documented full runs, not run.
//!
//! Not run here: the set-up and test scripts themselves (`./scripts/setup`, `./scripts/test`),
//! builds (`cargo build`, `make`), `gtkwave` (a GUI) and `tmcl serve` (runs until stopped;
//! tmcl/tests and scripts/test-tmcl cover it).

use std::path::Path;
use std::process::Command;

const SKIP: [&str; 7] = ["./scripts/test", "gtkwave ", "make ", "cargo build", "cargo test", "cargo bench", "tmcl serve"];

/// The ```sh blocks of a Markdown file, with the line each starts on.
fn sh_blocks(md: &str) -> Vec<(usize, String)> {
    let mut out = Vec::new();
    let mut cur: Option<(usize, String)> = None;
    for (i, line) in md.lines().enumerate() {
        let t = line.trim_start();
        match (&mut cur, t) {
            (None, "```sh") => cur = Some((i + 1, String::new())),
            (Some(_), "```") => out.push(cur.take().unwrap()),
            (Some((_, b)), _) => {
                b.push_str(t);
                b.push('\n');
            }
            _ => {}
        }
    }
    out
}

/// The block as the test runs it.
fn script(block: &str, bin: &str) -> String {
    let mut s = String::from("set -e\n");
    for line in block.lines() {
        let mut l = line.replace("./scripts/setup && ", "");
        if SKIP.iter().any(|k| l.contains(k)) {
            l = format!("# (not run here) {l}");
        }
        const B: &str = "__TMC429__";
        l = l.replace("cargo run --release --", B).replace("target/release/tmc429", B);
        if let Some(rest) = l.strip_prefix("tmc429 ") {
            l = format!("{B} {rest}");
        }
        s.push_str(&l.replace(B, bin));
        s.push('\n');
    }
    s
}

fn run_doc(rel: &str) {
    run_doc_with(rel, &[]);
}

/// Runs the blocks of a document with extra environment variables (`{dir}` in a value is the
/// scratch directory).
fn run_doc_with(rel: &str, env: &[(&str, &str)]) {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let md = std::fs::read_to_string(root.join(rel)).unwrap();
    let bin = env!("CARGO_BIN_EXE_tmc429");
    let blocks = sh_blocks(&md);
    assert!(!blocks.is_empty(), "{rel} has sh blocks");
    // one directory per document: later blocks use the files of earlier ones
    let dir = std::env::temp_dir().join(format!("tmc429-docs-{}-{}", rel.replace('/', "_"), std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    for d in ["examples", "rtl", "vectors", "fpga", "scripts", "tests", "sigrok"] {
        std::os::unix::fs::symlink(root.join(d), dir.join(d)).unwrap();
    }
    for (line, block) in &blocks {
        let sc = script(block, bin);
        let mut cmd = Command::new("bash");
        for (k, v) in env {
            cmd.env(k, v.replace("{dir}", dir.to_str().unwrap()));
        }
        let o = cmd.arg("-c").arg(&sc).current_dir(&dir).output().unwrap();
        assert!(
            o.status.success(),
            "{rel}:{line}: the block fails ({:?}):\n{sc}\nstdout:\n{}\nstderr:\n{}",
            o.status.code(),
            String::from_utf8_lossy(&o.stdout),
            String::from_utf8_lossy(&o.stderr)
        );
    }
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn readme_commands_run() {
    run_doc("README.md");
}

#[test]
fn scenarios_guide_commands_run() {
    run_doc("docs/scenarios.md");
}

#[test]
fn tmcl_guide_commands_run() {
    run_doc("docs/tmcl.md");
}

#[test]
fn vectors_guide_commands_run() {
    run_doc("docs/vectors.md");
}

/// Minutes of synthesis and place and route: scripts/test runs it with `--ignored`.
#[test]
#[ignore]
fn fpga_guide_commands_run() {
    run_doc("docs/fpga.md");
}

/// The files the README's first command names exist after it.
#[test]
fn readme_first_command_writes_what_it_names() {
    let md = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("README.md")).unwrap();
    let (_, first) = &sh_blocks(&md)[0];
    assert!(first.contains("./scripts/setup && cargo run --release -- demo\n"), "{first}");
    assert!(first.contains("./scripts/test\n"), "{first}");
    let dir = std::env::temp_dir().join(format!("tmc429-docs-first-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let sc = script("cargo run --release -- demo\n", env!("CARGO_BIN_EXE_tmc429"));
    let o = Command::new("bash").arg("-c").arg(&sc).current_dir(&dir).output().unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stdout));
    for f in [
        "demo.vcd",
        "demo.gtkw",
        "demo.svg",
        "demo.png",
        "chip-demo-tmc429.hex",
        "spi-demo-tmc429.csv",
        "ramp-demo-tmc429.csv",
        "chain-demo-tmc429.csv",
    ] {
        assert!(dir.join("demo-out").join(f).is_file(), "demo-out/{f}");
        assert!(md.contains(&format!("demo-out/{f}")), "the README names demo-out/{f}");
    }
    for f in ["chip-demo-tmc429.cols", "chip-demo-tmc429.meta"] {
        assert!(dir.join("demo-out").join(f).is_file(), "demo-out/{f}");
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// docs/bench.md installs the decoders into the user's data directory: here the scratch
/// directory's (sigrok-cli, a GLib program, follows XDG_DATA_HOME).
#[test]
fn bench_guide_commands_run() {
    run_doc_with("docs/bench.md", &[("XDG_DATA_HOME", "{dir}/xdg")]);
}
