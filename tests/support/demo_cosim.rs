/// Whether the RTL's motion core and driver chain are on this branch: then the demo
/// co-simulates with 0 mismatches (tests/cli_scenario.rs `demo_cosim_has_no_mismatch`, remove
/// its `#[ignore]` too), and the docs test runs the README's first command co-simulated
/// (tests/docs_commands.rs). Until then both run the demo on the model, and
/// `demo_cosim_runs_and_reports` checks that the co-simulated demo runs and reports.
pub const DEMO_COSIM_READY: bool = false;
