// tmc429_sync: two-flop synchronizer with a history flop (docs/model-contract.md C4).
//
// An input level applied before CLK edge t appears on `q` after edge t+1 and on `h`
// after edge t+2; an edge is detected between `q` and `h`, so it is acted on at edge
// t+2. The synchronizers run in power down as well (only the units behind them stop).
`default_nettype none

module tmc429_sync #(
    parameter       W   = 1,
    parameter [W-1:0] RST = {W{1'b0}}
) (
    input  wire         clk,
    input  wire         rst,
    input  wire [W-1:0] d,
    output reg  [W-1:0] q,
    output reg  [W-1:0] h
);
    reg [W-1:0] s1;

    always @(posedge clk) begin
        if (rst) begin
            s1 <= RST;
            q  <= RST;
            h  <= RST;
        end else begin
            s1 <= d;
            q  <= s1;
            h  <= q;
        end
    end
endmodule

`default_nettype wire
