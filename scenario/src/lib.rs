//! Scenarios of the tmc429 reference implementation (docs/scenarios.md): the TOML format and
//! its parser, the engines that run them (golden model, Verilated RTL, co-simulation), VCD and
//! GTKWave save files, test vectors, plots in physical units, the unit calculator of
//! `tmc429 calc`, and the built-in demo.

pub mod calc;
pub mod capture;
pub mod demo;
pub mod gtkw;
pub mod plot;
pub mod run;
pub mod scenario;
pub mod units;
pub mod vcdout;
pub mod vectors;

pub use run::{run, Engine, Options, Report};
pub use scenario::{parse, ParseError, Scenario};
