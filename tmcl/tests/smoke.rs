mod common;
use common::*;

use tmcl::chip::ModelChip;
use tmcl::proto::{op, Instruction};
use tmcl::{Module, Response};

fn cmd(m: &mut Module<ModelChip>, o: u8, t: u8, mo: u8, v: i32) -> (u8, i32) {
    match m.handle_instruction(&Instruction::new(o, t, mo, v)) {
        Response::Normal(r) => (r.status, r.value),
        other => panic!("unexpected {other:?}"),
    }
}

#[test]
fn move_and_speed() {
    let mut m = module();
    let t0 = std::time::Instant::now();
    assert_eq!(cmd(&mut m, op::MVP, 0, 0, 10000), (100, 10000));
    let mut ms = 0;
    while cmd(&mut m, op::GAP, 8, 0, 0).1 == 0 && ms < 5000 {
        m.run_ms(10);
        ms += 10;
    }
    eprintln!("move took {ms} ms model time, {:?} wall", t0.elapsed());
    assert_eq!(cmd(&mut m, op::GAP, 1, 0, 0), (100, 10000));
}
