//! Helpers shared by the TMCL tests.
#![allow(dead_code)]

use tmcl::chip::ModelChip;
use tmcl::personality::ModuleType;
use tmcl::proto::{checksum, Instruction};
use tmcl::{Module, Response};

/// A three-axis TMCM-3110 on a TMC429 at 16 MHz.
pub fn module() -> Module<ModelChip> {
    module_of(ModuleType::Tmcm3110)
}

/// A module of the given type on a TMC429 at 16 MHz.
pub fn module_of(kind: ModuleType) -> Module<ModelChip> {
    Module::of_type(ModelChip::new(tmc429_model::Chip::Tmc429, 16_000_000), kind)
}

/// A 9-byte command frame: the 8 bytes and their checksum.
pub fn frame(b8: [u8; 8]) -> [u8; 9] {
    let mut f = [0u8; 9];
    f[..8].copy_from_slice(&b8);
    f[8] = checksum(&b8);
    f
}

/// One command in direct mode: status and value of the reply.
pub fn direct(m: &mut Module<ModelChip>, o: u8, t: u8, mo: u8, v: i32) -> (u8, i32) {
    match m.handle_instruction(&Instruction::new(o, t, mo, v)) {
        Response::Normal(r) => (r.status, r.value),
        other => panic!("command {o}: {other:?}"),
    }
}

/// One command in direct mode that must succeed (status 100); its value.
pub fn ok(m: &mut Module<ModelChip>, o: u8, t: u8, mo: u8, v: i32) -> i32 {
    let (s, r) = direct(m, o, t, mo, v);
    assert_eq!(s, 100, "command {o} type {t} motor {mo} value {v}");
    r
}

/// Axis parameter `p` of motor `mo`.
pub fn gap(m: &mut Module<ModelChip>, p: u8, mo: u8) -> i32 {
    ok(m, tmcl::proto::op::GAP, p, mo, 0)
}

/// Runs the module until `done` holds (checked every 10 ms); the milliseconds it took.
/// Panics after `max_ms`.
pub fn run_until(m: &mut Module<ModelChip>, max_ms: u64, mut done: impl FnMut(&mut Module<ModelChip>) -> bool) -> u64 {
    let mut ms = 0;
    while !done(m) {
        assert!(ms < max_ms, "not done after {max_ms} ms");
        m.run_ms(10);
        ms += 10;
    }
    ms
}
