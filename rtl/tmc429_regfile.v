// tmc429_regfile: the register file and the motion core (docs/model-contract.md C20-C31,
// C40-C66; TMC428 §7-§9, TMC429 §8). The driver side (tmc429_chain, _current, _stepdir,
// _drvpins) takes its configuration from the `drv_*` ports and hands back the chain's
// handshake (C85, C88, C89), readback (C87) and the multiplexed switches (C87).
//
// Executes the 32-bit datagram `cmd` when `exec` pulses (C12), serves the read port of the
// SPI slave (data of the old state), builds the status byte, the interrupt output, the
// position compare and the power-down state. Holds the pre-divider counter and the frame
// schedule (C40, C41): the shared target velocity unit (tmc429_vtarget) and, per motor, the
// registers with the ramp and pulse generator (tmc429_motor_regs, tmc429_ramp). Per CHIP
// (0 TMC428, 1 TMC429, 2 TMC4210) the registers a variant lacks read 0 and ignore writes (C21).
`default_nettype none

module tmc429_regfile #(
    parameter CHIP = 1
) (
    input  wire        clk,
    input  wire        rst,
    input  wire        exec,
    input  wire [31:0] cmd,
    input  wire        frame_start,   // synchronized nSCS_C falling edge: wake-up (C66)
    input  wire [6:0]  rd_addr,
    input  wire [5:0]  rd_addr_q,     // the same address, stable one edge earlier (shadow RAM)
    output reg  [23:0] rd_data,
    input  wire [2:0]  ref_q,         // synchronized REF3..1
    input  wire [2:0]  refr_q,        // synchronized REFR3..1
    output wire [7:0]  status,        // INT CDGW RS3 xEQt3 RS2 xEQt2 RS1 xEQt1
    output reg         nint_q,        // nINT, registered from the state before the edge (C11)
    output wire        sdo_int,       // if_configuration sdo_int (TMC429/TMC4210)
    output reg         poscmp_q,      // position compare match, registered (C65)
    output reg         pd,            // powered down
    output reg  [19:0] prescaler,     // free-running CLK counter (C40), 20 bits as the model
    // probes, motor m in bits [w*(m+1)-1 : w*m]
    output wire [71:0] p_x_target,
    output wire [71:0] p_x_actual,
    output wire [59:0] p_v,
    output wire [35:0] p_v_target,
    output wire [35:0] p_a_actual,
    output wire [23:0] p_ustep,
    output wire [32:0] p_pulse_acc,
    output wire [2:0]  p_step,
    output wire [2:0]  p_dir,
    // driver side: configuration (old state, and new state for the output pin registers)
    output wire [23:0] drv_gconf,      // $7E as stored: mot1r refmux 000 cont_update clk2_div bits 7..0
    output wire [23:0] drv_gconf_nx,
    output wire        drv_gconf_we,   // a write of $7E executes in this edge
    output wire [23:0] drv_gconf_wd,   // $7E as that write stores it
    output wire [8:0]  drv_ifconf,     // if_configuration (TMC429, TMC4210)
    output wire [8:0]  drv_ifconf_nx,
    output wire [59:0] drv_conf,       // motor m in [20m+19:20m]: {is_*, a_threshold}
    output wire [2:0]  drv_ramp_tick,  // phase 30 of a ramp frame of motor m (not gated by run)
    output wire [2:0]  drv_ramp_tick_nx, // drv_ramp_tick of the next edge (its register's input)
    output wire        drv_cw,         // cover datagram waiting
    output wire        drv_dgw,        // datagram-word write waiting
    output wire [5:0]  drv_cover_pos,
    output wire [4:0]  drv_cover_len,
    output wire [23:0] drv_cover_datagram,
    // driver side: chain handshake and state
    input  wire        chain_take,     // a datagram starts: cw and dgw taken
    input  wire        chain_ret_cw,   // SPI mode left: a taken cover returns to waiting
    input  wire        chain_ret_dgw,
    input  wire        chain_cover_busy,
    input  wire        chain_dgw_busy,
    input  wire [47:0] chain_readback,
    input  wire [5:0]  mux_sw,         // switches sampled through the 74HC157
    input  wire        chain_ram_re,   // chain read port of the RAM (C80)
    input  wire [6:0]  chain_ram_addr,
    output wire [5:0]  chain_ram_q
);
    localparam HAS_CHAIN = (CHIP != 2);   // JDX 0..3 (driver chain), TMC4210: absent
    localparam HAS_429   = (CHIP != 0);   // JDX 4, 5, 6, 9
    localparam HAS_RAM   = (CHIP != 2);   // TMC4210: no driver chain, no RAM

    // ---- datagram decode ------------------------------------------------------------
    wire [6:0]  a7    = cmd[31:25];
    wire        wr    = exec & ~cmd[24];
    wire [23:0] wdata = cmd[23:0];
    wire        wr_g  = wr & (a7[6:4] == 3'b011);       // global register
    wire [3:0]  jdx   = a7[3:0];
    wire        wr_ram = wr & a7[6] & HAS_RAM;

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

    // ---- switches -------------------------------------------------------------------
    wire [2:0] sw_l, sw_r;
    tmc429_refsw #(.CHIP(CHIP)) u_refsw (
        .ref_q(ref_q), .refr_q(refr_q),
        .inv_ref(if_conf[0]), .en_refr(if_conf[8]), .refmux(refmux), .mot1r(mot1r),
        .mux_sw(mux_sw), .l(sw_l), .r(sw_r));

    // ---- frame schedule (C40, C41) ----------------------------------------------------
    // F mod 2^div = 2^div - 1 <=> the number of trailing ones of F is at least div. The ticks
    // are registers formed one edge ahead: the phase after this edge is p + run, the frame
    // does not change from phase 29 to 30 or 30 to 31 (nor while powered down), and the
    // divider after this edge is the one a µC write of IDX 12 in this edge stores.
    wire [14:0] frame = prescaler[19:5];
    reg  [3:0]  ones_d;
    integer k;
    always @(*) begin
        ones_d = 4'd15;
        for (k = 14; k >= 0; k = k - 1)
            if (!frame[k])
                ones_d = k[3:0];
    end
    // power_down after this edge (C66): set by a write of it, else cleared by the waking frame
    // start. The ticks include run of the edge after (powered down the core has no tick).
    wire [4:0] ph      = prescaler[4:0];
    wire pd_nx       = (wr_g & (jdx == 4'd8)) | (pd & ~frame_start);
    wire ph_ramp_nx  = ~pd_nx & (run ? (ph == 5'd29) : (ph == 5'd30));
    wire ph_pulse_nx = ~pd_nx & (run ? (ph == 5'd30) : (ph == 5'd31));

    // ---- read address decode (C10) ---------------------------------------------------------
    // The address is complete in the SPI input register from the edge after the 7th bit, and
    // the read data is loaded at the 8th bit's rising SCK_C edge, two edges later at the
    // earliest (a synchronized SCK_C needs a low cycle between two rising edges): a decode
    // registered every edge is the address's at the loading edge, and the read multiplexer
    // starts at flip-flops (one-hot selects, AND-OR).
    reg         rq_ram, rq_glb, rq_va;
    reg  [2:0]  rq_mot;
    reg  [15:0] rq_idx;
    reg  [23:0] rq_rst;
    integer     j;
    always @(posedge clk) begin
        if (rst) begin
            rq_ram <= 1'b0;  rq_glb <= 1'b0;  rq_va <= 1'b0;  rq_mot <= 3'd0;  rq_idx <= 16'd0;
            rq_rst <= 24'd0;
        end else begin
            rq_ram <= rd_addr[6];
            rq_glb <= rd_addr[5:4] == 2'd3;
            rq_mot <= {(rd_addr[5:4] == 2'd2) & (CHIP != 2), (rd_addr[5:4] == 2'd1) & (CHIP != 2),
                       rd_addr[5:4] == 2'd0};
            for (j = 0; j < 16; j = j + 1)
                rq_idx[j] <= rd_addr[3:0] == j[3:0];
            rq_va  <= (rd_addr[5:4] != 2'd3) & (rd_addr[3:0] == 4'd5);
            rq_rst <= sh_rst(rd_addr[5:0]);
        end
    end

    // ---- motors -----------------------------------------------------------------------
    wire [71:0] m_rdata;      // read data of motor m in [24m+23:24m]
    wire [2:0]  xeqt, irq;
    wire        m_present1 = (CHIP != 2);
    localparam  NMOT = (CHIP == 2) ? 1 : 3;

    wire [5:0]  m_rm;
    wire [11:0] m_pulse_div, m_ramp_div;
    wire [35:0] m_vt;
    reg  [2:0]  ramp_tick, pulse_tick;
    wire [2:0]  ramp_tick_nx;
    assign drv_ramp_tick = ramp_tick;
    assign drv_ramp_tick_nx = ramp_tick_nx;

    genvar g;
    generate
        for (g = 0; g < 3; g = g + 1) begin : mot
            wire present = (g == 0) | m_present1;
            wire w_div = wr & present & (a7[6:4] == g) & (jdx == 4'd12);
            wire [3:0] rdiv_nx = w_div ? wdata[11:8] : m_ramp_div[4*g+3:4*g];
            wire [3:0] pdiv_nx = w_div ? wdata[15:12] : m_pulse_div[4*g+3:4*g];
            assign ramp_tick_nx[g] = ph_ramp_nx & (ones_d >= rdiv_nx);
            always @(posedge clk) begin
                if (rst) begin
                    ramp_tick[g] <= 1'b0;
                    pulse_tick[g] <= 1'b0;
                end else begin
                    ramp_tick[g] <= ramp_tick_nx[g];
                    pulse_tick[g] <= ph_pulse_nx & (ones_d >= pdiv_nx);
                end
            end
            tmc429_motor_regs #(.CHIP(CHIP)) u_m (
                .clk(clk), .rst(rst), .run(run & present),
                .we(wr & present & (a7[6:4] == g)), .widx(a7[3:0]), .wdata(wdata),
                .rsel(rq_idx), .rdata(m_rdata[24*g+23:24*g]),
                .sw_l(sw_l[g]), .sw_r(sw_r[g]),
                .ramp_tick(ramp_tick[g]),
                .pulse_tick(pulse_tick[g]),
                .vt(m_vt[12*g+11:12*g]),
                .xeqt(xeqt[g]), .irq(irq[g]),
                .x_target(p_x_target[24*g+23:24*g]), .rm(m_rm[2*g+1:2*g]),
                .pulse_div(m_pulse_div[4*g+3:4*g]), .ramp_div(m_ramp_div[4*g+3:4*g]),
                .x_actual(p_x_actual[24*g+23:24*g]), .v(p_v[20*g+19:20*g]),
                .v_target(p_v_target[12*g+11:12*g]), .a_actual(p_a_actual[12*g+11:12*g]),
                .ustep(p_ustep[8*g+7:8*g]), .pulse_acc(p_pulse_acc[11*g+10:11*g]),
                .step(p_step[g]), .dir(p_dir[g]),
                .drv_conf(drv_conf[20*g+19:20*g]));
        end
    endgenerate

    // ---- target velocity (C41, C50) -------------------------------------------------------
    tmc429_vtarget #(.NMOT(NMOT)) u_vt (
        .clk(clk), .rst(rst), .run(run), .phase(prescaler[4:0]),
        .rm(m_rm), .x_target(p_x_target), .x_actual(p_x_actual),
        .v_target(p_v_target),
        .cfg_we(wr & ~a7[6] & (a7[5:4] != 2'd3) & ((a7[5:4] == 2'd0) | m_present1)),
        .cfg_m(a7[5:4]), .cfg_idx(jdx), .cfg_data(wdata[14:0]),
        .vt(m_vt));

    // ---- position compare (C65) -------------------------------------------------------
    reg [23:0] pc_x;
    always @(*) begin
        case (if_conf[7:6])
        2'd0:    pc_x = p_x_actual[23:0];
        2'd1:    pc_x = p_x_actual[47:24];
        default: pc_x = p_x_actual[71:48];   // 3 selects motor 3 as well
        endcase
    end
    wire pc_match = HAS_429 && (pc_x == pos_comp);
    wire pc_event = run & pc_match & ~pc_hist;
    wire w_pcint  = wr_g & HAS_429 & (jdx == 4'd6);
    wire pc_m_nx  = w_pcint ? wdata[8] : pc_m;
    wire pc_w1c   = w_pcint & wdata[0];

    assign sdo_int = HAS_429 && if_conf[1];
    assign int_o   = (|irq) | (pc_i & pc_m);
    // RSn = Ln ([429] §6.2.2.2, C60)
`ifdef PLANT_BUG_STATUS
    // Planted bug for the co-simulation self-test (testbench/tests/planted_bug.rs):
    // CDGW forgets the datagram-waiting flag of a datagram_low/high write.
    wire   cdgw    = cw | chain_cover_busy;
`else
    // C88: CDGW = cw OR the datagram-word flag, each waiting or taken by the datagram under way
    wire   cdgw    = cw | dw | chain_cover_busy | chain_dgw_busy;
`endif
    assign status  = {int_o, cdgw, sw_l[2], xeqt[2], sw_l[1], xeqt[1], sw_l[0], xeqt[0]};

    // ---- driver side ------------------------------------------------------------------
    wire w_gconf  = wr_g & (jdx == 4'd15);
    wire w_ifconf = wr_g & HAS_429 & (jdx == 4'd4);
    assign drv_gconf     = {2'd0, mot1r, refmux, 3'd0, cont_update, clk2_div, gp_low};
    assign drv_gconf_we  = w_gconf;
    assign drv_gconf_wd  = (CHIP == 2) ? {2'd0, wdata[21], 9'd0, wdata[11:8], 8'd0}
                                       : {2'd0, wdata[21:20], 3'd0, wdata[16:0]};
    assign drv_gconf_nx  = w_gconf ? drv_gconf_wd : drv_gconf;
    assign drv_ifconf    = if_conf;
    assign drv_ifconf_nx = w_ifconf ? wdata[8:0] : if_conf;
    assign drv_cw        = cw;
    assign drv_dgw       = dw;
    assign drv_cover_pos = cover_pos;
    assign drv_cover_len = cover_len;
    // cover_datagram (C85) is used only by the chain's start edge, which copies it: it lives
    // in a one-word RAM, read every edge. In the edge after a write the RAM output is not yet
    // the new word; the datagram is still in the SPI input register then (no frame can
    // follow within one edge), so that edge takes it from there.
    reg         cov_late;
    wire [23:0] cov_q;
    wire        cov_wq;
    wire        w_cover = wr_g & HAS_CHAIN & (jdx == 4'd3);
    tmc429_wram #(.AW(1), .DW(24), .WMASK(2'b01)) u_cover (
        .clk(clk), .rst(rst),
        .we(w_cover), .waddr(1'b0), .wdata(wdata),
        .re(1'b1), .raddr(1'b0), .q(cov_q), .wq(cov_wq));
    assign drv_cover_datagram = cov_late ? wdata : (cov_wq ? cov_q : 24'd0);

    always @(posedge clk) begin
        if (rst) begin
            dw <= 1'b0;  cw <= 1'b0;
            cover_pos <= 6'd0;  cover_len <= 5'd0;  cov_late <= 1'b0;
            if_conf <= 9'd0;  pos_comp <= 24'd0;
            pc_i <= 1'b0;  pc_m <= 1'b0;  pc_hist <= HAS_429;   // match holds at reset
            gp_low <= 8'd0;  clk2_div <= 8'd15;
            cont_update <= 1'b0;  refmux <= 1'b0;  mot1r <= 1'b0;
            pd <= 1'b0;
            prescaler <= 20'd0;
            nint_q <= 1'b1;
            poscmp_q <= HAS_429;
        end else begin
            nint_q   <= ~int_o;
            cov_late <= w_cover;
            poscmp_q <= pc_match;
            if (run) begin
                prescaler <= prescaler + 20'd1;
                pc_hist   <= pc_match;
            end
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
                4'd0, 4'd1: if (HAS_CHAIN) dw <= 1'b1;    // datagram_low/high: arm CDGW
                4'd2: if (HAS_CHAIN) begin
                          cover_pos <= wdata[13:8];
                          cover_len <= wdata[4:0];
                      end
                4'd3: if (HAS_CHAIN) cw <= 1'b1;    // the datagram: u_cover
                4'd4: if (HAS_429) if_conf <= wdata[8:0];
                4'd5: if (HAS_429) pos_comp <= wdata;
                // 4'd8: power_down, pd_nx
                4'd15: begin
                          mot1r <= wdata[21];
                          if (CHIP == 2) begin
                              clk2_div[3:0] <= wdata[11:8];   // C31: STPDIV only
                          end else begin
                              gp_low <= wdata[7:0];
                              clk2_div <= wdata[15:8];
                              cont_update <= wdata[16];
                              refmux <= wdata[20];
                          end
                      end
                default: ;
                endcase
            end
        end
    end

    // ---- RAM (C30) --------------------------------------------------------------------
    wire [11:0] ram_rdata;
    tmc429_ram #(.CHIP(CHIP)) u_ram (
        .clk(clk), .rst(rst),
        .we(wr_ram), .waddr(a7[5:0]), .wdata({wdata[13:8], wdata[5:0]}),
        .raddr(rd_addr_q), .rdata(ram_rdata),
        .re2(chain_ram_re), .raddr2(chain_ram_addr), .rdata2(chain_ram_q));

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
    localparam [15:0] MOT_W = (CHIP == 2) ? 16'b0011_1110_0100_1101   // IDX 0,2,3,6,9..13
                                          : 16'b0011_1111_0100_1101;  // and 8
    localparam [15:0] GLB_W = (CHIP == 0) ? 16'b1000_0000_0000_1100   // JDX 2, 3, 15
                            : (CHIP == 2) ? 16'b1000_0000_0111_0000   // JDX 4, 5, 6, 15
                                          : 16'b1000_0000_0111_1100;
    localparam [63:0] SH_W = {GLB_W, (CHIP == 2) ? 32'd0 : {MOT_W, MOT_W}, MOT_W};

    // the read value of register a7[5:0] after a write of wdata
    wire [3:0] sh_idx = a7[3:0];
    wire       sh_glb = a7[5:4] == 2'd3;
    reg [23:0] sh_wdata;
    always @(*) begin
        sh_wdata = 24'd0;
        if (!sh_glb) begin
            case (sh_idx)
            4'd0:  sh_wdata = wdata;                                        // x_target
            4'd2, 4'd3, 4'd6: sh_wdata = {13'd0, wdata[10:0]};              // v_min, v_max, a_max
            4'd8:  sh_wdata = {1'b0, wdata[22:20], 1'b0, wdata[18:16], 1'b0, wdata[14:12],
                               1'b0, wdata[10:0]};
            4'd9:  sh_wdata = {8'd0, 1'b1, wdata[14:8], 4'd0, wdata[3:0]};  // C22: bit 15 reads 1
            4'd10: sh_wdata = {12'd0, wdata[11:8], 6'd0, wdata[1:0]};       // ref_conf, rm (lp: state)
            4'd11: sh_wdata = {8'd0, wdata[15:8], 8'd0};                    // int_mask (flags: state)
            4'd12: sh_wdata = {8'd0, wdata[15:8], 5'd0, wdata[2:0]};
            4'd13: sh_wdata = {12'd0, wdata[11:0]};
            default: ;
            endcase
        end else begin
            case (sh_idx)
            4'd2:  sh_wdata = {10'd0, wdata[13:8] + 6'd1, 3'd0, wdata[4:0]};  // cover_pos + 1, len
            4'd3:  sh_wdata = wdata;                                          // cover_datagram
            4'd4:  sh_wdata = {15'd0, wdata[8:0]};                            // if_configuration
            4'd5:  sh_wdata = wdata;                                          // pos_comp
            4'd6:  sh_wdata = {15'd0, wdata[8], 8'd0};                        // pc mask (pc_i: state)
            default: sh_wdata = (CHIP == 2) ? {2'd0, wdata[21], 9'd0, wdata[11:8], 8'd0}
                                            : {2'd0, wdata[21:20], 3'd0, wdata[16:0]};
            endcase
        end
    end

    // reset value (C2) of the read value of register address a; C29 type_version
    function [23:0] sh_rst;
        input [5:0] a;
        begin
            sh_rst = 24'd0;
            if (a[5:4] != 2'd3) begin
                if (a[3:0] == 4'd9 && (a[5:4] == 2'd0 || CHIP != 2))
                    sh_rst = 24'h008000;
            end else begin
                case (a[3:0])
                4'd2:  sh_rst = (CHIP != 2) ? 24'h000100 : 24'd0;
                4'd9:  sh_rst = (CHIP != 0) ? 24'h429101 : 24'd0;
                4'd15: sh_rst = 24'h000F00;
                default: ;
                endcase
            end
        end
    endfunction

    wire [23:0] sh_q;
    wire        sh_wq;
    tmc429_wram #(.AW(6), .DW(24), .WMASK(SH_W)) u_shadow (
        .clk(clk), .rst(rst),
        .we(wr & ~a7[6]), .waddr(a7[5:0]), .wdata(sh_wdata),
        .re(1'b1), .raddr(rd_addr_q), .q(sh_q), .wq(sh_wq));
    wire [23:0] sh_data = sh_wq ? sh_q : rq_rst;

    // ---- read mux ---------------------------------------------------------------------
    wire [23:0] st_glb = ({24{rq_idx[0] & HAS_CHAIN}} & chain_readback[23:0])    // datagram_low_word
                       | ({24{rq_idx[1] & HAS_CHAIN}} & chain_readback[47:24])   // datagram_high_word
                       | {rq_idx[2] & HAS_CHAIN & (cw | chain_cover_busy), 23'd0}
                       | {23'd0, rq_idx[6] & HAS_429 & pc_i}
                       | {18'd0, {6{rq_idx[14]}} & {sw_l[2], sw_r[2], sw_l[1], sw_r[1], sw_l[0], sw_r[0]}};
    // power_down reads 0; the rest: shadow RAM
    wire [23:0] st_data = ({24{rq_mot[0]}} & m_rdata[23:0])
                        | ({24{rq_mot[1]}} & m_rdata[47:24])
                        | ({24{rq_mot[2]}} & m_rdata[71:48])
                        | ({24{rq_glb}} & st_glb);
    // IDX 5 (v_actual = V >> 8 rounded toward 0, C42): V of the selected motor, one
    // incrementer for the three motors on this path only
    wire [19:0] v_sel  = ({20{rq_mot[0]}} & p_v[19:0]) | ({20{rq_mot[1]}} & p_v[39:20])
                       | ({20{rq_mot[2]}} & p_v[59:40]);
    wire [11:0] v_inc  = v_sel[19:8] + 12'd1;     // the rounding selects after the increment
    wire [11:0] v_rd   = (v_sel[19] & (v_sel[7:0] != 8'd0)) ? v_inc : v_sel[19:8];
    wire [23:0] st_va  = st_data | {12'd0, {12{rq_va}} & v_rd};
    always @(*) begin
        if (rq_ram)
            rd_data = HAS_RAM ? {10'd0, ram_rdata[11:6], 2'd0, ram_rdata[5:0]} : 24'd0;
        else
            rd_data = st_va | sh_data;
    end
endmodule

`default_nettype wire
