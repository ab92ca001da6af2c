// tmc429_chip: the controller with its pins only, for synthesis into a device.
//
// tmc429_top in a package: the probe ports (co-simulation only) are left open, so synthesis
// keeps exactly the logic that reaches a pin. The tri-state pins come as a data output and an
// output enable (sdoz_c/sdoz_c_oe, sdi_s_o/sdi_s_oe); a target adds its own I/O buffers
// (docs/rtl.md, "Synthesizing for a target of one's own").
//
// PINS selects the package (docs/model-contract.md C90; TMC428 §3, §4, TMC429 §3, §4.2): 0 or
// the pin count of the package with every pin of the variant (TMC428 SOP24 / DIL20, TMC429
// QFN32, TMC4210 SSOP16) bonds every port; TMC429 SOP24 (24) lacks REFR3, TMC429 SSOP16 (16)
// REFR1..3, nSCS2, nSCS3, SDOZ_C and POSCMP, TMC428 SSOP16 (16) nSCS2 and nSCS3. An absent REFR
// input reads high (its internal pull-up), an absent output is tied off (nSCS2/nSCS3 1, POSCMP
// 0, SDOZ_C not driven), so synthesis removes the logic behind it.
// Same function as tmc429_model::Bonding.
`timescale 1ns / 1ps
`default_nettype none

module tmc429_chip #(
    parameter CHIP = 1,
    parameter PINS = 0
) (
    input  wire clk,
    input  wire rst,
    input  wire nscs_c,
    input  wire sck_c,
    input  wire sdi_c,
    output wire nint_sdo_c,
    output wire sdoz_c,
    output wire sdoz_c_oe,
    output wire nscs_s,
    output wire sck_s,
    output wire sdo_s,
    input  wire sdi_s,
    output wire sdi_s_o,
    output wire sdi_s_oe,
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
    localparam REFR3_ABSENT  = (CHIP == 1) && (PINS == 24 || PINS == 16);
    localparam REFR12_ABSENT = (CHIP == 1) && (PINS == 16);
    localparam NSCS23_ABSENT = (CHIP != 2) && (PINS == 16);
    localparam POSCMP_ABSENT = (CHIP == 1) && (PINS == 16);

    wire die_sdoz_c, die_sdoz_c_oe, die_nscs2, die_nscs3, die_poscmp;
    assign sdoz_c    = POSCMP_ABSENT ? 1'b0 : die_sdoz_c;
    assign sdoz_c_oe = POSCMP_ABSENT ? 1'b0 : die_sdoz_c_oe;
    assign poscmp    = POSCMP_ABSENT ? 1'b0 : die_poscmp;
    assign nscs2     = NSCS23_ABSENT ? 1'b1 : die_nscs2;
    assign nscs3     = NSCS23_ABSENT ? 1'b1 : die_nscs3;

    /* verilator lint_off PINCONNECTEMPTY */
    tmc429_top #(.CHIP(CHIP)) u_top (
        .clk(clk), .rst(rst),
        .nscs_c(nscs_c), .sck_c(sck_c), .sdi_c(sdi_c),
        .nint_sdo_c(nint_sdo_c), .sdoz_c(die_sdoz_c), .sdoz_c_oe(die_sdoz_c_oe),
        .nscs_s(nscs_s), .sck_s(sck_s), .sdo_s(sdo_s), .sdi_s(sdi_s),
        .sdi_s_o(sdi_s_o), .sdi_s_oe(sdi_s_oe), .nscs2(die_nscs2), .nscs3(die_nscs3),
        .ref1(ref1), .ref2(ref2), .ref3(ref3),
        .refr1(refr1 | REFR12_ABSENT), .refr2(refr2 | REFR12_ABSENT), .refr3(refr3 | REFR3_ABSENT),
        .poscmp(die_poscmp),
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
        .probe_chain_readback(),
        .probe_prescaler(), .probe_power_down(), .probe_status());
    /* verilator lint_on PINCONNECTEMPTY */
endmodule

`default_nettype wire
