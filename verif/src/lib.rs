//! The golden model's side of lock-step verification, without any RTL: what `tmc429 cosim`,
//! the Python package's cocotb harness and the C library's DPI-C entry share (docs/cosim.md,
//! docs/verify-your-rtl.md).
//!
//! - [`stimulus`]: transaction-level stimulus (proptest strategies, seeded stream, pin driver);
//! - [`coverage`]: functional coverage bins;
//! - [`signals`]: the compared pins and probes and the [`signals::Compare`] mask;
//! - [`pinword`]: the pins packed into one word per direction (cocotb wrapper, DPI-C);
//! - [`lockstep`]: the stimulus as pins with its transaction log, the golden model beside it,
//!   and the first-mismatch report.
//!
//! A seed means the same stimulus wherever it is used: `tests/seeds.rs` pins it down.
pub mod coverage;
pub mod lockstep;
mod motion_stim;
pub mod pinword;
pub mod signals;
pub mod stimulus;
