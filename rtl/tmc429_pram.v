// tmc429_pram: one configuration register of the three motors in block RAM, read for the
// motor whose slot comes next (docs/model-contract.md C41, C3, C2).
//
// A register that the motion core reads in one motor's slot alone needs no flip-flops: the
// µC writes it into this RAM (one word per motor) and the RAM is read in every edge at the
// word of the motor m with R(m) <= phase < R(m+1) (R(0) = 0; R1 and R2 are parameters; the
// phase is prescaler[4:0], which stands still while powered down, so the read goes on at the
// same word; the read address is a register formed in the edge before). `val` is the register
// of that motor as it holds in this cycle: the read of the edge before; or, when the µC wrote
// the word read in that edge (the read gives the old word then, C3), `fd`, the write data of
// the edge before (the datagram's data holds in the edge after its write: a user may pass wd,
// or a register of a wd formed by a carry chain, then not in the path from the forwarding into
// val's users); or the reset value RESET while the word was never written (C2). A µC write in
// this edge is not in `val` (the old state's value); `ra` is the word read in this edge, for a
// user whose own register takes the value after this edge. With one motor (NMOT = 1, the
// TMC4210) the word is a flip-flop register loaded by the write: the same `val`, less logic.
`timescale 1ns / 1ps
`default_nettype none

module tmc429_pram #(
    parameter DW = 11,
    parameter NMOT = 3,               // motors present (TMC4210: 1, whose word alone is read)
    parameter [4:0] R1 = 5'd0,        // the first phase whose edge reads motor 1's word
    parameter [4:0] R2 = 5'd0,        // ... motor 2's word
    parameter [DW-1:0] RESET = {DW{1'b0}}
) (
    input  wire          clk,
    input  wire          rst,
    /* verilator lint_off UNUSEDSIGNAL */   // NMOT = 1: one word, no read address
    input  wire          run,         // the phase moves in this edge (not powered down)
    input  wire [4:0]    phase,       // prescaler[4:0]
    input  wire          we,          // a µC write of this register executes in this edge ...
    input  wire [1:0]    wm,          // ... to this motor ...
    input  wire [DW-1:0] wd,          // ... with this data
    input  wire [DW-1:0] fd,          // wd as it was in the edge before (the forwarded data)
    /* verilator lint_on UNUSEDSIGNAL */
    output wire [1:0]    ra,          // the word read in this edge
    output wire [DW-1:0] val          // the register of the word read in the edge before
);
    generate
        if (NMOT == 1) begin : one
            // one motor: its word is a flip-flop register (the RAM and the forwarding would
            // cost more logic than the DW flip-flops they replace); fd is not needed
            reg [DW-1:0] r;
            always @(posedge clk) begin
                if (rst)
                    r <= RESET;
                else if (we)
                    r <= wd;
            end
            assign ra  = 2'd0;
            assign val = r;
        end else begin : three
            // the word read, a register formed one edge ahead: the phase after this edge is
            // p + run (0 after reset), so the word of phase p + 1 is bit p of each bound's
            // phase set rotated by one (GE*_NX), a decode of the counter and run with no
            // increment and no comparison in front of the RAM's address
            localparam [31:0] GE1 = ~((32'd1 << R1) - 32'd1);   // bit p: p >= R1
            localparam [31:0] GE2 = ~((32'd1 << R2) - 32'd1);
            localparam [31:0] GE1_NX = {GE1[0], GE1[31:1]};      // bit p: p + 1 >= R1 (mod 32)
            localparam [31:0] GE2_NX = {GE2[0], GE2[31:1]};
            wire ge1_nx = run ? GE1_NX[phase] : GE1[phase];
            wire ge2_nx = run ? GE2_NX[phase] : GE2[phase];
            reg  [1:0] ra_q;
            always @(posedge clk) begin
                if (rst)
                    ra_q <= {GE2[0], ~GE2[0] & GE1[0]};
                else
                    ra_q <= {ge2_nx, ~ge2_nx & ge1_nx};
            end
            assign ra = ra_q;
            wire [DW-1:0] q;
            wire          wq;
            tmc429_wram #(.AW(2), .DW(DW), .WMASK(4'b0111)) u_mem (
                .clk(clk), .rst(rst),
                .we(we), .waddr(wm), .wdata(wd),
                .re(1'b1), .raddr(ra), .q(q), .wq(wq));
            // a write of the word read in that edge: the read is void, the write's data holds
            reg fw;
            always @(posedge clk) begin
                if (rst)
                    fw <= 1'b0;
                else
                    fw <= we & (wm == ra);
            end
            assign val = fw ? fd : (wq ? q : RESET);
        end
    endgenerate
endmodule

`default_nettype wire
