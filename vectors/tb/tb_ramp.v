// tb_ramp: replays pin-level vectors of unit `ramp` on tmc429_ramp with the ramp tick's
// arithmetic tmc429_accel serving it alone, as it serves each motor in its ramp tick
// (docs/vectors.md).
//   iverilog -g2005 -I vectors/tb -I rtl -o tb_ramp vectors/tb/tb_ramp.v rtl/tmc429_ramp.v rtl/tmc429_accel.v rtl/tmc429_pram.v rtl/tmc429_wram.v
//   vvp tb_ramp +hex=X.hex +cols=X.cols +meta=X.meta
// One instance replays the motors of the file one after the other (each motor's lines begin
// with its reset line). CHIP sets HAS_USTEP as tmc429_motor_regs does (0 on the TMC428) and is
// checked against the .meta's chip_code.
`timescale 1ns / 1ps
`default_nettype none

module tb_ramp;
    parameter CHIP = 1;
    localparam W_IN  = 116;
    localparam W_OUT = 129;
    localparam UNIT  = "ramp";

`include "vec_player.vh"

    wire [19:0] v_rmp;
    wire [11:0] a_rmp;
    wire        mc_rmp, stop_soft;
    wire [19:0] v_hold;
    // the operands are registered in the edge before the ramp tick: the next line's ramp
    // tick, vt and a_max (a_max as it is after that edge's write: written into the unit's
    // parameter RAM in every edge, so the operand edge takes it as the write's data), the
    // unit's V after that edge and its soft stop action; the results are registered in the
    // tick (a line with ramp_tick and run) and stored by the unit in its next running edge
    tmc429_accel #(.NMOT(1)) accel (
        .clk(clk), .rst(vin[115]), .ld({2'b00, vin_nx[111]}), .tick({2'b00, vin[111] & vin[114]}),
        .run(vin[114]), .phase(5'd0),
        .v_hold({40'd0, v_hold}), .vt({24'd0, vin_nx[42:31]}),
        .stop_soft({2'b00, stop_soft}),
        .a_max_we(1'b1), .a_max_m(2'd0), .a_max_wd(vin_nx[72:62]),
        .v_rmp(v_rmp), .a_rmp(a_rmp), .mc_rmp(mc_rmp));
    tmc429_ramp #(.HAS_USTEP(CHIP != 0)) dut (
        .clk(clk), .rst(vin[115]),
        .run(vin[114]), .sample_tick(vin[113]), .cond_tick(vin[112]), .ramp_tick(vin[111]), .pulse_tick(vin[110]), .rm(vin[109:108]),
        .x_target(vin[107:84]), .v_min(vin[83:73]), .ref_conf(vin[61:58]),
        .usrs(vin[57:55]), .tol_m1({1'b0, vin[54:43]} - 13'd1), .vt(vin[42:31]),
        .sw_l(vin[30]), .sw_r(vin[29]),
        .v_rmp(v_rmp), .a_rmp(a_rmp), .mc_rmp(mc_rmp),
        .we(vin[28]), .widx(vin[27:24]), .wdata(vin[23:0]),
        .x_actual(vout[128:105]), .v(vout[104:85]), .v_target(vout[84:73]),
        .a_actual(vout[72:61]), .ustep(vout[60:53]), .acc(vout[52:42]), .step(vout[41]),
        .dir(vout[40]), .x_latched(vout[39:16]), .lp(vout[15]), .xeqt(vout[14]),
        .stop(vout[13]), .tol_ok(vout[12]), .v_actual(vout[11:0]),
        .c_stop(), .c_sel(), .c_tol(), .c_eq(),   // the interrupt's registered conditions: not in the vectors
        .v_rnd(),                           // the read path's rounding bit: not in the vectors
        .v_hold(v_hold), .stop_soft(stop_soft));
endmodule

`default_nettype wire
