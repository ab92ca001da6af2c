// tmc429_drvpins: the driver-side output pins and the 74HC157 switch sampling
// (docs/model-contract.md C81, C87, C90-C93; TMC428 §9.7, TMC429 §8.2.4, §10; TMC4210).
//
// Every pin is a register loaded from the new state of each edge (C1): the chain's and the
// Step/Dir units' next levels and the next values of the configuration bits. The chain's
// next CS/SCK/motor are given as the levels without a start plus `take` (a start: CS
// active, SCK high, motor 0).
//   SPI mode (TMC428; TMC429 en_sd = 0): nSCS_S = !cs XOR polarity_nscs_s, SCK_S = sck XOR
//     polarity_sck_s, SDO_S = sdo, nSCS2 = nSCS3 = 1; csCommonIndividual = 1: nSCS_S, nSCS2,
//     nSCS3 = !cs of motors 0, 1, 2 (low active, polarity ignored) (C81).
//   TMC429 Step/Dir (en_sd = 1): S1 = SDO_S, D1 = SCK_S, S2 = nSCS_S, D2 = SDI_S (driven),
//     S3 = nSCS2, D3 = nSCS3; STEP XOR inv_stp, DIR XOR inv_dir (C91, C93).
//   TMC4210: STEP = SDO_S, DIR = SCK_S, both 1 until en_sd = 1 (C92); nSCS_S/nSCS2/nSCS3 = 1,
//     SDI_S not driven (C90).
// refmux = 1 in SPI mode (C87): at an edge where the nSCS_S pin rises the synchronized
// REF1..3 (after inv_ref) are stored as the left switches, where it falls as the right ones
// (the 74HC157 presents the left switches while nSCS_S is high, the right ones while low).
// The sample is applied one edge late from registers (the pin before and after the edge,
// REF and the enable of that edge) and `mux_sw` shows it in the meantime through a
// multiplexer, so it reads exactly as if stored in that edge while the pin's next level
// does not reach a switch register in one cycle.
`timescale 1ns / 1ps
`default_nettype none

module tmc429_drvpins #(
    parameter CHIP = 1
) (
    input  wire       clk,
    input  wire       rst,
    // new state (`_pre_nx`: the chain's next level before a start overrides it)
    input  wire       spi_nx,         // SPI mode
    input  wire       sd_nx,          // Step/Dir mode (TMC4210: en_sd)
    input  wire       take,           // chain: a datagram starts (CS active, SCK high, motor 0)
    input  wire       cs_pre_nx,      // chain: chip select active, unless a datagram starts
    input  wire       sck_pre_nx,     // chain: SCK_S before polarity, unless one starts
    input  wire       sdo_nx,         // chain: SDO_S
    input  wire [1:0] motor_pre_nx,   // chain: motor of the current bit, unless one starts
    input  wire [2:0] step_nx,        // Step/Dir: STEP levels of motors 2..0 before inv_stp
    input  wire [2:0] dir_nx,         // Step/Dir: DIR levels before inv_dir
    input  wire       pol_nscs_s,
    input  wire       pol_sck_s,
    input  wire       cs_com_ind,
    input  wire       refmux,
    input  wire       inv_ref,
    input  wire       inv_stp,
    input  wire       inv_dir,
    // synchronized REF3..REF1 of the old state
    input  wire [2:0] ref_q,
    // pins
    output reg        nscs_s,
    output reg        sck_s,
    output reg        sdo_s,
    output reg        sdi_s_o,
    output reg        sdi_s_oe,
    output reg        nscs2,
    output reg        nscs3,
    // switches sampled through the 74HC157: bit 2m = R(m+1), bit 2m+1 = L(m+1)
    output wire [5:0] mux_sw
);
    // ---- pin levels of the new state ---------------------------------------------------------
    reg p_nscs_s, p_sck_s, p_sdo_s, p_sdi_s_o, p_sdi_s_oe, p_nscs2, p_nscs3;
    wire [2:0] st = step_nx ^ {3{inv_stp}};
    wire [2:0] dr = dir_nx ^ {3{inv_dir}};
    wire       spi = (CHIP == 0) | ((CHIP == 1) & spi_nx);

    always @(*) begin
        p_sdi_s_o = 1'b0;  p_sdi_s_oe = 1'b0;
        if (spi) begin
            // the levels without a start, then the start (take) selects: it comes last, so
            // the chain's request -> start path ends one LUT before the pin register
            p_sck_s = (sck_pre_nx | take) ^ pol_sck_s;
            p_sdo_s = sdo_nx;
            if (cs_com_ind) begin
                p_nscs_s = ~take & ~(cs_pre_nx & (motor_pre_nx == 2'd0));
                p_nscs2  = take | ~(cs_pre_nx & (motor_pre_nx == 2'd1));
                p_nscs3  = take | ~(cs_pre_nx & motor_pre_nx[1]);
            end else begin
                p_nscs_s = take ? pol_nscs_s : (~cs_pre_nx ^ pol_nscs_s);
                p_nscs2  = 1'b1;
                p_nscs3  = 1'b1;
            end
        end else if (CHIP == 1) begin
            p_sdo_s    = st[0];  p_sck_s = dr[0];
            p_nscs_s   = st[1];  p_sdi_s_o = dr[1];  p_sdi_s_oe = 1'b1;
            p_nscs2    = st[2];  p_nscs3 = dr[2];
        end else begin
            // TMC4210 (C92): STEP and DIR high until en_sd = 1
            p_sdo_s  = sd_nx ? st[0] : 1'b1;
            p_sck_s  = sd_nx ? dr[0] : 1'b1;
            p_nscs_s = 1'b1;  p_nscs2 = 1'b1;  p_nscs3 = 1'b1;
        end
    end

    wire [2:0] ref_i = ref_q ^ {3{inv_ref & (CHIP != 0)}};

    // the sample of the last edge (C87): the pin changed in it while refmux was on
    reg        nscs_prev, smp_en;
    reg  [2:0] smp_ref;
    reg  [5:0] mux_sw_r;
    wire       smp  = smp_en & (nscs_s != nscs_prev);
    assign mux_sw = ~smp ? mux_sw_r
                  : (nscs_prev ? {smp_ref[2], mux_sw_r[4], smp_ref[1], mux_sw_r[2], smp_ref[0], mux_sw_r[0]}
                               : {mux_sw_r[5], smp_ref[2], mux_sw_r[3], smp_ref[1], mux_sw_r[1], smp_ref[0]});

    always @(posedge clk) begin
        if (rst) begin
            nscs_s <= 1'b1;  sck_s <= 1'b1;  sdo_s <= 1'b1;
            sdi_s_o <= 1'b0;  sdi_s_oe <= 1'b0;  nscs2 <= 1'b1;  nscs3 <= 1'b1;
            nscs_prev <= 1'b1;  smp_en <= 1'b0;  smp_ref <= 3'd0;  mux_sw_r <= 6'd0;
        end else begin
            nscs_s <= p_nscs_s;  sck_s <= p_sck_s;  sdo_s <= p_sdo_s;
            sdi_s_o <= p_sdi_s_o;  sdi_s_oe <= p_sdi_s_oe;  nscs2 <= p_nscs2;  nscs3 <= p_nscs3;
            // at an edge where the pin changes: a high pin presented the left switches
            nscs_prev <= nscs_s;
            smp_en    <= spi & refmux;
            smp_ref   <= ref_i;
            mux_sw_r  <= mux_sw;
        end
    end
endmodule

`default_nettype wire
