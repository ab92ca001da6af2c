// tmc429_sync: two-flop synchronizer with a history flop (docs/model-contract.md C4).
//
// An input level applied before CLK edge t appears on `q` after edge t+1 and on `h`
// after edge t+2; an edge is detected between `q` and `h`, so it is acted on at edge
// t+2. The synchronizers run in power down as well (only the units behind them stop).
// `s` is the first stage: the level `q` takes at the next edge, for a unit that forms an
// edge-detect one edge ahead into a register (it must not be used as a level).
`timescale 1ns / 1ps
`default_nettype none

module tmc429_sync #(
    parameter       W   = 1,
    parameter [W-1:0] RST = {W{1'b0}}
) (
    input  wire         clk,
    input  wire         rst,
    input  wire [W-1:0] d,
    output reg  [W-1:0] s,
    output reg  [W-1:0] q,
    output reg  [W-1:0] h
);
    always @(posedge clk) begin
        if (rst) begin
            s  <= RST;
            q  <= RST;
            h  <= RST;
        end else begin
            s  <= d;
            q  <= s;
            h  <= q;
        end
    end
endmodule

`default_nettype wire
