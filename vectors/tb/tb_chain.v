// tb_chain: replays pin-level vectors of unit `chain` on tmc429_chain (docs/vectors.md).
//   iverilog -g2005 -I vectors/tb -o tb_chain vectors/tb/tb_chain.v rtl/tmc429_chain.v rtl/tmc429_microstep.v
//   vvp tb_chain +hex=X.hex +cols=X.cols +meta=X.meta
// The RAM read port is driven from the file (`ram_q`: the cell read at the last edge with
// `ram_re`); `ram_addr` is compared only while `ram_re` (the column holds 0 otherwise).
`timescale 1ns / 1ps
`default_nettype none

module tb_chain;
    parameter CHIP = 1;
    localparam W_IN  = 105;
    localparam W_OUT = 88;
    localparam UNIT  = "chain";

`include "vec_player.vh"

    wire [6:0] ram_addr;
    assign vout[86:80] = ram_addr & {7{vout[87]}};

    tmc429_chain dut (
        .clk(clk), .rst(vin[104]),
        .run(vin[103]),
        .spi_mode(vin[102]),
        .step(vin[101:99]),
        .dir(vin[98:96]),
        .ustep(vin[95:72]),
        .i_scale(vin[71:63]),
        .ramp_tick_nx(vin[62:60]),
        .clk2_div_we(vin[59]),
        .clk2_div_wd(vin[58:51]),
        .lsmd(vin[50:49]),
        .pol_ph_ab(vin[48]),
        .pol_fd_ab(vin[47]),
        .pol_dac_ab(vin[46]),
        .cont_update_nx(vin[45]),
        .cw(vin[44]),
        .dgw(vin[43]),
        .readback_clr(vin[42]),
        .cover_pos(vin[41:36]),
        .cover_len(vin[35:31]),
        .cover_datagram(vin[30:7]),
        .sdi_s(vin[6]),
        .ram_q(vin[5:0]),
        .ram_re(vout[87]),
        .ram_addr(ram_addr),
        .take(vout[79]),
        .ret_cw(vout[78]),
        .ret_dgw(vout[77]),
        .cover_busy(vout[76]),
        .dgw_busy(vout[75]),
        .readback(vout[74:27]),
        .cs(vout[26]),
        .sck(vout[25]),
        .sdo(vout[24]),
        .motor(vout[23:22]),
        .cs_pre_nx(vout[21]),
        .sck_pre_nx(vout[20]),
        .sdo_nx(vout[19]),
        .motor_pre_nx(vout[18:17]),
        .state(vout[16:14]),
        .cidx(vout[13:8]),
        .bits(vout[7:1]),
        .req(vout[0]));
endmodule

`default_nettype wire
