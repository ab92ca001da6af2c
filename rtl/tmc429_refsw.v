// tmc429_refsw: reference switch mapping (docs/model-contract.md C60; TMC428 Table 9-3,
// TMC429 §8.2.4, TMC4210 §1.5.4).
//
// From the synchronized pins: inv_ref inverts every REF/REFR input first. refmux = 0,
// mot1r = 0: Ln = REFn, and on the TMC429 with en_refr = 1 Rn = REFRn, else no right
// switches. mot1r = 1: L1 = REF1, L2 = REF2, R1 = REF3, motor 3 has no switches. A missing
// switch reads inactive (0). TMC4210: L1 = REF_L (REF1), L2 = GP_IN (REF2), R1 = REF_R
// (REF3) with mot1r = 1, no refmux and no REFR inputs. refmux = 1 (TMC428, TMC429): the
// switches are the ones sampled through the 74HC157 on nSCS_S (tmc429_drvpins, C87).
`timescale 1ns / 1ps
`default_nettype none

module tmc429_refsw #(
    parameter CHIP = 1
) (
    input  wire [2:0] ref_q,    // REF3..REF1, synchronized
    input  wire [2:0] refr_q,   // REFR3..REFR1, synchronized
    input  wire       inv_ref,
    input  wire       en_refr,
    input  wire       refmux,
    input  wire       mot1r,
    input  wire [5:0] mux_sw,   // sampled switches: bit 2m = R(m+1), bit 2m+1 = L(m+1)
    output reg  [2:0] l,        // L3..L1
    output reg  [2:0] r         // R3..R1
);
    wire [2:0] rf  = ref_q  ^ {3{inv_ref}};
    wire [2:0] rfr = refr_q ^ {3{inv_ref}};

    always @(*) begin
        if (CHIP == 2) begin
            // TMC4210: REF_L = REF1 (l1), GP_IN = REF2 (read as l2), REF_R = REF3 with mot1r
            l = {1'b0, rf[1], rf[0]};
            r = {2'b00, rf[2] & mot1r};
        end else if (refmux) begin
            l = {mux_sw[5], mux_sw[3], mux_sw[1]};
            r = {mux_sw[4], mux_sw[2], mux_sw[0]};
        end else if (mot1r) begin
            l = {1'b0, rf[1], rf[0]};
            r = {2'b00, rf[2]};
        end else begin
            l = rf;
            r = (CHIP == 1 && en_refr) ? rfr : 3'b000;
        end
    end
endmodule

`default_nettype wire
