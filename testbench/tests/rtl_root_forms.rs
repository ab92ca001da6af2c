//! The two forms of the square root's running steps (rtl/tmc429_vroot.v's parameter
//! `ROOT_SPEC`: 0 non-restoring steps, 1 restoring steps with three differences side by side,
//! docs/rtl.md "The target-velocity pipeline") give the same committed target velocities
//! (C50), with Icarus Verilog: the forms side by side, for three motors and for one (the
//! TMC4210's unit), under one random stream of register values, positions and µC writes, and
//! compared after every edge. Every variant builds form 0, which co-simulation checks against
//! the model; this test keeps form 1, the option of one carry chain per cycle, exact too.

mod common;

/// Edges of each stream; two streams (two tests, run side by side).
const CYCLES: usize = 150_000;
/// Each stream makes more than MIN_CHANGES changes of the committed velocities, and motor 0's
/// velocity takes more than MIN_DISTINCT values.
const MIN_CHANGES: u32 = 500;
const MIN_DISTINCT: u32 = 100;

/// The inputs of one edge, as the bench's 224-bit line (nibble-aligned fields, see BENCH).
struct Edge {
    run: bool,
    rm: [u8; 3],
    x_target: [u32; 3],
    x_actual: [u32; 3],
    v_target: [u16; 3],
    brake_en: u8,
    we: bool,
    m: u8,
    sel: u8,
    data: u16,
}

impl Edge {
    fn hex(&self) -> String {
        let rm = self.rm[0] as u32 | (self.rm[1] as u32) << 2 | (self.rm[2] as u32) << 4;
        let x = |v: &[u32; 3]| format!("{:06x}{:06x}{:06x}", v[2] & 0xFF_FFFF, v[1] & 0xFF_FFFF, v[0] & 0xFF_FFFF);
        let vt = |v: &[u16; 3]| format!("{:03x}{:03x}{:03x}", v[2] & 0xFFF, v[1] & 0xFFF, v[0] & 0xFFF);
        format!(
            "{:x}{:02x}{}{}{}{:x}{:x}{:x}{:x}{:04x}",
            self.run as u8,
            rm,
            x(&self.x_target),
            x(&self.x_actual),
            vt(&self.v_target),
            self.brake_en & 7,
            self.we as u8,
            self.m,
            self.sel,
            self.data & 0x7FFF
        )
    }
}

fn stream(seed: u64) -> Vec<String> {
    let mut draw = common::draws(seed);
    let mut e =
        Edge { run: true, rm: [0; 3], x_target: [0; 3], x_actual: [0; 3], v_target: [0; 3], brake_en: 0, we: false, m: 0, sel: 0, data: 0 };
    let mut out = Vec::with_capacity(CYCLES);
    for _ in 0..CYCLES {
        if e.run {
            e.run = draw(20_000) != 0;
        } else {
            e.run = draw(200) == 0;
        }
        for m in 0..3 {
            if draw(3000) == 0 {
                // RAMP_MODE most of the time: its target velocity is the square root
                e.rm[m] = [0, 0, 0, 1, 2, 3][draw(6) as usize] as u8;
            }
            if draw(2000) == 0 {
                e.x_target[m] = match draw(3) {
                    0 => draw(1 << 24),
                    1 => e.x_actual[m].wrapping_add(draw(1 << 13)).wrapping_sub(1 << 12),
                    _ => e.x_actual[m].wrapping_add(draw(1 << 20)).wrapping_sub(1 << 19),
                };
            }
            match draw(8) {
                0 => e.x_actual[m] = e.x_actual[m].wrapping_add(1),
                1 => e.x_actual[m] = e.x_actual[m].wrapping_sub(1),
                _ => {}
            }
            if draw(5000) == 0 {
                e.x_actual[m] = draw(1 << 24);
            }
            if draw(3000) == 0 {
                e.v_target[m] = draw(1 << 12) as u16;
            }
        }
        if draw(3000) == 0 {
            e.brake_en = draw(8) as u8;
        }
        // a write's motor, register and data still hold in the edge after it (the port's rule)
        if e.we {
            e.we = false;
        } else if draw(150) == 0 {
            e.we = true;
            e.m = draw(3) as u8;
            e.sel = draw(4) as u8;
            // v_max mostly high, so that the root, not the clamp, sets the velocity
            e.data = match (e.sel, draw(4)) {
                (1, 0) => draw(1 << 15) as u16,
                (1, _) => (1024 + draw(1024)) as u16,
                _ => draw(1 << 15) as u16,
            };
        }
        out.push(e.hex());
    }
    out
}

const BENCH: &str = r#"
`timescale 1ns / 1ps
`include "tmc429_regmap.vh"
module tb;
    reg clk = 0, rst = 1;
    reg [223:0] vec [0:NVEC-1];
    reg [223:0] v = 224'd0;
    reg [4:0] phase = 5'd0;
    wire       run      = v[220];
    wire [5:0] rm       = v[217:212];
    wire [71:0] x_t     = v[211:140];
    wire [71:0] x_a     = v[139:68];
    wire [35:0] v_t     = v[67:32];
    wire [2:0] brake_en = v[30:28];
    wire       we       = v[24];
    wire [1:0] m        = v[21:20];
    wire [1:0] sel      = v[17:16];
    wire [14:0] data    = v[14:0];
    wire [3:0] idx = (sel == 2'd0) ? `TMC429_IDX_V_MIN : (sel == 2'd1) ? `TMC429_IDX_V_MAX
                   : (sel == 2'd2) ? `TMC429_IDX_A_MAX : `TMC429_IDX_PMUL_PDIV;
    wire [35:0] vt30, vt31, vt10, vt11;
    tmc429_vtarget #(.NMOT(3), .ROOT_SPEC(0)) u30 (.clk(clk), .rst(rst), .run(run), .phase(phase),
        .rm(rm), .x_target(x_t), .x_actual(x_a), .v_target(v_t), .brake_en(brake_en),
        .cfg_we(we), .cfg_m(m), .cfg_idx(idx), .cfg_data(data), .vt(vt30));
    tmc429_vtarget #(.NMOT(3), .ROOT_SPEC(1)) u31 (.clk(clk), .rst(rst), .run(run), .phase(phase),
        .rm(rm), .x_target(x_t), .x_actual(x_a), .v_target(v_t), .brake_en(brake_en),
        .cfg_we(we), .cfg_m(m), .cfg_idx(idx), .cfg_data(data), .vt(vt31));
    tmc429_vtarget #(.NMOT(1), .ROOT_SPEC(0)) u10 (.clk(clk), .rst(rst), .run(run), .phase(phase),
        .rm(rm), .x_target(x_t), .x_actual(x_a), .v_target(v_t), .brake_en(brake_en),
        .cfg_we(we & (m == 2'd0)), .cfg_m(m), .cfg_idx(idx), .cfg_data(data), .vt(vt10));
    tmc429_vtarget #(.NMOT(1), .ROOT_SPEC(1)) u11 (.clk(clk), .rst(rst), .run(run), .phase(phase),
        .rm(rm), .x_target(x_t), .x_actual(x_a), .v_target(v_t), .brake_en(brake_en),
        .cfg_we(we & (m == 2'd0)), .cfg_m(m), .cfg_idx(idx), .cfg_data(data), .vt(vt11));
    reg [35:0] last;
    reg [4095:0] seen = 4096'd0;      // the values motor 0's velocity took
    integer i, bad, changes, distinct;
    always #5 clk = ~clk;
    initial begin
        $readmemh("vectors.hex", vec);
        bad = 0;
        changes = 0;
        last = 36'd0;
        @(posedge clk); #1 rst = 0;
        for (i = 0; i < NVEC; i = i + 1) begin
            v = vec[i];
            @(posedge clk); #1;
            phase = phase + {4'd0, run};
            if (vt30 !== vt31 || vt10[11:0] !== vt11[11:0]) begin
                if (bad < 5)
                    $display("MISMATCH at edge %0d: three motors %h / %h, one motor %h / %h",
                             i + 1, vt30, vt31, vt10[11:0], vt11[11:0]);
                bad = bad + 1;
            end
            if (vt30 !== last)
                changes = changes + 1;
            last = vt30;
            seen[vt30[11:0]] = 1'b1;
        end
        distinct = 0;
        for (i = 0; i < 4096; i = i + 1)
            distinct = distinct + seen[i];
        $display("EDGES %0d MISMATCHES %0d CHANGES %0d DISTINCT %0d", NVEC, bad, changes, distinct);
        $finish;
    end
endmodule
"#;

/// Both forms commit the same velocities in every edge of the stream of `seed`, and the
/// stream moves them: commits of new roots over a range of values.
fn both_forms_agree(seed: u64) {
    let lines = stream(seed);
    let text = common::icarus_modules(&["tmc429_vtarget", "tmc429_vroot", "tmc429_wram"], BENCH, &lines);
    let tail = text.lines().find(|l| l.starts_with("EDGES")).unwrap_or_else(|| panic!("{text}"));
    let f: Vec<&str> = tail.split_whitespace().collect();
    assert_eq!(f[1], CYCLES.to_string(), "{text}");
    assert_eq!(f[3], "0", "{text}");
    let changes: u32 = f[5].parse().unwrap();
    let distinct: u32 = f[7].parse().unwrap();
    assert!(changes > MIN_CHANGES, "only {changes} changes of the committed velocities\n{text}");
    assert!(distinct > MIN_DISTINCT, "motor 0's velocity took only {distinct} values\n{text}");
}

#[test]
fn both_root_forms_commit_the_same_target_velocities_stream_1() {
    both_forms_agree(1);
}

#[test]
fn both_root_forms_commit_the_same_target_velocities_stream_2() {
    both_forms_agree(2);
}
