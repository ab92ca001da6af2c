// tmc429_motor_regs: the registers of one motor (IDX 0..15, docs/model-contract.md C21-C29,
// C63; TMC428 §8, TMC429 §8.1) with its ramp and pulse generator (tmc429_ramp) and the
// interrupt logic.
//
// The motion state (x_actual, V, v_target, a_actual, ustep_count, x_latched, lp) lives in
// tmc429_ramp, which also takes the µC writes to it; this block holds the configuration
// registers the motion core uses every cycle, the read mux of the state and the interrupt
// conditions, events and flags. The read value of a register that only the µC writes comes
// from the register file's shadow RAM (tmc429_regfile); v_max, p_mul and pdiv, which only
// the target velocity unit reads, live in its parameter RAM alone (tmc429_vtarget), and a_max,
// which only that unit's snapshot and the ramp tick's operands read, in parameter RAMs of
// those two units (tmc429_vtarget, tmc429_accel). v_min and dx_ref_tolerance, which the ramp
// unit reads for the conditions its condition slot applies (C52, C61) and the target
// velocity unit at its snapshot, are parameter RAMs of the register file read for the motor
// whose condition slot is next (tmc429_pram) and of tmc429_vtarget. Register indices and
// fields: rtl/tmc429_regmap.vh.
`timescale 1ns / 1ps
`default_nettype none
`include "tmc429_regmap.vh"

module tmc429_motor_regs #(
    parameter CHIP = 1
) (
    input  wire        clk,
    input  wire        rst,
    input  wire        run,       // 0 while powered down (C66)
    input  wire        we,        // µC write to this motor (executed now)
    input  wire [3:0]  widx,
    input  wire [23:0] wdata,
    /* verilator lint_off UNUSEDSIGNAL */  // the IDX whose read value is in the shadow RAM
    input  wire [15:0] rsel,      // read address IDX, one-hot (registered in tmc429_regfile)
    /* verilator lint_on UNUSEDSIGNAL */
    input  wire        rd_load,   // the read data is loaded in this edge (tmc429_spi_slave)
    output reg  [23:0] rdata,     // 0 outside rd_load
    input  wire        sw_l,      // mapped left switch (C60)
    input  wire        sw_r,      // mapped right switch
    input  wire        sample_tick, // the next edge is the condition slot: this one takes its
                                    // conditions (C52)
    input  wire        cond_tick, // the motor's commit phase: its condition slot (C41)
    input  wire        ramp_tick, // ramp phase of a ramp frame (C40, C41)
    input  wire        pulse_tick,// pulse phase of a pulse frame
    input  wire [11:0] vt,        // committed target velocity (C41)
    // v_min and dx_ref_tolerance - 1 (-1 for 0) of the motor whose condition slot is next:
    // valid in the cycle before this motor's condition slot (tmc429_pram in tmc429_regfile)
    input  wire [10:0] v_min,
    input  wire [12:0] tol_m1,
    // the ramp tick's operands and results (tmc429_accel, shared by the motors)
    output wire [19:0] v_hold,    // V after this edge without a tick (tmc429_ramp)
    output wire        stop_soft,
    input  wire [19:0] v_rmp,
    input  wire [11:0] a_rmp,
    input  wire        mc_rmp,
    output wire        xeqt,      // x_actual == x_target
    output wire        irq,       // interrupt flags != 0
    // registers for the target velocity unit and the frame schedule
    output reg  [23:0] x_target,
    output reg  [1:0]  rm,
    output reg  [3:0]  pulse_div,
    output reg  [3:0]  ramp_div,
    output wire        brake_en,  // ramp_div >= pulse_div: the braking law's correction applies (C50)
    // motion state (probes)
    output wire [23:0] x_actual,
    output wire [19:0] v,
    output wire        v_rnd,     // v_actual = V[19:8] + v_rnd (tmc429_ramp), for the read path
    output wire [11:0] v_target,
    output wire [11:0] a_actual,
    output wire [7:0]  ustep,
    output wire [10:0] pulse_acc,
    output wire        step,
    output wire        dir,
    // driver side (C75): current_scaling as a read shows it (is_agtat, is_aleat, is_v0,
    // a_threshold at their TMC429_F_* bits)
    output reg  [23:0] drv_conf
);
    reg [2:0]  usrs;
    reg [3:0]  ref_conf;
    reg [7:0]  int_mask, int_flags, int_hist;
    wire       lp;
    /* verilator lint_off UNUSEDSIGNAL */   // the unit's condition levels (its vector boundary):
    wire       stop, tol_ok;                // the interrupt takes their registered copies
    /* verilator lint_on UNUSEDSIGNAL */
    wire       c_stop, c_sel, c_tol, c_eq;
    wire [23:0] x_latched;
    /* verilator lint_off UNUSEDSIGNAL */
    wire [11:0] v_actual;     // formed once for all motors in the read path (tmc429_regfile)
    /* verilator lint_on UNUSEDSIGNAL */

    localparam [7:0] COND_RESET = 8'b0011_0101;   // POS_END, REF_MISS, STOP_LEFT_LOW, STOP_RIGHT_LOW
    localparam HAS_CUR_SCALE = `TMC429_HAS(`TMC429_CHIPS_CURRENT_SCALING, CHIP);   // TMC4210: absent
    localparam HAS_USTEP     = `TMC429_HAS(`TMC429_CHIPS_USTEP_COUNT, CHIP);       // TMC428: unused

    // ---- ramp and pulse generator, switch stop, latch ------------------------------------
    tmc429_ramp #(.HAS_USTEP(HAS_USTEP)) u_ramp (
        .clk(clk), .rst(rst), .run(run), .sample_tick(sample_tick), .cond_tick(cond_tick), .ramp_tick(ramp_tick), .pulse_tick(pulse_tick),
        .rm(rm), .x_target(x_target), .v_min(v_min), .ref_conf(ref_conf),
        .usrs(usrs), .tol_m1(tol_m1), .vt(vt), .sw_l(sw_l), .sw_r(sw_r),
        .v_rmp(v_rmp), .a_rmp(a_rmp), .mc_rmp(mc_rmp),
        .we(we), .widx(widx), .wdata(wdata),
        .x_actual(x_actual), .v(v), .v_target(v_target), .a_actual(a_actual), .ustep(ustep),
        .acc(pulse_acc), .step(step), .dir(dir), .x_latched(x_latched), .lp(lp),
        .v_hold(v_hold), .stop_soft(stop_soft),
        .xeqt(xeqt), .stop(stop), .tol_ok(tol_ok), .c_stop(c_stop), .c_sel(c_sel), .c_tol(c_tol), .c_eq(c_eq),
        .v_actual(v_actual), .v_rnd(v_rnd));

    // ---- interrupt conditions (C63), from the old state of the edge before the slot ------
    // registered in that edge (sample_tick): the slot applies them (C52).
    // The switch stop, the selected switch (REF_RnL), |x_actual| < tolerance and xEQt are
    // registered beside the stop actions in tmc429_ramp (c_stop, c_sel, c_tol, c_eq); here the
    // two switch levels (each HIGH condition and its LOW complement) and x_actual = 0
    reg        cq_r, cq_l, cq_x0;
    // the conditions the slot applies, formed in the clocked block only in the slot and in a
    // write of the interrupt register (docs/rtl.md, "Logic in its slot")
    function [7:0] cond_of;
        input r, l, stp, x0, sl, tl, eq;
        begin
            cond_of = {
                r, l, ~r, ~l,   // 7..4 STOP_RIGHT_HIGH, STOP_LEFT_HIGH, _RIGHT_LOW, _LEFT_LOW
                stp,            // 3 STOP
                x0 & ~sl,       // 2 REF_MISS
                sl & ~tl,       // 1 REF_WRONG: the selected switch, |x_actual| >= tolerance
                eq              // 0 POS_END
            };
        end
    endfunction
    wire       slot   = run & cond_tick;

    wire       w_int   = we & (widx == `TMC429_IDX_INTERRUPT);
    wire [7:0] mask_nx = w_int ? wdata[`TMC429_F_INTERRUPT_MASK] : int_mask;
    wire [7:0] w1c     = w_int ? wdata[`TMC429_F_INTERRUPT_FLAGS] : 8'd0;

    // the braking law corrects for the velocity held between ramp ticks when ramp_div >=
    // pulse_div (C50; tmc429_vtarget forms the correction from its copy of a_max)
    assign brake_en = ramp_div >= pulse_div;
    assign irq  = int_flags != 8'd0;

    always @(posedge clk) begin
        if (rst) begin
            x_target <= 24'd0;
            drv_conf <= `TMC429_RESET_CURRENT_SCALING;
            ref_conf <= 4'd0;   rm <= 2'd0;
            int_mask <= 8'd0;   int_flags <= 8'd0;
            int_hist <= COND_RESET;     // the conditions of the reset state: no event at power-on
            cq_r <= COND_RESET[7];  cq_l <= COND_RESET[6];    // the LOW bits 5, 4 their complements
            cq_x0 <= COND_RESET[2];      // xEQt: c_eq, 1 from reset (COND_RESET[0])
            pulse_div <= 4'd0;  ramp_div <= 4'd0;  usrs <= 3'd0;
        end else begin
            if (sample_tick) begin   // only where taken (docs/rtl.md, "Logic in its slot")
                cq_r    <= sw_r;
                cq_l    <= sw_l;
                cq_x0   <= x_actual == 24'd0;
            end
            if (slot | w_int) begin : irq_flags   // only where they change
                reg [7:0] cond_q, events;
                cond_q = cond_of(cq_r, cq_l, c_stop, cq_x0, c_sel, c_tol, c_eq);
                events = slot ? (cond_q & ~int_hist) : 8'd0;
                if (slot)
                    int_hist <= cond_q;
                int_mask  <= mask_nx;
                int_flags <= ((int_flags & ~w1c) | events) & mask_nx;   // C3, C26
            end
            if (we) begin
                case (widx)
                `TMC429_IDX_X_TARGET: x_target <= wdata[`TMC429_F_X_TARGET];
                `TMC429_IDX_CURRENT_SCALING:
                       if (HAS_CUR_SCALE) drv_conf <= wdata & `TMC429_WMASK_CURRENT_SCALING;
                `TMC429_IDX_REF_CONF_RM: begin   // ref_conf: REF_RnL, SOFT_STOP, DISABLE_STOP_R, _L
                           ref_conf <= wdata[`TMC429_F_REF_RNL:`TMC429_F_DISABLE_STOP_L];
                           rm <= wdata[`TMC429_F_RM];
                       end
                `TMC429_IDX_CLK_CONFIG: begin
                           pulse_div <= wdata[`TMC429_F_PULSE_DIV];
                           ramp_div <= wdata[`TMC429_F_RAMP_DIV];
                           usrs <= wdata[`TMC429_F_USRS];
                       end
                // x_actual, v_target, v_actual, x_latched, ustep_count: motion state in
                // tmc429_ramp; v_max, pmul_pdiv: parameter RAM of tmc429_vtarget; a_max: the
                // parameter RAMs of tmc429_accel and tmc429_vtarget; v_min: those of
                // tmc429_vtarget and tmc429_regfile; dx_ref_tolerance: that of
                // tmc429_regfile; a_actual and interrupt (above): no storage here
                default: ;
                endcase
            end
        end
    end

    // read value of the state (C21-C27); the bits a µC write sets come from the shadow RAM
    // of the register file and are 0 here (ref_conf_rm: lp only; interrupt: int_flags only).
    // The IDX is one-hot, so the multiplexer is an AND-OR. It is 0 outside the edge that loads
    // it, as the register file's rd_data (a simulator evaluates it only there; docs/rtl.md,
    // "Logic in its slot").
    // v_actual (C42) is formed in the register file from V of the selected motor
    always @(*) begin
        if (!rd_load)
            rdata = 24'd0;
        else
            rdata = ({24{rsel[`TMC429_IDX_X_ACTUAL]}} & x_actual)
                  | ({24{rsel[`TMC429_IDX_V_TARGET]}} & {12'd0, v_target})
                  | ({24{rsel[`TMC429_IDX_A_ACTUAL]}} & {12'd0, a_actual})
                  | ({24{rsel[`TMC429_IDX_REF_CONF_RM]}} & ({23'd0, lp} << `TMC429_F_LP))
                  | ({24{rsel[`TMC429_IDX_INTERRUPT]}} & {16'd0, int_flags})
                  | ({24{rsel[`TMC429_IDX_X_LATCHED]}} & x_latched)
                  | ({24{rsel[`TMC429_IDX_USTEP_COUNT] & (HAS_USTEP != 0)}} & {16'd0, ustep});
    end
endmodule

`default_nettype wire
