//! TMCL module layer (see docs/tmcl.md): the TMCL protocol, a module firmware that drives the
//! golden model through its SPI port as a TMCM-3110 or as the TMCM-1311 of the TMCL firmware
//! manual ([TMCL]), an assembler, and a server.

pub mod asm;
mod asm_expr;
mod asm_symbols;
pub mod calc;
pub mod chip;
pub mod config;
mod disasm;
pub mod eeprom;
pub mod io;
pub mod link;
pub mod module;
pub mod personality;
pub mod proto;
pub mod seed;
pub mod server;
pub mod units;

pub use chip::Spi429;
pub use module::{Module, Origin};
pub use proto::{Command, Instruction, Reply, Response, Status};
