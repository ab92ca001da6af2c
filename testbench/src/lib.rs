//! Co-simulation harness: the golden model and the Verilated RTL in lock-step
//! (docs/cosim.md).
pub mod rtl;
