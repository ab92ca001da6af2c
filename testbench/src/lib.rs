//! Co-simulation harness: the golden model and the Verilated RTL in lock-step
//! (docs/cosim.md).
//!
//! - [`rtl`]: the Verilated `tmc429_top` behind a cxx bridge, one FFI call per CLK cycle;
//! - [`signals`], [`stimulus`], [`coverage`]: the compared signals, the transaction-level
//!   stimulus and the functional coverage, from `tmc429-verif` (the model's side of lock-step
//!   verification, shared with the Python package and the C library);
//! - [`trace`]: the side-by-side VCD;
//! - [`cosim`]: the lock-step run and its report;
//! - [`pair`]: the lock-step pair on two threads (model side and RTL side);
//! - [`vectors`]: test vectors from the golden model (docs/vectors.md).
pub mod cosim;
pub mod pair;
pub mod rtl;
pub mod trace;
pub mod vectors;

pub use cosim::{run, Config, Mismatch, Outcome};
pub use rtl::{Rtl, Variant};
pub use tmc429_verif::{coverage, signals, stimulus};
