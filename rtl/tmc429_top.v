// tmc429_top: TMC428 / TMC429 / TMC4210 motion controller, top level.
//
// CHIP: 0 = TMC428, 1 = TMC429, 2 = TMC4210. All variants share this port list; pins a
// variant lacks are tied off (docs/model-contract.md C90). The pins are those of
// tmc429_model::Inputs / Outputs; the probe_* ports are the probe bundle
// (tmc429_model::Probes) that co-simulation compares every cycle.
//
// Blocks present: synchronizers (C4), µC SPI slave (C10-C13), frame schedule (C40, C41), register
// file (C20-C31, C64-C66), RAM (C30), switches (C60), the motion core (C42-C63: per motor its
// registers with the ramp and pulse generator, switch stop, latch and interrupts; shared by the
// motors the target velocity and the ramp tick's arithmetic), and the driver side: current
// scaling (C75-C77), driver chain with the microstep unit (C70-C74, C80-C89), Step/Dir
// (C91-C96), driver pins (C81, C87, C90). This module only wires them.
`timescale 1ns / 1ps
`default_nettype none
`include "tmc429_regmap.vh"

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
    wire       sdi_s_q;
    /* verilator lint_off UNUSEDSIGNAL */
    wire [6:0] in_s, in_h;  // first stages, history flops: the edge detectors live in the motion core
    /* verilator lint_on UNUSEDSIGNAL */

    tmc429_sync #(.W(7), .RST(7'b1110000)) u_sync_in (
        .clk(clk), .rst(rst),
        .d({refr3, refr2, refr1, ref3, ref2, ref1, sdi_s}),
        .s(in_s), .q({refr_q, ref_q, sdi_s_q}), .h(in_h));

    // ---- µC SPI slave --------------------------------------------------------------------
    wire [7:0]  status;
    wire [6:0]  rd_addr;
    wire [5:0]  rd_addr_q;
    wire        rd_addr_new;
    wire [23:0] rd_data;
    wire        rd_round;
    wire        frame_start, exec, exec_nx, active, sdo, rd_load;
    wire [31:0] cmd;
    wire [7:0]  addr_nx;

    tmc429_spi_slave u_spi (
        .clk(clk), .rst(rst),
        .nscs_c(nscs_c), .sck_c(sck_c), .sdi_c(sdi_c),
        .status(status), .rd_addr(rd_addr), .rd_addr_q(rd_addr_q), .rd_addr_new(rd_addr_new), .rd_data(rd_data),
        .rd_round(rd_round), .rd_load(rd_load), .frame_start(frame_start), .exec(exec), .cmd(cmd),
        .exec_nx(exec_nx), .addr_nx(addr_nx), .active(active), .sdo(sdo));

    // ---- register file (C20-C31, C64-C66) -------------------------------------------------
    wire        nint_q, sdo_int, poscmp_q, pd;
    wire        run = ~pd;     // everything behind the SPI slave stops while powered down (C66)
    wire [19:0] prescaler;
    wire [71:0] p_x_target, p_x_actual;
    wire [59:0] p_v;
    wire [35:0] p_v_target, p_a_actual;
    wire [23:0] p_ustep;
    wire [32:0] p_pulse_acc;
    wire [2:0]  p_step, p_dir;
    // the decoded write and the read's register index
    wire        mot_we, ram_we;
    wire [1:0]  mot_sel;
    wire [2:0]  mot_wm;
    wire [5:0]  w_addr;
    wire [3:0]  w_idx;
    wire [23:0] w_data;
    wire [15:0] rd_idx;
    // motors, RAM and switch mapping <-> register file
    wire [71:0] m_rdata;
    wire [2:0]  m_xeqt, m_irq, m_v_rnd;
    wire [11:0] ram_rdata;
    wire [2:0]  sw_l, sw_r;
    wire [10:0] cond_vmin;
    wire [12:0] cond_tol_m1;
    // driver side <-> register file (whole registers; the driver side uses some fields)
    /* verilator lint_off UNUSEDSIGNAL */
    wire [23:0] gconf, gconf_nx, gconf_wd;
    wire        gconf_we;
    wire [8:0]  ifconf, ifconf_nx;
    wire [71:0] drv_conf;     // current_scaling of motor m in [24m+23:24m]
    wire [23:0] drv_m0 = drv_conf[23:0], drv_m1 = drv_conf[47:24], drv_m2 = drv_conf[71:48];
    /* verilator lint_on UNUSEDSIGNAL */
    // frame schedule <-> register file and motors
    wire        pd_nx;
    wire [2:0]  sample_tick, cond_tick, rtick, rtick_nx, ptick, ramp_ld, w_div;
    wire [11:0] ramp_div, pulse_div;
    wire [3:0]  w_ramp_div, w_pulse_div;
    wire [23:0] cover_datagram;
    wire        cw, dgw, dw_write, take, ret_cw, ret_dgw, cover_busy, dgw_busy, ram_re;
    wire [5:0]  cover_pos, mux_sw, ram_q;
    wire [4:0]  cover_len;
    wire [47:0] readback;
    wire [6:0]  ram_addr;

    tmc429_regfile #(.CHIP(CHIP)) u_regs (
        .clk(clk), .rst(rst),
        .exec(exec), .cmd(cmd), .exec_nx(exec_nx), .addr_nx(addr_nx), .frame_start(frame_start),
        .rd_addr(rd_addr), .rd_addr_q(rd_addr_q), .rd_addr_new(rd_addr_new), .rd_load(rd_load), .rd_data(rd_data), .rd_round(rd_round),
        .mot_we(mot_we), .mot_sel(mot_sel), .mot_wm(mot_wm), .ram_we(ram_we), .w_addr(w_addr), .w_idx(w_idx),
        .w_data(w_data), .rd_idx(rd_idx),
        .m_rdata(m_rdata), .m_xeqt(m_xeqt), .m_irq(m_irq),
        .m_v_hi({p_v[59:48], p_v[39:28], p_v[19:8]}), .m_v_rnd(m_v_rnd), .m_x_actual(p_x_actual),
        .ram_rdata(ram_rdata), .sw_l(sw_l), .sw_r(sw_r),
        .cond_vmin(cond_vmin), .cond_tol_m1(cond_tol_m1),
        .status(status), .nint_q(nint_q), .sdo_int(sdo_int),
        .poscmp_q(poscmp_q), .pd(pd), .pd_nx(pd_nx),
        .phase(prescaler[4:0]),
        .w_div(w_div), .w_ramp_div(w_ramp_div), .w_pulse_div(w_pulse_div),
        .drv_gconf(gconf), .drv_gconf_nx(gconf_nx),
        .drv_gconf_we(gconf_we), .drv_gconf_wd(gconf_wd), .drv_ifconf(ifconf),
        .drv_ifconf_nx(ifconf_nx),
        .drv_cw(cw), .drv_dgw(dgw), .drv_dw_write(dw_write),
        .drv_cover_pos(cover_pos), .drv_cover_len(cover_len),
        .drv_cover_datagram(cover_datagram),
        .chain_take(take), .chain_ret_cw(ret_cw), .chain_ret_dgw(ret_dgw),
        .chain_cover_busy(cover_busy), .chain_dgw_busy(dgw_busy), .chain_readback(readback));

    // ---- RAM (C30): µC port and driver chain port ------------------------------------------
    tmc429_ram #(.CHIP(CHIP)) u_ram (
        .clk(clk), .rst(rst),
        .we(ram_we), .waddr(w_addr),
        .wdata({w_data[`TMC429_F_RAM_ODD], w_data[`TMC429_F_RAM_EVEN]}),
        .raddr(rd_addr_q), .rdata(ram_rdata),
        .re2(ram_re), .raddr2(ram_addr), .rdata2(ram_q));

    // ---- switches (C60) -------------------------------------------------------------------
    tmc429_refsw #(.CHIP(CHIP)) u_refsw (
        .ref_q(ref_q), .refr_q(refr_q),
        .inv_ref(ifconf[`TMC429_F_INV_REF]), .en_refr(ifconf[`TMC429_F_EN_REFR]),
        .refmux(gconf[`TMC429_F_REFMUX]), .mot1r(gconf[`TMC429_F_MOT1R]),
        .mux_sw(mux_sw), .l(sw_l), .r(sw_r));

    // ---- motors (C21-C29, C42-C63): registers, ramp and pulse generator, interrupts ---------
    localparam NMOT = `TMC429_MOTORS(CHIP);   // TMC4210: one motor
    wire [5:0]  m_rm;
    wire [2:0]  m_brake_en, m_stop_soft;
    wire [35:0] m_vt;
    wire [59:0] m_v_hold;
    wire [19:0] v_rmp;
    wire [11:0] a_rmp;
    wire        mc_rmp;
    genvar g;
    generate
        for (g = 0; g < 3; g = g + 1) begin : mot
            // a motor the variant lacks (the TMC4210's 1 and 2) never runs and is never written:
            // both as constants, so that synthesis removes its registers (its mot_wm is 0
            // already, but only through a flip-flop simplified after the registers are;
            // scripts/motor-check)
            tmc429_motor_regs #(.CHIP(CHIP)) u_m (
                .clk(clk), .rst(rst), .run(run & (g < NMOT)),
                .we((g < NMOT) ? mot_wm[g] : 1'b0), .widx(w_idx), .wdata(w_data),
                .rsel(rd_idx), .rd_load(rd_load), .rdata(m_rdata[24*g+23:24*g]),
                .sw_l(sw_l[g]), .sw_r(sw_r[g]),
                .sample_tick(sample_tick[g]), .cond_tick(cond_tick[g]),
                .ramp_tick(rtick[g]), .pulse_tick(ptick[g]),
                .vt(m_vt[12*g+11:12*g]), .v_min(cond_vmin), .tol_m1(cond_tol_m1),
                .v_hold(m_v_hold[20*g+19:20*g]), .stop_soft(m_stop_soft[g]),
                .v_rmp(v_rmp), .a_rmp(a_rmp), .mc_rmp(mc_rmp),
                .xeqt(m_xeqt[g]), .irq(m_irq[g]),
                .x_target(p_x_target[24*g+23:24*g]), .rm(m_rm[2*g+1:2*g]),
                .pulse_div(pulse_div[4*g+3:4*g]), .ramp_div(ramp_div[4*g+3:4*g]),
                .brake_en(m_brake_en[g]),
                .x_actual(p_x_actual[24*g+23:24*g]), .v(p_v[20*g+19:20*g]), .v_rnd(m_v_rnd[g]),
                .v_target(p_v_target[12*g+11:12*g]), .a_actual(p_a_actual[12*g+11:12*g]),
                .ustep(p_ustep[8*g+7:8*g]), .pulse_acc(p_pulse_acc[11*g+10:11*g]),
                .step(p_step[g]), .dir(p_dir[g]),
                .drv_conf(drv_conf[24*g+23:24*g]));
        end
    endgenerate

    // ---- the ramp tick's arithmetic, one unit for the three motors' staggered ticks (C41,
    // C51): its operands are registered in the edge into a motor's ramp phase
    tmc429_accel #(.NMOT(NMOT)) u_accel (
        .clk(clk), .rst(rst), .ld(ramp_ld), .tick(rtick), .run(run), .phase(prescaler[4:0]),
        .v_hold(m_v_hold), .vt(m_vt), .stop_soft(m_stop_soft),
        .a_max_we(mot_we & (w_idx == `TMC429_IDX_A_MAX)), .a_max_m(mot_sel),
        .a_max_wd(w_data[`TMC429_F_A_MAX]),
        .v_rmp(v_rmp), .a_rmp(a_rmp), .mc_rmp(mc_rmp));

    // ---- target velocity, one datapath for the three motors (C41, C50) ---------------------
    tmc429_vtarget #(.NMOT(NMOT), .ROOT_SPEC(0)) u_vt (
        .clk(clk), .rst(rst), .run(run), .phase(prescaler[4:0]),
        .rm(m_rm), .x_target(p_x_target), .x_actual(p_x_actual),
        .v_target(p_v_target), .brake_en(m_brake_en),
        .cfg_we(mot_we), .cfg_m(mot_sel), .cfg_idx(w_idx),
        .cfg_data(w_data[`TMC429_F_PMUL_MSB - 1:0]),   // every bit v_min, v_max, a_max, pmul_pdiv store
        .vt(m_vt));

    // ---- frame schedule (C40, C41) -----------------------------------------------------------
    tmc429_schedule u_sched (
        .clk(clk), .rst(rst), .run(~pd), .pd_nx(pd_nx),
        .ramp_div(ramp_div), .pulse_div(pulse_div),
        .w_div(w_div), .w_ramp_div(w_ramp_div), .w_pulse_div(w_pulse_div),
        .prescaler(prescaler), .sample_tick(sample_tick), .cond_tick(cond_tick),
        .ramp_tick(rtick), .pulse_tick(ptick),
        .ramp_tick_nx(rtick_nx), .ramp_ld(ramp_ld));

    // ---- pins (C11, C90) --------------------------------------------------------------------
    // While a frame is active the pin carries the data bit, otherwise nINT (registered: INT
    // of the state before the edge); with sdo_int
    // (TMC429/TMC4210) it is nINT always and the data goes only to SDOZ_C. SDOZ_C and POSCMP
    // are TMC429 pins: the TMC428 and the TMC4210 (which has the position compare registers,
    // [4210] §3.2) tie them off.
    assign nint_sdo_c = (active & ~sdo_int) ? sdo : nint_q;
    assign sdoz_c     = (CHIP == 1) ? sdo : 1'b0;
    assign sdoz_c_oe  = (CHIP == 1) ? active : 1'b0;
    assign poscmp     = (CHIP == 1) ? poscmp_q : 1'b0;

    // ---- driver side (C70-C96) ------------------------------------------------------------
    // Inputs from the motors: the signals behind probe_m*_step / _dir / _ustep /
    // _v_internal / _a_actual (old state, C70).
    wire [2:0] m_step = {probe_m2_step, probe_m1_step, probe_m0_step};
    wire [2:0] m_dir  = {probe_m2_dir, probe_m1_dir, probe_m0_dir};
    wire [2:0] v_nz   = {|probe_m2_v_internal, |probe_m1_v_internal, |probe_m0_v_internal};
    // driver interface mode (C89, C91): en_sd of if_configuration
    wire       spi_mode = (CHIP == 0) | ((CHIP == 1) & ~ifconf[`TMC429_F_EN_SD]);
    wire       spi_nx   = (CHIP == 0) | ((CHIP == 1) & ~ifconf_nx[`TMC429_F_EN_SD]);
    /* verilator lint_off UNUSEDSIGNAL */
    wire       sd_mode  = (CHIP != 0) & ifconf[`TMC429_F_EN_SD];    // unused on the TMC428
    /* verilator lint_on UNUSEDSIGNAL */
    wire       sd_nx    = (CHIP != 0) & ifconf_nx[`TMC429_F_EN_SD];

    // ramp ticks (C40, C41): phase 16 + 7m of the frames whose low ramp_div bits are all 1, from the
    // frame schedule of the register file (the motors' own ramp ticks)
    wire [2:0]  ramp_tick = rtick;      // 0 while powered down

    // current scaling (C75-C77); the TMC4210 has none
    wire [2:0] is0, is1, is2;
    tmc429_current u_cur0 (
        .clk(clk), .rst(rst), .tick(ramp_tick[0] & (CHIP != 2)), .v_nz(v_nz[0]),
        .a_actual(probe_m0_a_actual), .a_threshold(drv_m0[`TMC429_F_A_THRESHOLD]),
        .is_agtat(drv_m0[`TMC429_F_IS_AGTAT]), .is_aleat(drv_m0[`TMC429_F_IS_ALEAT]),
        .is_v0(drv_m0[`TMC429_F_IS_V0]),
        .i_scale(is0));
    tmc429_current u_cur1 (
        .clk(clk), .rst(rst), .tick(ramp_tick[1] & (CHIP != 2)), .v_nz(v_nz[1]),
        .a_actual(probe_m1_a_actual), .a_threshold(drv_m1[`TMC429_F_A_THRESHOLD]),
        .is_agtat(drv_m1[`TMC429_F_IS_AGTAT]), .is_aleat(drv_m1[`TMC429_F_IS_ALEAT]),
        .is_v0(drv_m1[`TMC429_F_IS_V0]),
        .i_scale(is1));
    tmc429_current u_cur2 (
        .clk(clk), .rst(rst), .tick(ramp_tick[2] & (CHIP != 2)), .v_nz(v_nz[2]),
        .a_actual(probe_m2_a_actual), .a_threshold(drv_m2[`TMC429_F_A_THRESHOLD]),
        .is_agtat(drv_m2[`TMC429_F_IS_AGTAT]), .is_aleat(drv_m2[`TMC429_F_IS_ALEAT]),
        .is_v0(drv_m2[`TMC429_F_IS_V0]),
        .i_scale(is2));

    // driver chain (C80-C89)
    wire       c_cs, c_sck, c_sdo, c_cs_pre_nx, c_sck_pre_nx, c_sdo_nx, c_req;
    wire [1:0] c_motor, c_motor_pre_nx;
    wire [2:0] c_state;
    wire [5:0] c_cell;
    wire [6:0] c_bits;
    /* verilator lint_off UNUSEDSIGNAL */
    wire       c_unused = c_cs ^ c_sck ^ c_sdo;   // current levels: the pins take the new ones
    /* verilator lint_on UNUSEDSIGNAL */
    tmc429_chain u_chain (
        .clk(clk), .rst(rst), .run(run), .spi_mode(spi_mode),
        .step(m_step), .dir(m_dir),
        .ustep({probe_m2_ustep, probe_m1_ustep, probe_m0_ustep}),
        .i_scale({is2, is1, is0}), .ramp_tick_nx(rtick_nx),
        .clk2_div_we(gconf_we), .clk2_div_wd(gconf_wd[`TMC429_F_CLK2_DIV]), .lsmd(gconf[`TMC429_F_LSMD]),
        .pol_ph_ab(gconf[`TMC429_F_POLARITY_PH_AB]), .pol_fd_ab(gconf[`TMC429_F_POLARITY_FD_AB]),
        .pol_dac_ab(gconf[`TMC429_F_POLARITY_DAC_AB]), .cont_update_nx(gconf_nx[`TMC429_F_CONT_UPDATE]), .cw(cw), .dgw(dgw), .readback_clr(dw_write),
        .cover_pos(cover_pos), .cover_len(cover_len), .cover_datagram(cover_datagram),
        .sdi_s(sdi_s_q),
        .ram_re(ram_re), .ram_addr(ram_addr), .ram_q(ram_q),
        .take(take), .ret_cw(ret_cw), .ret_dgw(ret_dgw),
        .cover_busy(cover_busy), .dgw_busy(dgw_busy), .readback(readback),
        .cs(c_cs), .sck(c_sck), .sdo(c_sdo), .motor(c_motor),
        .cs_pre_nx(c_cs_pre_nx), .sck_pre_nx(c_sck_pre_nx),
        .sdo_nx(c_sdo_nx), .motor_pre_nx(c_motor_pre_nx),
        .state(c_state), .cidx(c_cell), .bits(c_bits), .req(c_req));

    // Step/Dir (C91-C96): three motors on the TMC429, one on the TMC4210, none on the TMC428
    wire [2:0] sd_step, sd_dir, sd_step_nx, sd_dir_nx;
    generate
        if (CHIP == 0) begin : g_sd_off
            assign {sd_step, sd_dir, sd_step_nx, sd_dir_nx} = 12'd0;
        end else begin : g_sd
            localparam SDM = (CHIP == 1) ? 3 : 1;
            tmc429_stepdir #(.MOTORS(SDM)) u_sd (
                .clk(clk), .rst(rst), .run(run), .en(sd_mode), .phase(prescaler[3:0]),
                .step_in(m_step[SDM-1:0]), .dir_in(m_dir[SDM-1:0]),
                .stpdiv(gconf[`TMC429_F_STPDIV]), .step_half(ifconf[`TMC429_F_STEP_HALF]),
                .step(sd_step[SDM-1:0]), .dir(sd_dir[SDM-1:0]),
                .step_nx(sd_step_nx[SDM-1:0]), .dir_nx(sd_dir_nx[SDM-1:0]));
            if (SDM < 3) begin : g_tie
                assign sd_step[2:SDM] = 0;   assign sd_dir[2:SDM] = 0;
                assign sd_step_nx[2:SDM] = 0; assign sd_dir_nx[2:SDM] = 0;
            end
        end
    endgenerate
    /* verilator lint_off UNUSEDSIGNAL */
    wire sd_unused = ^{sd_step, sd_dir};   // current levels: the pins take the new ones
    /* verilator lint_on UNUSEDSIGNAL */

    // output pins and the 74HC157 switch sampling (C81, C87, C90-C93)
    tmc429_drvpins #(.CHIP(CHIP)) u_pins (
        .clk(clk), .rst(rst), .spi_nx(spi_nx), .sd_nx(sd_nx),
        .take(take), .cs_pre_nx(c_cs_pre_nx), .sck_pre_nx(c_sck_pre_nx),
        .sdo_nx(c_sdo_nx), .motor_pre_nx(c_motor_pre_nx),
        .step_nx(sd_step_nx), .dir_nx(sd_dir_nx),
        .pol_nscs_s(gconf_nx[`TMC429_F_POLARITY_NSCS_S]), .pol_sck_s(gconf_nx[`TMC429_F_POLARITY_SCK_S]),
        .cs_com_ind(gconf_nx[`TMC429_F_CS_COM_IND]), .refmux(gconf_nx[`TMC429_F_REFMUX]),
        .inv_ref(ifconf_nx[`TMC429_F_INV_REF]), .inv_stp(ifconf_nx[`TMC429_F_INV_STP]),
        .inv_dir(ifconf_nx[`TMC429_F_INV_DIR]), .ref_q(ref_q),
        .nscs_s(nscs_s), .sck_s(sck_s), .sdo_s(sdo_s), .sdi_s_o(sdi_s_o),
        .sdi_s_oe(sdi_s_oe), .nscs2(nscs2), .nscs3(nscs3), .mux_sw(mux_sw));

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
    assign probe_chain_state = {5'd0, c_state};
    assign probe_chain_cell = {2'd0, c_cell};
    assign probe_chain_motor = {6'd0, c_motor};
    assign probe_chain_bit_count = {1'd0, c_bits};
    assign probe_chain_pending = c_req;
    assign probe_chain_cover_waiting = cw | cover_busy;
    assign probe_chain_readback = readback;
    assign probe_prescaler = {12'd0, prescaler};
    assign probe_power_down = pd;
    assign probe_status = status;
endmodule

`default_nettype wire
