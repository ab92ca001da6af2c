//! The built-in scenario of `tmc429 demo` (examples/scenarios/demo.toml).

/// The demo's scenario text.
pub const DEMO_TOML: &str = include_str!("../../examples/scenarios/demo.toml");

/// The name the demo's scenario goes by in messages.
pub const DEMO_FILE: &str = "examples/scenarios/demo.toml";
