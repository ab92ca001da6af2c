// tmc429_schedule: the frame schedule (docs/model-contract.md C40, C41; TMC428 §8.7, §8.13;
// TMC429 §8.1.7): the pre-divider counter C, its phase p = C[4:0] in the 32-cycle frame and
// its frame F = C[19:5], and each motor's ticks in its lane, motor m's 7·m cycles after motor
// 0's (rtl/tmc429_schedule.vh):
//   condition slot  phase TMC429_PH_COMMIT(m) = 14 + 7m of every frame (C52, C61-C63)
//   ramp tick       phase TMC429_PH_RAMP(m) = 16 + 7m of a frame with F mod 2^ramp_div =
//                   2^ramp_div - 1, i.e. F has at least ramp_div trailing ones (C40)
//   pulse tick      phase TMC429_PH_PULSE(m) = 17 + 7m of a frame with at least pulse_div
//                   trailing ones
// The counter stands still while powered down (C66), and the ticks are 0 then. The ticks are
// registers formed one edge ahead: the phase after this edge is p + run, the frame changes
// only from phase 31 to 0, and the divider after this edge is the one a µC write of
// clk_config in this edge stores (`w_div`, a strobe the register file decodes one edge ahead,
// with that write's data `w_ramp_div`, `w_pulse_div`). The slots' phases themselves (each
// slot's and the one before it) are flip-flops decoded one edge ahead from p + run, so a tick's
// input starts at flip-flops, run and the power-down state after the edge. Same function as
// tmc429_model::schedule.
`timescale 1ns / 1ps
`default_nettype none
`include "tmc429_schedule.vh"

module tmc429_schedule (
    input  wire        clk,
    input  wire        rst,
    input  wire        run,          // not powered down (old state)
    input  wire        pd_nx,        // powered down after this edge (C66)
    // per motor, motor m in bits [4m+3:4m]: the dividers stored (old state)
    input  wire [11:0] ramp_div,
    input  wire [11:0] pulse_div,
    // a write of motor m's clk_config executes in this edge (bit m), with these dividers
    input  wire [2:0]  w_div,
    input  wire [3:0]  w_ramp_div,
    input  wire [3:0]  w_pulse_div,
    output reg  [19:0] prescaler,    // the pre-divider counter C (C40), 20 bits as the model
    output reg  [2:0]  cond_tick,    // motor m's condition slot is this edge's (bit m)
    output wire [2:0]  sample_tick,  // cond_tick after this edge: this edge takes the slot's
                                     // conditions (C52)
    output reg  [2:0]  ramp_tick,    // motor m's ramp tick (0 while powered down)
    output reg  [2:0]  pulse_tick,   // motor m's pulse tick (0 while powered down)
    output wire [2:0]  ramp_tick_nx, // ramp_tick after this edge (its register's input)
    output wire [2:0]  ramp_ld       // the next edge is motor m's ramp phase, due or not
);
    // the frame's count of trailing ones (0..15)
    function [3:0] ones_of;
        input [14:0] f;
        integer k;
        begin
            ones_of = 4'd15;
            for (k = 14; k >= 0; k = k - 1)
                if (!f[k])
                    ones_of = k[3:0];
        end
    endfunction
    // the count registered in each edge at phase 0, the first of the frame (the prescaler
    // stands still while powered down, so the frame is the same there): every tick falls at
    // phase 2 or later (the schedule's test), so ones_q is the frame's count there, and the
    // priority encoder is not in the ticks' paths. Formed in the clocked block, only in that
    // edge (docs/rtl.md, "Logic in its slot")
    reg  [3:0]  ones_q;
    always @(posedge clk) begin
        if (rst) begin
            ones_q <= 4'd0;
            prescaler <= 20'd0;
        end else begin
            if (~|prescaler[4:0])        // the frame's first phase (C40: F = C >> 5)
                ones_q <= ones_of(prescaler[19:5]);
            if (run)
                prescaler <= prescaler + 20'd1;
        end
    end

    wire [4:0] ph      = prescaler[4:0];
    // the phase after this edge is k (the counter moves only with run)
    function at_nx;
        input [4:0] k;
        at_nx = run ? (ph == k - 5'd1) : (ph == k);
    endfunction
    // a frame of the divider a µC write of clk_config in this edge stores (C40)
    wire       r_due_w = ones_q >= w_ramp_div;
    wire       p_due_w = ones_q >= w_pulse_div;

    genvar g;
    generate
        for (g = 0; g < 3; g = g + 1) begin : lane
            // the frame's trailing ones against the divider stored and the one written, each a
            // comparison from flip-flops; the write selects after them
            wire r_due = w_div[g] ? r_due_w : (ones_q >= ramp_div[4*g+3:4*g]);
            wire p_due = w_div[g] ? p_due_w : (ones_q >= pulse_div[4*g+3:4*g]);
            localparam [4:0] PH_RAMP = `TMC429_PH_RAMP(g);
            localparam [4:0] PH_PULSE = `TMC429_PH_PULSE(g);
            localparam [4:0] PH_COND = `TMC429_PH_COMMIT(g);
            // the phase is each slot's, or the one before it (at_*: the phase is the slot's,
            // pre_*: the slot's minus 1), as flip-flops formed one edge ahead from the phase
            // after this edge (p + run; 0 after reset), so that the ticks after this edge come
            // from flip-flops and run, not from the counter's decode (docs/rtl.md, "How the
            // RTL's timing maps to the model contract")
            reg  pre_ramp, at_ramp, pre_pulse, at_pulse, pre_cond, at_cond;
            wire ph_ramp_nx  = ~pd_nx & (run ? pre_ramp : at_ramp);
            wire ph_pulse_nx = ~pd_nx & (run ? pre_pulse : at_pulse);
            assign ramp_ld[g] = ph_ramp_nx;
            assign ramp_tick_nx[g] = ph_ramp_nx & r_due;
            // the condition slot: the commit phase of every frame, whether the core runs in
            // it or not (tmc429_ramp acts on it only with run)
            assign sample_tick[g] = run ? pre_cond : at_cond;
            always @(posedge clk) begin
                if (rst) begin
                    {pre_ramp, at_ramp} <= {PH_RAMP == 5'd1, PH_RAMP == 5'd0};
                    {pre_pulse, at_pulse} <= {PH_PULSE == 5'd1, PH_PULSE == 5'd0};
                    {pre_cond, at_cond} <= {PH_COND == 5'd1, PH_COND == 5'd0};
                end else begin
                    {pre_ramp, at_ramp} <= {at_nx(PH_RAMP - 5'd1), at_nx(PH_RAMP)};
                    {pre_pulse, at_pulse} <= {at_nx(PH_PULSE - 5'd1), at_nx(PH_PULSE)};
                    {pre_cond, at_cond} <= {at_nx(PH_COND - 5'd1), at_nx(PH_COND)};
                end
            end
            always @(posedge clk) begin
                if (rst) begin
                    ramp_tick[g] <= 1'b0;
                    pulse_tick[g] <= 1'b0;
                    cond_tick[g] <= PH_COND == 5'd0;
                end else begin
                    ramp_tick[g] <= ramp_tick_nx[g];
                    pulse_tick[g] <= ph_pulse_nx & p_due;
                    cond_tick[g] <= sample_tick[g];
                end
            end
        end
    endgenerate
endmodule

`default_nettype wire
