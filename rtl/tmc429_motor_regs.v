// tmc429_motor_regs: the registers of one motor (IDX 0..15, docs/model-contract.md C21-C29,
// C63; TMC428 §8, TMC429 §8.1) with its ramp and pulse generator (tmc429_ramp) and the
// interrupt logic.
//
// The motion state (x_actual, V, v_target, a_actual, ustep_count, x_latched, lp) lives in
// tmc429_ramp, which also takes the µC writes to it; this block holds the configuration
// registers the motion core uses every cycle, the read mux of the state and the interrupt
// conditions, events and flags. The read value of a register that only the µC writes comes
// from the register file's shadow RAM (tmc429_regfile); v_max, p_mul and pdiv, which only
// the target velocity unit reads, live in its parameter RAM alone (tmc429_vtarget).
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
    /* verilator lint_off UNUSEDSIGNAL */  // the IDX whose read value is in the shadow RAM
    input  wire [15:0] rsel,      // read address IDX, one-hot (registered in tmc429_regfile)
    /* verilator lint_on UNUSEDSIGNAL */
    output wire [23:0] rdata,
    input  wire        sw_l,      // mapped left switch (C60)
    input  wire        sw_r,      // mapped right switch
    input  wire        ramp_tick, // phase 30 of a ramp frame (C40, C41)
    input  wire        pulse_tick,// phase 31 of a pulse frame
    input  wire [11:0] vt,        // committed target velocity (C41)
    output wire        xeqt,      // x_actual == x_target
    output wire        irq,       // interrupt flags != 0
    // registers for the target velocity unit and the frame schedule
    output reg  [23:0] x_target,
    output reg  [1:0]  rm,
    output reg  [3:0]  pulse_div,
    output reg  [3:0]  ramp_div,
    // motion state (probes)
    output wire [23:0] x_actual,
    output wire [19:0] v,
    output wire [11:0] v_target,
    output wire [11:0] a_actual,
    output wire [7:0]  ustep,
    output wire [10:0] pulse_acc,
    output wire        step,
    output wire        dir,
    // driver side (C75): {is_agtat, is_aleat, is_v0, a_threshold}
    output wire [19:0] drv_conf
);
    reg [10:0] v_min, a_max, a_threshold;
    reg [2:0]  is_agtat, is_aleat, is_v0, usrs;
    reg [3:0]  ref_conf;
    reg [7:0]  int_mask, int_flags, int_hist;
    reg [11:0] dx_ref_tolerance;
    reg [12:0] tol_k;          // 4096 - dx_ref_tolerance, for the tolerance window's speed
    wire       lp, stop, tol_ok;
    wire [23:0] x_latched;
    /* verilator lint_off UNUSEDSIGNAL */
    wire [11:0] v_actual;     // formed once for all motors in the read path (tmc429_regfile)
    /* verilator lint_on UNUSEDSIGNAL */

    localparam HAS_IDX8  = (CHIP != 2);   // TMC4210: no current scaling register
    localparam HAS_IDX15 = (CHIP != 0);   // TMC428: IDX 15 unused

    // ---- ramp and pulse generator, switch stop, latch ------------------------------------
    tmc429_ramp #(.HAS_USTEP(HAS_IDX15)) u_ramp (
        .clk(clk), .rst(rst), .run(run), .ramp_tick(ramp_tick), .pulse_tick(pulse_tick),
        .rm(rm), .x_target(x_target), .v_min(v_min), .a_max(a_max), .ref_conf(ref_conf),
        .usrs(usrs), .dx_ref_tolerance(dx_ref_tolerance), .tol_k(tol_k), .vt(vt), .sw_l(sw_l), .sw_r(sw_r),
        .we(we), .widx(widx), .wdata(wdata),
        .x_actual(x_actual), .v(v), .v_target(v_target), .a_actual(a_actual), .ustep(ustep),
        .acc(pulse_acc), .step(step), .dir(dir), .x_latched(x_latched), .lp(lp),
        .xeqt(xeqt), .stop(stop), .tol_ok(tol_ok), .v_actual(v_actual));

    // ---- interrupt conditions (C63), from the old state -------------------------------
    wire        sel_sw   = ref_conf[3] ? sw_r : sw_l;          // REF_RnL selects the switch
    wire        x_ge_tol = ~tol_ok;                             // |x_actual| >= tolerance
    wire [7:0]  cond = {
        sw_r,                       // 7 STOP_RIGHT_HIGH
        sw_l,                       // 6 STOP_LEFT_HIGH
        ~sw_r,                      // 5 STOP_RIGHT_LOW
        ~sw_l,                      // 4 STOP_LEFT_LOW
        stop,                       // 3 STOP
        (x_actual == 24'd0) & ~sel_sw,  // 2 REF_MISS
        sel_sw & x_ge_tol,          // 1 REF_WRONG
        xeqt                        // 0 POS_END
    };
    wire [7:0] events = run ? (cond & ~int_hist) : 8'd0;

    wire       w_int   = we & (widx == 4'd11);
    wire [7:0] mask_nx = w_int ? wdata[15:8] : int_mask;
    wire [7:0] w1c     = w_int ? wdata[7:0] : 8'd0;

    assign drv_conf = {is_agtat, is_aleat, is_v0, a_threshold};
    assign irq  = int_flags != 8'd0;

    always @(posedge clk) begin
        if (rst) begin
            x_target <= 24'd0;
            v_min <= 11'd0;
            a_max <= 11'd0;
            is_agtat <= 3'd0;   is_aleat <= 3'd0;  is_v0 <= 3'd0;  a_threshold <= 11'd0;
            ref_conf <= 4'd0;   rm <= 2'd0;
            int_mask <= 8'd0;   int_flags <= 8'd0;
            int_hist <= 8'b0011_0101;   // the conditions of the reset state: no event at power-on
            pulse_div <= 4'd0;  ramp_div <= 4'd0;  usrs <= 3'd0;
            dx_ref_tolerance <= 12'd0;
            tol_k <= 13'd4096;
        end else begin
            if (run)
                int_hist <= cond;
            int_mask  <= mask_nx;
            int_flags <= ((int_flags & ~w1c) | events) & mask_nx;   // C3, C26
            if (we) begin
                case (widx)
                4'd0:  x_target <= wdata;
                4'd2:  v_min <= wdata[10:0];
                4'd6:  a_max <= wdata[10:0];
                4'd8:  if (HAS_IDX8) begin
                           is_agtat <= wdata[22:20];
                           is_aleat <= wdata[18:16];
                           is_v0 <= wdata[14:12];
                           a_threshold <= wdata[10:0];
                       end
                4'd10: begin ref_conf <= wdata[11:8]; rm <= wdata[1:0]; end
                4'd12: begin
                           pulse_div <= wdata[15:12];
                           ramp_div <= wdata[11:8];
                           usrs <= wdata[2:0];
                       end
                4'd13: begin
                           dx_ref_tolerance <= wdata[11:0];
                           tol_k <= 13'd4096 - {1'b0, wdata[11:0]};
                       end
                // IDX 1, 4, 5, 14, 15: motion state in tmc429_ramp; IDX 3, 9: parameter
                // RAM of tmc429_vtarget; IDX 7 (a_actual) and 11 (above): no storage here
                default: ;
                endcase
            end
        end
    end

    // read value of the state (C21-C27); the bits a µC write sets come from the shadow RAM
    // of the register file and are 0 here (IDX 10: lp only; IDX 11: int_flags only). The IDX
    // is one-hot, so the multiplexer is an AND-OR.
    // v_actual (IDX 5, C42) is formed in the register file from V of the selected motor
    assign rdata = ({24{rsel[1]}} & x_actual)
                 | ({24{rsel[4]}} & {12'd0, v_target})
                 | ({24{rsel[7]}} & {12'd0, a_actual})
                 | ({24{rsel[10]}} & {7'd0, lp, 16'd0})
                 | ({24{rsel[11]}} & {16'd0, int_flags})
                 | ({24{rsel[14]}} & x_latched)
                 | ({24{rsel[15] & (HAS_IDX15 != 0)}} & {16'd0, ustep});
endmodule

`default_nettype wire
