// tb_spi: replays pin-level vectors of unit `spi` on tmc429_spi_slave (docs/vectors.md).
//   iverilog -g2005 -I vectors/tb -o tb_spi vectors/tb/tb_spi.v rtl/tmc429_spi_slave.v rtl/tmc429_sync.v
//   vvp tb_spi +hex=X.hex +cols=X.cols +meta=X.meta
// The unit has no CHIP parameter; CHIP here only checks the .meta's chip_code.
`timescale 1ns / 1ps
`default_nettype none

module tb_spi;
    parameter CHIP = 1;
    localparam W_IN  = 37;
    localparam W_OUT = 43;
    localparam UNIT  = "spi";

`include "vec_player.vh"

    tmc429_spi_slave dut (
        .clk(clk), .rst(vin[36]),
        .nscs_c(vin[35]), .sck_c(vin[34]), .sdi_c(vin[33]),
        .status(vin[32:25]), .rd_data(vin[24:1]), .rd_round(vin[0]),
        .rd_addr(vout[42:36]), .frame_start(vout[35]), .exec(vout[34]),
        .cmd(vout[33:2]), .active(vout[1]), .sdo(vout[0]));
endmodule

`default_nettype wire
