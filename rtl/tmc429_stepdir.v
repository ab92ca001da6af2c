// tmc429_stepdir: the Step/Dir output of the motors, one unit in the frame's slots
// (docs/model-contract.md C91-C96; TMC429 §10, §8.2.4; TMC4210).
//
// Per motor a state machine with one down-counter:
//   READY --backlog != 0, same direction--> PULSE (STEP active or toggled, T edges)
//     -> SPACE (STEP inactive, T edges; skipped with step_half) -> READY
//   READY --backlog != 0, other direction--> DIRSET (DIR changed, T edges) -> READY
// with T = t_STEP = 16 (1 + STPDIV) CLK (C93, C94). Steps of the motion core (old state,
// C70) add +-1 to a 24-bit signed backlog; READY takes the step of the same edge into
// account (C95). While disabled (`en` = 0: not in Step/Dir mode) the unit is held in its
// reset state; while powered down (`run` = 0) it holds (C66).
//
// Motor m's step flag is 1 only after the edge of its pulse tick's step (C53), so the unit
// takes a step only in the edge at phase TMC429_PH_STEPDIR(m) (rtl/tmc429_schedule.vh; the
// prescaler and this unit both stand still while powered down). A pulse, space or DIR set-up
// lasts T = 16 (1 + STPDIV) edges, so every change of motor m's state falls in an edge at that
// phase or 16 after it: its Step/Dir slots. A state counts the slots it lasts (STPDIV down to
// 0), and the motors share one backlog adder: each slot registers the change of its motor's
// backlog, and the edge after it adds the change (their slots and those edges never coincide:
// the schedule's test). The three backlogs are words of a block RAM (one motor: a register);
// the backlog = 0, 1, -1 and its sign are flip-flops of each motor, formed with the word, so
// that a slot's decisions wait for neither the RAM nor the adder.
//
// `step_nx` / `dir_nx` are the levels of the new state (before inv_stp / inv_dir), for the
// output pin registers. Same function as tmc429_model::stepdir::StepDir.
`timescale 1ns / 1ps
`default_nettype none
`include "tmc429_schedule.vh"

module tmc429_stepdir #(
    parameter MOTORS = 3           // 3 (TMC429) or 1 (TMC4210)
) (
    input  wire              clk,
    input  wire              rst,
    input  wire              run,          // not powered down
    input  wire              en,           // Step/Dir mode (old state)
    input  wire [3:0]        phase,        // prescaler[3:0] (old state): the phase in the half frame
    input  wire [MOTORS-1:0] step_in,      // the motion core stepped (old state)
    input  wire [MOTORS-1:0] dir_in,       // direction of that step, 1 = negative
    input  wire [3:0]        stpdiv,       // clk2_div[3:0]
    input  wire              step_half,
    output wire [MOTORS-1:0] step,         // STEP level before inv_stp (toggle state with step_half)
    output wire [MOTORS-1:0] dir,          // DIR level before inv_dir, 1 = negative
    output wire [MOTORS-1:0] step_nx,
    output wire [MOTORS-1:0] dir_nx
);
    localparam READY = 2'd0, PULSE = 2'd1, SPACE = 2'd2, DIRSET = 2'd3;

    // b = backlog + s: {b != 0, b < 0}, from backlog = 0, 1, -1 and its sign
    function [1:0] b_of;
        input       s_pos, s_neg, bl_neg, z, p1, m1;
        begin
            b_of = {~(s_pos ? m1 : (s_neg ? p1 : z)),
                    s_pos ? (bl_neg & ~m1) : (s_neg ? (bl_neg | z) : bl_neg)};
        end
    endfunction
    // the backlog's change, -2..2: dlt = s + t, where take needs b's sign = dir, so t = dir ?
    // +1 : -1
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
    // backlog = 3 .. -3, one bit each (e[v + 3])
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

    // the new backlog is negative: with the old one beyond -3..3 its sign (|dlt| <= 2), else
    // v + dlt < 0 for the v it is (e[v + 3]); a table, no sum
    function neg_after;
        input [6:0] ev;
        input       bl_neg;
        input [2:0] d;
        begin
            case (d)
            3'd1:    neg_after = |ev[1:0];           // v < -1
            3'd2:    neg_after = ev[0];              // v < -2
            3'd7:    neg_after = |ev[3:0];           // v < 1
            3'd6:    neg_after = |ev[4:0];           // v < 2
            default: neg_after = |ev[2:0];           // v < 0
            endcase
            neg_after = neg_after | (~|ev & bl_neg);
        end
    endfunction

    // ---- the slots: motor m's in the edges at phase PH_STEPDIR(m) and 16 after it ----------
    // `slot` is a register formed one edge ahead (the phase after an edge is phase + run), so
    // that the decisions start at flip-flops
    reg  [MOTORS-1:0] slot;
    /* verilator lint_off UNUSEDSIGNAL */      // one motor: its backlog is a register
    wire [MOTORS-1:0] rd;                      // motor m's backlog word is read in this edge
    /* verilator lint_on UNUSEDSIGNAL */
    wire [MOTORS-1:0] ev    = {MOTORS{run & en}} & slot;
    wire              clear = run & ~en;       // held in the reset state (C91)

    // ---- the backlog: one adder and one set of comparisons, in the edge after a slot ----------
    // A slot decides from the motor's flags alone and registers the backlog's change (`d_q`,
    // `wb`: the motor, one-hot); the edge after it adds the change to the motor's word and
    // forms its flags, which the motor's next slot, 16 running edges later, reads. That edge
    // follows the slot whether the unit runs in it or not, and no other motor's slot or write
    // falls in it (the schedule's test). With three motors the words are in a block RAM, each
    // read in the edge before its motor's slot (at phase PH_STEPDIR(m) - 1 (mod 16), which is
    // no slot) and held through the edge after the slot: a read in that edge (motor 0's read
    // is the edge after motor 2's slot) gives its word only after it.
    // The word and the motor's b_z hold from the slot through the edge after it, so with three
    // motors the comparisons of the flags (`near`, the sign) are formed in the slot and
    // registered (`e_q`, `bn_q`): the edge after the slot takes them from flip-flops, not from
    // the RAM's read port. One motor's backlog is a register, formed there from it.
    // The decisions and the flags are formed only in the edges that take them (docs/rtl.md,
    // "Logic in its slot").
    reg  [MOTORS-1:0] wb;
    reg  [2:0]        d_q;
    reg  [MOTORS-1:0] b_z, b_p1, b_m1, b_neg;  // backlog = 0 (its word void), 1, -1, < 0
    wire [3*MOTORS-1:0] dlt;                   // a motor's change in its slot, else 0
    wire [23:0]       bl_q;                    // the word of the motor in its slot and after it
    reg  [6:0]        e_q;                     // near() of that motor's backlog, formed in its slot
    reg               bn_q;                    // its sign
    // the backlog of the motor `sel` selects: one motor's register is cleared with its flags;
    // a RAM word is void while the motor's b_z holds
    function [23:0] word_of;
        input [MOTORS-1:0] sel;
        begin
            word_of = ((MOTORS > 1) & |(sel & b_z)) ? 24'd0 : bl_q;
        end
    endfunction
    wire [23:0]       base   = word_of(wb);
    wire [23:0]       bl_new = base + {{21{d_q[2]}}, d_q};
    integer k;
    always @(posedge clk) begin
        if (rst) begin
            wb  <= {MOTORS{1'b0}};
            d_q <= 3'd0;
            e_q <= 7'd0;
            bn_q <= 1'b0;
        end else begin
            wb  <= ev;
            if (|ev) begin : change
                reg [2:0]  d;
                reg [23:0] b;
                d = 3'd0;
                for (k = 0; k < MOTORS; k = k + 1)
                    d = d | dlt[3*k +: 3];               // 0 but for the slot's motor
                d_q <= d;
                if (MOTORS > 1) begin
                    b = word_of(ev);
                    e_q  <= near(b);
                    bn_q <= b[23];
                end
            end
        end
        if (rst | clear) begin
            b_z   <= {MOTORS{1'b1}};
            b_p1  <= {MOTORS{1'b0}};
            b_m1  <= {MOTORS{1'b0}};
            b_neg <= {MOTORS{1'b0}};
        end else if (|wb) begin : flags
            reg [6:0] e;
            reg       bn;
            e  = (MOTORS > 1) ? e_q : near(base);
            bn = (MOTORS > 1) ? bn_q : base[23];
            for (k = 0; k < MOTORS; k = k + 1)
                if (wb[k]) begin
                    b_z[k]   <= bl_is(e, d_q, 0);
                    b_p1[k]  <= bl_is(e, d_q, 1);
                    b_m1[k]  <= bl_is(e, d_q, -1);
                    b_neg[k] <= neg_after(e, bn, d_q);
                end
        end
    end

    genvar g;
    generate
        if (MOTORS == 1) begin : g_reg
            reg [23:0] bl;
            always @(posedge clk)
                if (rst | clear)
                    bl <= 24'd0;
                else if (wb[0])
                    bl <= bl_new;
            assign bl_q = bl;
        end else begin : g_ram
            reg  [1:0] w_m, r_m;
            always @(*) begin
                w_m = 2'd0;
                r_m = 2'd0;
                for (k = 0; k < MOTORS; k = k + 1) begin
                    w_m = w_m | ({2{wb[k]}} & k[1:0]);
                    r_m = r_m | ({2{rd[k]}} & k[1:0]);
                end
            end
            /* verilator lint_off UNUSEDSIGNAL */
            wire wq;                           // the motor's b_z says when the word is 0
            /* verilator lint_on UNUSEDSIGNAL */
            tmc429_wram #(.AW(2), .DW(24), .WMASK(4'b0111)) u_bl (
                .clk(clk), .rst(rst), .we(|wb), .waddr(w_m), .wdata(bl_new),
                .re(|rd), .raddr(r_m), .q(bl_q), .wq(wq));
        end

        // ---- per motor: the state machine, decided in its slot alone ---------------------------
        for (g = 0; g < MOTORS; g = g + 1) begin : g_m
            localparam [4:0] PH = `TMC429_PH_STEPDIR(g);
            // the edge before the slot, which reads the motor's backlog word; the slot is the
            // edge after it with run, that edge itself without: run selects after the two
            // comparisons of the phase
            assign rd[g] = phase == PH[3:0] - 4'd1;
            always @(posedge clk)
                if (rst)
                    slot[g] <= PH[3:0] == 4'd0;
                else
                    slot[g] <= run ? rd[g] : phase == PH[3:0];

            reg  [1:0] state, state_nx;
            reg  [3:0] rem, rem_nx;          // slots the state still lasts after this one
            reg        st, dr, st_nx, dr_nx;
            reg  [2:0] d;
            reg        s_pos, s_neg, nz, ng, idle, pend, take;   // the slot's decision
            assign dlt[3*g +: 3] = d;
            assign step[g]   = st;
            assign dir[g]    = dr;
            assign step_nx[g] = st_nx;
            assign dir_nx[g]  = dr_nx;

            always @(*) begin
                st_nx    = st;
                dr_nx    = dr;
                state_nx = state;
                rem_nx   = rem;
                d        = 3'd0;
                {s_pos, s_neg, nz, ng, idle, pend, take} = 7'd0;
                if (clear) begin
                    st_nx    = 1'b0;
                    dr_nx    = 1'b0;
                    state_nx = READY;
                    rem_nx   = 4'd0;
                end else if (ev[g]) begin
                    s_pos = step_in[g] & ~dir_in[g];
                    s_neg = step_in[g] & dir_in[g];
                    // b = backlog + s: b != 0, b < 0
                    {nz, ng} = b_of(s_pos, s_neg, b_neg[g], b_z[g], b_p1[g], b_m1[g]);
                    idle = ~|rem;
                    pend = idle & (state == PULSE) & ~step_half;
                    take = idle & ~pend & nz & (ng == dr);
                    d    = dlt_of(s_pos, s_neg, take, dr);
                    if (!idle)
                        rem_nx = rem - 4'd1;
                    else if (pend) begin
                        st_nx    = 1'b0;
                        state_nx = SPACE;
                        rem_nx   = stpdiv;
                    end else if (nz) begin
                        if (take)
                            st_nx = step_half ? ~st : 1'b1;          // C93
                        else
                            dr_nx = ng;                              // C94: DIR first
                        state_nx = take ? PULSE : DIRSET;
                        rem_nx   = stpdiv;
                    end else
                        state_nx = READY;
                end
            end

            always @(posedge clk) begin
                if (rst) begin
                    state <= READY;
                    rem   <= 4'd0;
                    st    <= 1'b0;
                    dr    <= 1'b0;
                end else begin
                    state <= state_nx;
                    rem   <= rem_nx;
                    st    <= st_nx;
                    dr    <= dr_nx;
                end
            end
        end
    endgenerate
endmodule

`default_nettype wire
