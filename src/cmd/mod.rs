//! One module per subcommand.
pub mod common;
pub mod regmap;
pub mod spi;
