// tmc429_spi_slave: the µC SPI port (docs/model-contract.md C10-C13; TMC428 §6.2).
//
// nSCS_C, SCK_C and SDI_C pass tmc429_sync (C4). The frame starts at the synchronized
// falling edge of nSCS_C: the bit counter clears and the status byte is loaded into
// bits 31..24 of the output register. Each synchronized rising SCK_C edge while nSCS_C
// is low shifts SDI_C in (MSB first, counter saturates at 63); when the 8th bit is in
// and RW = 1 the read data is loaded in the same cycle, where data bit 23 leaves on the
// next falling edge; v_actual's rounding toward 0 (rd_round) is added to the data's bits 11..0 in
// the edge after (a falling edge in that edge shifts the sum), twelve falling edges before they
// leave. Each synchronized falling SCK_C edge after the first bit shifts the
// output register left (the first falling edge presents bit 31, already on the pin). An SCK_C
// edge in the cycle of the nSCS_C falling edge is ignored (C13). At the synchronized
// rising edge of nSCS_C a frame of exactly 32 bits is executed (`exec` pulse, a register).
`timescale 1ns / 1ps
`default_nettype none

module tmc429_spi_slave (
    input  wire        clk,
    input  wire        rst,
    input  wire        nscs_c,
    input  wire        sck_c,
    input  wire        sdi_c,
    // status byte of the old state, loaded at the start of a frame
    input  wire [7:0]  status,
    // read port: address of the frame being received, data of the old state
    output wire [6:0]  rd_addr,
    // the same address (bits 5..0) from the edge after the 7th bit on: it is stable for at
    // least one edge before the read data is loaded, for a synchronous (block RAM) read
    output wire [5:0]  rd_addr_q,
    // the input register shifted (or was reset) in the last edge: rd_addr may differ from
    // the edge before (a user that registers a decode of it loads only after such an edge)
    output reg         rd_addr_new,
    input  wire [23:0] rd_data,
    // the read value is rd_data plus 1 in bits 11..0 (v_actual of a negative V with a nonzero
    // low byte, C42): the register file's read multiplexer has no incrementer
    input  wire        rd_round,
    // the read data is loaded in this edge (the 8th bit of a read arrives): rd_data is used
    // in no other edge
    output wire        rd_load,
    // synchronized nSCS_C falling edge (frame start, wake-up from power down)
    output wire        frame_start,
    // one-cycle pulse: execute `cmd` (a 32-bit frame ended)
    output wire        exec,
    output wire [31:0] cmd,
    // exec and the address byte of cmd (RRS, SMDA, IDX, RW) after this edge: a write is known
    // one edge before it executes, for write strobes that are flip-flops
    output wire        exec_nx,
    output wire [7:0]  addr_nx,
    // 1 while the frame is active (output register drives the data pin)
    output wire        active,
    // current data bit
    output wire        sdo
);
    wire nscs_s, nscs_q, nscs_h, sck_q, sck_h, sdi_q;
    /* verilator lint_off UNUSEDSIGNAL */
    wire sck_s, sdi_s, sdi_h;   // SDI_C is sampled, not edge-detected: its history flop is unused
    /* verilator lint_on UNUSEDSIGNAL */

    tmc429_sync #(.W(1), .RST(1'b1)) u_sync_nscs (
        .clk(clk), .rst(rst), .d(nscs_c), .s(nscs_s), .q(nscs_q), .h(nscs_h));
    tmc429_sync #(.W(1), .RST(1'b1)) u_sync_sck (
        .clk(clk), .rst(rst), .d(sck_c), .s(sck_s), .q(sck_q), .h(sck_h));
    tmc429_sync #(.W(1), .RST(1'b0)) u_sync_sdi (
        .clk(clk), .rst(rst), .d(sdi_c), .s(sdi_s), .q(sdi_q), .h(sdi_h));

    reg [31:0] in_sr;
    reg [31:0] out_sr;
    reg [5:0]  cnt;
    reg        exec_q;
    reg        fall_q;
    reg        round_q;   // the read value loaded in the last edge gets its rounding now

    // the falling edge ~nscs_q & nscs_h, formed one edge ahead into a register (after an edge
    // nscs_h is the nscs_q before it and nscs_q the first stage's level): the frame start, which
    // wakes the core from power down (C66) and so enters the frame schedule's next state,
    // starts at a flip-flop that the placement puts beside its users, not at the synchronizer
    wire nscs_fall = fall_q;
    wire sel       = ~nscs_q & ~nscs_h;   // low, and not the cycle of the falling edge (C13)
    wire sck_rise  = sel & sck_q & ~sck_h;
    // the first falling edge presents bit 31, which is already out (SPI mode 3)
    wire sck_fall  = sel & ~sck_q & sck_h & (cnt != 6'd0);

    wire [31:0] in_sr_nx = {in_sr[30:0], sdi_q};
    // the 8th bit arrives now and it is a read
    assign      rd_load = sck_rise & (cnt == 6'd7) & sdi_q;

    assign rd_addr     = in_sr_nx[7:1];
    assign rd_addr_q   = in_sr[5:0];
    assign frame_start = nscs_fall;
    assign exec        = exec_q;
    assign cmd         = in_sr;
    assign addr_nx     = (~nscs_fall & sck_rise) ? in_sr_nx[31:24] : in_sr[31:24];
    assign active      = ~nscs_h;
    assign sdo         = out_sr[31];

    // exec = nscs_rise & (cnt == 32) of the old state, formed one edge ahead into a register:
    // after this edge nscs_q is the first stage's level and nscs_h the present nscs_q, and the
    // counter is cnt_nx (the write decode behind exec then starts at a flip-flop). The bit
    // counter clears at the frame start and counts rising SCK_C edges, saturating at 63.
    wire [5:0]  cnt_nx  = nscs_fall ? 6'd0
                        : ((sck_rise & (cnt != 6'd63)) ? cnt + 6'd1 : cnt);
    assign exec_nx      = nscs_s & ~nscs_q & (cnt_nx == 6'd32);
    always @(posedge clk) begin
        if (rst) begin
            cnt    <= 6'd0;
            exec_q <= 1'b0;
            fall_q <= 1'b0;
        end else begin
            cnt    <= cnt_nx;
            exec_q <= exec_nx;
            fall_q <= ~nscs_s & nscs_q;
        end
    end

    // the data's bits 11..0 sit at bits 18..7 after the load; the rounding is formed in the
    // clocked block, only in the edge after a load that rounds (docs/rtl.md, "Logic in its
    // slot")
    function [31:0] rounded;
        input [31:0] o;
        input        r;
        reg   [11:0] f;
        begin
            f       = o[18:7] + 12'd1;
            rounded = r ? {o[31:19], f, o[6:0]} : o;
        end
    endfunction
    always @(posedge clk) begin
        if (rst) begin
            in_sr   <= 32'd0;
            out_sr  <= 32'd0;
            round_q <= 1'b0;
            rd_addr_new <= 1'b1;
        end else if (nscs_fall) begin
            out_sr  <= {status, 24'd0};
            round_q <= 1'b0;
            rd_addr_new <= 1'b0;
        end else begin
            if (sck_rise)
                in_sr <= in_sr_nx;
            rd_addr_new <= sck_rise;
            round_q <= rd_load & rd_round;
            if (rd_load)
                // after 7 falling edges the reply's bit 23 sits at bit 30
                out_sr <= {out_sr[31], rd_data, 7'd0};
            else if (sck_fall)
                out_sr <= rounded(out_sr, round_q) << 1;
            else if (round_q)
                out_sr <= rounded(out_sr, 1'b1);
        end
    end
endmodule

`default_nettype wire
