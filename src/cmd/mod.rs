//! One module per subcommand.
pub mod calc;
pub mod capture;
pub mod common;
pub mod cosim;
pub mod demo;
pub mod regmap;
pub mod run;
pub mod spi;
pub mod tmcl;
pub mod vectors;
