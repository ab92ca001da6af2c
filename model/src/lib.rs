//! Cycle-accurate, pin-level golden model of the Trinamic TMC428 / TMC429 / TMC4210.
pub mod chip;
pub mod pins;
pub use chip::Chip;
pub use pins::{ChainProbe, Inputs, MotorProbe, Outputs, Probes};
