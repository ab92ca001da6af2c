// tmc429_chain: the driver-chain SPI master (docs/model-contract.md C80-C89; TMC428 §6.3,
// §9.1-§9.3, §9.7, §10, §11; TMC429 §8.2.1-§8.2.5, §11).
//
// One state machine with one down-counter `cnt` (edges left in the state). Frame of one
// datagram (C82), LO/HI = SCK_S low/high half periods, P = LO + HI, G = NxM gap (C81):
//
//   IDLE --request--> SETUP (CS active, SCK high, HI edges: t_HDSCSdrv)
//     -> LOW (bit on SDO_S, SCK low, LO edges) -> HIGH (SCK high, SDI_S shifted into the
//        readback at its first edge, HI edges) -> next bit, or GAP (NxM, motor < LSMD,
//        G edges, motor + 1) -> next bit, or HOLD (NxM, motor = LSMD, CS active, HI edges)
//     -> CSOFF (CS inactive, SDO_S high, P edges) -> next datagram in the same edge, or IDLE
//
// Readback (C87): SDI_S shifts in at each rising SCK_S edge; a datagram_low/high_word write
// (`readback_clr`) initializes the 48 bits to 0.
//
// Start edge (C80, C85, C88): snapshot of each motor's full-wave index, current scale,
// direction and step flag (step flags since the last start included) and of the three
// signal polarities; cw and the datagram-word flag are taken (`take`: the register file
// clears them) and the cover position, length (max 24) and data are latched.
//
// RAM reads (C80): the state before a bit's LOW entry (SETUP, HIGH or GAP, >= 8 edges) reads
// the bit's configuration cell at its edge with cnt = 4 (the current cell in SETUP and GAP,
// the following one in HIGH) and, at cnt = 3, the LUT cell that cell's code needs for the
// current motor (tmc429_microstep). The RAM read port is synchronous with a read enable:
// `ram_q` holds the cell read at the last enabled edge. Pipeline to the SDO_S pin register:
// cnt = 3: `cfg` := configuration cell; cnt = 2: `dac` := scaled LUT value, cover decision
// registered; cnt = 1 (LOW entry): the bit from `cfg`, `dac` and the snapshot. The snapshot
// is kept as a shift register whose slot 0 is the current motor (shifted at the NxM gap).
// SCK_S timing values are registers, loaded from the new clk2_div of every edge.
//
// Requests (C83): a step flag, cw, a continuous-update counter wrapping (per motor, 10 bits,
// counts the motor's ramp ticks while cont_update = 1, reset 0 / 341 / 682). Leaving SPI
// mode (C89, `spi_mode` = 0) aborts a datagram: back to IDLE, taken flags are given back
// (`ret_cw`, `ret_dgw`). Powered down (`run` = 0) everything holds (C66).
//
// Pin levels before polarity: `cs`, `sck`, `sdo` and `motor` (for csCommonIndividual) of
// the current state; for the registered output pins `sdo_nx` of the new state and
// `cs_pre_nx`, `sck_pre_nx`, `motor_pre_nx` of the new state before a start overrides them
// (`take` sets CS active, SCK high, motor 0), so that the start is the last input of the
// pin levels.
// Same function as tmc429_model::chain::Chain.
`timescale 1ns / 1ps
`default_nettype none
`include "tmc429_regmap.vh"

module tmc429_chain (
    input  wire        clk,
    input  wire        rst,
    input  wire        run,            // not powered down (C66)
    input  wire        spi_mode,       // SPI mode, old state (TMC428; TMC429 en_sd = 0)
    // motors, old state (C70)
    input  wire [2:0]  step,           // step flags of motors 2..0
    input  wire [2:0]  dir,            // direction of the last step, 1 = negative
    input  wire [23:0] ustep,          // full-wave indices {m2, m1, m0}
    input  wire [8:0]  i_scale,        // selected current scales {m2, m1, m0}
    input  wire [2:0]  ramp_tick_nx,   // ramp ticks of the next edge (C40)
    // global registers, old state
    input  wire        clk2_div_we,    // a µC write stores clk2_div_wd in this edge
    input  wire [7:0]  clk2_div_wd,    // clk2_div as that write stores it (timing registers)
    input  wire [1:0]  lsmd,
    input  wire        pol_ph_ab,
    input  wire        pol_fd_ab,
    input  wire        pol_dac_ab,
    input  wire        cont_update_nx, // cont_update of the new state (after this edge's write)
    input  wire        cw,             // cover datagram waiting
    input  wire        dgw,            // datagram_low/high_word write waiting (C88)
    input  wire        readback_clr,   // a datagram_low/high_word write executes: readback := 0 (C87)
    input  wire [5:0]  cover_pos,
    input  wire [4:0]  cover_len,
    input  wire [23:0] cover_datagram,
    input  wire        sdi_s,          // synchronized SDI_S (C4)
    // RAM read port (cells 0..127, synchronous, read enable)
    output wire        ram_re,
    output wire [6:0]  ram_addr,
    input  wire [5:0]  ram_q,
    // handshake with the register file
    output reg         take,           // start edge: cw and dgw are taken
    output reg         ret_cw,         // abort: the cover returns to waiting
    output reg         ret_dgw,        // abort: the datagram-word flag returns
    output reg         cover_busy,     // the datagram under way carries the cover
    output reg         dgw_busy,       // the datagram under way took the datagram-word flag
    output reg  [47:0] readback,       // SDI_S readback register (C87)
    // pins before polarity
    output reg         cs,
    output reg         sck,
    output reg         sdo,
    output reg  [1:0]  motor,
    output reg         cs_pre_nx,      // cs of the new state if no datagram starts (take = 0)
    output reg         sck_pre_nx,     // sck likewise
    output reg         sdo_nx,         // sdo of the new state
    output reg  [1:0]  motor_pre_nx,   // motor likewise
    // probes
    output reg  [2:0]  state,
    output reg  [5:0]  cidx,           // configuration cell of the current bit
    output reg  [6:0]  bits,
    output reg         req
);
    localparam IDLE = 3'd0, SETUP = 3'd1, LOW = 3'd2, HIGH = 3'd3, GAP = 3'd4, HOLD = 3'd5,
               CSOFF = 3'd6;

    // ---- SCK_S timing (C81), registered: the values of the current clk2_div --------------
    // clk2_div changes only by a µC write, so the registers load at that write, from the
    // written data (the SPI input register) while the write decode only enables them
    wire [7:0] wd     = clk2_div_wd;
    wire [8:0] nx_lo  = {1'b0, wd} + 9'd1;
    wire [8:0] nx_hi  = (wd >= 8'd7) ? nx_lo : (9'd15 - {1'b0, wd});
    // t_lo + t_hi is 16 up to clk2_div 7 ((clk2_div + 1) + (15 - clk2_div)) and 2·t_lo above;
    // the gap 3·t_lo = 4·clk2_div + 3 - clk2_div above 7, one carry chain from the written
    // data (not t_lo's sum added to itself shifted: a carry chain behind a carry chain)
    wire [9:0] nx_p   = (wd >= 8'd7) ? {nx_lo, 1'b0} : 10'd16;
    wire [9:0] nx_gap = (wd <= 8'd7) ? 10'd16 : ({wd, 2'b11} - {2'b00, wd});
    reg  [8:0] t_lo, t_hi;
    reg  [9:0] t_p, t_gap;
    // the counter's cnt > 1 after a load: t_hi >= 8 (clk2_div >= 7: clk2_div + 1, else
    // 15 - clk2_div), t_p = t_lo + t_hi >= 9 and t_gap >= t_p are always above 1; t_lo =
    // clk2_div + 1 is 1 for clk2_div = 0
    reg        g_lo;                    // t_lo > 1
    always @(posedge clk) begin
        if (rst) begin
            t_lo <= 9'd16;  t_hi <= 9'd16;  t_p <= 10'd32;  t_gap <= 10'd48;   // clk2_div 15
            g_lo <= 1'b1;
        end else if (clk2_div_we) begin
            t_lo <= nx_lo;  t_hi <= nx_hi;  t_p <= nx_p;  t_gap <= nx_gap;
            g_lo <= wd != 8'd0;
        end
    end

    // ---- state ----------------------------------------------------------------------------
    reg [9:0]  cnt, cnt_nx;
    reg [2:0]  state_nx;
    reg [5:0]  cidx_nx;
    reg [6:0]  bits_nx;
    reg        req_nx;
    reg [2:0]  stepped, stepped_nx;
    reg [23:0] snap_w;                  // slots {2, 1, 0}; slot 0 = current motor
    reg [8:0]  snap_is;
    reg [2:0]  snap_dir, snap_step, snap_pol;
    reg [5:0]  cfg, dac;
    reg        cov_sel, cov_bit;
    reg        nxm, nxm_nx;
    reg [5:0]  cov_pos;
    reg [6:0]  cov_end;                 // cover_pos + cover_len (length at most 24)
    // cover_len > 24 (25 to 31) as a bit test: a comparison written `>` is a carry chain, in
    // front of the sum's own (scripts/carry-paths)
    wire       len_over = cover_len[4] & cover_len[3] & (|cover_len[2:0]);
    reg [23:0] cov_data;
    reg [9:0]  cupd0, cupd1, cupd2;
    reg        cover_busy_nx, dgw_busy_nx, start;
    // the HIGH state's last edge with an NxM bit (state HIGH, cnt <= 1, nxm): a register formed
    // with the next state, so that the NxM gap's shift of the snapshot (below) is an AND of
    // flip-flops and the snapshot's enable leaves the next-state logic (the requests and the
    // start) out of its cone
    reg        hi_nxm;
    wire       hi_nxm_nx;
    // can_start = (state == IDLE) | (CSOFF with cnt <= 1): a datagram may start in this edge.
    // A register formed with the next state (HOLD enters CSOFF with cnt = P >= 16), so that
    // `start` is request AND a flip-flop.
    // The counter's comparisons with constants are bit tests (cnt <= 2: none above bit 1 and
    // not 3), LUTs only: written as `>` and `<=`, synthesis (Yosys' synth_ice40) builds each
    // as a carry chain, which lay on the path from the counter through the chip select's next
    // state into the nSCS_S pin register. cnt > 1 is a register formed with the counter's next
    // state (a count down from cnt: cnt > 2; a load: the loaded value's, 1 but for t_lo,
    // whose is registered with it), so that the OR of nine bits is not in front of every next
    // state.
    reg        cnt_gt1, gt1_nx;         // = |cnt[9:1]
    wire       cnt_le2 = ~|cnt[9:2] & ~&cnt[1:0];
    reg        can_start;
    wire       can_start_nx = ~run ? can_start
                           : (~spi_mode | (~start & ((state == IDLE)
                                                     | ((state[2:1] == 2'b11) & cnt_le2))));
    reg [47:0] readback_nx;

    // ---- RAM reads ahead of a bit (C80) ------------------------------------------------------
    // The two reads are registers formed with the next state (below), so that the RAM's read
    // enable and address start at flip-flops: rd_cfg = pre_bit & cnt = 4, rd_lut = pre_bit &
    // cnt = 3 in every edge, a start (SETUP, cnt = t_hi) entering only at their last LUT
    function pre_bit_of;                // the states whose counter leads to a bit (RAM reads)
        input [2:0] st;
        pre_bit_of = (st == SETUP) | (st == HIGH) | (st == GAP);
    endfunction
    wire       pre_bit  = pre_bit_of(state);
    reg        rd_cfg, rd_lut, rd_cfg_pre_nx, rd_lut_pre_nx;
    wire       pre_dac  = pre_bit & (cnt == 10'd2);
    wire [5:0] cfg_cell = (state == HIGH) ? cidx + 6'd1 : cidx;

    wire [5:0] lut_idx, dac_nx;
    wire       sig_bit;
    tmc429_microstep u_ustep (
        .w(snap_w[7:0]), .coil_b(ram_q[3]), .lut_idx(lut_idx),
        .lut(ram_q), .i_scale(snap_is[2:0]), .dac(dac_nx),
        .code(cfg[4:0]), .dac_q(dac), .negative(snap_dir[0]), .step(snap_step[0]),
        .pol_ph_ab(snap_pol[0]), .pol_fd_ab(snap_pol[1]), .pol_dac_ab(snap_pol[2]),
        .bit_out(sig_bit));

    assign ram_re   = run & spi_mode & (rd_cfg | rd_lut);
    // RAM cell = 2 * word + half: the driver configuration's cells, then the sine table's (C80)
    localparam [6:0] CELL_CFG = {`TMC429_ADDR_RAM_DRIVER_CONFIG, 1'b0};
    localparam [6:0] CELL_LUT = {`TMC429_ADDR_RAM_MICROSTEP_TABLE, 1'b0};
    assign ram_addr = rd_cfg ? (CELL_CFG | {1'b0, cfg_cell}) : (CELL_LUT | {1'b0, lut_idx});

    // ---- cover (C85): positions cover_pos <= k < cover_pos + len carry data[len-1-(k-pos)];
    // decided at cnt = 2 (bits does not change before the LOW entry). With the end
    // e = pos + len latched, the two bounds are compared side by side and the index
    // len - 1 - (k - pos) = e - 1 - k is one sum, e + ~k (mod 32). The bounds' comparison and
    // the index are registered at cnt = 3 with the LUT cell's read (`rd_lut`: the edge before,
    // in the same state; bits and the latch do not change in between), so that the selection
    // of the datagram's bit starts at flip-flops
    reg        cov_hit;
    reg  [4:0] cov_i;
    wire       bit_now = cov_sel ? cov_bit : sig_bit;

    // ---- requests (C83) ---------------------------------------------------------------------
    // The ramp ticks and cont_update come as the values of the next edge and are registered
    // here (ramp_tick, cont_update: equal to the register file's), so that the wrap of a
    // continuous-update counter is a flip-flop formed one edge ahead and `request`, an OR of
    // flip-flops, is one LUT level before `start`. A motor's ramp ticks are a frame apart (one
    // ramp phase per frame, C40), so in an edge before a tick the motor has no tick and its
    // counter keeps its value: the wrap's next state takes the counter's registered compare
    // (cupd_top = counter at 1023), not the compare of the next count, and the ticks' next
    // state meets one AND-OR before the flip-flop.
    reg  [2:0] ramp_tick;
    reg        cont_update;
    wire [2:0] cu_tick = ramp_tick & {3{cont_update}};
    reg  [2:0] cupd_top;                // counter at 1023 (registered compare)
    wire [2:0] cupd_top_nx = (run & spi_mode)
                          ? {cupd2 + {9'd0, cu_tick[2]} == 10'd1023,
                             cupd1 + {9'd0, cu_tick[1]} == 10'd1023,
                             cupd0 + {9'd0, cu_tick[0]} == 10'd1023}
                          : cupd_top;
    reg        wrap;                    // = |(cu_tick & cupd_top)
    wire       request = req | (|step) | cw | wrap;
    wire [1:0] lsmd_e  = (lsmd == 2'd3) ? 2'd2 : lsmd;       // C86: LSMD 3 acts as 2

    // ---- next state -------------------------------------------------------------------------
    always @(*) begin
        state_nx = state;  cnt_nx = cnt;  gt1_nx = cnt_gt1;  cidx_nx = cidx;  bits_nx = bits;
        motor_pre_nx = motor;  req_nx = req;  stepped_nx = stepped;  nxm_nx = nxm;
        cover_busy_nx = cover_busy;  dgw_busy_nx = dgw_busy;  readback_nx = readback;
        cs_pre_nx = cs;  sck_pre_nx = sck;  sdo_nx = sdo;
        start = 1'b0;  take = 1'b0;  ret_cw = 1'b0;  ret_dgw = 1'b0;
        rd_cfg_pre_nx = rd_cfg;  rd_lut_pre_nx = rd_lut;
        if (run) begin
            if (!spi_mode) begin
                if (state != IDLE || cs || req || stepped != 3'd0) begin
                    // C89: leaving SPI mode aborts; taken flags return to waiting
                    ret_cw = cover_busy;   ret_dgw = dgw_busy;
                    state_nx = IDLE;  cnt_nx = 10'd0;  gt1_nx = 1'b0;  cidx_nx = 6'd0;  bits_nx = 7'd0;
                    motor_pre_nx = 2'd0;  req_nx = 1'b0;  stepped_nx = 3'd0;  nxm_nx = 1'b0;
                    cover_busy_nx = 1'b0;  dgw_busy_nx = 1'b0;
                    cs_pre_nx = 1'b0;  sck_pre_nx = 1'b1;  sdo_nx = 1'b1;
                    rd_cfg_pre_nx = 1'b0;  rd_lut_pre_nx = 1'b0;
                end
            end else begin
                start = can_start & request;
                if (state == IDLE) begin
                    // waiting for a request (start)
                end else if (cnt_gt1) begin
                    cnt_nx = cnt - 10'd1;  gt1_nx = ~cnt_le2;
                end else begin
                    case (state)
                    SETUP, GAP: begin
                        // falling SCK_S: the bit goes out (C84, C85)
                        sdo_nx = bit_now;  nxm_nx = cfg[5];  sck_pre_nx = 1'b0;
                        state_nx = LOW;  cnt_nx = {1'b0, t_lo};  gt1_nx = g_lo;
                    end
                    LOW: begin
                        // rising SCK_S: SDI_S into the readback (C87)
                        sck_pre_nx = 1'b1;
                        readback_nx = {readback[46:0], sdi_s};
                        if (bits != 7'd127)
                            bits_nx = bits + 7'd1;
                        state_nx = HIGH;  cnt_nx = {1'b0, t_hi};  gt1_nx = 1'b1;
                    end
                    HIGH: begin
                        if (nxm) begin
                            if (motor >= lsmd_e) begin
                                state_nx = HOLD;  cnt_nx = {1'b0, t_hi};  gt1_nx = 1'b1;
                            end else begin
                                motor_pre_nx = motor + 2'd1;  cidx_nx = cidx + 6'd1;   // shift (below)
                                state_nx = GAP;  cnt_nx = t_gap;  gt1_nx = 1'b1;
                            end
                        end else begin
                            cidx_nx = cidx + 6'd1;
                            sdo_nx = bit_now;  nxm_nx = cfg[5];  sck_pre_nx = 1'b0;
                            state_nx = LOW;  cnt_nx = {1'b0, t_lo};  gt1_nx = g_lo;
                        end
                    end
                    HOLD: begin
                        // end of the datagram: CS inactive, SDO_S back high (C81), CDGW
                        // handshake done (C87, C88)
                        cs_pre_nx = 1'b0;  sdo_nx = 1'b1;  cover_busy_nx = 1'b0;  dgw_busy_nx = 1'b0;
                        state_nx = CSOFF;  cnt_nx = t_p;  gt1_nx = 1'b1;
                    end
                    default: begin
                        // CSOFF over: the next datagram starts at once if one is requested
                        state_nx = IDLE;
                    end
                    endcase
                end
                // the reads after this edge unless it starts a datagram
                rd_cfg_pre_nx = pre_bit_of(state_nx) & (cnt_nx == 10'd4);
                rd_lut_pre_nx = pre_bit_of(state_nx) & (cnt_nx == 10'd3);
                if (start) begin
                    take = 1'b1;
                    cover_busy_nx = cw;  dgw_busy_nx = dgw;
                    req_nx = 1'b0;  stepped_nx = 3'd0;
                    cidx_nx = 6'd0;  bits_nx = 7'd0;
                    state_nx = SETUP;  cnt_nx = {1'b0, t_hi};  gt1_nx = 1'b1;
                end else begin
                    req_nx = request;
                    stepped_nx = stepped | step;
                end
            end
        end
        // a µC write wins over the shift of the same edge (C3, C87); also while powered down
        if (readback_clr)
            readback_nx = 48'd0;
    end

    assign     hi_nxm_nx = (state_nx == HIGH) & ~gt1_nx & nxm_nx;
    // the NxM gap's entry (HIGH's last edge, nxm, motor < LSMD): the next motor's snapshot
    // moves to slot 0
    wire       shift    = run & spi_mode & hi_nxm & (motor < lsmd_e);

    // a start sets CS active, SCK high and motor 0; the pin registers (tmc429_drvpins)
    // select the same after `take`, so that the start is the last input of a pin's level
    wire       cs_nx    = take | cs_pre_nx;
    // a start enters SETUP with cnt = t_hi
    wire       rd_cfg_nx = take ? (t_hi == 9'd4) : rd_cfg_pre_nx;
    wire       rd_lut_nx = take ? (t_hi == 9'd3) : rd_lut_pre_nx;
    wire       sck_nx   = take | sck_pre_nx;
    wire [1:0] motor_nx = take ? 2'd0 : motor_pre_nx;

    always @(posedge clk) begin
        if (rst) begin
            state <= IDLE;  cnt <= 10'd0;  cnt_gt1 <= 1'b0;  cidx <= 6'd0;  motor <= 2'd0;  bits <= 7'd0;
            can_start <= 1'b1;  hi_nxm <= 1'b0;  rd_cfg <= 1'b0;  rd_lut <= 1'b0;
            req <= 1'b0;  stepped <= 3'd0;  nxm <= 1'b0;
            cover_busy <= 1'b0;  dgw_busy <= 1'b0;  readback <= 48'd0;
            cs <= 1'b0;  sck <= 1'b1;  sdo <= 1'b1;
            cupd0 <= 10'd0;  cupd1 <= 10'd341;  cupd2 <= 10'd682;  cupd_top <= 3'd0;
            ramp_tick <= 3'd0;  cont_update <= 1'b0;  wrap <= 1'b0;
        end else begin
            state <= state_nx;  cnt <= cnt_nx;  cnt_gt1 <= gt1_nx;  cidx <= cidx_nx;  motor <= motor_nx;
            can_start <= can_start_nx;  hi_nxm <= hi_nxm_nx;  rd_cfg <= rd_cfg_nx;  rd_lut <= rd_lut_nx;
            bits <= bits_nx;  req <= req_nx;  stepped <= stepped_nx;  nxm <= nxm_nx;
            cover_busy <= cover_busy_nx;  dgw_busy <= dgw_busy_nx;  readback <= readback_nx;
            cs <= cs_nx;  sck <= sck_nx;  sdo <= sdo_nx;
            if (run & spi_mode) begin
                cupd0 <= cupd0 + {9'd0, cu_tick[0]};
                cupd1 <= cupd1 + {9'd0, cu_tick[1]};
                cupd2 <= cupd2 + {9'd0, cu_tick[2]};
            end
            cupd_top <= cupd_top_nx;
            ramp_tick <= ramp_tick_nx;
            cont_update <= cont_update_nx;
            wrap <= |(ramp_tick_nx & {3{cont_update_nx}} & cupd_top);
        end
    end

    // snapshot, cover latch, bit pipeline: no reset needed (written before use). The snapshot
    // and the cover latch load in every edge that may start a datagram (can_start), so the
    // last load before a datagram is its start edge; they are read only while one runs.
    always @(posedge clk) begin
        if (can_start) begin
            snap_w    <= ustep;
            snap_is   <= i_scale;
            snap_dir  <= dir;
            snap_step <= stepped | step;
            snap_pol  <= {pol_dac_ab, pol_fd_ab, pol_ph_ab};
            cov_pos   <= cover_pos;
            cov_end   <= {1'b0, cover_pos} + (len_over ? 7'd24 : {2'd0, cover_len});
            cov_data  <= cover_datagram;
        end else if (shift) begin
            // the NxM gap: the next motor's snapshot moves to slot 0
            snap_w    <= {snap_w[23:16], snap_w[23:8]};
            snap_is   <= {snap_is[8:6], snap_is[8:3]};
            snap_dir  <= {snap_dir[2], snap_dir[2:1]};
            snap_step <= {snap_step[2], snap_step[2:1]};
        end
        if (run & spi_mode & rd_lut) begin
            cfg     <= ram_q;
            cov_hit <= (bits >= {1'b0, cov_pos}) & (bits < cov_end);
            cov_i   <= cov_end[4:0] + ~bits[4:0];
        end
        if (run & spi_mode & pre_dac) begin
            dac     <= dac_nx;
            cov_sel <= cover_busy & cov_hit;
            cov_bit <= cov_data[cov_i];
        end
    end
endmodule

`default_nettype wire
