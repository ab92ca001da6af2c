// tmc429_microstep: the microstep unit, one bit of a motor's primary signal vector
// (docs/model-contract.md C71-C74, C76, C80; TMC428 §11 Table 11-1, §12 Tables 12-3/12-4,
// Table 8-1). Purely combinational, three functions the driver chain uses one after the
// other for each datagram bit (with registers between them):
//
//   1. LUT index: for the full-wave index w and the coil of the bit's code (coil_b = code
//      bit 3: 0 = coil A / sine, 1 = coil B / cosine) it names the LUT cell to read
//      (RAM cell 64 + lut_idx). Quadrant q = w[7:6], j = w[5:0]: q even -> sine index j,
//      cosine index min(63, 64 - j); q odd -> the reverse (C71).
//   2. Scaling: dac = the LUT value scaled by i_scale (%000 = 1, else (LUT * i_scale) >> 3,
//      Table 8-1, C76).
//   3. Bit: from the code, the scaled value `dac_q` (output 2 of the LUT value read for this
//      code), w and the snapshot bits: DAC_A/DAC_B bit (code & 7) XOR polarity_dac_ab;
//      PH_A, PH_B, FD_A, FD_B by quadrant (Table 12-3) XOR polarity_ph_ab / polarity_fd_ab;
//      Zero = 0, One = 1, Direction ($12, 1 = negative), Step ($13); unused codes $14-$1F
//      read 1 (C74).
//
// Same function as tmc429_model::microstep::{lut_cell, scale, signal_bit}: bit_out for
// (code, w, lut, i_scale, ...) is signal_bit when dac_q = dac.
`timescale 1ns / 1ps
`default_nettype none

module tmc429_microstep (
    // LUT index
    input  wire [7:0] w,           // full-wave index (ustep_count)
    input  wire       coil_b,      // code bit 3 of the cell whose LUT value is needed
    output wire [5:0] lut_idx,     // LUT index: RAM cell 64 + lut_idx
    // scaling
    input  wire [5:0] lut,         // LUT value
    input  wire [2:0] i_scale,     // current scale of the motor (C75, C76)
    output wire [5:0] dac,         // scaled LUT value
    // bit of the signal vector
    input  wire [4:0] code,        // primary signal code of the bit (Table 11-1)
    input  wire [5:0] dac_q,       // scaled LUT value for this code (`dac`, registered)
    input  wire       negative,    // Direction: last step negative
    input  wire       step,        // Step: stepped since the previous datagram start
    input  wire       pol_ph_ab,
    input  wire       pol_fd_ab,
    input  wire       pol_dac_ab,
    output reg        bit_out
);
    // ---- LUT index (C71) --------------------------------------------------------------
    wire [5:0] j      = w[5:0];
    wire [5:0] mirror = (j == 6'd0) ? 6'd63 : (6'd0 - j);   // min(63, 64 - j)
    assign lut_idx = (w[6] ^ coil_b) ? mirror : j;

    // ---- scaling (C76): %000 = 1, else (lut * i_scale) >> 3 ------------------------------
    /* verilator lint_off UNUSEDSIGNAL */
    wire [8:0] prod = ({3'd0, lut} & {9{i_scale[0]}})
                    + ({2'd0, lut, 1'b0} & {9{i_scale[1]}})
                    + ({1'd0, lut, 2'b0} & {9{i_scale[2]}});
    /* verilator lint_on UNUSEDSIGNAL */   // >> 3 drops the low product bits
    assign dac = (i_scale == 3'd0) ? lut : prod[8:3];

    // ---- quadrant bits (Table 12-3): q = %00: 1 1 0 1, %01: 1 0 1 0, %10: 0 0 0 1, %11: 0 1 1 0
    wire ph_a = ~w[7];
    wire ph_b = ~(w[7] ^ w[6]);
    wire fd_a = w[6];
    wire fd_b = ~w[6];

    always @(*) begin
        case (code)
        5'h00, 5'h01, 5'h02, 5'h03, 5'h04, 5'h05,
        5'h08, 5'h09, 5'h0A, 5'h0B, 5'h0C, 5'h0D:
                 bit_out = dac_q[code[2:0]] ^ pol_dac_ab;
        5'h06:   bit_out = ph_a ^ pol_ph_ab;     // PH_A
        5'h07:   bit_out = fd_a ^ pol_fd_ab;     // FD_A
        5'h0E:   bit_out = ph_b ^ pol_ph_ab;     // PH_B
        5'h0F:   bit_out = fd_b ^ pol_fd_ab;     // FD_B
        5'h10:   bit_out = 1'b0;                 // Zero
        5'h12:   bit_out = negative;             // Direction
        5'h13:   bit_out = step;                 // Step
        default: bit_out = 1'b1;                 // One ($11), unused $14-$1F (C74)
        endcase
    end
endmodule

`default_nettype wire
