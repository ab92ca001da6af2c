//! rtl/tmc429_stepdir.v against the model's Step/Dir unit (tmc429_model::stepdir, C91–C96) at
//! the unit boundary, with Icarus Verilog: random step streams of the three motors (bursts
//! faster than the output, direction changes, step_half, STPDIV changes, Step/Dir mode off and
//! on, power down) drive the model, whose STEP/DIR levels after every edge become the vectors a
//! Verilog test bench checks. As in the chip, motor m's step flag can be 1 only in the edge at
//! its phase `PHASE_STEPDIR[m]` (the edge after its step, C53), the frame's phase advances
//! in the running edges alone, and the unit sees the phase's low four bits. The co-simulation of
//! the whole chip checks the same unit with the motion core's own steps.

mod common;

use tmc429_model::motor_regs::Motor;
use tmc429_model::schedule::PHASE_STEPDIR;
use tmc429_model::stepdir::StepDir;

const CYCLES: usize = 400_000;

/// One edge: inputs of the unit and the expected levels after it.
#[derive(Clone, Copy)]
struct Vector {
    run: bool,
    en: bool,
    phase: u32,
    step: u8,
    dir: u8,
    step_half: bool,
    stpdiv: u8,
    want_step: u8,
    want_dir: u8,
}

impl Vector {
    /// run, en, phase[3:0], step[2:0], dir[2:0], step_half, stpdiv[3:0], want_step[2:0],
    /// want_dir[2:0] from bit 22 down.
    fn hex(&self) -> String {
        let v = (self.run as u32) << 22
            | (self.en as u32) << 21
            | (self.phase & 15) << 17
            | (self.step as u32) << 14
            | (self.dir as u32) << 11
            | (self.step_half as u32) << 10
            | (self.stpdiv as u32 & 15) << 6
            | (self.want_step as u32) << 3
            | self.want_dir as u32;
        format!("{v:06x}")
    }
}

fn bits(b: [bool; 3]) -> u8 {
    b[0] as u8 | (b[1] as u8) << 1 | (b[2] as u8) << 2
}

/// The vectors and, per motor, the largest backlog magnitude the model reached.
fn vectors(seed: u64) -> (Vec<Vector>, [i32; 3]) {
    let mut draw = common::draws(seed);
    let mut sd = StepDir::reset();
    let mut motors = [Motor::reset(); 3];
    let (mut now, mut phase) = (0u64, 0u32);
    let (mut en, mut run, mut step_half, mut stpdiv) = (true, true, false, 0u8);
    let mut dir = [false; 3];
    // step probability per slot in 1/1024: bursts above the output rate and quiet stretches
    let mut rate = 400u32;
    let mut out = Vec::with_capacity(CYCLES);
    let mut deepest = [0i32; 3];
    for _ in 0..CYCLES {
        match draw(4000) {
            0 => en = !en,
            1..=2 => run = !run,
            3..=5 => step_half = !step_half,
            6..=9 => stpdiv = if draw(4) == 0 { draw(16) as u8 } else { draw(3) as u8 },
            10..=40 => rate = [0, 100, 400, 900, 1024][draw(5) as usize],
            41..=100 => dir[draw(3) as usize] ^= true,
            _ => {}
        }
        if !run && draw(300) == 0 {
            run = true;
        }
        for (m, mo) in motors.iter_mut().enumerate() {
            // the step flag of the old state: 1 only after the motor's step edge
            mo.step = phase == PHASE_STEPDIR[m] && draw(1024) < rate;
            mo.dir = dir[m];
        }
        if run {
            now += 1;
            sd.tick(now, en, 3, &motors, stpdiv as u32, step_half);
            for m in 0..3 {
                deepest[m] = deepest[m].max(sd.backlog[m].abs());
            }
        }
        out.push(Vector {
            run,
            en,
            phase,
            step: bits(motors.map(|mo| mo.step)),
            dir: bits(dir),
            step_half,
            stpdiv,
            want_step: bits(sd.step),
            want_dir: bits(sd.dir),
        });
        if run {
            phase = (phase + 1) % 32;
        }
    }
    (out, deepest)
}

const BENCH: &str = r#"
`timescale 1ns / 1ps
module tb;
    reg clk = 0, rst = 1;
    reg run = 0, en = 0, step_half = 0;
    reg [3:0] phase = 0, stpdiv = 0;
    reg [2:0] step_in = 0, dir_in = 0;
    wire [2:0] step, dir, step_nx, dir_nx;
    reg [22:0] vec [0:NVEC-1];
    integer i, bad;
    tmc429_stepdir #(.MOTORS(3)) dut (.clk(clk), .rst(rst), .run(run), .en(en), .phase(phase),
        .step_in(step_in), .dir_in(dir_in), .stpdiv(stpdiv), .step_half(step_half),
        .step(step), .dir(dir), .step_nx(step_nx), .dir_nx(dir_nx));
    always #5 clk = ~clk;
    initial begin
        $readmemh("vectors.hex", vec);
        bad = 0;
        @(posedge clk); #1 rst = 0;
        for (i = 0; i < NVEC; i = i + 1) begin
            {run, en, phase, step_in, dir_in, step_half, stpdiv} = vec[i][22:6];
            @(posedge clk); #1;
            if ({step, dir} !== vec[i][5:0]) begin
                if (bad < 5)
                    $display("MISMATCH at edge %0d: rtl %b %b model %b", i + 1, step, dir, vec[i][5:0]);
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
    let (v, deepest) = vectors(1);
    // the stream must exercise every motor: pulses, direction changes, a backlog beyond the
    // flags the unit keeps (0, 1, -1), so that the RAM's words are read back
    for m in 0..3 {
        let rises = v.windows(2).filter(|w| (!w[0].want_step & w[1].want_step) >> m & 1 != 0).count();
        let turns = v.windows(2).filter(|w| (w[0].want_dir ^ w[1].want_dir) >> m & 1 != 0).count();
        assert!(rises > 1000 && turns > 100 && deepest[m] >= 20, "motor {m}: {rises} {turns} {}", deepest[m]);
    }
    let lines: Vec<String> = v.iter().map(|x| x.hex()).collect();
    let text = common::icarus_modules(&["tmc429_stepdir", "tmc429_wram"], BENCH, &lines);
    assert!(text.contains(&format!("EDGES {} MISMATCHES 0", v.len())), "{text}");
}
