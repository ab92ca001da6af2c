// tmc429_motor_regs: the registers of one motor (IDX 0..15, docs/model-contract.md C21-C29,
// C63; TMC428 §8, TMC429 §8.1) with the interrupt logic that has no motion behind it.
//
// Motion (ramp generator, pulse generator, switch stop, latch) is not part of this block:
// x_actual, v_actual, v_target and ustep_count change here only by µC writes, a_actual and
// x_latched read 0, the STOP condition is 0.
`default_nettype none

module tmc429_motor_regs #(
    parameter CHIP = 1
) (
    input  wire        clk,
    input  wire        rst,
    input  wire        run,       // 0 while powered down (C66)
    input  wire        we,        // µC write to this motor (executed now)
    input  wire [3:0]  widx,
    input  wire [23:0] wdata,
    input  wire [3:0]  ridx,
    output reg  [23:0] rdata,
    input  wire        sw_l,      // mapped left switch (C60)
    input  wire        sw_r,      // mapped right switch
    output wire        xeqt,      // x_actual == x_target
    output wire        irq,       // interrupt flags != 0
    output reg  [23:0] x_target,
    output reg  [23:0] x_actual,
    output reg  [11:0] v_actual,  // v_actual register: V = v_actual * 256 (C23)
    output reg  [11:0] v_target,
    output reg  [7:0]  ustep,
    // driver side (C75, C40): {ramp_div, is_agtat, is_aleat, is_v0, a_threshold}
    output wire [23:0] drv_conf
);
    reg [10:0] v_min, v_max, a_max, a_threshold;
    reg [2:0]  is_agtat, is_aleat, is_v0, usrs;
    reg [6:0]  pmul;
    reg [3:0]  pdiv, ref_conf, pulse_div, ramp_div;
    reg [1:0]  rm;
    reg [7:0]  int_mask, int_flags, int_hist;
    reg [11:0] dx_ref_tolerance;
    reg        lp;

    localparam HAS_IDX8  = (CHIP != 2);   // TMC4210: no current scaling register
    localparam HAS_IDX15 = (CHIP != 0);   // TMC428: IDX 15 unused

    // ---- interrupt conditions (C63), from the old state -------------------------------
    wire        sel_sw   = ref_conf[3] ? sw_r : sw_l;          // REF_RnL selects the switch
    wire [23:0] x_abs    = x_actual[23] ? (~x_actual + 24'd1) : x_actual;
    wire        x_is_min = x_actual == 24'h800000;              // |x| = 2^23
    wire        x_ge_tol = x_is_min | (x_abs >= {12'd0, dx_ref_tolerance});
    wire [7:0]  cond = {
        sw_r,                       // 7 STOP_RIGHT_HIGH
        sw_l,                       // 6 STOP_LEFT_HIGH
        ~sw_r,                      // 5 STOP_RIGHT_LOW
        ~sw_l,                      // 4 STOP_LEFT_LOW
        1'b0,                       // 3 STOP (switch stop: motion core)
        (x_actual == 24'd0) & ~sel_sw,  // 2 REF_MISS
        sel_sw & x_ge_tol,          // 1 REF_WRONG
        x_actual == x_target        // 0 POS_END
    };
    wire [7:0] events = run ? (cond & ~int_hist) : 8'd0;

    wire       w_int   = we & (widx == 4'd11);
    wire [7:0] mask_nx = w_int ? wdata[15:8] : int_mask;
    wire [7:0] w1c     = w_int ? wdata[7:0] : 8'd0;

    assign xeqt = x_actual == x_target;
    assign drv_conf = {ramp_div, is_agtat, is_aleat, is_v0, a_threshold};
    assign irq  = int_flags != 8'd0;

    always @(posedge clk) begin
        if (rst) begin
            x_target <= 24'd0;  x_actual <= 24'd0;
            v_min <= 11'd0;     v_max <= 11'd0;
            v_target <= 12'd0;  v_actual <= 12'd0;
            a_max <= 11'd0;
            is_agtat <= 3'd0;   is_aleat <= 3'd0;  is_v0 <= 3'd0;  a_threshold <= 11'd0;
            pmul <= 7'd0;       pdiv <= 4'd0;
            ref_conf <= 4'd0;   rm <= 2'd0;        lp <= 1'b0;
            int_mask <= 8'd0;   int_flags <= 8'd0;
            int_hist <= 8'b0011_0101;   // the conditions of the reset state: no event at power-on
            pulse_div <= 4'd0;  ramp_div <= 4'd0;  usrs <= 3'd0;
            dx_ref_tolerance <= 12'd0;
            ustep <= 8'd0;
        end else begin
            if (run)
                int_hist <= cond;
            int_mask  <= mask_nx;
            int_flags <= ((int_flags & ~w1c) | events) & mask_nx;   // C3, C26
            if (we) begin
                case (widx)
                4'd0:  x_target <= wdata;
                4'd1:  x_actual <= wdata;
                4'd2:  v_min <= wdata[10:0];
                4'd3:  v_max <= wdata[10:0];
                4'd4:  v_target <= wdata[11:0];
                // C23: -2048 is stored as -2047 (the magnitude has 11 bits)
                4'd5:  v_actual <= (wdata[11:0] == 12'h800) ? 12'h801 : wdata[11:0];
                4'd6:  a_max <= wdata[10:0];
                4'd8:  if (HAS_IDX8) begin
                           is_agtat <= wdata[22:20];
                           is_aleat <= wdata[18:16];
                           is_v0 <= wdata[14:12];
                           a_threshold <= wdata[10:0];
                       end
                4'd9:  begin pmul <= wdata[14:8]; pdiv <= wdata[3:0]; end
                4'd10: begin ref_conf <= wdata[11:8]; rm <= wdata[1:0]; end
                4'd12: begin
                           pulse_div <= wdata[15:12];
                           ramp_div <= wdata[11:8];
                           usrs <= wdata[2:0];
                       end
                4'd13: dx_ref_tolerance <= wdata[11:0];
                4'd14: lp <= 1'b1;          // C27: a write arms the latch, data discarded
                4'd15: if (HAS_IDX15) ustep <= wdata[7:0];
                default: ;                  // IDX 7 (a_actual) and 11 (above): no storage
                endcase
            end
        end
    end

    always @(*) begin
        case (ridx)
        4'd0:  rdata = x_target;
        4'd1:  rdata = x_actual;
        4'd2:  rdata = {13'd0, v_min};
        4'd3:  rdata = {13'd0, v_max};
        4'd4:  rdata = {12'd0, v_target};
        4'd5:  rdata = {12'd0, v_actual};
        4'd6:  rdata = {13'd0, a_max};
        4'd7:  rdata = 24'd0;           // a_actual: no ramp tick without the motion core
        4'd8:  rdata = HAS_IDX8 ? {1'b0, is_agtat, 1'b0, is_aleat, 1'b0, is_v0, 1'b0, a_threshold}
                                : 24'd0;
        4'd9:  rdata = {8'd0, 1'b1, pmul, 4'd0, pdiv};     // C22: bit 15 reads 1
        4'd10: rdata = {7'd0, lp, 4'd0, ref_conf, 6'd0, rm};
        4'd11: rdata = {8'd0, int_mask, int_flags};
        4'd12: rdata = {8'd0, pulse_div, ramp_div, 5'd0, usrs};
        4'd13: rdata = {12'd0, dx_ref_tolerance};
        4'd14: rdata = 24'd0;           // x_latched: latched only while moving
        default: rdata = HAS_IDX15 ? {16'd0, ustep} : 24'd0;
        endcase
    end
endmodule

`default_nettype wire
