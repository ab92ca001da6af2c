//! rtl/tmc429_stepdir.v against the model's Step/Dir unit (tmc429_model::stepdir, C91–C96) at
//! the unit boundary, with Icarus Verilog: random step streams (bursts faster than the output,
//! direction changes, step_half, STPDIV changes, Step/Dir mode off and on, power down) drive the
//! model, whose STEP/DIR levels after every edge become the vectors a Verilog test bench checks.
//! The co-simulation of the whole chip cannot do this yet: without the motion core no motor
//! steps.

mod common;

use tmc429_model::motor_regs::Motor;
use tmc429_model::stepdir::StepDir;

const CYCLES: usize = 400_000;

/// One edge: inputs of the unit and the expected levels after it.
#[derive(Clone, Copy)]
struct Vector {
    run: bool,
    en: bool,
    step: bool,
    dir: bool,
    step_half: bool,
    stpdiv: u8,
    want_step: bool,
    want_dir: bool,
}

impl Vector {
    fn hex(&self) -> String {
        let v = (self.run as u32) << 10
            | (self.en as u32) << 9
            | (self.step as u32) << 8
            | (self.dir as u32) << 7
            | (self.step_half as u32) << 6
            | (self.stpdiv as u32 & 15) << 2
            | (self.want_step as u32) << 1
            | self.want_dir as u32;
        format!("{v:03x}")
    }
}

fn vectors(seed: u64) -> Vec<Vector> {
    let mut draw = common::draws(seed);
    let mut sd = StepDir::reset();
    let mut motors = [Motor::reset(); 3];
    let mut now = 0u64;
    let (mut en, mut run, mut dir, mut step_half, mut stpdiv) = (true, true, false, false, 0u8);
    // step probability per edge in 1/1024: bursts above the output rate and quiet stretches
    let mut rate = 40u32;
    let mut out = Vec::with_capacity(CYCLES);
    for _ in 0..CYCLES {
        match draw(4000) {
            0 => en = !en,
            1..=2 => run = !run,
            3..=5 => step_half = !step_half,
            6..=9 => stpdiv = if draw(4) == 0 { draw(16) as u8 } else { draw(3) as u8 },
            10..=40 => rate = [0, 5, 40, 200, 1024][draw(5) as usize],
            41..=70 => dir = !dir,
            _ => {}
        }
        if !run && draw(300) == 0 {
            run = true;
        }
        let step = draw(1024) < rate;
        motors[0].step = step;
        motors[0].dir = dir;
        if run {
            now += 1;
            sd.tick(now, en, 1, &motors, (stpdiv as u32) << 0, step_half);
        }
        out.push(Vector { run, en, step, dir, step_half, stpdiv, want_step: sd.step[0], want_dir: sd.dir[0] });
    }
    out
}

const BENCH: &str = r#"
`timescale 1ns / 1ps
module tb;
    reg clk = 0, rst = 1;
    reg run = 0, en = 0, step_in = 0, dir_in = 0, step_half = 0;
    reg [3:0] stpdiv = 0;
    wire step, dir, step_n, dir_n;
    reg [10:0] vec [0:NVEC-1];
    integer i, bad;
    tmc429_stepdir dut (.clk(clk), .rst(rst), .run(run), .en(en), .step_in(step_in),
        .dir_in(dir_in), .stpdiv(stpdiv), .step_half(step_half), .step(step), .dir(dir),
        .step_n(step_n), .dir_n(dir_n));
    always #5 clk = ~clk;
    initial begin
        $readmemh("vectors.hex", vec);
        bad = 0;
        @(posedge clk); #1 rst = 0;
        for (i = 0; i < NVEC; i = i + 1) begin
            {run, en, step_in, dir_in, step_half, stpdiv} = vec[i][10:2];
            @(posedge clk); #1;
            if ({step, dir} !== vec[i][1:0]) begin
                if (bad < 5)
                    $display("MISMATCH at edge %0d: rtl %b%b model %b", i + 1, step, dir, vec[i][1:0]);
                bad = bad + 1;
            end
        end
        $display("EDGES %0d MISMATCHES %0d", NVEC, bad);
        $finish;
    end
endmodule
"#;

#[test]
fn stepdir_unit_matches_the_model() {
    let v = vectors(1);
    // the stream must exercise the unit: pulses, direction changes, a backlog
    assert!(v.windows(2).filter(|w| !w[0].want_step && w[1].want_step).count() > 1000);
    assert!(v.windows(2).filter(|w| w[0].want_dir != w[1].want_dir).count() > 100);
    let lines: Vec<String> = v.iter().map(|x| x.hex()).collect();
    let text = common::icarus_unit("tmc429_stepdir", BENCH, &lines);
    assert!(text.contains(&format!("EDGES {} MISMATCHES 0", v.len())), "{text}");
}
