//! One module per subcommand.
pub mod common;
pub mod cosim;
pub mod regmap;
pub mod spi;
pub mod tmcl;
pub mod vectors;
