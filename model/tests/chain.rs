//! Driver-chain SPI master at pin level (TMC428 §6.3, §9.1–§9.7, §11; spec-digest §5.2;
//! contract C80–C89).

mod common;
use common::*;
use tmc429_model::Chip;

#[test]
fn smoke() {
    let (mut h, log) = host_with_events(Chip::Tmc429);
    load_tables(&mut h);
    request(&mut h);
    settle(&mut h, 10_000);
    println!("{:X?}", chains(&log));
}
