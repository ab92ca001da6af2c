// tmc429_regfile: the register file (docs/model-contract.md C20-C31, C64-C66; TMC428 §7-§9,
// TMC429 §8). The driver side (tmc429_chain, _current, _stepdir, _drvpins) takes its
// configuration from the `drv_*` ports and hands back the chain's handshake (C85, C88, C89)
// and readback (C87).
//
// Executes the 32-bit datagram `cmd` when `exec` pulses (C12): the global registers here, the
// motors' registers, the RAM and the parameter RAMs of the shared motion units through the
// decoded write (`w_*`, `mot_we`, `ram_we`), which tmc429_top wires to them. Serves the read
// port of the SPI slave (data of the old state) from the shadow RAM and the read multiplexer
// of the motors' and the RAM's read data, builds the status byte, the interrupt output, the
// position compare and the power-down state, and holds v_min and dx_ref_tolerance for the
// motor whose condition slot is next (tmc429_pram). Per CHIP (0 TMC428, 1 TMC429, 2 TMC4210)
// the registers a variant lacks read 0 and ignore writes (C21). Register indices, fields and
// presence per variant: rtl/tmc429_regmap.vh.
`timescale 1ns / 1ps
`default_nettype none
`include "tmc429_regmap.vh"
`include "tmc429_schedule.vh"

module tmc429_regfile #(
    parameter CHIP = 1
) (
    input  wire        clk,
    input  wire        rst,
    input  wire        exec,
    input  wire [31:0] cmd,
    input  wire        exec_nx,       // exec and cmd's address byte after this edge
    input  wire [7:0]  addr_nx,
    input  wire        frame_start,   // synchronized nSCS_C falling edge: wake-up (C66)
    input  wire [6:0]  rd_addr,
    input  wire [5:0]  rd_addr_q,     // the same address, stable one edge earlier (shadow RAM)
    input  wire        rd_addr_new,   // rd_addr may differ from the edge before
    input  wire        rd_load,       // the SPI slave loads rd_data in this edge
    output reg  [23:0] rd_data,
    output wire        rd_round,      // rd_data's bits 11..0 are 1 more (v_actual's rounding, C42)
    // the decoded write: a register of a motor the variant has (mot_we, motor mot_sel), a RAM
    // word (ram_we, address w_addr), the register index and the datagram's data
    output wire        mot_we,
    output wire [1:0]  mot_sel,
    output wire [2:0]  mot_wm,        // mot_we of motor m alone (bit m)
    output wire        ram_we,
    output wire [5:0]  w_addr,
    output wire [3:0]  w_idx,
    output wire [23:0] w_data,
    output reg  [15:0] rd_idx,        // the read's register index, one-hot, registered (C10)
    // read data and state of the motors (motor m in bits [w*(m+1)-1 : w*m]) and of the RAM
    input  wire [71:0] m_rdata,
    input  wire [2:0]  m_xeqt,        // x_actual = x_target (status byte, C44)
    input  wire [2:0]  m_irq,         // the motor's interrupt request (C63)
    input  wire [35:0] m_v_hi,        // V[19:8]: v_actual before its rounding (C42)
    input  wire [2:0]  m_v_rnd,       // v_actual = V[19:8] + v_rnd
    input  wire [71:0] m_x_actual,    // position compare (C65)
    input  wire [11:0] ram_rdata,     // the RAM word at rd_addr_q (C30)
    input  wire [2:0]  sw_l,          // mapped switches (tmc429_refsw, C60)
    input  wire [2:0]  sw_r,
    // v_min and dx_ref_tolerance - 1 of the motor whose condition slot is next (C52, C61)
    output wire [10:0] cond_vmin,
    output wire [12:0] cond_tol_m1,
    output wire [7:0]  status,        // INT CDGW RS3 xEQt3 RS2 xEQt2 RS1 xEQt1
    output reg         nint_q,        // nINT, registered from the state before the edge (C11)
    output wire        sdo_int,       // if_configuration sdo_int (TMC429/TMC4210)
    output reg         poscmp_q,      // position compare match, registered (C65)
    output reg         pd,            // powered down
    output wire        pd_nx,         // powered down after this edge (C66)
    // frame schedule (tmc429_schedule): the phase prescaler[4:0], and the writes of motor m's
    // clk_config that execute in this edge (bit m) with their dividers
    input  wire [4:0]  phase,
    output wire [2:0]  w_div,
    output wire [3:0]  w_ramp_div,
    output wire [3:0]  w_pulse_div,
    // driver side: configuration (old state, and new state for the output pin registers)
    output wire [23:0] drv_gconf,      // $7E as stored: mot1r refmux 000 cont_update clk2_div bits 7..0
    output wire [23:0] drv_gconf_nx,
    output wire        drv_gconf_we,   // a write of $7E executes in this edge
    output wire [23:0] drv_gconf_wd,   // $7E as that write stores it
    output wire [8:0]  drv_ifconf,     // if_configuration (TMC429, TMC4210)
    output wire [8:0]  drv_ifconf_nx,
    output wire        drv_cw,         // cover datagram waiting
    output wire        drv_dgw,        // datagram-word write waiting
    output wire        drv_dw_write,   // a datagram_low/high_word write executes in this edge
    output wire [5:0]  drv_cover_pos,
    output wire [4:0]  drv_cover_len,
    output wire [23:0] drv_cover_datagram,
    // driver side: chain handshake and state
    input  wire        chain_take,     // a datagram starts: cw and dgw taken
    input  wire        chain_ret_cw,   // SPI mode left: a taken cover returns to waiting
    input  wire        chain_ret_dgw,
    input  wire        chain_cover_busy,
    input  wire        chain_dgw_busy,
    input  wire [47:0] chain_readback
);
    localparam HAS_CHAIN = `TMC429_HAS(`TMC429_CHIPS_DATAGRAM_LOW_WORD, CHIP);   // JDX 0..3 (driver chain)
    localparam HAS_429   = `TMC429_HAS(`TMC429_CHIPS_IF_CONFIGURATION, CHIP);   // JDX 4, 5, 6, 9
    // global_parameters in the TMC4210's layout (C31: STPDIV and mot1r only)
    localparam GCONF_4210 = `TMC429_HAS(`TMC4210_CHIPS_GLOBAL_PARAMETERS, CHIP);
    localparam NMOT      = `TMC429_MOTORS(CHIP);   // TMC4210: one motor
    localparam [23:0] GCONF_WMASK = GCONF_4210 ? `TMC4210_WMASK_GLOBAL_PARAMETERS
                                               : `TMC429_WMASK_GLOBAL_PARAMETERS;
    localparam [23:0] GCONF_RST = GCONF_4210 ? `TMC4210_RESET_GLOBAL_PARAMETERS
                                             : `TMC429_RESET_GLOBAL_PARAMETERS;

    localparam [2:0] NMOT3 = NMOT;

    // ---- datagram decode ------------------------------------------------------------
    wire [6:0]  a7    = cmd[`TMC429_DG_A7];
    wire        wr    = exec & ~cmd[`TMC429_DG_RW];
    wire [23:0] wdata = cmd[`TMC429_DG_DATA];
    wire        wr_g  = wr & ~a7[`TMC429_A7_RRS] & (a7[`TMC429_A7_SMDA] == `TMC429_SMDA_GLOBAL);
    wire [3:0]  jdx   = a7[`TMC429_A7_IDX];
    wire        wr_ram = wr & a7[`TMC429_A7_RRS];
    wire        wr_reg = wr & ~a7[`TMC429_A7_RRS];                      // one of the 64 registers
    reg         wr_mot;        // of a motor the variant has: a flip-flop (one edge ahead, below)
    assign mot_we  = wr_mot;
    assign mot_sel = a7[`TMC429_A7_SMDA];
    assign ram_we  = wr_ram;
    assign w_addr  = a7[`TMC429_A7_ADDR];
    assign w_idx   = jdx;
    assign w_data  = wdata;

    // ---- write strobes one edge ahead -------------------------------------------------
    // The writes that the frame schedule and the driver side take into next states formed one
    // edge ahead (power_down, each motor's clk_config, global_parameters, if_configuration)
    // and the write of a motor's register (mot_we, and each motor's mot_wm) are flip-flops:
    // decoded from exec and the address byte of the next edge (tmc429_spi_slave), so in the
    // edge a write executes each equals the decode of exec and cmd above
    /* verilator lint_off UNUSEDSIGNAL */
    wire [31:0] cmd_nx = {addr_nx, 24'd0};
    /* verilator lint_on UNUSEDSIGNAL */
    wire [6:0]  a7_nx  = cmd_nx[`TMC429_DG_A7];
    wire        reg_nx = exec_nx & ~cmd_nx[`TMC429_DG_RW] & ~a7_nx[`TMC429_A7_RRS];
    wire        glb_nx = reg_nx & (a7_nx[`TMC429_A7_SMDA] == `TMC429_SMDA_GLOBAL);
    reg         w_pd, w_gconf, w_ifconf;
    always @(posedge clk) begin
        if (rst) begin
            w_pd <= 1'b0;  w_gconf <= 1'b0;  w_ifconf <= 1'b0;  wr_mot <= 1'b0;
        end else begin
            wr_mot   <= reg_nx & ({1'b0, a7_nx[`TMC429_A7_SMDA]} < NMOT3);
            w_pd     <= glb_nx & (a7_nx[`TMC429_A7_IDX] == `TMC429_JDX_POWER_DOWN);
            w_gconf  <= glb_nx & (a7_nx[`TMC429_A7_IDX] == `TMC429_JDX_GLOBAL_PARAMETERS);
            w_ifconf <= glb_nx & HAS_429 & (a7_nx[`TMC429_A7_IDX] == `TMC429_JDX_IF_CONFIGURATION);
        end
    end

    // ---- global registers -----------------------------------------------------------
    reg        dw;             // datagram waiting (JDX 0/1 write), CDGW
    reg        cw;             // cover datagram waiting
    reg [5:0]  cover_pos;
    reg [4:0]  cover_len;
    reg [8:0]  if_conf;        // en_refr, pos_comp_sel[1:0], en_sd, inv_dir, inv_stp, step_half, sdo_int, inv_ref
    reg [23:0] pos_comp;
    reg        pc_i, pc_m, pc_hist;
    reg [7:0]  gp_low;         // $7E bits 7..0
    reg [7:0]  clk2_div;
    reg        cont_update, refmux, mot1r;

    // everything behind the SPI slave stops while powered down; the waking edge itself
    // still counts as powered down (the wake-up takes effect in its new state)
    wire run = ~pd;
    wire int_o;

    // ---- power down (C66) -------------------------------------------------------------
    // power_down after this edge: set by a write of it, else cleared by the waking frame start
    wire [4:0] ph      = phase;
    assign pd_nx       = w_pd | (pd & ~frame_start);
    assign w_ramp_div  = wdata[`TMC429_F_RAMP_DIV];
    assign w_pulse_div = wdata[`TMC429_F_PULSE_DIV];

    // ---- read address decode (C10) ---------------------------------------------------------
    // The address is complete in the SPI input register from the edge after the 7th bit, and
    // the read data is loaded at the 8th bit's rising SCK_C edge, two edges later at the
    // earliest (a synchronized SCK_C needs a low cycle between two rising edges): a decode
    // registered every edge is the address's at the loading edge, and the read multiplexer
    // starts at flip-flops (one-hot selects, AND-OR). The decode is loaded only in the edges
    // after the address may have changed (the same registers; a simulator evaluates it in no
    // other edge: docs/rtl.md, "Logic in its slot").
    reg         rq_ram, rq_glb, rq_va;
    reg  [2:0]  rq_mot;
    reg  [23:0] rq_rst;
    integer     j;
    always @(posedge clk) begin
        if (rst) begin
            rq_ram <= 1'b0;  rq_glb <= 1'b0;  rq_va <= 1'b0;  rq_mot <= 3'd0;  rd_idx <= 16'd0;
            rq_rst <= 24'd0;
        end else if (rd_addr_new) begin
            rq_ram <= rd_addr[`TMC429_A7_RRS];
            rq_glb <= rd_addr[`TMC429_A7_SMDA] == `TMC429_SMDA_GLOBAL;
            for (j = 0; j < 3; j = j + 1)
                rq_mot[j] <= (rd_addr[`TMC429_A7_SMDA] == j[1:0]) & (j < NMOT);
            for (j = 0; j < 16; j = j + 1)
                rd_idx[j] <= rd_addr[`TMC429_A7_IDX] == j[3:0];
            rq_va  <= (rd_addr[`TMC429_A7_SMDA] != `TMC429_SMDA_GLOBAL)
                    & (rd_addr[`TMC429_A7_IDX] == `TMC429_IDX_V_ACTUAL);
            rq_rst <= sh_rst(rd_addr[`TMC429_A7_REG]);
        end
    end

    // ---- clk_config writes and each motor's writes, one edge ahead -------------------------
    genvar g;
    generate
        for (g = 0; g < 3; g = g + 1) begin : mot
            // a write of this motor's clk_config executes in this edge (one edge ahead, above)
            reg  w_clk;
            always @(posedge clk) begin
                if (rst)
                    w_clk <= 1'b0;
                else
                    w_clk <= reg_nx & (g < NMOT) & (a7_nx[`TMC429_A7_SMDA] == g)
                           & (a7_nx[`TMC429_A7_IDX] == `TMC429_IDX_CLK_CONFIG);
            end
            assign w_div[g] = w_clk;
            // a write of one of this motor's registers executes in this edge
            reg  w_m;
            always @(posedge clk) begin
                if (rst)
                    w_m <= 1'b0;
                else
                    w_m <= reg_nx & (g < NMOT) & (a7_nx[`TMC429_A7_SMDA] == g);
            end
            assign mot_wm[g] = w_m;
        end
    endgenerate

    // ---- v_min and dx_ref_tolerance of the motor whose condition slot is next ------------
    // The ramp unit reads them for the conditions its condition slot applies, from the cycle
    // before that slot (C52, C61): at phase TMC429_PH_COMMIT(m) - 1, or TMC429_PH_COMMIT(m)
    // while powered down. The parameter RAMs are read in every edge at the word of the motor
    // whose commit phase is at most two edges away; the other motors' conditions formed from
    // that value are not applied. The tolerance is stored as dx_ref_tolerance - 1 (-1 for 0,
    // the reset value), the form of the window's comparison (tmc429_ramp); the forwarded copy
    // of a write is that difference registered (the datagram holds, so it is the written one),
    // so that its carry chain and the window's are not in one path.
    /* verilator lint_off UNUSEDSIGNAL */   // the word read: for a user taking a write of its edge
    wire [1:0]  cond_ra_v, cond_ra_t;
    /* verilator lint_on UNUSEDSIGNAL */
    localparam [4:0] RC1 = `TMC429_PH_COMMIT(1) - 5'd2;
    localparam [4:0] RC2 = `TMC429_PH_COMMIT(2) - 5'd2;
    wire [12:0] tol_wd = {1'b0, wdata[`TMC429_F_DX_REF_TOLERANCE]} - 13'd1;
    reg  [12:0] tol_fd;
    always @(posedge clk) begin
        if (rst)
            tol_fd <= 13'h1FFF;
        else
            tol_fd <= tol_wd;
    end
    tmc429_pram #(.DW(11), .NMOT(NMOT), .R1(RC1), .R2(RC2)) u_vmin (
        .clk(clk), .rst(rst), .run(run), .phase(ph),
        .we(wr_mot & (jdx == `TMC429_IDX_V_MIN)), .wm(a7[`TMC429_A7_SMDA]),
        .wd(wdata[`TMC429_F_V_MIN]), .fd(wdata[`TMC429_F_V_MIN]), .ra(cond_ra_v), .val(cond_vmin));
    tmc429_pram #(.DW(13), .NMOT(NMOT), .R1(RC1), .R2(RC2), .RESET(13'h1FFF)) u_tol (
        .clk(clk), .rst(rst), .run(run), .phase(ph),
        .we(wr_mot & (jdx == `TMC429_IDX_DX_REF_TOLERANCE)), .wm(a7[`TMC429_A7_SMDA]),
        .wd(tol_wd), .fd(tol_fd), .ra(cond_ra_t), .val(cond_tol_m1));

    // ---- position compare (C65) -------------------------------------------------------
    reg [23:0] pc_x;
    always @(*) begin
        case (if_conf[`TMC429_F_POS_COMP_SEL])
        2'd0:    pc_x = m_x_actual[23:0];
        2'd1:    pc_x = m_x_actual[47:24];
        default: pc_x = m_x_actual[71:48];   // 3 selects motor 3 as well
        endcase
    end
    wire pc_match = HAS_429 && (pc_x == pos_comp);
    // I follows the registered match (the POSCMP level): a rising edge between running edges
    wire pc_event = run & poscmp_q & ~pc_hist;
    wire w_pcint  = wr_g & HAS_429 & (jdx == `TMC429_JDX_POS_COMP_INT);
    wire pc_m_nx  = w_pcint ? wdata[`TMC429_F_POS_COMP_INT_M] : pc_m;
    wire pc_w1c   = w_pcint & wdata[`TMC429_F_POS_COMP_INT_I];

    assign sdo_int = HAS_429 && if_conf[`TMC429_F_SDO_INT];
    assign int_o   = (|m_irq) | (pc_i & pc_m);
    // RSn = Ln ([429] §6.2.2.2, C60)
`ifdef PLANT_BUG_STATUS
    // Planted bug for the co-simulation self-test (testbench/tests/planted_bug.rs):
    // CDGW forgets the datagram-waiting flag of a datagram_low/high write.
    wire   cdgw    = cw | chain_cover_busy;
`else
    // C88: CDGW = cw OR the datagram-word flag, each waiting or taken by the datagram under way
    wire   cdgw    = cw | dw | chain_cover_busy | chain_dgw_busy;
`endif
    assign status  = {int_o, cdgw, sw_l[2], m_xeqt[2], sw_l[1], m_xeqt[1], sw_l[0], m_xeqt[0]};

    // ---- driver side ------------------------------------------------------------------
    assign drv_gconf     = ({23'd0, mot1r} << `TMC429_F_MOT1R) | ({23'd0, refmux} << `TMC429_F_REFMUX)
                         | ({23'd0, cont_update} << `TMC429_F_CONT_UPDATE)
                         | ({16'd0, clk2_div} << `TMC429_F_CLK2_DIV_LSB) | {16'd0, gp_low};
    assign drv_gconf_we  = w_gconf;
    assign drv_gconf_wd  = wdata & GCONF_WMASK;
    assign drv_gconf_nx  = w_gconf ? drv_gconf_wd : drv_gconf;
    assign drv_ifconf    = if_conf;
    assign drv_ifconf_nx = w_ifconf ? wdata[`TMC429_F_EN_REFR:`TMC429_F_INV_REF] : if_conf;
    assign drv_cw        = cw;
    assign drv_dgw       = dw;
    assign drv_dw_write  = wr_g & HAS_CHAIN & ((jdx == `TMC429_JDX_DATAGRAM_LOW_WORD)
                                        | (jdx == `TMC429_JDX_DATAGRAM_HIGH_WORD));
    assign drv_cover_pos = cover_pos;
    assign drv_cover_len = cover_len;
    // cover_datagram (C85) is used only by the chain's start edge, which copies it: it lives
    // in a one-word RAM, read every edge. In the edge after a write the RAM output is not yet
    // the new word; the datagram is still in the SPI input register then (no frame can
    // follow within one edge), so that edge takes it from there.
    reg         cov_late;
    wire [23:0] cov_q;
    wire        cov_wq;
    wire        w_cover = wr_g & HAS_CHAIN & (jdx == `TMC429_JDX_COVER_DATAGRAM);
    tmc429_wram #(.AW(1), .DW(24), .WMASK(2'b01)) u_cover (
        .clk(clk), .rst(rst),
        .we(w_cover), .waddr(1'b0), .wdata(wdata),
        .re(1'b1), .raddr(1'b0), .q(cov_q), .wq(cov_wq));
    assign drv_cover_datagram = cov_late ? wdata : (cov_wq ? cov_q : 24'd0);

    always @(posedge clk) begin
        if (rst) begin
            dw <= 1'b0;  cw <= 1'b0;
            cover_pos <= 6'd63;  cover_len <= 5'd0;  cov_late <= 1'b0;   // stored +1 = 0 (C29)
            if_conf <= 9'd0;  pos_comp <= 24'd0;
            pc_i <= 1'b0;  pc_m <= 1'b0;  pc_hist <= HAS_429;   // the match holds at reset
            gp_low <= 8'd0;  clk2_div <= GCONF_RST[`TMC429_F_CLK2_DIV];
            cont_update <= 1'b0;  refmux <= 1'b0;  mot1r <= 1'b0;
            pd <= 1'b0;
            nint_q <= 1'b1;
            poscmp_q <= HAS_429;
        end else begin
            nint_q   <= ~int_o;
            cov_late <= w_cover;
            poscmp_q <= pc_match;
            if (run)
                pc_hist <= poscmp_q;
            pc_m <= pc_m_nx;
            pc_i <= ((pc_i & ~pc_w1c) | pc_event) & pc_m_nx;
            pd <= pd_nx;
            // the chain's handshake first, a µC write of the same edge wins (C3, C88, C89)
            if (chain_take) begin
                cw <= 1'b0;
                dw <= 1'b0;
            end else begin
                cw <= cw | chain_ret_cw;
                dw <= dw | chain_ret_dgw;
            end
            if (wr_g) begin
                case (jdx)
                `TMC429_JDX_DATAGRAM_LOW_WORD, `TMC429_JDX_DATAGRAM_HIGH_WORD:
                      if (HAS_CHAIN) dw <= 1'b1;    // arm CDGW
                `TMC429_JDX_COVER_POS_LEN: if (HAS_CHAIN) begin
                          cover_pos <= wdata[`TMC429_F_COVER_POS];
                          cover_len <= wdata[`TMC429_F_COVER_LEN];
                      end
                `TMC429_JDX_COVER_DATAGRAM: if (HAS_CHAIN) cw <= 1'b1;    // the datagram: u_cover
                `TMC429_JDX_IF_CONFIGURATION:
                      if (HAS_429) if_conf <= wdata[`TMC429_F_EN_REFR:`TMC429_F_INV_REF];
                `TMC429_JDX_POS_COMP: if (HAS_429) pos_comp <= wdata;
                // power_down: pd_nx
                `TMC429_JDX_GLOBAL_PARAMETERS: begin
                          mot1r <= wdata[`TMC429_F_MOT1R];
                          if (GCONF_4210) begin
                              clk2_div[3:0] <= wdata[`TMC429_F_STPDIV];   // C31: STPDIV only
                          end else begin
                              gp_low <= wdata[`TMC429_F_CS_COM_IND:`TMC429_F_LSMD_LSB];
                              clk2_div <= wdata[`TMC429_F_CLK2_DIV];
                              cont_update <= wdata[`TMC429_F_CONT_UPDATE];
                              refmux <= wdata[`TMC429_F_REFMUX];
                          end
                      end
                default: ;
                endcase
            end
        end
    end

    // ---- shadow RAM of the read values (C20-C29) -------------------------------------------
    // A register that only the µC writes reads back what the write stored: each write of a
    // register address (0..63) also stores its read value, formatted, in a word of the shadow
    // RAM, and the read port of the SPI slave reads it with the address of the frame. The read
    // is synchronous: the address is complete after the 7th bit (rd_addr_q) and the data is
    // loaded at the 8th bit's rising SCK_C edge, at least one edge later (C10), and no write
    // executes inside a frame. Words that are not written (state, constants, registers a
    // variant lacks) have no "written" flag and read the reset value; the state registers
    // (x_actual, v_target, v_actual, a_actual, lp, int_flags, x_latched, ustep_count, pc_i,
    // cw, readback, switches) are ORed in from the combinational mux below.
    localparam [15:0] MOT_SH = (16'd1 << `TMC429_IDX_X_TARGET) | (16'd1 << `TMC429_IDX_V_MIN)
                             | (16'd1 << `TMC429_IDX_V_MAX) | (16'd1 << `TMC429_IDX_A_MAX)
                             | (16'd1 << `TMC429_IDX_CURRENT_SCALING) | (16'd1 << `TMC429_IDX_PMUL_PDIV)
                             | (16'd1 << `TMC429_IDX_REF_CONF_RM) | (16'd1 << `TMC429_IDX_INTERRUPT)
                             | (16'd1 << `TMC429_IDX_CLK_CONFIG) | (16'd1 << `TMC429_IDX_DX_REF_TOLERANCE);
    localparam [15:0] GLB_SH = (16'd1 << `TMC429_JDX_COVER_POS_LEN) | (16'd1 << `TMC429_JDX_COVER_DATAGRAM)
                             | (16'd1 << `TMC429_JDX_IF_CONFIGURATION) | (16'd1 << `TMC429_JDX_POS_COMP)
                             | (16'd1 << `TMC429_JDX_POS_COMP_INT) | (16'd1 << `TMC429_JDX_GLOBAL_PARAMETERS);
    // of those, the ones the variant has
    localparam [15:0] MOT_W = MOT_SH & `TMC429_IDX_PRESENT(CHIP);
    localparam [15:0] GLB_W = GLB_SH & `TMC429_JDX_PRESENT(CHIP);
    localparam [63:0] SH_W = {GLB_W, (NMOT == 1) ? 32'd0 : {MOT_W, MOT_W}, MOT_W};

    // the read value of the register a7 addresses after a write of wdata
    wire [3:0] sh_idx = a7[`TMC429_A7_IDX];
    wire       sh_glb = a7[`TMC429_A7_SMDA] == `TMC429_SMDA_GLOBAL;
    reg [23:0] sh_wdata;
    always @(*) begin
        sh_wdata = 24'd0;
        if (!sh_glb) begin
            case (sh_idx)
            `TMC429_IDX_X_TARGET:  sh_wdata = wdata & `TMC429_WMASK_X_TARGET;
            `TMC429_IDX_V_MIN:     sh_wdata = wdata & `TMC429_WMASK_V_MIN;
            `TMC429_IDX_V_MAX:     sh_wdata = wdata & `TMC429_WMASK_V_MAX;
            `TMC429_IDX_A_MAX:     sh_wdata = wdata & `TMC429_WMASK_A_MAX;
            `TMC429_IDX_CURRENT_SCALING: sh_wdata = wdata & `TMC429_WMASK_CURRENT_SCALING;
            `TMC429_IDX_PMUL_PDIV: sh_wdata = (wdata & `TMC429_WMASK_PMUL_PDIV)
                                            | (24'd1 << `TMC429_F_PMUL_MSB);   // C22: bit 15 reads 1
            `TMC429_IDX_REF_CONF_RM: sh_wdata = wdata & `TMC429_WMASK_REF_CONF_RM;   // lp: state
            `TMC429_IDX_INTERRUPT: sh_wdata = wdata & `TMC429_WMASK_INTERRUPT;       // flags: state
            `TMC429_IDX_CLK_CONFIG: sh_wdata = wdata & `TMC429_WMASK_CLK_CONFIG;
            `TMC429_IDX_DX_REF_TOLERANCE: sh_wdata = wdata & `TMC429_WMASK_DX_REF_TOLERANCE;
            default: ;
            endcase
        end else begin
            case (sh_idx)
            `TMC429_JDX_COVER_POS_LEN:          // cover_pos reads back + 1 (C29); cw: state
                sh_wdata = ({18'd0, wdata[`TMC429_F_COVER_POS] + 6'd1} << `TMC429_F_COVER_POS_LSB)
                         | ({19'd0, wdata[`TMC429_F_COVER_LEN]} << `TMC429_F_COVER_LEN_LSB);
            `TMC429_JDX_COVER_DATAGRAM:   sh_wdata = wdata & `TMC429_WMASK_COVER_DATAGRAM;
            `TMC429_JDX_IF_CONFIGURATION: sh_wdata = wdata & `TMC429_WMASK_IF_CONFIGURATION;
            `TMC429_JDX_POS_COMP:         sh_wdata = wdata & `TMC429_WMASK_POS_COMP;
            `TMC429_JDX_POS_COMP_INT:     sh_wdata = wdata & `TMC429_WMASK_POS_COMP_INT;   // I: state
            default: sh_wdata = wdata & GCONF_WMASK;                                        // global_parameters
            endcase
        end
    end

    // reset value (C2) of the read value of register address a; C29 type_version
    function [23:0] sh_rst;
        input [5:0] a;
        begin
            sh_rst = 24'd0;
            if (a[`TMC429_A7_SMDA] != `TMC429_SMDA_GLOBAL) begin
                if (a[`TMC429_A7_IDX] == `TMC429_IDX_PMUL_PDIV && {1'b0, a[`TMC429_A7_SMDA]} < NMOT3)
                    sh_rst = `TMC429_RESET_PMUL_PDIV;
            end else begin
                case (a[`TMC429_A7_IDX])
                `TMC429_JDX_TYPE_VERSION:  sh_rst = HAS_429 ? `TMC429_RESET_TYPE_VERSION : 24'd0;
                `TMC429_JDX_GLOBAL_PARAMETERS: sh_rst = GCONF_RST;
                default: ;
                endcase
            end
        end
    endfunction

    wire [23:0] sh_q;
    wire        sh_wq;
    tmc429_wram #(.AW(6), .DW(24), .WMASK(SH_W)) u_shadow (
        .clk(clk), .rst(rst),
        .we(wr_reg), .waddr(a7[`TMC429_A7_REG]), .wdata(sh_wdata),
        .re(1'b1), .raddr(rd_addr_q), .q(sh_q), .wq(sh_wq));
    wire [23:0] sh_data = sh_wq ? sh_q : rq_rst;

    // ---- read mux ---------------------------------------------------------------------
    wire        rq_sw  = rd_idx[`TMC429_JDX_REF_SWITCHES];
    wire [23:0] st_glb = ({24{rd_idx[`TMC429_JDX_DATAGRAM_LOW_WORD] & HAS_CHAIN}} & chain_readback[23:0])
                       | ({24{rd_idx[`TMC429_JDX_DATAGRAM_HIGH_WORD] & HAS_CHAIN}} & chain_readback[47:24])
                       | ({23'd0, rd_idx[`TMC429_JDX_COVER_POS_LEN] & HAS_CHAIN & (cw | chain_cover_busy)}
                          << `TMC429_F_CW)
                       | ({23'd0, rd_idx[`TMC429_JDX_POS_COMP_INT] & HAS_429 & pc_i} << `TMC429_F_POS_COMP_INT_I)
                       | ({23'd0, rq_sw & sw_r[0]} << `TMC429_F_R1) | ({23'd0, rq_sw & sw_l[0]} << `TMC429_F_L1)
                       | ({23'd0, rq_sw & sw_r[1]} << `TMC429_F_R2) | ({23'd0, rq_sw & sw_l[1]} << `TMC429_F_L2)
                       | ({23'd0, rq_sw & sw_r[2]} << `TMC429_F_R3) | ({23'd0, rq_sw & sw_l[2]} << `TMC429_F_L3);
    // power_down reads 0; the rest: shadow RAM
    wire [23:0] st_data = ({24{rq_mot[0]}} & m_rdata[23:0])
                        | ({24{rq_mot[1]}} & m_rdata[47:24])
                        | ({24{rq_mot[2]}} & m_rdata[71:48])
                        | ({24{rq_glb}} & st_glb);
    // v_actual (V >> 8 rounded toward 0, C42): V[19:8] of the selected motor and its rounding
    // bit (a LUT of flip-flops in tmc429_ramp), which the SPI slave adds in the next edge
    wire [11:0] v_sel  = ({12{rq_mot[0]}} & m_v_hi[11:0]) | ({12{rq_mot[1]}} & m_v_hi[23:12])
                       | ({12{rq_mot[2]}} & m_v_hi[35:24]);
    wire        v_up   = |(rq_mot & m_v_rnd);
    // rd_data is 0 outside the edge that loads it (rd_load): the value matters in that edge
    // alone, and a simulator then evaluates the multiplexer only when a read takes it (the
    // SPI slave's load already selects on rd_load, so synthesis forms the same logic). The
    // rounding bit is added by the SPI slave in the edge after the load (rd_round)
    wire        rd_va = rd_load & ~rq_ram & rq_va;
    assign      rd_round = rd_va & v_up;
    always @(*) begin
        if (!rd_load)
            rd_data = 24'd0;
        else if (rq_ram)
            rd_data = ({18'd0, ram_rdata[11:6]} << `TMC429_F_RAM_ODD_LSB)
                    | ({18'd0, ram_rdata[5:0]} << `TMC429_F_RAM_EVEN_LSB);
        else
            rd_data = st_data | sh_data | {12'd0, {12{rq_va}} & v_sel};
    end
endmodule

`default_nettype wire
