// tb_lut: replays pin-level vectors of unit `lut` on tmc429_microstep (docs/vectors.md).
//   iverilog -g2005 -I vectors/tb -o tb_lut vectors/tb/tb_lut.v rtl/tmc429_microstep.v
//   vvp tb_lut +hex=X.hex +cols=X.cols +meta=X.meta
// The unit is combinational and has no reset and no CHIP parameter; CHIP here only checks the
// .meta's chip_code. The player's clock only paces the lines: inputs at the falling edge,
// outputs compared after the rising edge.
`timescale 1ns / 1ps
`default_nettype none

module tb_lut;
    parameter CHIP = 1;
    localparam W_IN  = 34;
    localparam W_OUT = 13;
    localparam UNIT  = "lut";

`include "vec_player.vh"

    tmc429_microstep dut (
        .w(vin[33:26]), .coil_b(vin[25]), .lut(vin[24:19]), .i_scale(vin[18:16]),
        .code(vin[15:11]), .dac_q(vin[10:5]), .negative(vin[4]), .step(vin[3]),
        .pol_ph_ab(vin[2]), .pol_fd_ab(vin[1]), .pol_dac_ab(vin[0]),
        .lut_idx(vout[12:7]), .dac(vout[6:1]), .bit_out(vout[0]));
endmodule

`default_nettype wire
