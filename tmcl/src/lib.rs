//! TMCL module layer (see docs/tmcl.md).
