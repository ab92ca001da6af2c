// tmc429_chip: the controller with its pins only, for synthesis into a device.
//
// tmc429_top plus nothing: the probe ports (co-simulation only) are left open, so synthesis
// keeps exactly the logic that reaches a pin. The tri-state pins come as a data output and an
// output enable (sdoz_c/sdoz_c_oe, sdi_s_o/sdi_s_oe); a target adds its own I/O buffers
// (docs/rtl.md, "Synthesizing for a target of one's own").
`default_nettype none

module tmc429_chip #(
    parameter CHIP = 1
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
    /* verilator lint_off PINCONNECTEMPTY */
    tmc429_top #(.CHIP(CHIP)) u_top (
        .clk(clk), .rst(rst),
        .nscs_c(nscs_c), .sck_c(sck_c), .sdi_c(sdi_c),
        .nint_sdo_c(nint_sdo_c), .sdoz_c(sdoz_c), .sdoz_c_oe(sdoz_c_oe),
        .nscs_s(nscs_s), .sck_s(sck_s), .sdo_s(sdo_s), .sdi_s(sdi_s),
        .sdi_s_o(sdi_s_o), .sdi_s_oe(sdi_s_oe), .nscs2(nscs2), .nscs3(nscs3),
        .ref1(ref1), .ref2(ref2), .ref3(ref3), .refr1(refr1), .refr2(refr2), .refr3(refr3),
        .poscmp(poscmp),
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
