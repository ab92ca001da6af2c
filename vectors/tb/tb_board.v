// tb_board: replays pin-level vectors of unit `chip` on the board top fpga/tmc429_board.v, as a
// tester replays them on the board (docs/fpga.md, "Replaying the vectors on the board"):
//   - nrst is driven two lines ahead (nrst = ~rst of line i + 2): the board's reset
//     synchronizer passes it two edges late; its power-on state resets at the first edge
//     (line 0);
//   - SDOZ_C is one three-state pin: it is compared with sdoz_c while sdoz_c_oe is expected,
//     and must float (z) otherwise;
//   - SDI_S is driven with the line's sdi_s while the chip does not drive it (sdi_s_oe of this
//     and the previous line 0); while sdi_s_oe is expected the pin is compared with sdi_s_o,
//     and in the line after it the pin must float.
// A column the pins do not show (sdoz_c while the output is off; sdi_s_o and sdi_s_oe while the
// tester drives SDI_S) is taken as expected. Used by scripts/gate-replay on the netlist
// icebox_vlog reads back from the bitstream, and on fpga/tmc429_board.v itself.
//   iverilog -g2005 -P tb_board.CHIP=1 -I vectors/tb -I rtl -o tb_board vectors/tb/tb_board.v \
//       fpga/tmc429_board.v rtl/*.v
`timescale 1ns / 1ps
`default_nettype none

module tb_board;
    parameter CHIP = 1;
    localparam W_IN  = 11;
    localparam W_OUT = 11;
    localparam UNIT  = "chip";

`include "vec_player.vh"

    // the line two ahead, for nrst (the rst column is the first bit after the sentinel)
    wire [W_LINE-1:0] ahead = (i + 2 < n_cycles) ? mem[i + 2] : {W_LINE{1'b0}};
    wire nrst = ~ahead[W_LINE-5];
    // SDI_S: the tester drives it unless the chip drives it in this line or did in the last
    wire [W_LINE-1:0] last_line = (i > 0) ? mem[i - 1] : {W_LINE{1'b0}};
    wire tester_drives = !exp_out[3] && !last_line[W_CHECK + 3];
    wire sdi_s = tester_drives ? vin[6] : 1'bz;
    wire sdoz_c;

    tmc429_board #(.CHIP(CHIP)) dut (
        .clk(clk), .nrst(nrst),
        .nscs_c(vin[9]), .sck_c(vin[8]), .sdi_c(vin[7]),
        .ref1(vin[5]), .ref2(vin[4]), .ref3(vin[3]),
        .refr1(vin[2]), .refr2(vin[1]), .refr3(vin[0]),
        .nint_sdo_c(vout[10]), .sdoz_c(sdoz_c),
        .nscs_s(vout[7]), .sck_s(vout[6]), .sdo_s(vout[5]), .sdi_s(sdi_s),
        .nscs2(vout[2]), .nscs3(vout[1]), .poscmp(vout[0]));

    // what the pins show, in the columns of the vectors
    wire sdoz_on = (sdoz_c !== 1'bz);
    assign vout[9] = sdoz_on ? sdoz_c : exp_out[9];
    assign vout[8] = sdoz_on;
    wire sdi_s_on = !tester_drives && (sdi_s !== 1'bz);
    assign vout[4] = sdi_s_on ? sdi_s : exp_out[4];
    assign vout[3] = tester_drives ? (exp_out[3] ^ (sdi_s !== vin[6])) : sdi_s_on;
endmodule

`default_nettype wire
