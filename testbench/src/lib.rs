//! Co-simulation harness (see docs/cosim.md).
