// tmc429_accel: the arithmetic of the ramp tick, one unit for the three motors
// (docs/model-contract.md C51, C41; TMC428 §8.7, §8.11).
//
// The motors' ramp ticks fall in different phases of the frame (16, 23 and 30, C41), so at most
// one motor ramps in a cycle. Its operands are registered in the edge before its ramp tick
// (`ld`, one-hot: the next cycle is motor m's ramp phase), from the state they have after that
// edge: V as it holds without a tick (`v_hold` of tmc429_ramp: µC write, stop_hard), the
// registered soft stop action (set only in the motor's condition slot, phase 7m + 14, the
// edge before that one), a_max with a µC write of that edge, and the committed target
// vt (committed at phase 7m + 14, stable in that edge); T is registered with the soft stop
// applied. So the tick's arithmetic starts at flip-flops; its results are registered in the
// ramp tick (`tick`) and the motor's tmc429_ramp stores them in its next running edge (C51), so
// that the sums end at this unit's flip-flops and no path runs from them into the three motors:
//   T = 256 vt, or 0 while stop_soft; V moves toward T by at most a_max and lands on T when
//   |T - V| <= a_max; a_rmp = the change of V; mc_rmp = the new V's v_mc (tmc429_ramp).
// Range: |V|, |T| <= 2047*256, a_max <= 2047. V - T and V + a_max - T >= -2*2047*256 fit in
// 21 bits; a sum above 2^20 - 1 (wrapping to a negative sign) needs |T - V| > 2^20 - 2^11,
// and then the other sum is negative anyway, so `land` is exact.
//
// a_max is read by nothing else in the ramp tick, so its store is a parameter RAM of this unit
// (tmc429_pram, one word per motor; the µC writes it beside the register file's shadow RAM,
// and tmc429_vtarget keeps a copy for the braking law): the RAM is read in every edge at the
// word of the motor whose ramp phase comes within two edges (phases 14-16, 21-23, 28-30: the
// edge before the operand edge, or the frozen phase while powered down), and the operand edge
// takes that value unless the µC writes the motor's a_max in the operand edge itself, whose
// data then holds (C3: the operand is a_max after the operand edge). A word not written since
// reset reads 0 (C2).
`timescale 1ns / 1ps
`default_nettype none
`include "tmc429_schedule.vh"

module tmc429_accel #(
    parameter NMOT = 3             // motors present (TMC4210: 1, whose operands need no select)
) (
    input  wire        clk,
    input  wire        rst,
    /* verilator lint_off UNUSEDSIGNAL */   // NMOT = 1: motor 0's operands alone
    input  wire [2:0]  ld,         // the next cycle is motor m's ramp phase (at most one)
    input  wire [2:0]  tick,       // motor m's ramp tick is this edge's (0 while powered down)
    input  wire        run,        // not powered down: the phase moves in this edge
    input  wire [4:0]  phase,      // prescaler[4:0]
    // per-motor operands after this edge, motor m in bits [w*(m+1)-1 : w*m]
    input  wire [59:0] v_hold,     // V unless its tick loads it, 1/256 units, two's complement
    input  wire [35:0] vt,         // committed target velocity (tmc429_vtarget)
    input  wire [2:0]  stop_soft,  // soft stop action (C61), which this edge does not change
    input  wire        a_max_we,   // a µC write of a_max executes in this edge ...
    input  wire [1:0]  a_max_m,    // ... of this motor ...
    input  wire [10:0] a_max_wd,   // ... with this data, which holds in the edge after
    /* verilator lint_on UNUSEDSIGNAL */
    // the results of the last ramp tick, registered in it
    output reg  [19:0] v_rmp,      // V after the tick
    output reg  [11:0] a_rmp,      // a_actual after the tick
    output reg         mc_rmp      // v_mc of v_rmp
);
    // ---- operands of the motor whose ramp tick is next ------------------------------------
    // t_hi = T / 256: vt, 0 while the soft stop acts; each motor's term is ld & ~stop_soft & vt.
    // The operands and the tick's arithmetic below are formed in the clocked blocks, only in
    // the edges that take them (docs/rtl.md, "Logic in its slot"): a simulator evaluates them
    // in no other edge
    function [31:0] operands;      // {V, vt or 0} of the motor whose ramp phase is next
        input [2:0]  l;
        input [59:0] vh;
        input [35:0] vtg;
        input [2:0]  ss;
        reg   [19:0] v_o;
        reg   [11:0] t_o;
        integer      m;
        begin
            if (NMOT == 1) begin
                v_o = vh[19:0];
                t_o = ss[0] ? 12'd0 : vtg[11:0];
            end else begin
                v_o = 20'd0;  t_o = 12'd0;
                for (m = 0; m < 3; m = m + 1) begin
                    v_o = v_o | (vh[20*m +: 20] & {20{l[m]}});
                    t_o = t_o | (vtg[12*m +: 12] & {12{l[m] & ~ss[m]}});
                end
            end
            operands = {v_o, t_o};
        end
    endfunction
    reg  [19:0] vs;
    reg  [11:0] t_hi;
    reg  [10:0] as;

    // a_max's parameter RAM: the word of the motor whose ramp phase is at most two edges away
    wire [1:0]  am_ra;
    wire [10:0] am_val;
    tmc429_pram #(.DW(11), .NMOT(NMOT),
                  .R1(`TMC429_PH_RAMP(1) - 5'd2), .R2(`TMC429_PH_RAMP(2) - 5'd2)) u_amax (
        .clk(clk), .rst(rst), .run(run), .phase(phase),
        .we(a_max_we), .wm(a_max_m), .wd(a_max_wd), .fd(a_max_wd), .ra(am_ra), .val(am_val));
    always @(posedge clk) begin
        if (rst) begin
            vs <= 20'd0;  t_hi <= 12'd0;  as <= 11'd0;
        end else if (|ld[NMOT-1:0]) begin : load
            // the operand is a_max after the operand edge: a write of the word read in this
            // edge holds
            reg aw_now;
            aw_now = a_max_we & (a_max_m == am_ra);
            {vs, t_hi} <= operands(ld, v_hold, vt, stop_soft);
            as <= aw_now ? a_max_wd : am_val;
        end
    end

    // ---- V toward T (C51) -------------------------------------------------------------------
    // up = V < T; lands on T when V + a_max - T >= 0 and T + a_max - V >= 0: the step sums
    // V +- a_max (21 bits, no wrap-around) minus / from T, each one sign test; else V +- a_max.
    // The change of V is d = T - V when landing, else the step; v_mc of the new V (negative
    // with low byte 0) comes from the sums' low bytes, which leave their carry chains before
    // the signs; landed on T = 256 vt, it is T's sign.
    always @(posedge clk) begin
        if (rst) begin
            v_rmp <= 20'd0;  a_rmp <= 12'd0;  mc_rmp <= 1'b0;
        end else if (|tick[NMOT-1:0]) begin : ramp_tick
            reg [20:0] t_w, v_w;
            reg [19:0] v_up, v_dn;
            /* verilator lint_off UNUSEDSIGNAL */     // only the signs are used
            reg [20:0] s_vt, s_lo, s_hi;
            /* verilator lint_on UNUSEDSIGNAL */
            reg        up, land, mc_up, mc_dn;
            reg [11:0] d_lo, a_neg;
            integer    i;
            t_w   = {t_hi[11], t_hi, 8'd0};
            v_w   = {vs[19], vs};
            v_up  = vs + {9'd0, as};       // used only short of T: within +-2047*256
            v_dn  = vs - {9'd0, as};
            s_vt  = v_w - t_w;                                      // V - T
            s_lo  = v_w + {10'd0, as} - t_w;                        // V + a_max - T
            s_hi  = t_w + {10'd0, as} - v_w;                        // T + a_max - V
            up    = s_vt[20];
            land  = ~s_lo[20] & ~s_hi[20];
            d_lo  = {t_hi[3:0], 8'd0} - vs[11:0];                   // T - V, bits 11..0
            // -a_max without a carry chain (so that no adder is chained behind it): bit i is
            // bit i of a_max inverted when a lower bit is 1 (two's complement: the bits above
            // the lowest 1 flip)
            a_neg[0] = as[0];
            for (i = 1; i < 11; i = i + 1)
                a_neg[i] = as[i] ^ (|(as & ((11'd1 << i) - 11'd1)));
            a_neg[11] = |as;
            mc_up = v_up[19] & (v_up[7:0] == 8'd0);
            mc_dn = v_dn[19] & (v_dn[7:0] == 8'd0);
            v_rmp  <= land ? {t_hi, 8'd0} : (up ? v_up : v_dn);
            a_rmp  <= land ? d_lo : (up ? {1'b0, as} : a_neg);
            mc_rmp <= land ? t_hi[11] : (up ? mc_up : mc_dn);
        end
    end
endmodule

`default_nettype wire
