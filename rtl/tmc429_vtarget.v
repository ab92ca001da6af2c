// tmc429_vtarget: the target velocity of the three motors (docs/model-contract.md C41, C50;
// TMC428 §8.7-§8.10), one time-multiplexed datapath for all motors.
//
// Schedule inside the 32-cycle frame (phase p = prescaler[4:0], C41):
//   p = 7m        snapshot of motor m: dx = x_target - x_actual, rm, pmul, pdiv, v_min,
//                 v_max, a_max, v_target and ramp_div >= pulse_div are taken from the old
//                 state into the A registers (v_min, v_max, a_max, pmul and pdiv: the
//                 synchronous read of the parameter RAMs, whose output register is their
//                 snapshot)
//   p = 7m+1      c = min(|dx|, 2^19-1) - 1 (RAMP_MODE) or min(|dx|, 2^19-1) (SOFT_MODE),
//                 registered shifted by u; h = ⌈a_max/128⌉ when ramp_div >= pulse_div (C50)
//   p = 7m+2..+5  acc = (c << u) * p_mul (8-bit multiplier word, Horner, 2 bits per cycle)
//   p = 7m+6..+12 B (tmc429_vroot): q = 4·v + h in every mode: RAMP_MODE the square root of
//                 the radicand of C50, two bits per cycle; SOFT_MODE (c * p_mul) >> (3+pdiv),
//                 shifted out four bits per cycle; VELOCITY_MODE 4·|v_target| loaded. The
//                 clamp's bounds are formed and registered at the load (7m+6)
//   p = 7m+13     C: RAMP_MODE: v = (q - h) >> 2 with q the root and h = ⌈a_max/128⌉ when
//                 ramp_div >= pulse_div (the velocity held between ramp ticks, C50), the
//                 comparisons for the clamp to [v_min, v_max] (VELOCITY_MODE: |v_target| to
//                 v_max), sign: registered
//   p = 7m+14     commit: vt[m] := the result (used from phase 7m+15 on)
// Stages A, B and C work on three motors at once (A on m+1 while B runs m): each stage reads
// the other's registers from the old state.
//
// v_max and p_mul/pdiv are read by nothing but the snapshot, so they have no flip-flops, and
// v_min and a_max have a copy for the snapshot: the µC writes them into four parameter RAMs
// (tmc429_wram, one word per motor) and the snapshot edge reads the word of motor m. A write in
// a snapshot edge is written one edge later, so the snapshot gives the old value, as the
// register did (C3); a word not written since reset reads 0 (C2). Register indices and fields:
// rtl/tmc429_regmap.vh.
`timescale 1ns / 1ps
`default_nettype none
`include "tmc429_regmap.vh"
`include "tmc429_schedule.vh"

module tmc429_vtarget #(
    parameter NMOT = 3,           // motors present (TMC4210: 1)
    parameter ROOT_SPEC = 0       // the square root's form (tmc429_vroot)
) (
    input  wire        clk,
    input  wire        rst,
    input  wire        run,       // 0 while powered down (C66)
    input  wire [4:0]  phase,     // prescaler[4:0]
    // per-motor registers, motor m in bits [w*(m+1)-1 : w*m]
    input  wire [5:0]  rm,
    input  wire [71:0] x_target,
    input  wire [71:0] x_actual,
    input  wire [35:0] v_target,
    // per motor ramp_div >= pulse_div: the braking law's correction h applies (C50)
    input  wire [2:0]  brake_en,
    // µC write to motor cfg_m's register cfg_idx (v_min, v_max, a_max, pmul_pdiv: C22) with data word
    // bits 14..0; cfg_m, cfg_idx and cfg_data still hold in the edge after cfg_we
    input  wire        cfg_we,
    input  wire [1:0]  cfg_m,
    input  wire [3:0]  cfg_idx,
    input  wire [14:0] cfg_data,
    // committed target velocities (12-bit two's complement), motor m in [12m+11:12m]
    output wire [35:0] vt
);
    // ---- schedule ----------------------------------------------------------------------
    // decoded from the phase after each edge (p + run) into registers, so that every stage
    // starts at a flip-flop
    reg        a_snap, a_c, a_mul, b_load, b_run, c_pre;
    reg [1:0]  a_m;
    reg [2:0]  c_out;             // commit of motor m's result (one-hot)
    reg [2:0]  b_k;               // B cycle index 0..6
    reg        n_a_snap, n_a_c, n_a_mul, n_b_load, n_b_run, n_c_pre;
    reg [2:0]  n_c_out;
    reg [1:0]  n_a_m;
    reg [2:0]  n_b_k;
    // motor m's stages from its snapshot phase Sm = TMC429_PH_SNAPSHOT(m): A at Sm (snapshot),
    // Sm + 1 (c), Sm + 2 .. Sm + 5 (multiply); B at Sm + 6 .. Sm + 12 (k = 0 .. 6, the load at
    // k = 0); C at Sm + 13 (c_pre) and the commit edge Sm + 14 = TMC429_PH_COMMIT(m)
    // (rtl/tmc429_schedule.vh; the model's lanes are tested to have this shape)
    localparam [4:0] S0 = `TMC429_PH_SNAPSHOT(0);
    localparam [4:0] S1 = `TMC429_PH_SNAPSHOT(1);
    localparam [4:0] S2 = `TMC429_PH_SNAPSHOT(2);
    // the phases of each stage, one bit per phase: a pattern from the lane's start, for the
    // three lanes
    function [31:0] lanes;
        input [31:0] pat;
        input [4:0]  off;
        begin
            lanes = (pat << (S0 + off)) | (pat << (S1 + off)) | (pat << (S2 + off));
        end
    endfunction
    localparam [31:0] PH_SNAP = lanes(32'h1, 5'd0);
    localparam [31:0] PH_M1   = 32'd1 << S1;                 // the snapshot's motor, 1 ...
    localparam [31:0] PH_M2   = 32'd1 << S2;                 // ... and 2
    localparam [31:0] PH_C    = lanes(32'h1, 5'd1);
    localparam [31:0] PH_MUL  = lanes(32'hF, 5'd2);
    localparam [31:0] PH_LOAD = lanes(32'h1, 5'd6);
    localparam [31:0] PH_B    = lanes(32'h7F, 5'd6);
    localparam [31:0] PH_BK0  = lanes(32'b0101010, 5'd6);   // B's cycle index k, bit 0 ...
    localparam [31:0] PH_BK1  = lanes(32'b1001100, 5'd6);   // ... bit 1 (k = 2, 3, 6) ...
    localparam [31:0] PH_BK2  = lanes(32'b1110000, 5'd6);   // ... bit 2 (k = 4, 5, 6)
    localparam [31:0] PH_CPRE = lanes(32'h1, 5'd13);
    localparam [31:0] PH_CO0  = 32'd1 << `TMC429_PH_COMMIT(0);
    localparam [31:0] PH_CO1  = 32'd1 << `TMC429_PH_COMMIT(1);
    localparam [31:0] PH_CO2  = 32'd1 << `TMC429_PH_COMMIT(2);
    // the phase after this edge (p + 1 while running, else p) is one of the set m: m's bit p,
    // or the bit p of m rotated by one phase, so that no sum p + run is in front of the decode
    function nx_in;
        input [31:0] m;
        input [4:0]  p;
        input        r;
        reg   [31:0] m_r;
        begin
            m_r   = {m[0], m[31:1]};
            nx_in = r ? m_r[p] : m[p];
        end
    endfunction
    always @(*) begin
        n_a_snap = nx_in(PH_SNAP, phase, run);
        n_a_m    = {nx_in(PH_M2, phase, run), nx_in(PH_M1, phase, run)};
        n_a_c    = nx_in(PH_C, phase, run);
        n_a_mul  = nx_in(PH_MUL, phase, run);
        n_b_load = nx_in(PH_LOAD, phase, run);
        n_b_run  = nx_in(PH_B, phase, run);
        n_b_k    = {nx_in(PH_BK2, phase, run), nx_in(PH_BK1, phase, run), nx_in(PH_BK0, phase, run)};
        n_c_pre  = nx_in(PH_CPRE, phase, run);
        n_c_out  = {nx_in(PH_CO2, phase, run), nx_in(PH_CO1, phase, run), nx_in(PH_CO0, phase, run)};
    end
    always @(posedge clk) begin
        if (rst) begin
            // phase 0 after reset
            a_snap <= 1'b1; a_c <= 1'b0; a_mul <= 1'b0; b_load <= 1'b0; b_run <= 1'b0;
            c_pre <= 1'b0; c_out <= 3'd0; a_m <= 2'd0; b_k <= 3'd0;
        end else begin
            a_snap <= n_a_snap; a_c <= n_a_c; a_mul <= n_a_mul; b_load <= n_b_load;
            b_run <= n_b_run; c_pre <= n_c_pre; c_out <= n_c_out; a_m <= n_a_m; b_k <= n_b_k;
        end
    end

    // ---- A: snapshot, c, multiply ------------------------------------------------------
    // The snapshot's select of motor a_m, and every stage's arithmetic below, are formed in the
    // clocked blocks, only in the edges that take them (docs/rtl.md, "Logic in its slot"): a
    // simulator evaluates them in no other edge.
    function [62:0] snap_of;      // {x_target, x_actual, rm, v_target, brake_en} of motor m
        input [1:0]  m;
        input [71:0] xt, xa;
        input [5:0]  r;
        input [35:0] vtg;
        input [2:0]  be;
        begin
            case (m)
            2'd1:    snap_of = {xt[47:24], xa[47:24], r[3:2], vtg[23:12], be[1]};
            2'd2:    snap_of = {xt[71:48], xa[71:48], r[5:4], vtg[35:24], be[2]};
            default: snap_of = {xt[23:0], xa[23:0], r[1:0], vtg[11:0], be[0]};
            endcase
        end
    endfunction

    // parameter RAMs: the read at the snapshot edge is the snapshot of v_min, v_max, pmul, pdiv.
    // A write in a snapshot edge is deferred by one edge (the snapshot takes the old value,
    // C3; the next snapshot is 7 edges later): `cfg_*` still hold the datagram in the next
    // edge (the SPI input register stays until the next frame), so only the write enable is
    // delayed and no read ever meets a write.
    wire        snap_re = run & a_snap;
    reg         cfg_late;
    always @(posedge clk) begin
        if (rst)
            cfg_late <= 1'b0;
        else
            cfg_late <= cfg_we & snap_re;
    end
    wire        cfg_wr = (cfg_we & ~snap_re) | cfg_late;
    wire [10:0] q_vmax, q_pd;
    wire        wq_vmax, wq_pd;
    tmc429_wram #(.AW(2), .DW(11), .WMASK(4'b0111)) u_vmax (
        .clk(clk), .rst(rst),
        .we(cfg_wr & (cfg_idx == `TMC429_IDX_V_MAX)), .waddr(cfg_m), .wdata(cfg_data[`TMC429_F_V_MAX]),
        .re(snap_re), .raddr(a_m), .q(q_vmax), .wq(wq_vmax));
    tmc429_wram #(.AW(2), .DW(11), .WMASK(4'b0111)) u_pd (
        .clk(clk), .rst(rst),
        .we(cfg_wr & (cfg_idx == `TMC429_IDX_PMUL_PDIV)), .waddr(cfg_m),   // pmul bit 15 reads 1 (C22)
        .wdata({cfg_data[`TMC429_F_PMUL_MSB-1:`TMC429_F_PMUL_LSB], cfg_data[`TMC429_F_PDIV]}),
        .re(snap_re), .raddr(a_m), .q(q_pd), .wq(wq_pd));
    wire [10:0] q_vmin;
    wire        wq_vmin;
    tmc429_wram #(.AW(2), .DW(11), .WMASK(4'b0111)) u_vmin (
        .clk(clk), .rst(rst),
        .we(cfg_wr & (cfg_idx == `TMC429_IDX_V_MIN)), .waddr(cfg_m), .wdata(cfg_data[`TMC429_F_V_MIN]),
        .re(snap_re), .raddr(a_m), .q(q_vmin), .wq(wq_vmin));
    wire [10:0] q_amax;
    wire        wq_amax;
    tmc429_wram #(.AW(2), .DW(11), .WMASK(4'b0111)) u_amax (
        .clk(clk), .rst(rst),
        .we(cfg_wr & (cfg_idx == `TMC429_IDX_A_MAX)), .waddr(cfg_m), .wdata(cfg_data[`TMC429_F_A_MAX]),
        .re(snap_re), .raddr(a_m), .q(q_amax), .wq(wq_amax));
    wire [10:0] a_vmin = wq_vmin ? q_vmin : 11'd0;
    wire [10:0] a_amax = wq_amax ? q_amax : 11'd0;
    wire [10:0] a_vmax = wq_vmax ? q_vmax : 11'd0;
    wire [6:0]  a_pmul = wq_pd ? q_pd[10:4] : 7'd0;
    wire [3:0]  a_pdiv = wq_pd ? q_pd[3:0] : 4'd0;

    reg [23:0] a_dx;
    reg [1:0]  a_rm;
    reg        a_soft;            // a_rm == SOFT_MODE
    reg [11:0] a_vtg;
    reg        a_be;              // ramp_div >= pulse_div
    reg [4:0]  a_h;
    reg        a_sgn, a_zero;
    reg [20:0] a_cv;              // c << u
    reg [7:0]  a_w;               // multiplier word p_mul, consumed from the top
    reg [28:0] acc;

    always @(posedge clk) begin
        if (rst) begin
            a_dx <= 24'd0; a_rm <= 2'd0; a_soft <= 1'b0;
            a_vtg <= 12'd0; a_be <= 1'b0; a_h <= 5'd0;
            a_sgn <= 1'b0; a_zero <= 1'b1; a_cv <= 21'd0; a_w <= 8'd0; acc <= 29'd0;
        end else if (run) begin
            if (a_snap) begin : snap
                reg [62:0] sn;
                sn      = snap_of(a_m, x_target, x_actual, rm, v_target, brake_en);
                a_dx   <= sn[62:39] - sn[38:15];     // C43: 24-bit wrap-around
                a_rm   <= sn[14:13];
                a_soft <= sn[14:13] == 2'd1;
                a_vtg  <= sn[12:1];
                a_be   <= sn[0];
            end
            if (a_c) begin : cval
                reg        dx_neg, c_big;
                /* verilator lint_off UNUSEDSIGNAL */   // bits 23:19 are replaced by c_big
                reg [23:0] c0;
                /* verilator lint_on UNUSEDSIGNAL */
                reg [18:0] c_val;
                reg [1:0]  u;
                dx_neg = a_dx[23];
                // |dx| - 1 (RAMP) or |dx| (SOFT): dx ^ sign plus 0, +1 or -1
                c0     = (a_dx ^ {24{dx_neg}}) + (a_soft ? {23'd0, dx_neg} : {24{~dx_neg}});
                // |dx| >= 2^19, from dx itself beside the sum (dx = 0 in RAMP_MODE, where
                // |dx| - 1 wraps, gives no target velocity whatever c is)
                c_big  = dx_neg ? ((a_dx[22:19] != 4'hF) | (a_dx[18:0] == 19'd0))
                                : (a_dx[22:19] != 4'h0);
                c_val  = c_big ? {18'h3FFFF, a_soft} : c0[18:0];   // C43: |dx| <= 2^19-1
                // u: RAMP 1-e; SOFT 2, 1, 0, 0 for pdiv[1:0] = 0..3
                u      = a_soft ? (a_pdiv[1] ? 2'd0 : (a_pdiv[0] ? 2'd1 : 2'd2))
                                : {1'b0, ~a_pdiv[0]};
                // the braking law's correction for the velocity held between ramp ticks (C50)
                a_h    <= a_be ? ({1'b0, a_amax[10:7]} + {4'd0, a_amax[6:0] != 7'd0}) : 5'd0;
                a_sgn  <= dx_neg;
                a_zero <= a_dx == 24'd0;
                a_cv   <= {2'b00, c_val} << u;
                a_w    <= {1'b1, a_pmul};
                acc    <= 29'd0;
            end
            if (a_mul) begin : mul
                reg [28:0] h1;
                h1   = {acc[26:0], 2'b00} + (a_w[7] ? {7'd0, a_cv, 1'b0} : 29'd0);
                acc <= h1 + (a_w[6] ? {8'd0, a_cv} : 29'd0);
                a_w <= {a_w[5:0], 2'b00};
            end
        end
    end

    // ---- B: square root / shift (tmc429_vroot), the clamp's bounds ------------------------
    wire [13:0] q;                // 4·v + h of the motor in B (tmc429_vroot)
    wire        st_l;             // RAMP_MODE's radicand saturates the root (at the load)
    tmc429_vroot #(.ROOT_SPEC(ROOT_SPEC)) u_root (
        .clk(clk), .rst(rst), .run(run),
        .b_load(b_load), .b_run(b_run), .b_k(b_k), .n_b_load(n_b_load), .n_b_k(n_b_k),
        .a_c(a_c), .a_rm(a_rm), .a_soft(a_soft), .a_pdiv(a_pdiv), .a_vtg(a_vtg), .acc(acc),
        .ovf(st_l), .q(q));

    reg [11:0] b_vmin;            // the signed result lo (sign applied at the load)
    reg [13:0] b_lo4, b_hi4;      // 4·lo + h and 4·(v_max + 1) + h (C: the clamp on 4·v + h)
    reg [14:0] b_hk;              // -h, or h + 4 when negative: the signed (q - h) >> 2 is q ^ neg + hk
    reg        b_neg;             // sign of the result
    // the clamp's selections without the comparisons, formed at the load: b_use, q may be used
    // (a target velocity, and no saturated root); b_sel, the bound lo is taken when q is below
    // it (also lo <= v_max); b_vmaxz, the bound taken otherwise (0 with no target velocity)
    reg        b_use, b_sel;
    reg [11:0] b_vmaxz;

    always @(posedge clk) begin
        if (rst) begin
            b_vmin <= 12'd0; b_vmaxz <= 12'd0; b_use <= 1'b0; b_sel <= 1'b0;
            b_lo4 <= 14'd0; b_hi4 <= 14'd4; b_hk <= 15'd0; b_neg <= 1'b0;
        end else if (run & b_load) begin : bounds
            reg        l_vel, l_neg, l_none, l_qsat;
            reg [10:0] l_lo;
            reg [4:0]  l_h;
            reg [11:0] l_vmax;
            // clamp bounds at the load: lo = v_min (0 in VELOCITY_MODE), h only in RAMP_MODE
            l_vel  = a_rm == 2'd2;
            l_lo   = l_vel ? 11'd0 : a_vmin;
            l_h    = (a_rm == 2'd0) ? a_h : 5'd0;
            l_neg  = l_vel ? a_vtg[11] : a_sgn;
            // RAMP_MODE's root saturates from the load on (the running steps keep sticky), so
            // that the clamp's selections are known there
            l_none = (a_rm == 2'd3) | (~a_rm[1] & a_zero);
            l_qsat = (a_rm == 2'd0) & st_l;
            l_vmax = l_neg ? 12'd0 - {1'b0, a_vmax} : {1'b0, a_vmax};
            b_vmin <= l_neg ? 12'd0 - {1'b0, l_lo} : {1'b0, l_lo};
            b_vmaxz <= l_none ? 12'd0 : l_vmax;
            b_use <= ~l_none & ~l_qsat;
            b_sel <= ~l_none & ~l_qsat & (l_lo <= a_vmax);
            b_lo4 <= {1'b0, l_lo, 2'b00} + {9'd0, l_h};
            b_hi4 <= {1'b0, a_vmax, 2'b00} + {9'd0, l_h} + 14'd4;
            b_hk <= l_neg ? {10'd0, l_h} + 15'd4 : 15'd0 - {10'd0, l_h};
            b_neg <= l_neg;
        end
    end

    // ---- C: clamp, sign -------------------------------------------------------------------
    // The clamp min(max(v, lo), v_max) on q = 4·v + h (RAMP_MODE: q = isqrt(16·X), v =
    // (q - h) >> 2, 0 below h; SOFT and VELOCITY: q = 4·mag, h = 0): both comparisons of q
    // against the bounds formed at the load, the subtraction beside them (C50). The sign is
    // known at the load: the bounds are negated there, and (q - h) >> 2 is formed signed,
    // -((q - h) >> 2) = (h + 3 - q) >> 2 = (~q + h + 4) >> 2, so that no negation follows
    // q is a register in every mode (tmc429_vroot: SOFT_MODE and VELOCITY_MODE leave 4·mag
    // there), so that each comparison is one carry chain from flip-flops followed by the
    // selection alone
    // in the edge before the commit (c_pre) the comparisons are registered: the result is
    // (q - h) >> 2 when q lies between the bounds, else the bound (lo when below and
    // lo <= v_max, else v_max; two's complement), 0 with no target velocity
    reg  [11:0] c_q, c_bnd;
    reg         c_use;
    always @(posedge clk) begin
        if (rst) begin
            c_q <= 12'd0;  c_bnd <= 12'd0;  c_use <= 1'b0;
        end else if (run & c_pre) begin : clamp
            reg        below, above;
            /* verilator lint_off UNUSEDSIGNAL */   // the two fraction bits and the sign's copy
            reg [14:0] q_h;
            /* verilator lint_on UNUSEDSIGNAL */
            below  = q < b_lo4;
            above  = q >= b_hi4;
            q_h    = ({1'b0, q} ^ {15{b_neg}}) + b_hk;
            c_q   <= q_h[13:2];
            c_bnd <= (b_sel & below) ? b_vmin : b_vmaxz;
            c_use <= b_use & ~below & ~above;
        end
    end
    // the commit, formed in the clocked block only in a commit edge (docs/rtl.md, "Logic in
    // its slot")
    reg [35:0] vt_r;
    localparam [35:0] PRESENT = (NMOT == 1) ? 36'h000000FFF : 36'hFFFFFFFFF;
    integer     k;
    always @(posedge clk) begin
        if (rst) begin
            vt_r <= 36'd0;
        end else if (run & (|c_out)) begin : commit
            reg [35:0] res_c;
            res_c = {3{c_use ? c_q : c_bnd}} & PRESENT;
            for (k = 0; k < 3; k = k + 1)
                if (c_out[k])
                    vt_r[12*k +: 12] <= res_c[12*k +: 12];
        end
    end

    assign vt = vt_r;
endmodule

`default_nettype wire
