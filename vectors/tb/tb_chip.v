// tb_chip: replays pin-level vectors of unit `chip` on tmc429_top (docs/vectors.md).
//   iverilog -g2005 -P tb_chip.CHIP=1 -I vectors/tb -o tb_chip vectors/tb/tb_chip.v rtl/tmc429_*.v
//   vvp tb_chip +hex=X.hex +cols=X.cols +meta=X.meta
`timescale 1ns / 1ps
`default_nettype none

module tb_chip;
    parameter CHIP = 1;
    localparam W_IN  = 11;
    localparam W_OUT = 11;
    localparam UNIT  = "chip";

`include "vec_player.vh"

    tmc429_top #(.CHIP(CHIP)) dut (
        .clk(clk), .rst(vin[10]),
        .nscs_c(vin[9]), .sck_c(vin[8]), .sdi_c(vin[7]), .sdi_s(vin[6]),
        .ref1(vin[5]), .ref2(vin[4]), .ref3(vin[3]),
        .refr1(vin[2]), .refr2(vin[1]), .refr3(vin[0]),
        .nint_sdo_c(vout[10]), .sdoz_c(vout[9]), .sdoz_c_oe(vout[8]),
        .nscs_s(vout[7]), .sck_s(vout[6]), .sdo_s(vout[5]),
        .sdi_s_o(vout[4]), .sdi_s_oe(vout[3]), .nscs2(vout[2]), .nscs3(vout[1]),
        .poscmp(vout[0]),
        // probes: not pins, not compared here (co-simulation compares them, docs/cosim.md)
        .probe_m0_x_target(), .probe_m1_x_target(), .probe_m2_x_target(),
        .probe_m0_x_actual(), .probe_m1_x_actual(), .probe_m2_x_actual(),
        .probe_m0_v_internal(), .probe_m1_v_internal(), .probe_m2_v_internal(),
        .probe_m0_v_target(), .probe_m1_v_target(), .probe_m2_v_target(),
        .probe_m0_a_actual(), .probe_m1_a_actual(), .probe_m2_a_actual(),
        .probe_m0_ustep(), .probe_m1_ustep(), .probe_m2_ustep(),
        .probe_m0_step(), .probe_m1_step(), .probe_m2_step(),
        .probe_m0_dir(), .probe_m1_dir(), .probe_m2_dir(),
        .probe_m0_pulse_acc(), .probe_m1_pulse_acc(), .probe_m2_pulse_acc(),
        .probe_chain_state(), .probe_chain_cell(), .probe_chain_motor(),
        .probe_chain_bit_count(), .probe_chain_pending(), .probe_chain_cover_waiting(),
        .probe_chain_readback(), .probe_prescaler(), .probe_power_down(), .probe_status());
endmodule

`default_nettype wire
