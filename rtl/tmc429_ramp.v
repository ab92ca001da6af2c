// tmc429_ramp: ramp generator and pulse generator of one motor, with switch stop, stop at
// target and position latch (docs/model-contract.md C42-C44, C51-C54, C61, C62, C3;
// TMC428 §8.6-§8.16).
//
// Every input is a level of the old state (C1); every output is a register of this unit
// except the combinational condition outputs (xeqt, stop, tol_ok, v_actual) which are
// functions of its registers and inputs. The port list is the boundary at which test vectors of
// the unit are taken (rtl/README.md).
//
// The conditions of the old state are registered in the edge before the motor's condition slot
// (sample_tick), so that the slot (cond_tick: its commit phase, every frame) with run = 1
// applies those of the edge before it (C52):
//   stop (C61)     stop_L = !DISABLE_STOP_L & L & (V < 0 | V = 0 & vt < 0) & !tol, stop_R
//                  symmetric; tol = |x_actual| < dx_ref_tolerance masks both switches
//   stop flops     stop_hard := at_stop (RAMP/SOFT, x_actual = x_target, |V|>>8 <= v_min, C52)
//                  | (stop & !SOFT_STOP); stop_soft := stop & SOFT_STOP (C61): the conditions
//                  act from the edge after the slot to the next slot's
//   latch (C62)    lp & V_ACTUAL != 0 & selected switch changed since the last slot:
//                  x_latched := x_actual (of the slot's old state), lp := 0
// Per cycle with run = 1, from the old state:
//   ramp tick      (ramp_tick, rm != HOLD) tmc429_accel, shared by the three motors, moves V
//                  toward T = 256*vt (0 while stop_soft) by at most a_max and registers the
//                  results, which V and a_actual store in the next edge with run = 1 (pend_v,
//                  pend_a; V's not while stop_hard, and a µC write of V_ACTUAL in the tick or
//                  after it voids it); RAMP/SOFT: v_target := vt (C51)
//   V := 0         while stop_hard (C3)
//   pulse tick     (pulse_tick) acc += |V|>>8 of the edge's V, with a tick's V stored in it
//                  (0 while stop_hard); a carry is a step due
//                  (step_due, with step_neg = sign(V)), made in the next edge with run = 1:
//                  x_actual +-1, ustep +- 2^(6-usrs), step := 1, dir := step_neg (C53)
// µC writes (we, widx, wdata; any run level) take priority over all of these (C3); register
// indices and fields: rtl/tmc429_regmap.vh.
`timescale 1ns / 1ps
`default_nettype none
`include "tmc429_regmap.vh"

module tmc429_ramp #(
    parameter HAS_USTEP = 1       // ustep_count writable (TMC429, TMC4210)
) (
    input  wire        clk,
    input  wire        rst,
    input  wire        run,        // 0 while powered down (C66)
    input  wire        sample_tick,// the next edge is motor m's condition slot: this edge takes
                                   // the conditions the slot applies (C52)
    input  wire        cond_tick,  // phase 14 + 7m, motor m's commit: its condition slot (C41)
    input  wire        ramp_tick,  // phase 16 + 7m of a ramp frame of this motor m (C40, C41)
    input  wire        pulse_tick, // phase 17 + 7m of a pulse frame of this motor
    // registers of the motor (old state)
    input  wire [1:0]  rm,
    input  wire [23:0] x_target,
    input  wire [10:0] v_min,
    input  wire [3:0]  ref_conf,   // REF_RnL, SOFT_STOP, DISABLE_STOP_R, DISABLE_STOP_L
    input  wire [2:0]  usrs,
    input  wire [12:0] tol_m1,     // dx_ref_tolerance - 1, two's complement (-1 for 0)
    input  wire [11:0] vt,         // committed target velocity (tmc429_vtarget)
    input  wire        sw_l,       // left and right switch (C60)
    input  wire        sw_r,
    // the last ramp tick's results (tmc429_accel, registered in the tick from this motor's
    // operands; stored in the edge after this motor's tick)
    input  wire [19:0] v_rmp,
    input  wire [11:0] a_rmp,
    input  wire        mc_rmp,
    // µC write to this motor (executed in this edge)
    input  wire        we,
    input  wire [3:0]  widx,
    input  wire [23:0] wdata,
    // state
    output reg  [23:0] x_actual,
    output reg  [19:0] v,          // internal velocity V, 1/256 units, two's complement
    output reg  [11:0] v_target,
    output reg  [11:0] a_actual,
    output reg  [7:0]  ustep,
    output reg  [10:0] acc,        // pulse accumulator
    output reg         step,       // a step was made in the last edge
    output reg         dir,        // direction of the last step (1 = negative)
    output reg  [23:0] x_latched,
    output reg         lp,
    // what V holds after this edge unless the ramp tick loads V, and the registered soft stop
    // action: the operands the shared tick unit takes in the edge before the tick
    // (tmc429_accel; that edge is never the condition slot, so stop_soft then holds)
    output wire [19:0] v_hold,
    output reg         stop_soft,  // registered soft stop action (C61)
    // conditions of the old state
    output wire        xeqt,       // x_actual == x_target
    output wire        stop,       // switch stop condition (STOP interrupt, C63)
    output wire        tol_ok,     // |x_actual| < dx_ref_tolerance
    // the same conditions of the last sample_tick edge (registers): the switch stop, the
    // selected switch (REF_RnL), the tolerance window and x_actual = x_target, which the
    // motor's condition slot applies (C52, C63); c_eq is 1 from reset (POS_END's condition of
    // the reset state) to the first sample
    output reg         c_stop,
    output reg         c_sel,
    output reg         c_tol,
    output reg         c_eq,
    output wire [11:0] v_actual,   // readout sign(V) * (|V| >> 8) (C42)
    // V >> 8 rounds up toward 0: V < 0 with a nonzero low byte (v_actual = V[19:8] + v_rnd),
    // one LUT of two flip-flops: the read path's rounding bit (rd_round, tmc429_spi_slave)
    output wire        v_rnd
);
    reg ref_prev;
    reg pend_v, pend_a;              // the ramp tick's V and a_actual stored in the next edge
                                     // with run = 1 (C51)
    reg step_due, step_neg;          // the pulse tick's carry and V's sign: the step made in
                                     // the next edge with run = 1 (C53)
    reg stop_hard;                   // registered hard stop action (C52, C61)
    // the conditions of the edge before, which the condition slot applies (C52): the stop
    // actions and the latch (and the outputs c_stop, c_sel, c_tol, c_eq). The hard stop action
    // is kept as its terms, combined in the slot: the stop at target's (c_eq: x_actual =
    // x_target, c_slow: RAMP/SOFT mode and |V|>>8 <= v_min) and the switch's (c_hsw), so that
    // the 24-bit comparison x_actual = x_target ends in a flip-flop, not in further LUTs
    reg c_slow, c_hsw, c_soft, c_latch;

    // ---- velocity magnitude, readout ---------------------------------------------------
    wire        v_neg  = v[19];
    wire        v_zero = v == 20'd0;
    // |V| >> 8: for V < 0, (~V + 1) >> 8 = ~V[18:8] + (V[7:0] == 0), i.e. v_mx + v_mc; the
    // sum is not formed on its own: its users add v_mc as the carry into their own adder.
    // v_mc is a flip-flop loaded with every load of V (from the new V's sign and low byte)
    wire [10:0] v_mx   = v[18:8] ^ {11{v_neg}};
    reg         v_mc;            // = v_neg & (V[7:0] == 0), formed with V's next state
    // sign(V) * (|V| >> 8): V >> 8 rounded toward 0
    assign v_rnd    = v_neg & ~v_mc;
    assign v_actual = v[19:8] + {11'd0, v_rnd};
    // V_ACTUAL != 0 without the adder: |V| >> 8 = v_mx + v_mc is 0 only when both are 0
    wire        va_nz  = (|v_mx) | v_mc;

    // ---- tolerance window, switch stop (C61) ----------------------------------------------
    // |x_actual| < tolerance needs x_actual[23:12] all 0 (x >= 0) or all 1 (x < 0), a tolerance
    // above 0 and the low bits below it. With t = dx_ref_tolerance - 1 (a register, t >= 0) and
    // n = x_actual[23]: x >= 0: x_lo < tol, i.e. x_lo + ~t has no carry out of 12 bits; x < 0:
    // |x| = ~x_lo + 1 < tol, i.e. ~x_lo + ~t + 1 has none. One carry chain, (x_lo ^ n) + ~t + n,
    // whose carry out enters the conditions below last: one AND with the high bits' test, no
    // second chain
    function win;
        input [23:0] x;
        input [12:0] t;
        reg          n;
        /* verilator lint_off UNUSEDSIGNAL */     // only the carry out is used
        reg   [12:0] w;
        /* verilator lint_on UNUSEDSIGNAL */
        begin
            n   = x[23];
            w   = {1'b0, x[11:0] ^ {12{n}}} + {1'b0, ~t[11:0]} + {12'd0, n};
            win = (x[22:12] == {11{n}}) & ~t[12] & ~w[12];
        end
    endfunction
    assign tol_ok = win(x_actual, tol_m1);

    // ref_conf is bits REF_RnL..DISABLE_STOP_L of ref_conf_rm
    localparam RC_L = 0;
    localparam RC_R = `TMC429_F_DISABLE_STOP_R - `TMC429_F_DISABLE_STOP_L;
    localparam RC_SOFT = `TMC429_F_SOFT_STOP - `TMC429_F_DISABLE_STOP_L;
    localparam RC_RNL = `TMC429_F_REF_RNL - `TMC429_F_DISABLE_STOP_L;
    wire rnl      = ref_conf[RC_RNL];
    wire soft_sw  = ref_conf[RC_SOFT];
    // a switch stop but for the tolerance window (the window's carry out enters each condition
    // last): moving toward an enabled switch that is active
    function pre_stop;
        input [3:0]  rc;
        input        l, r, vn, vz;
        input [11:0] t;
        reg          mov_neg, mov_pos;
        begin
            mov_neg  = vn | (vz & t[11]);
            mov_pos  = (~vn & ~vz) | (vz & ~t[11] & (t != 12'd0));
            pre_stop = (~rc[RC_L] & l & mov_neg) | (~rc[RC_R] & r & mov_pos);
        end
    endfunction
    assign stop   = pre_stop(ref_conf, sw_l, sw_r, v_neg, v_zero, vt) & ~tol_ok;
    wire sel      = rnl ? sw_r : sw_l;

    // ---- stop at target (C52) ------------------------------------------------------------------
    assign xeqt   = x_actual == x_target;
    // the stop at target but for x_actual = x_target: RAMP or SOFT mode, |V|>>8 <= v_min (no
    // borrow of v_min - |V|>>8)
    function slow;
        input        rs;     // RAMP_MODE or SOFT_MODE
        input [10:0] vmin, mx;
        input        mc;
        /* verilator lint_off UNUSEDSIGNAL */
        reg   [12:0] d;
        /* verilator lint_on UNUSEDSIGNAL */
        begin
            d       = {1'b0, vmin, 1'b0} - {1'b0, mx, mc};
            slow    = rs & ~d[12];
        end
    endfunction

    // ---- ramp tick (C51): the results of tmc429_accel ------------------------------------
    wire        tick  = ramp_tick & (rm != 2'd3);

    // ---- pulse generator (C53) ----------------------------------------------------------------
    // The edge's V: the tick's result stored in this edge (pend_v), else V. Its sign and
    // magnitude bits, from flip-flops through one selection
    wire        f_neg = pend_v ? v_rmp[19] : v_neg;
    wire [10:0] f_mx  = pend_v ? (v_rmp[18:8] ^ {11{v_rmp[19]}}) : v_mx;
    wire        f_mc  = pend_v ? mc_rmp : v_mc;
    // acc + (|V| >> 8): v_mc (a flip-flop) enters as the carry into bit 1 (bit 0 adds v_mc
    // and 1, its sum unused), so the step, the carry out, is one carry chain from
    // flip-flops; while stop_hard holds the sum is acc (no step). Not v_mc + v_mc in bit 0:
    // a carry cell with one net on both operands can keep nextpnr-ice40 0.4's router from
    // ever finishing (docs/rtl.md, "Checks"; scripts/carry-check)
    /* verilator lint_off UNUSEDSIGNAL */
    wire [12:0] p_t   = {1'b0, acc, f_mc} + {1'b0, f_mx, 1'b1};
    /* verilator lint_on UNUSEDSIGNAL */
    wire [10:0] p_sum = stop_hard ? acc : p_t[11:1];
    wire        p_step = pulse_tick & ~stop_hard & p_t[12];
    // The carry out p_step is registered (step_due) and the step is made in the next edge
    // (C53), so that no path runs from V through the accumulator's carry chain into the
    // step's enables. The step's sums are formed in the clocked block, only in an edge that
    // steps (docs/rtl.md, "Logic in its slot"): a simulator evaluates them in no other edge
    function [7:0] inc;              // +-2^(6-usrs) by the sign of the step, usrs 7 as 6
        input       neg;
        input [2:0] rs;
        begin
            case ({neg, rs})
            4'd0: inc = 8'd64;  4'd1: inc = 8'd32;  4'd2: inc = 8'd16;  4'd3: inc = 8'd8;
            4'd4: inc = 8'd4;   4'd5: inc = 8'd2;   4'd6, 4'd7: inc = 8'd1;
            4'd8: inc = 8'hC0;  4'd9: inc = 8'hE0;  4'd10: inc = 8'hF0; 4'd11: inc = 8'hF8;
            4'd12: inc = 8'hFC; 4'd13: inc = 8'hFE; default: inc = 8'hFF;
            endcase
        end
    endfunction

    // ---- µC writes (C3, C23) ------------------------------------------------------------------
    wire        w_x   = we & (widx == `TMC429_IDX_X_ACTUAL);
    wire        w_vt  = we & (widx == `TMC429_IDX_V_TARGET);
    wire        w_va  = we & (widx == `TMC429_IDX_V_ACTUAL);
    wire        w_lp  = we & (widx == `TMC429_IDX_X_LATCHED);
    wire        w_us  = we & (widx == `TMC429_IDX_USTEP_COUNT) & (HAS_USTEP != 0);
    wire [11:0] w_v   = (wdata[`TMC429_F_V_ACTUAL] == 12'h800) ? 12'h801 : wdata[`TMC429_F_V_ACTUAL];

    // ---- V's next state (C3, C51, C61) ----------------------------------------------------
    // the µC write wins; else stop_hard zeroes V; else a ramp tick's result due in this edge
    // (pend_v, never with stop_hard) is stored; else V holds. v_hold is that next state without
    // the stored result, so the registered result enters V's input last; the shared unit's
    // operand register takes v_hold in the edge before the tick, which is never a motor's
    // edge after its own tick.
    wire        zero_v  = run & stop_hard;
    assign v_hold       = w_va ? {w_v, 8'd0} : (zero_v ? 20'd0 : v);
    wire        mc_hold = w_va ? w_v[11] : (~zero_v & v_mc);
    wire        v_load  = run & pend_v & ~w_va;

    always @(posedge clk) begin
        if (rst) begin
            x_actual <= 24'd0;  v <= 20'd0;      v_target <= 12'd0;  a_actual <= 12'd0;
            ustep <= 8'd0;      acc <= 11'd0;    step <= 1'b0;       dir <= 1'b0;
            x_latched <= 24'd0; lp <= 1'b0;      ref_prev <= 1'b0;
            stop_hard <= 1'b0;  stop_soft <= 1'b0;  v_mc <= 1'b0;
            c_eq <= 1'b1;       c_slow <= 1'b0;     c_hsw <= 1'b0;
            c_soft <= 1'b0;     c_sel <= 1'b0;      c_latch <= 1'b0;
            c_stop <= 1'b0;     c_tol <= 1'b0;
            step_due <= 1'b0;   step_neg <= 1'b0;
            pend_v <= 1'b0;     pend_a <= 1'b0;
        end else begin
            // the conditions are formed only in the edge that takes them (docs/rtl.md, "Logic
            // in its slot"): a simulator evaluates them in no other edge
            if (sample_tick) begin : sample
                reg tol, pre;
                tol      = win(x_actual, tol_m1);
                pre      = pre_stop(ref_conf, sw_l, sw_r, v_neg, v_zero, vt);
                // with SOFT_STOP the switch stop is the soft action, without it the hard one
                c_eq    <= xeqt;
                c_slow  <= slow(~rm[1], v_min, v_mx, v_mc);
                c_hsw   <= pre & ~soft_sw & ~tol;
                c_soft  <= pre & soft_sw & ~tol;
                c_sel   <= sel;
                c_stop  <= pre & ~tol;
                c_tol   <= tol;
                c_latch <= lp & va_nz & (sel != ref_prev);
            end
            if (run) begin
                if (cond_tick) begin
                    ref_prev <= c_sel;
                    stop_hard <= (c_eq & c_slow) | c_hsw;
                    stop_soft <= c_soft;
                    if (c_latch) begin
                        x_latched <= x_actual;
                        lp <= 1'b0;
                    end
                end
                pend_a <= tick;
                if (pend_a)
                    a_actual <= a_rmp;
                if (tick & ~rm[1])
                    v_target <= vt;
                step <= step_due;
                step_due <= p_step;
                if (p_step)
                    step_neg <= f_neg;
                if (pulse_tick)
                    acc <= p_sum;
                if (step_due) begin
                    x_actual <= x_actual + {{23{step_neg}}, 1'b1};
                    ustep <= ustep + inc(step_neg, usrs);
                    dir <= step_neg;
                end
            end
            v <= v_load ? v_rmp : v_hold;
            v_mc <= v_load ? mc_rmp : mc_hold;
            // a µC write of V_ACTUAL wins over a tick's V: in the tick, and after it while
            // powered down
            pend_v <= ~w_va & (run ? tick & ~stop_hard : pend_v);
            if (w_x)  x_actual <= wdata[`TMC429_F_X_ACTUAL];
            if (w_vt) v_target <= wdata[`TMC429_F_V_TARGET];
            if (w_lp) lp <= 1'b1;
            if (w_us) ustep <= wdata[`TMC429_F_USTEP_COUNT];
        end
    end
endmodule

`default_nettype wire
