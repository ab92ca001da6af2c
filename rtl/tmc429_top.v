// tmc429_top: TMC428 / TMC429 / TMC4210 motion controller, top level.
//
// CHIP: 0 = TMC428, 1 = TMC429, 2 = TMC4210. All variants share this port list; pins a
// variant lacks are tied off (docs/model-contract.md C90). The pins are those of
// tmc429_model::Inputs / Outputs; the probe_* ports are the probe bundle
// (tmc429_model::Probes) that co-simulation compares every cycle.
//
// Blocks present: synchronizers (C4), µC SPI slave (C10-C13), register file (C20-C31) with
// the motion core (C40-C66: target velocity, ramp and pulse generators, switch stop, latch,
// interrupts), RAM (C30). Not yet present: the driver chain; its pins and probes are driven
// to their reset values.
`default_nettype none

module tmc429_top #(
    parameter CHIP = 1
) (
    input  wire        clk,
    input  wire        rst,
    // µC SPI
    input  wire        nscs_c,
    input  wire        sck_c,
    input  wire        sdi_c,
    output wire        nint_sdo_c,
    output wire        sdoz_c,
    output wire        sdoz_c_oe,
    // driver chain
    output wire        nscs_s,
    output wire        sck_s,
    output wire        sdo_s,
    input  wire        sdi_s,
    output wire        sdi_s_o,
    output wire        sdi_s_oe,
    output wire        nscs2,
    output wire        nscs3,
    // reference switches, position compare
    input  wire        ref1,
    input  wire        ref2,
    input  wire        ref3,
    input  wire        refr1,
    input  wire        refr2,
    input  wire        refr3,
    output wire        poscmp,
    // probes: motors
    output wire [23:0] probe_m0_x_target,  probe_m1_x_target,  probe_m2_x_target,
    output wire [23:0] probe_m0_x_actual,  probe_m1_x_actual,  probe_m2_x_actual,
    output wire [19:0] probe_m0_v_internal, probe_m1_v_internal, probe_m2_v_internal,
    output wire [11:0] probe_m0_v_target,  probe_m1_v_target,  probe_m2_v_target,
    output wire [11:0] probe_m0_a_actual,  probe_m1_a_actual,  probe_m2_a_actual,
    output wire [7:0]  probe_m0_ustep,     probe_m1_ustep,     probe_m2_ustep,
    output wire        probe_m0_step,      probe_m1_step,      probe_m2_step,
    output wire        probe_m0_dir,       probe_m1_dir,       probe_m2_dir,
    output wire [10:0] probe_m0_pulse_acc, probe_m1_pulse_acc, probe_m2_pulse_acc,
    // probes: driver chain
    output wire [7:0]  probe_chain_state,
    output wire [7:0]  probe_chain_cell,
    output wire [7:0]  probe_chain_motor,
    output wire [7:0]  probe_chain_bit_count,
    output wire        probe_chain_pending,
    output wire        probe_chain_cover_waiting,
    output wire [47:0] probe_chain_readback,
    // probes: global
    output wire [31:0] probe_prescaler,
    output wire        probe_power_down,
    output wire [7:0]  probe_status
);
    // ---- synchronizers of the non-SPI inputs (C4) -----------------------------------------
    wire [2:0] ref_q, refr_q;
    /* verilator lint_off UNUSEDSIGNAL */
    wire [6:0] in_h;    // history flops: the edge detectors live in the motion core
    wire       sdi_s_q; // driver-chain readback: the chain is not built yet
    /* verilator lint_on UNUSEDSIGNAL */

    tmc429_sync #(.W(7), .RST(7'b1110000)) u_sync_in (
        .clk(clk), .rst(rst),
        .d({refr3, refr2, refr1, ref3, ref2, ref1, sdi_s}),
        .q({refr_q, ref_q, sdi_s_q}), .h(in_h));

    // ---- µC SPI slave --------------------------------------------------------------------
    wire [7:0]  status;
    wire [6:0]  rd_addr;
    wire [23:0] rd_data;
    wire        frame_start, exec, active, sdo;
    wire [31:0] cmd;

    tmc429_spi_slave u_spi (
        .clk(clk), .rst(rst),
        .nscs_c(nscs_c), .sck_c(sck_c), .sdi_c(sdi_c),
        .status(status), .rd_addr(rd_addr), .rd_data(rd_data),
        .frame_start(frame_start), .exec(exec), .cmd(cmd),
        .active(active), .sdo(sdo));

    // ---- register file and motion core ---------------------------------------------------
    wire        nint_q, sdo_int, poscmp_q, pd;
    wire [19:0] prescaler;
    wire [71:0] p_x_target, p_x_actual;
    wire [59:0] p_v;
    wire [35:0] p_v_target, p_a_actual;
    wire [23:0] p_ustep;
    wire [32:0] p_pulse_acc;
    wire [2:0]  p_step, p_dir;

    tmc429_regfile #(.CHIP(CHIP)) u_regs (
        .clk(clk), .rst(rst),
        .exec(exec), .cmd(cmd), .frame_start(frame_start),
        .rd_addr(rd_addr), .rd_data(rd_data),
        .ref_q(ref_q), .refr_q(refr_q),
        .status(status), .nint_q(nint_q), .sdo_int(sdo_int),
        .poscmp_q(poscmp_q), .pd(pd), .prescaler(prescaler),
        .p_x_target(p_x_target), .p_x_actual(p_x_actual), .p_v(p_v),
        .p_v_target(p_v_target), .p_a_actual(p_a_actual), .p_ustep(p_ustep),
        .p_pulse_acc(p_pulse_acc), .p_step(p_step), .p_dir(p_dir));

    // ---- pins (C11, C90) --------------------------------------------------------------------
    // While a frame is active the pin carries the data bit, otherwise nINT (registered: INT
    // of the state before the edge); with sdo_int
    // (TMC429/TMC4210) it is nINT always and the data goes only to SDOZ_C.
    assign nint_sdo_c = (active & ~sdo_int) ? sdo : nint_q;
    assign sdoz_c     = (CHIP == 0) ? 1'b0 : sdo;
    assign sdoz_c_oe  = (CHIP == 0) ? 1'b0 : active;
    assign poscmp     = poscmp_q;

    // driver chain not built yet: idle levels
    assign nscs_s   = 1'b1;
    assign sck_s    = 1'b1;
    assign sdo_s    = 1'b0;
    assign sdi_s_o  = 1'b0;
    assign sdi_s_oe = 1'b0;
    assign nscs2    = 1'b1;
    assign nscs3    = 1'b1;

    // ---- probes -------------------------------------------------------------------------------
    assign {probe_m2_x_target, probe_m1_x_target, probe_m0_x_target} = p_x_target;
    assign {probe_m2_x_actual, probe_m1_x_actual, probe_m0_x_actual} = p_x_actual;
    assign {probe_m2_v_internal, probe_m1_v_internal, probe_m0_v_internal} = p_v;
    assign {probe_m2_v_target, probe_m1_v_target, probe_m0_v_target} = p_v_target;
    assign {probe_m2_a_actual, probe_m1_a_actual, probe_m0_a_actual} = p_a_actual;
    assign {probe_m2_ustep, probe_m1_ustep, probe_m0_ustep} = p_ustep;
    assign {probe_m2_pulse_acc, probe_m1_pulse_acc, probe_m0_pulse_acc} = p_pulse_acc;
    assign {probe_m2_step, probe_m1_step, probe_m0_step} = p_step;
    assign {probe_m2_dir, probe_m1_dir, probe_m0_dir} = p_dir;
    assign probe_chain_state = 8'd0;
    assign probe_chain_cell = 8'd0;
    assign probe_chain_motor = 8'd0;
    assign probe_chain_bit_count = 8'd0;
    assign probe_chain_pending = 1'b0;
    assign probe_chain_cover_waiting = 1'b0;
    assign probe_chain_readback = 48'd0;
    assign probe_prescaler = {12'd0, prescaler};
    assign probe_power_down = pd;
    assign probe_status = status;
endmodule

`default_nettype wire
