// tmc429_current: current-scale selection of one motor (docs/model-contract.md C75-C77;
// TMC428 §8.9 Table 8-2, TMC429 §8.1.9).
//
// At each ramp tick of the motor (`tick`, C40), from the old state: moving (V != 0) selects
// is_agtat when a_threshold <= 1023 and |a_actual| > a_threshold, else is_aleat, and clears
// the rest counter; at rest the 8-bit counter counts up to 255 and from then on is_v0 is
// selected if is_agtat and is_aleat are both > 0 (TMC429 §8.1.9 footnote *2), else is_aleat
// (the previous selection holds while it counts). Between ramp ticks the selection holds. Power-on: is_aleat, counter 0. `i_scale` is the selected register value
// of the current state. Same function as tmc429_model::current::CurrentScale.
`timescale 1ns / 1ps
`default_nettype none

module tmc429_current (
    input  wire        clk,
    input  wire        rst,
    input  wire        tick,          // ramp tick of this motor (and not powered down)
    input  wire        v_nz,          // internal velocity V != 0
    input  wire [11:0] a_actual,      // signed velocity change of the last ramp tick
    input  wire [10:0] a_threshold,
    input  wire [2:0]  is_agtat,
    input  wire [2:0]  is_aleat,
    input  wire [2:0]  is_v0,
    output reg  [2:0]  i_scale
);
    localparam SEL_ALEAT = 2'd0, SEL_AGTAT = 2'd1, SEL_V0 = 2'd2;

    reg [7:0] v0_count;
    reg [1:0] sel;

    // |a_actual| > a_threshold without forming |a_actual|, one carry chain whose sign is the
    // answer (thr <= 1023 in 12 bits): a >= 0: thr - a = thr + ~a + 1 is negative; a < 0:
    // -a > thr, i.e. thr + a is negative. Both are thr + (a ^ {12{~s}}) + ~s with s = a's sign
    /* verilator lint_off UNUSEDSIGNAL */     // only the sign of the sum is used
    wire        a_pos = ~a_actual[11];
    wire [11:0] d     = {2'b00, a_threshold[9:0]} + (a_actual ^ {12{a_pos}}) + {11'd0, a_pos};
    /* verilator lint_on UNUSEDSIGNAL */
    // Table 8-2: a_threshold > 1023 always selects is_aleat
    wire        agt   = ~a_threshold[10] & d[11];

    // The tick loads both registers, its enable the registered tick alone: V != 0, the last
    // input, selects between the next states of a moving and of a resting motor in front of
    // them. Formed in the clocked block, only in the tick (docs/rtl.md, "Logic in its slot")
    always @(posedge clk) begin
        if (rst) begin
            v0_count <= 8'd0;
            sel      <= SEL_ALEAT;
        end else if (tick) begin : at_tick
            reg [7:0] cnt_rest;
            reg [1:0] sel_rest, sel_mov;
            cnt_rest = v0_count + {7'd0, ~&v0_count};     // counts up to 255 and stays there
            sel_rest = ~&v0_count[7:1] ? sel             // below 254: the selection holds
                     : ((|is_agtat & |is_aleat) ? SEL_V0 : SEL_ALEAT);
            sel_mov  = agt ? SEL_AGTAT : SEL_ALEAT;
            v0_count <= v_nz ? 8'd0 : cnt_rest;
            sel      <= v_nz ? sel_mov : sel_rest;
        end
    end

    always @(*) begin
        case (sel)
        SEL_AGTAT: i_scale = is_agtat;
        SEL_V0:    i_scale = is_v0;
        default:   i_scale = is_aleat;
        endcase
    end
endmodule

`default_nettype wire
