// tmc429_stepdir: the Step/Dir output of one motor (docs/model-contract.md C91-C96;
// TMC429 §10, §8.2.4; TMC4210).
//
// A state machine with one down-counter:
//   READY --backlog != 0, same direction--> PULSE (STEP active or toggled, T edges)
//     -> SPACE (STEP inactive, T edges; skipped with step_half) -> READY
//   READY --backlog != 0, other direction--> DIRSET (DIR changed, T edges) -> READY
// with T = t_STEP = 16 (1 + STPDIV) CLK (C93, C94). Steps of the motion core (old state,
// C70) add +-1 to a 24-bit signed backlog; READY takes the step of the same edge into
// account (C95). While disabled (`en` = 0: not in Step/Dir mode) the unit is held in its
// reset state; while powered down (`run` = 0) it holds (C66).
//
// `step_n` / `dir_n` are the levels of the new state (before inv_stp / inv_dir), for the
// output pin registers. Same function as tmc429_model::stepdir::StepDir.
`timescale 1ns / 1ps
`default_nettype none

module tmc429_stepdir (
    input  wire       clk,
    input  wire       rst,
    input  wire       run,         // not powered down
    input  wire       en,          // Step/Dir mode (old state)
    input  wire       step_in,     // the motion core stepped (old state)
    input  wire       dir_in,      // direction of that step, 1 = negative
    input  wire [3:0] stpdiv,      // clk2_div[3:0]
    input  wire       step_half,
    output reg        step,        // STEP level before inv_stp (toggle state with step_half)
    output reg        dir,         // DIR level before inv_dir, 1 = negative
    output reg        step_n,
    output reg        dir_n
);
    localparam READY = 2'd0, PULSE = 2'd1, SPACE = 2'd2, DIRSET = 2'd3;

    reg [1:0]  state, state_n;
    reg [8:0]  cnt, cnt_n;
    reg [23:0] backlog;

    // The backlog after the motion core's step, b = backlog + s (s = +-1 or 0), is not formed:
    // its sign and b != 0 follow from backlog = 0, 1, -1, and the new backlog is one addition
    // backlog + s + t with t = -sign(b) when a STEP pulse starts (take), else 0.
    // backlog = 0, 1, -1 as registers formed with the next state: the new backlog is
    // backlog + dlt (dlt = -2..2), so it is v exactly when backlog = v - dlt, and the
    // comparisons of the backlog with -3..3 do not wait for the addition
    reg         b_z, b_p1, b_m1;
    // hold = state != READY and cnt > 1, a register formed with the next state: a counting
    // state keeps it while cnt > 2, a pulse / space / DIR set-up starts with cnt = T >= 16
    reg         hold, hold_n;
    // b = backlog + s: {b != 0, b < 0}
    function [1:0] b_of;
        input       s_pos, s_neg, bl_neg, z, p1, m1;
        begin
            b_of = {~(s_pos ? m1 : (s_neg ? p1 : z)),
                    s_pos ? (bl_neg & ~m1) : (s_neg ? (bl_neg | z) : bl_neg)};
        end
    endfunction
    // the backlog's change, -2..2: dlt = s + t, where take needs b's sign = dir, so t = dir ?
    // +1 : -1, and both sums are formed from flip-flops without an adder; take selects
    // between them
    function [2:0] dlt_of;
        input       s_pos, s_neg, take, d;
        begin
            if (take)
                dlt_of = d ? (s_pos ? 3'd2 : (s_neg ? 3'd0 : 3'd1))
                           : (s_pos ? 3'd0 : (s_neg ? 3'd6 : 3'd7));
            else
                dlt_of = s_pos ? 3'd1 : (s_neg ? 3'd7 : 3'd0);
        end
    endfunction
    // backlog = 3 .. -3, one bit each (e[v + 3]); the backlog's next state and these
    // comparisons are formed only where the unit runs in Step/Dir mode (the clocked block
    // below), so that a simulator evaluates them only there (docs/rtl.md, "Logic in its slot")
    function [6:0] near;
        input [23:0] b;
        reg hi0, hi1;
        begin
            hi0  = b[23:3] == 21'd0;
            hi1  = b[23:3] == 21'h1FFFFF;
            near = {hi0 & (b[2:0] == 3'd3), hi0 & (b[2:0] == 3'd2), hi0 & (b[2:0] == 3'd1),
                    hi0 & (b[2:0] == 3'd0), hi1 & (b[2:0] == 3'd7), hi1 & (b[2:0] == 3'd6),
                    hi1 & (b[2:0] == 3'd5)};
        end
    endfunction
    // the new backlog is v (v = -1, 0, 1) when backlog = v - dlt: e index v - dlt + 3
    function bl_is;
        input [6:0] ev;
        input [2:0] d;
        input integer v;
        begin
            case (d)
            3'd0: bl_is = ev[v + 3];
            3'd1: bl_is = ev[v + 2];
            3'd2: bl_is = ev[v + 1];
            3'd7: bl_is = ev[v + 4];
            3'd6: bl_is = ev[v + 5];
            default: bl_is = 1'b0;
            endcase
        end
    endfunction

    // The next state; the decisions are formed only where the unit runs in Step/Dir mode, so
    // that a simulator evaluates them in no other edge (docs/rtl.md, "Logic in its slot")
    reg        s_pos, s_neg, neg, bl_nz, pend, cnt_gt2;
    reg  [8:0] t_step;
    always @(*) begin
        state_n   = state;
        cnt_n     = cnt;
        step_n    = step;
        dir_n     = dir;
        hold_n    = hold;
        {s_pos, s_neg, neg, bl_nz, pend, cnt_gt2} = 6'd0;
        t_step    = 9'd0;
        if (run) begin
            if (!en) begin
                state_n   = READY;
                cnt_n     = 9'd0;
                step_n    = 1'b0;
                dir_n     = 1'b0;
                hold_n    = 1'b0;
            end else begin
                t_step = {stpdiv + 5'd1, 4'd0};
                s_pos  = step_in & ~dir_in;
                s_neg  = step_in & dir_in;
                {bl_nz, neg} = b_of(s_pos, s_neg, backlog[23], b_z, b_p1, b_m1);
                pend   = (state == PULSE) && !step_half;
                // cnt > 2 as a bit test (a bit above bit 1 set, or 3): LUTs, where `>` with a
                // constant is a carry chain in synthesis (Yosys' synth_ice40)
                cnt_gt2 = (|cnt[8:2]) | (&cnt[1:0]);
                hold_n  = hold ? cnt_gt2 : (pend | bl_nz);
                if (hold) begin
                    cnt_n = cnt - 9'd1;
                end else if (pend) begin
                    step_n  = 1'b0;
                    state_n = SPACE;
                    cnt_n   = t_step;
                end else begin
                    state_n = READY;
                    if (bl_nz) begin
                        cnt_n = t_step;
                        if (neg != dir) begin
                            dir_n   = neg;             // C94: DIR first, STEP T later
                            state_n = DIRSET;
                        end else begin
                            step_n    = step_half ? ~step : 1'b1;   // take: bl moves
                            state_n   = PULSE;                      // toward 0 (t_d)
                        end
                    end
                end
            end
        end
    end

    always @(posedge clk) begin
        if (rst) begin
            state   <= READY;
            cnt     <= 9'd0;
            hold    <= 1'b0;
            b_z     <= 1'b1;
            b_p1    <= 1'b0;
            b_m1    <= 1'b0;
            backlog <= 24'd0;
            step    <= 1'b0;
            dir     <= 1'b0;
        end else begin
            state   <= state_n;
            cnt     <= cnt_n;
            hold    <= hold_n;
            if (run & en) begin : backlog_nx
                // the same decision as the next state's above (a STEP pulse starts: take),
                // formed here only in Step/Dir mode, so that the backlog's sum does not wait
                // for run and en
                reg       sp, sn, nz, ng, tk;
                reg [2:0] dlt;
                sp  = step_in & ~dir_in;
                sn  = step_in & dir_in;
                {nz, ng} = b_of(sp, sn, backlog[23], b_z, b_p1, b_m1);
                tk  = ~hold & ~((state == PULSE) && !step_half) & nz & (ng == dir);
                dlt = dlt_of(sp, sn, tk, dir);
                backlog <= backlog + {{21{dlt[2]}}, dlt};
                b_z  <= bl_is(near(backlog), dlt, 0);
                b_p1 <= bl_is(near(backlog), dlt, 1);
                b_m1 <= bl_is(near(backlog), dlt, -1);
            end else if (run) begin
                backlog <= 24'd0;
                b_z  <= 1'b1;
                b_p1 <= 1'b0;
                b_m1 <= 1'b0;
            end
            step    <= step_n;
            dir     <= dir_n;
        end
    end
endmodule

`default_nettype wire
