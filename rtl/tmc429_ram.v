// tmc429_ram: the 128 x 6 bit configuration and microstep RAM (docs/model-contract.md C30;
// TMC428 §10, TMC429 §11.4).
//
// Organised as 64 words of two cells: word w holds cell 2w in bits 5..0 and cell 2w+1 in
// bits 11..6, as a RAM datagram addresses them (TMC428 Table 10-1). The array has no reset
// (it maps to a RAM). The power-on contents come from a ROM (C30): in the 65 edges after
// reset a sweep copies the ROM into the array, one word per edge (the ROM read one edge
// ahead of the write), and until the sweep is done a µC read returns the ROM value. No µC
// write can meet the sweep: a frame needs the synchronized nSCS_C falling edge (3 edges after
// reset at the earliest) and 32 rising SCK_C edges at least 2 edges apart before it executes
// (C4, C10, C12), i.e. not before the 67th edge; the sweep's last write is at the 65th.
// Two read ports, each on its own copy of the array (two block RAMs written together):
// port 1 (µC reads) is synchronous and reads every edge: `rdata` is the word at `raddr` as
// it was before the last edge. Its user (the SPI read, tmc429_regfile) presents the address
// at least one edge before it takes the data and never takes a word read in the edge of a
// write (no µC write executes inside a frame), so this copy needs no read/write collision
// logic (no_rw_check). Port 2 (driver chain, C80) addresses one 6-bit cell and is
// synchronous with a read enable: `rdata2` is the cell as it was before the last edge with
// `re2` (a write in that edge is not seen). The chain reads no cell before the sweep is
// done: it reads only inside a datagram, which needs a request (C83): a step (V is 0 until a
// µC write), a cover datagram or a continuous update (both off until a µC write), so not
// before the first µC write; port 2 therefore reads the array alone. The ROM, a case table
// that the sweep and port 1 read synchronously, maps to block RAM as well (rom_style).
// ROM (CHIP = 1, TMC429, and CHIP = 2, TMC4210, whose contents are not published): cells
// 0..35 = TMC429 Table 11-2 with One ($11) at the Zero/FD positions (TMC429 §11.4.2), cells
// 36..63 = 0, cells 64..127 = the sine table of TMC428 Table 12-2, y(i) = min(63, int(1/2 +
// 64 sin(pi i / 128))). CHIP = 0 (TMC428): all 0.
`timescale 1ns / 1ps
`default_nettype none

module tmc429_ram #(
    parameter CHIP = 1
) (
    input  wire        clk,
    input  wire        rst,
    input  wire        we,
    input  wire [5:0]  waddr,
    input  wire [11:0] wdata,
    input  wire [5:0]  raddr,      // port 1: read every edge
    output wire [11:0] rdata,
    input  wire        re2,
    input  wire [6:0]  raddr2,     // cell 0..127
    output wire [5:0]  rdata2
);
    (* ram_style = "block", no_rw_check *)
    reg [11:0] mem1 [0:63];        // copy for port 1
    (* ram_style = "block" *)
    reg [11:0] mem [0:63];         // copy for port 2

    // ---- power-on sweep ---------------------------------------------------------------
    reg  [6:0]  sw_c;       // next ROM word to read; 64: all read
    reg         sw_v;       // this edge writes rom_q to word sw_a
    reg  [5:0]  sw_a;
    reg  [11:0] rom_q;
    always @(posedge clk) begin
        rom_q <= (CHIP != 0) ? rom_word(sw_c[5:0]) : 12'h000;
        sw_a  <= sw_c[5:0];
    end
    always @(posedge clk) begin
        if (rst) begin
            sw_c <= 7'd0;
            sw_v <= 1'b0;
        end else begin
            if (!sw_c[6])
                sw_c <= sw_c + 7'd1;
            sw_v <= ~sw_c[6];
        end
    end
    // every word holds its contents once the sweep's last write is done. Until then a read
    // takes the ROM value: no µC write can come before the sweep ends, so a word copied
    // already holds that value as well, and no address is compared with the sweep's
    wire        swept = sw_c[6] & ~sw_v;

    wire        wr_e = sw_v | we;
    wire [5:0]  wr_a = sw_v ? sw_a : waddr;
    wire [11:0] wr_data = sw_v ? rom_q : wdata;
    always @(posedge clk) begin
        if (wr_e) begin
            mem1[wr_a] <= wr_data;
            mem[wr_a] <= wr_data;
        end
    end

    // Power-on contents of word a (C30): TMC429 only, zero otherwise.
    function [11:0] rom_word;
        input [5:0] a;
        begin
            (* rom_style = "block" *)
            case (a)
            6'd0: rom_word = 12'h151;
            6'd1: rom_word = 12'h0C4;
            6'd2: rom_word = 12'h182;
            6'd3: rom_word = 12'h351;
            6'd4: rom_word = 12'h2CC;
            6'd5: rom_word = 12'hB8A;
            6'd6: rom_word = 12'h151;
            6'd7: rom_word = 12'h0C4;
            6'd8: rom_word = 12'h182;
            6'd9: rom_word = 12'h351;
            6'd10: rom_word = 12'h2CC;
            6'd11: rom_word = 12'hB8A;
            6'd12: rom_word = 12'h151;
            6'd13: rom_word = 12'h0C4;
            6'd14: rom_word = 12'h182;
            6'd15: rom_word = 12'h351;
            6'd16: rom_word = 12'h2CC;
            6'd17: rom_word = 12'hB8A;
            6'd32: rom_word = 12'h080;
            6'd33: rom_word = 12'h143;
            6'd34: rom_word = 12'h206;
            6'd35: rom_word = 12'h2C9;
            6'd36: rom_word = 12'h38C;
            6'd37: rom_word = 12'h450;
            6'd38: rom_word = 12'h513;
            6'd39: rom_word = 12'h5D6;
            6'd40: rom_word = 12'h698;
            6'd41: rom_word = 12'h75B;
            6'd42: rom_word = 12'h81E;
            6'd43: rom_word = 12'h8A1;
            6'd44: rom_word = 12'h964;
            6'd45: rom_word = 12'h9E6;
            6'd46: rom_word = 12'hAA9;
            6'd47: rom_word = 12'hB2B;
            6'd48: rom_word = 12'hBAD;
            6'd49: rom_word = 12'hC2F;
            6'd50: rom_word = 12'hCB1;
            6'd51: rom_word = 12'hD33;
            6'd52: rom_word = 12'hDB5;
            6'd53: rom_word = 12'hE37;
            6'd54: rom_word = 12'hE78;
            6'd55: rom_word = 12'hEFA;
            6'd56: rom_word = 12'hF3B;
            6'd57: rom_word = 12'hF7C;
            6'd58: rom_word = 12'hFBD;
            6'd59: rom_word = 12'hFBE;
            6'd60: rom_word = 12'hFFF;
            6'd61: rom_word = 12'hFFF;
            6'd62: rom_word = 12'hFFF;
            6'd63: rom_word = 12'hFFF;
            default: rom_word = 12'h000;
            endcase
        end
    endfunction

    // ---- port 1 -----------------------------------------------------------------------
    reg [11:0] q1, rom1;
    reg        w1;
    always @(posedge clk) begin
        q1 <= mem1[raddr];
        rom1 <= (CHIP != 0) ? rom_word(raddr) : 12'h000;
    end
    always @(posedge clk) begin
        if (rst)
            w1 <= 1'b0;
        else
            w1 <= swept;
    end
    assign rdata = w1 ? q1 : rom1;

    // ---- port 2 -----------------------------------------------------------------------
    // The chain reads no cell before the sweep is done (see the top), so this port has no
    // ROM fallback: the word it reads holds its contents.
    reg [11:0] q2;
    reg        h2;                 // the cell's half of the word
    always @(posedge clk) begin
        if (re2)
            q2 <= mem[raddr2[6:1]];
    end
    always @(posedge clk) begin
        if (rst)
            h2 <= 1'b0;
        else if (re2)
            h2 <= raddr2[0];
    end
    assign rdata2 = h2 ? q2[11:6] : q2[5:0];
endmodule

`default_nettype wire
