//! rtl/tmc429_current.v against the model's current-scale selection (tmc429_model::current,
//! C75–C77; TMC428 §8.9 Table 8-2, TMC429 §8.1.9) at the unit boundary, with Icarus Verilog:
//! ramp ticks while moving with |a_actual| at a_threshold − 1, a_threshold and a_threshold + 1 on
//! both signs (a_actual −2048 included), thresholds across 0..1023 and above 1023 (always
//! is_aleat), and rests of 255 ramp ticks with is_agtat and is_aleat zero and nonzero. After every
//! edge the RTL's i_scale must be the model's.

mod common;

use tmc429_model::current::{CurrentScale, SEL_AGTAT, SEL_ALEAT, SEL_V0};
use tmc429_model::motor_regs::Motor;

/// One edge: inputs of the unit and the expected i_scale after it.
#[derive(Clone, Copy)]
struct Vector {
    tick: bool,
    v_nz: bool,
    a_actual: i32,
    a_threshold: u16,
    is: [u8; 3],
    want: u8,
}

impl Vector {
    fn hex(&self) -> String {
        let v = (self.tick as u64) << 37
            | (self.v_nz as u64) << 36
            | ((self.a_actual as u64) & 0xFFF) << 24
            | (self.a_threshold as u64 & 0x7FF) << 13
            | (self.is[0] as u64) << 10
            | (self.is[1] as u64) << 7
            | (self.is[2] as u64) << 4
            | self.want as u64;
        format!("{v:010x}")
    }
}

/// The a_actual values at and beside threshold `t`, on both signs, in the 12-bit range.
fn around(t: i32) -> Vec<i32> {
    let mut a: Vec<i32> = [t - 1, t, t + 1].iter().flat_map(|&x| [x, -x]).collect();
    a.extend([0, 2047, -2047, -2048]);
    a.retain(|x| (-2048..=2047).contains(x));
    a
}

/// The vectors and how often each selection followed a tick.
fn vectors() -> (Vec<Vector>, [usize; 3]) {
    let mut m = Motor::reset();
    let mut cs = CurrentScale::default();
    let mut out = Vec::new();
    let mut seen = [0usize; 3];
    let mut edge = |m: &Motor, cs: &mut CurrentScale, tick: bool, out: &mut Vec<Vector>| {
        if tick {
            cs.ramp_tick(m);
            seen[cs.sel as usize] += 1;
        }
        out.push(Vector {
            tick,
            v_nz: m.v != 0,
            a_actual: m.a_actual,
            a_threshold: m.a_threshold,
            is: [m.is_agtat, m.is_aleat, m.is_v0],
            want: cs.i_scale(m),
        });
    };
    let thresholds = [0, 1, 2, 7, 255, 511, 512, 1000, 1022, 1023, 1024, 1025, 1500, 2047];
    for (k, &t) in thresholds.iter().enumerate() {
        m.a_threshold = t;
        (m.is_agtat, m.is_aleat, m.is_v0) = (1 + (k % 7) as u8, 7 - (k % 7) as u8, 3);
        for a in around(t as i32) {
            m.v = 256;
            m.a_actual = a;
            edge(&m, &mut cs, true, &mut out);
            edge(&m, &mut cs, false, &mut out);
        }
        // at rest: 255 ticks, then is_v0 (is_agtat and is_aleat > 0) or is_aleat (one is 0)
        if k % 3 == 0 {
            m.is_agtat = 0;
        }
        m.v = 0;
        for _ in 0..260 {
            edge(&m, &mut cs, true, &mut out);
        }
    }
    (out, seen)
}

const BENCH: &str = r#"
`timescale 1ns / 1ps
module tb;
    reg clk = 0, rst = 1;
    reg tick = 0, v_nz = 0;
    reg [11:0] a_actual = 0;
    reg [10:0] a_threshold = 0;
    reg [2:0] is_agtat = 0, is_aleat = 0, is_v0 = 0;
    wire [2:0] i_scale;
    reg [37:0] vec [0:NVEC-1];
    integer i, bad;
    tmc429_current dut (.clk(clk), .rst(rst), .tick(tick), .v_nz(v_nz), .a_actual(a_actual),
        .a_threshold(a_threshold), .is_agtat(is_agtat), .is_aleat(is_aleat), .is_v0(is_v0),
        .i_scale(i_scale));
    always #5 clk = ~clk;
    initial begin
        $readmemh("vectors.hex", vec);
        bad = 0;
        @(posedge clk); #1 rst = 0;
        for (i = 0; i < NVEC; i = i + 1) begin
            {tick, v_nz, a_actual, a_threshold, is_agtat, is_aleat, is_v0} = vec[i][37:4];
            @(posedge clk); #1;
            if (i_scale !== vec[i][2:0]) begin
                if (bad < 5)
                    $display("MISMATCH at edge %0d: rtl %0d model %0d", i + 1, i_scale, vec[i][2:0]);
                bad = bad + 1;
            end
        end
        $display("EDGES %0d MISMATCHES %0d", NVEC, bad);
        $finish;
    end
endmodule
"#;

#[test]
fn current_unit_matches_the_model_at_the_threshold() {
    let (v, seen) = vectors();
    // every selection is made, is_agtat and is_aleat on both sides of the threshold
    assert!(seen[SEL_AGTAT as usize] > 50 && seen[SEL_ALEAT as usize] > 50 && seen[SEL_V0 as usize] > 50, "{seen:?}");
    let lines: Vec<String> = v.iter().map(|x| x.hex()).collect();
    let text = common::icarus_unit("tmc429_current", BENCH, &lines);
    assert!(text.contains(&format!("EDGES {} MISMATCHES 0", v.len())), "{text}");
}

/// Table 8-2 at the threshold itself, in the model the RTL is held to: |a_actual| equal to
/// a_threshold is not above it, one more is; a_threshold above 1023 never selects is_agtat.
#[test]
fn the_threshold_is_exclusive() {
    let mut m = Motor::reset();
    (m.v, m.is_agtat, m.is_aleat) = (256, 5, 2);
    let sel = |m: &Motor| {
        let mut cs = CurrentScale::default();
        cs.ramp_tick(m);
        cs.sel
    };
    for (t, a, want) in [
        (100, 100, SEL_ALEAT),
        (100, 101, SEL_AGTAT),
        (100, -100, SEL_ALEAT),
        (100, -101, SEL_AGTAT),
        (1023, -2048, SEL_AGTAT),
        (1024, -2048, SEL_ALEAT),
        (0, 0, SEL_ALEAT),
        (0, -1, SEL_AGTAT),
    ] {
        (m.a_threshold, m.a_actual) = (t, a);
        assert_eq!(sel(&m), want, "a_threshold {t}, a_actual {a}");
    }
}
