//! Any datagram to any address, in any order, never panics and keeps the state inside its
//! widths (run in the dev profile, arithmetic overflow checks are on).

mod common;
use common::*;

use proptest::prelude::*;
use tmc429_model::motor_regs::V_MAG_MAX;
use tmc429_model::Chip;

#[derive(Clone, Debug)]
enum Op {
    Datagram(u32),
    Short(u32, u32),
    Wait(u64),
    Pins(u8),
}

fn ops() -> impl Strategy<Value = Vec<Op>> {
    prop::collection::vec(
        prop_oneof![
            4 => any::<u32>().prop_map(Op::Datagram),
            1 => (1u32..32, any::<u32>()).prop_map(|(n, v)| Op::Short(n, v)),
            2 => (1u64..50_000).prop_map(Op::Wait),
            1 => any::<u8>().prop_map(Op::Pins),
        ],
        1..60,
    )
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]
    #[test]
    fn arbitrary_traffic_never_panics(chip in prop::sample::select(Chip::ALL.to_vec()), ops in ops()) {
        let mut h = host(chip);
        for op in ops {
            match op {
                Op::Datagram(d) => {
                    // the TMC4210 has no SDOZ_C: with sdo_int its replies reach no pin (C90)
                    let muted = chip == Chip::Tmc4210 && h.chip().global().ifc(tmc429_model::regmap::f::SDO_INT);
                    let r = h.datagram(d);
                    if (d >> 24) & 1 == 0 && !muted {
                        prop_assert_eq!(r & 0xFF_FFFF, 0, "write replies carry 24 zero bits");
                    }
                }
                Op::Short(n, v) => {
                    h.frame(v & ((1 << n) - 1), n);
                }
                Op::Wait(n) => h.wait(n),
                Op::Pins(p) => {
                    let i = h.pins_mut();
                    i.ref1 = p & 1 != 0;
                    i.ref2 = p & 2 != 0;
                    i.ref3 = p & 4 != 0;
                    i.refr1 = p & 8 != 0;
                    i.refr2 = p & 16 != 0;
                    i.refr3 = p & 32 != 0;
                    i.sdi_s = p & 64 != 0;
                }
            }
            for m in 0..3 {
                let mo = h.chip().motor(m);
                prop_assert!(mo.v.abs() <= V_MAG_MAX);
                prop_assert!(mo.x_actual < 1 << 24 && mo.x_target < 1 << 24 && mo.x_latched < 1 << 24);
                prop_assert!(mo.acc < 2048);
                prop_assert!(mo.a_actual.unsigned_abs() <= mo.a_max as u32 || mo.a_actual.unsigned_abs() <= 2047);
            }
        }
    }
}
