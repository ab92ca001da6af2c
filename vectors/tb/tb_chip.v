// tb_chip: replays pin-level vectors of unit `chip` on tmc429_chip (docs/vectors.md); CHIP and
// PINS (the package, C90) are the .meta's chip_code and pins.
//   iverilog -g2005 -P tb_chip.CHIP=1 -P tb_chip.PINS=32 -I vectors/tb -I rtl -o tb_chip vectors/tb/tb_chip.v rtl/tmc429_*.v
//   vvp tb_chip +hex=X.hex +cols=X.cols +meta=X.meta
`timescale 1ns / 1ps
`default_nettype none

module tb_chip;
    parameter CHIP = 1;
    parameter PINS = 0;
    localparam W_IN  = 11;
    localparam W_OUT = 11;
    localparam UNIT  = "chip";

`include "vec_player.vh"

    // the pins-only top (rtl/tmc429_chip.v): what a device or an FPGA build has
    tmc429_chip #(.CHIP(CHIP), .PINS(PINS)) dut (
        .clk(clk), .rst(vin[10]),
        .nscs_c(vin[9]), .sck_c(vin[8]), .sdi_c(vin[7]), .sdi_s(vin[6]),
        .ref1(vin[5]), .ref2(vin[4]), .ref3(vin[3]),
        .refr1(vin[2]), .refr2(vin[1]), .refr3(vin[0]),
        .nint_sdo_c(vout[10]), .sdoz_c(vout[9]), .sdoz_c_oe(vout[8]),
        .nscs_s(vout[7]), .sck_s(vout[6]), .sdo_s(vout[5]),
        .sdi_s_o(vout[4]), .sdi_s_oe(vout[3]), .nscs2(vout[2]), .nscs3(vout[1]),
        .poscmp(vout[0]));
endmodule

`default_nettype wire
