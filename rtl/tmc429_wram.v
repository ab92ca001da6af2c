// tmc429_wram: a register store in block RAM: 2^AW words of DW bits, one write port, one
// synchronous read port, and a resettable "written" flag per word (docs/model-contract.md
// C2: the power-on state), as tmc429_ram keeps its ROM contents.
//
// The array has no reset (it maps to a RAM). `q` is the word as it was before the last edge
// with `re` (a write in that edge is not seen) and `wq` says whether that word was written
// since reset; the user takes the reset value where `wq` is 0. WMASK selects the words that
// can be written at all: the flags of the others are constant 0 (no flip-flop), so their
// read value is always the user's reset value, whatever a write put into the array.
// A read in the edge of a write to the same word gives the old word in simulation; the user
// never uses such a read (no_rw_check: a block RAM needs no collision logic for it).
`timescale 1ns / 1ps
`default_nettype none

module tmc429_wram #(
    parameter AW = 6,
    parameter DW = 24,
    parameter [(1<<AW)-1:0] WMASK = {(1<<AW){1'b1}}
) (
    input  wire          clk,
    input  wire          rst,
    input  wire          we,
    input  wire [AW-1:0] waddr,
    input  wire [DW-1:0] wdata,
    input  wire          re,
    input  wire [AW-1:0] raddr,
    output reg  [DW-1:0] q,
    output reg           wq
);
    (* ram_style = "block", no_rw_check *)
    reg [DW-1:0]        mem [0:(1<<AW)-1];
    reg [(1<<AW)-1:0]   written;

    always @(posedge clk) begin
        if (we)
            mem[waddr] <= wdata;
        if (re)
            q <= mem[raddr];
    end

    integer i;
    always @(posedge clk) begin
        if (rst) begin
            written <= {(1<<AW){1'b0}};
            wq <= 1'b0;
        end else begin
            // the write enable tested once per edge, so that a simulator does not test it per
            // word (docs/rtl.md, "Logic in its slot")
            if (we)
                for (i = 0; i < (1<<AW); i = i + 1)
                    if (waddr == i[AW-1:0] && WMASK[i])
                        written[i] <= 1'b1;
            if (re)
                wq <= written[raddr];
        end
    end
endmodule

`default_nettype wire
