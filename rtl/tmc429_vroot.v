// tmc429_vroot: the square root or shift of the target-velocity unit (tmc429_vtarget's stage
// B; docs/model-contract.md C41, C50; TMC428 §8.7-§8.10): from the product acc = (c << u) *
// p_mul of stage A it forms q = 4·v + h, the value the clamp of stage C works on, in every
// mode, in the seven cycles Sm + 6 .. Sm + 12 of motor m's lane (S = the snapshot phase,
// rtl/tmc429_schedule.vh):
//   RAMP_MODE      q = isqrt(Y), Y = (acc << 11) >> pdiv the radicand of C50, two root
//                  bits per cycle (14 bits); a radicand of 2^28 or more saturates (ovf)
//   SOFT_MODE      q = 4·((c * p_mul) >> (3+pdiv)): four bits per cycle shifted out of acc,
//                  aligned and saturated in the cycle after the last shift
//   VELOCITY_MODE  q = 4·|v_target|, loaded
// With t = pdiv >> 1, e = pdiv & 1 and u = 1 - e (RAMP_MODE), acc * 2^11 = p_mul * (|dx|-1)
// * 2^(12-e), so Y = floor(acc * 2^11 / 4^t). A root of 2^14 or more is beyond any v_max
// (q - h >= 2^14 - 16 gives v >= 4092), so the load takes the 28 bits [27:0] of that quotient
// (a shift of acc by 11 - 2t) and a nonzero bit above them saturates; 14 steps (7 cycles)
// give the root. SOFT_MODE uses the same registers to shift (c * p_mul * 2^u) out four bits
// per cycle; u and "odd" align the last bit with 3 + pdiv.
//
// The inputs are stage A's registers of the motor being loaded (they hold until the load);
// the stage's schedule is decoded by tmc429_vtarget from the next phase into registers
// (b_load, b_run, b_k) and given here with the decodes they are formed from (n_b_load, n_b_k).
`timescale 1ns / 1ps
`default_nettype none

module tmc429_vroot #(
    // square root steps: 0 two non-restoring steps per cycle (two carry chains, one XOR between
    // them; every variant); 1 three restoring differences side by side and a register 3y + 1 (one
    // carry chain per cycle, ~100 logic cells more); the same root (testbench/tests/rtl_root_forms.rs)
    parameter ROOT_SPEC = 0
) (
    input  wire        clk,
    input  wire        rst,
    input  wire        run,       // 0 while powered down (C66)
    // the stage's cycles: the load (k = 0), the seven cycles, their index k 0..6, and the
    // load and index after this edge
    input  wire        b_load,
    input  wire        b_run,
    input  wire [2:0]  b_k,
    input  wire        n_b_load,
    input  wire [2:0]  n_b_k,
    // stage A: its c cycle (pdiv is read there), mode, pdiv, v_target and product
    input  wire        a_c,
    input  wire [1:0]  a_rm,
    input  wire        a_soft,    // a_rm == SOFT_MODE
    input  wire [3:0]  a_pdiv,
    input  wire [11:0] a_vtg,
    input  wire [28:0] acc,
    // RAMP_MODE's radicand is 2^28 or more (a root beyond any v_max), at the load
    output wire        ovf,
    // q = 4·v + h (RAMP_MODE: the root so far; every mode's result from Sm + 13 on)
    output wire [13:0] q
);
    reg        b_soft;            // SOFT_MODE
    reg        b_odd;
    reg [2:0]  b_ne;
    reg [27:0] sr;
    /* verilator lint_off UNUSEDSIGNAL */   // form 0 reads bits 13:0 and the sign, 15
    reg [15:0] rem;
    /* verilator lint_on UNUSEDSIGNAL */
    reg [13:0] y;
    reg        sticky;

    // control of the motor in A, formed from pdiv at the c cycle (the parameter RAM's output
    // holds the snapshot until the next snapshot edge, after the load) and taken at the load
    reg        l_odd;
    reg [2:0]  l_ne, l_t;
    always @(posedge clk) begin
        if (rst) begin
            l_odd <= 1'b0; l_ne <= 3'd0; l_t <= 3'd0;
        end else if (run & a_c) begin
            l_odd  <= a_soft & a_pdiv[1] & a_pdiv[0];
            l_ne   <= a_soft ? (3'd6 - {1'b0, a_pdiv[3:2]}) : (a_rm[1] ? 3'd0 : 3'd7);
            l_t    <= a_pdiv[3:1];
        end
    end

    // RAMP_MODE radicand: Y = floor(acc·2^11 / 4^t) (acc·2^11 = p_mul·c·2^(12-e)); its
    // square root below 2^14 needs the 28 bits [27:0], a nonzero bit above saturates
    wire [39:0] z_sh   = {acc, 11'd0} >> {l_t, 1'b0};
    wire        m_soft = b_load ? a_soft : b_soft;
    wire [27:0] src_l  = a_soft ? acc[28:1] : z_sh[27:0];         // radicand / shift at the load
    wire [23:0] sr_nx  = b_load ? src_l[23:0] : sr[23:0];          // the bits after these four
    wire        st_l   = ~a_soft & (z_sh[39:28] != 12'd0);
    // a step in this cycle: b_load | (b_k < b_ne), a register formed with the next state of
    // the three (b_ne is loaded at the load, b_load and b_k are decoded from the next phase),
    // so that the comparison is not in the paths of the steps' enables
    reg         step;
    wire [2:0]  b_ne_nx = (run & b_load) ? l_ne : b_ne;
    always @(posedge clk) begin
        if (rst)
            step <= 1'b0;
        else
            step <= n_b_load | (n_b_k < b_ne_nx);
    end

    // two square-root steps per cycle; below saturation the root has at most 14 bits. ROOT_SPEC
    // selects how (the root is the same):
    wire [4:0]  q_ld;             // the load's two steps (sqrt_ld below)
    wire        b1, b0;
    wire [15:0] r_rn;             // the remainder after both steps
    wire        y0_nr;            // the root's last bit is the remainder's sign (form 0), below
    wire [13:0] yv;               // the root so far
    generate
        if (ROOT_SPEC == 0) begin : nonrestoring
            // non-restoring steps: the remainder R (16 bits, two's complement) is kept whatever
            // its sign, and the next step subtracts 4y + 1 from 4R + s (R >= 0) or adds 4y + 3
            // (R < 0); the new root bit is 1 when the new R >= 0. The load's restoring remainder
            // (>= 0) is a state of the same steps. |R| <= 2y + 1 < 2^15, so every sum is taken
            // modulo 2^16 (exhaustively the same root as isqrt for every 28-bit radicand). The
            // step subtracting is an addition of ~(4y + 1) + 1 = {~y, 11}, so each step is one
            // sum {R, s} + {y XOR ~sign, 11}: no multiplexer after either carry chain.
            wire        neg0 = rem[15];
            /* verilator lint_off UNUSEDSIGNAL */   // bit 14 of the first sum is not needed
            wire [15:0] n1 = {rem[13:0], sr[27:26]} + {yv ^ {14{~neg0}}, 2'b11};
            /* verilator lint_on UNUSEDSIGNAL */
            assign b1 = ~n1[15];
            // the second step's root is {y, b1} and its sign R1 < 0 is ~b1
            wire [15:0] n2 = {n1[13:0], sr[25:24]} + {{yv[12:0], b1} ^ {14{b1}}, 2'b11};
            assign b0 = ~n2[15];
            assign r_rn = n2;
            // the new root bit b0 is not written into y (a multiplexer after the carry chain):
            // after a running step y[0] is read as ~rem[15]
            reg y0_r;
            always @(posedge clk) begin
                if (rst)
                    y0_r <= 1'b0;
                else if (run & b_run & step)
                    y0_r <= ~m_soft & ~b_load;
            end
            assign y0_nr = y0_r;
        end else begin : side_by_side
            // restoring steps, R = 16·rem + s4 (the remainder with the next four radicand bits);
            // the three differences either pair of steps can keep, side by side from flip-flops,
            // each one subtraction:
            //   D1 = R - (16y + 4)    b1 = 1 when D1 >= 0
            //   D2 = R - (8y + 1)     b1 = 0: b0 = 1 when D2 >= 0 (else R is kept)
            //   D3 = R - (24y + 9)    b1 = 1: b0 = 1 when D3 >= 0 (else D1 is kept)
            // 24y + 9 = 8·y3p + 1 with y3p = 3y + 1, a register of its own: y' = 4y + b gives
            // y3p' = 4·(y3p + c) + l with (c, l) = (-1, 1), (0, 0), (0, 3), (1, 2) for b = 0..3,
            // so y3p - 1 and y3p + 1 are formed beside the differences and the new bits select.
            reg  [15:0] y3p;
            wire [19:0] r_w = {1'b0, rem[14:0], sr[27:24]};
            /* verilator lint_off UNUSEDSIGNAL */   // bits 19:15 of a kept difference are 0
            wire [19:0] d1  = r_w - {2'b00, y, 4'b0100};
            wire [19:0] d2  = r_w - {3'b000, y, 3'b001};
            wire [19:0] d3  = r_w - {1'b0, y3p, 3'b001};
            wire [15:0] y3m = y3p - 16'd1;
            wire [15:0] y3i = y3p + 16'd1;
            /* verilator lint_on UNUSEDSIGNAL */
            assign b1 = ~d1[19];
            assign b0 = b1 ? ~d3[19] : ~d2[19];
            assign r_rn = {1'b0, b1 ? (b0 ? d3[14:0] : d1[14:0]) : (b0 ? d2[14:0] : r_w[14:0])};
            wire [15:0] y3_rn = b1 ? (b0 ? {y3i[13:0], 2'd2} : {y3p[13:0], 2'd3})
                                   : (b0 ? {y3p[13:0], 2'd0} : {y3m[13:0], 2'd1});
            // 3y + 1 of the loaded root 0..3: 1, 4, 7, 10
            wire [3:0]  y3_ld = {q_ld[1] & q_ld[0], q_ld[1] ^ q_ld[0], q_ld[1], ~q_ld[0]};
            always @(posedge clk) begin
                if (rst)
                    y3p <= 16'd1;
                else if (run & b_run & step & ~m_soft)
                    y3p <= b_load ? {12'd0, y3_ld} : y3_rn;
            end
            assign y0_nr = 1'b0;
        end
    endgenerate
    assign yv = {y[13:1], y0_nr ? ~rem[15] : y[0]};
    // the two steps from remainder and result 0: root and remainder of the four bits, a table
    // (written out, so that synthesis does not share the running steps' subtractors with it)
    function [4:0] sqrt_ld;         // {r[2:0], y[1:0]}
        input [3:0] s4;
        case (s4)
        4'd0:  sqrt_ld = {3'd0, 2'd0};  4'd1:  sqrt_ld = {3'd0, 2'd1};
        4'd2:  sqrt_ld = {3'd1, 2'd1};  4'd3:  sqrt_ld = {3'd2, 2'd1};
        4'd4:  sqrt_ld = {3'd0, 2'd2};  4'd5:  sqrt_ld = {3'd1, 2'd2};
        4'd6:  sqrt_ld = {3'd2, 2'd2};  4'd7:  sqrt_ld = {3'd3, 2'd2};
        4'd8:  sqrt_ld = {3'd4, 2'd2};  4'd9:  sqrt_ld = {3'd0, 2'd3};
        4'd10: sqrt_ld = {3'd1, 2'd3};  4'd11: sqrt_ld = {3'd2, 2'd3};
        4'd12: sqrt_ld = {3'd3, 2'd3};  4'd13: sqrt_ld = {3'd4, 2'd3};
        4'd14: sqrt_ld = {3'd5, 2'd3};  default: sqrt_ld = {3'd6, 2'd3};
        endcase
    endfunction
    assign q_ld = sqrt_ld(src_l[27:24]);
    wire [2:0]  r2    = b_load ? q_ld[4:2] : r_rn[2:0];
    wire [13:0] y2    = b_load ? {12'd0, q_ld[1:0]} : {yv[11:0], b1, b0};
    // y[0]: form 0 writes it at the load alone (a running step's b0 is read as ~rem[15]), so
    // its next state is the load's bit and never depends on the running steps' sums
    wire        y0_keep = ~b_load & (ROOT_SPEC == 0);
    wire        y0_nx   = (ROOT_SPEC == 0) ? q_ld[0] : y2[0];
    wire        st_q  = b_load ? st_l : sticky;
    // SOFT_MODE: four bits shifted into y[11:0]
    wire [11:0] y_p   = b_load ? {8'd0, src_l[27:24]} : {y[7:0], sr[27:24]};
    wire        st_p  = b_load ? st_l : (sticky | (y[11:8] != 4'd0));
    // VELOCITY_MODE: q = 4·|v_target| is loaded into y and kept (no steps); -2048 -> 2048
    wire        l_vel  = a_rm == 2'd2;
    wire [11:0] l_vabs = a_vtg[11] ? (~a_vtg + 12'd1) : a_vtg;
    // SOFT_MODE: in the cycle after the last shift (k = 6: at most six shifts) y becomes
    // q = 4·mag, the quotient's twelve bits aligned by "odd", saturated by sticky
    wire        s_norm = ~step & b_soft & (b_k == 3'd6);
    wire        y_sat  = sticky | (~b_odd & y[11]);
    wire [10:0] y_mag  = b_odd ? y[11:1] : y[10:0];

    always @(posedge clk) begin
        if (rst) begin
            b_soft <= 1'b0; b_odd <= 1'b0; b_ne <= 3'd0;
            sr <= 28'd0; rem[2:0] <= 3'd0; y <= 14'd0; sticky <= 1'b0;
        end else if (run) begin
            if (b_load) begin
                b_soft <= a_soft;
                b_odd <= l_odd; b_ne <= l_ne;
            end
            if (b_run & step) begin
                sr <= {sr_nx, 4'd0};
                if (m_soft) begin
                    y <= {2'b00, y_p};
                    sticky <= st_p;
                end else begin
                    rem[2:0] <= r2;
                    if (b_load & l_vel)
                        y[13:1] <= {l_vabs, 1'b0};
                    else
                        y[13:1] <= y2[13:1];
                    if (~y0_keep)
                        y[0] <= y0_nx & ~(b_load & l_vel);
                    sticky <= st_q;
                end
            end
            if (b_run & s_norm)
                y <= {y_sat, y_mag, 2'b00};
        end
    end

    // the remainder's upper bits: 0 at the load (the table's remainder is below 8), so that the
    // load is the flip-flops' synchronous reset and the sum enters them without a multiplexer
    wire rem_clr = rst | (run & b_run & b_load);
    always @(posedge clk) begin
        if (rem_clr)
            rem[15:3] <= 13'd0;
        else if (run & b_run & step & ~m_soft)
            rem[15:3] <= r_rn[15:3];
    end

    assign ovf = st_l;
    assign q   = yv;
endmodule

`default_nettype wire
