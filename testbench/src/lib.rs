//! Co-simulation harness: the golden model and the Verilated RTL in lock-step
//! (docs/cosim.md).
//!
//! - [`rtl`]: the Verilated `tmc429_top` behind a cxx bridge, one FFI call per CLK cycle;
//! - [`signals`]: the compared pins and probes and the [`signals::Compare`] mask;
//! - [`stimulus`]: transaction-level stimulus (proptest strategies, seeded stream, pin driver);
//! - [`coverage`]: functional coverage bins;
//! - [`trace`]: the side-by-side VCD;
//! - [`cosim`]: the lock-step run and its report;
//! - [`pair`]: the lock-step pair on two threads (model side and RTL side);
//! - [`vectors`]: test vectors from the golden model (docs/vectors.md).
pub mod cosim;
pub mod coverage;
mod motion_stim;
pub mod pair;
pub mod rtl;
pub mod signals;
pub mod stimulus;
pub mod trace;
pub mod vectors;

pub use cosim::{run, Config, Mismatch, Outcome};
pub use rtl::{Rtl, Variant};
