//! C ABI (see docs/c-api.md).
