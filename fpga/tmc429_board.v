// tmc429_board: tmc429_chip on an FPGA board, one pin per chip pin (docs/fpga.md).
//
// The tri-state pins become real three-state pins: SDOZ_C (high impedance while the chip does
// not drive it, [429] §4.2) and SDI_S (an input; the TMC429's D2 output with en_sd = 1). The
// chip has no reset pin ([429] §4.2: internal power-on reset); the board has one, nrst (active
// low, pulled up), for a microcontroller, a push button or a tester. The reset synchronizer
// takes its first state from the configuration: the first CLK edge after configuration is a
// reset edge (the power-on reset), and nrst reaches the chip two CLK edges after it is
// sampled (vector replay on the board: docs/fpga.md). Generic Verilog only: the synthesis tool
// puts the I/O buffers on the pins.
`timescale 1ns / 1ps
`default_nettype none

module tmc429_board #(
    parameter CHIP = 1
) (
    input  wire clk,
    input  wire nrst,
    input  wire nscs_c,
    input  wire sck_c,
    input  wire sdi_c,
    output wire nint_sdo_c,
    output wire sdoz_c,
    output wire nscs_s,
    output wire sck_s,
    output wire sdo_s,
    inout  wire sdi_s,
    output wire nscs2,
    output wire nscs3,
    input  wire ref1,
    input  wire ref2,
    input  wire ref3,
    input  wire refr1,
    input  wire refr2,
    input  wire refr3,
    output wire poscmp
);
    // reset synchronizer: {rs[1], rs[0]} = 2'b10 after configuration, so the first edge resets
    reg [1:0] rs = 2'b10;
    always @(posedge clk) rs <= {rs[0], ~nrst};

    wire sdoz_d, sdoz_oe, sdi_s_o, sdi_s_oe;

    tmc429_chip #(.CHIP(CHIP)) u_chip (
        .clk(clk), .rst(rs[1]),
        .nscs_c(nscs_c), .sck_c(sck_c), .sdi_c(sdi_c),
        .nint_sdo_c(nint_sdo_c), .sdoz_c(sdoz_d), .sdoz_c_oe(sdoz_oe),
        .nscs_s(nscs_s), .sck_s(sck_s), .sdo_s(sdo_s), .sdi_s(sdi_s),
        .sdi_s_o(sdi_s_o), .sdi_s_oe(sdi_s_oe), .nscs2(nscs2), .nscs3(nscs3),
        .ref1(ref1), .ref2(ref2), .ref3(ref3), .refr1(refr1), .refr2(refr2), .refr3(refr3),
        .poscmp(poscmp));

    assign sdoz_c = sdoz_oe ? sdoz_d : 1'bz;
    assign sdi_s  = sdi_s_oe ? sdi_s_o : 1'bz;
endmodule

`default_nettype wire
