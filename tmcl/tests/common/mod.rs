//! Helpers shared by the TMCL tests.
#![allow(dead_code)]

use tmcl::chip::ModelChip;
use tmcl::proto::checksum;
use tmcl::Module;

/// A three-axis TMC429 module at 16 MHz.
pub fn module() -> Module<ModelChip> {
    Module::new(ModelChip::new(tmc429_model::Chip::Tmc429, 16_000_000))
}

/// A 9-byte command frame: the 8 bytes and their checksum.
pub fn frame(b8: [u8; 8]) -> [u8; 9] {
    let mut f = [0u8; 9];
    f[..8].copy_from_slice(&b8);
    f[8] = checksum(&b8);
    f
}
