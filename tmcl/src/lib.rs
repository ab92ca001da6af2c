//! TMCL module layer (see docs/tmcl.md): the TMCL protocol, a TMCM-3110-compatible module
//! firmware that drives the golden model through its SPI port, an assembler, and a server.

pub mod asm;
pub mod calc;
pub mod chip;
pub mod config;
pub mod eeprom;
pub mod io;
pub mod link;
pub mod module;
pub mod proto;
pub mod server;

pub use chip::Spi429;
pub use module::{Module, Origin};
pub use proto::{Command, Instruction, Reply, Response, Status};
