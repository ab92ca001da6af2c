//! `scripts/equiv --against REV`: Yosys' equivalence passes prove a module of the working tree's
//! `rtl/` against the same module at a git revision (docs/fpga.md "Formal equivalence"). A module
//! the revision has unchanged proves every pair; a name that is no revision is a usage error.

use std::path::Path;
use std::process::{Command, Output};

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn equiv(args: &[&str]) -> Output {
    Command::new(root().join("scripts/equiv")).args(args).current_dir(root()).output().unwrap()
}

fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

/// The line's part before the wall time, e.g. "  tmc429 tmc429_sync: 3 of 3 pairs proven".
fn without_time(line: &str) -> &str {
    line.rsplit_once(" (").map_or(line, |(a, _)| a)
}

#[test]
fn a_module_against_the_checked_out_revision_proves_every_pair() {
    // the synchronizer at HEAD against the working tree's (the same, or a change that keeps
    // it): its three registers (first stage, output, history) are the pairs
    let o = equiv(&["--chip", "tmc429", "--module", "tmc429_sync", "--against", "HEAD"]);
    assert_eq!(o.status.code(), Some(0), "stderr: {}", text(&o.stderr));
    let out = text(&o.stdout);
    let lines: Vec<&str> = out.lines().map(without_time).collect();
    assert_eq!(lines, ["  tmc429 tmc429_sync: 3 of 3 pairs proven"]);
}

#[test]
fn a_name_that_is_no_revision_exits_2_and_says_so() {
    let o = equiv(&["--chip", "tmc429", "--module", "tmc429_sync", "--against", "no-such-revision"]);
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(text(&o.stderr), "equiv: 'no-such-revision' is not a revision of this repository\n");
    assert_eq!(text(&o.stdout), "");
}

#[test]
fn against_without_a_revision_is_a_usage_error() {
    let o = equiv(&["--against"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(text(&o.stderr).starts_with("usage: scripts/equiv "), "stderr: {}", text(&o.stderr));
}
