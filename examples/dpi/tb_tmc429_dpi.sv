// tb_tmc429_dpi: the self-checking DPI-C example — this repository's RTL and the tmc429 golden
// model in lock-step for each variant (tmc429_dpi_lockstep), on the seeded stimulus of
// `tmc429 cosim`. Plusargs: +seed=S (default 1), +cycles=N (default 50000), +variants=MASK
// (bit c = CHIP c, default 7: all three), +profile=P (TMC429_PROFILE_*, default motion).
// Exit status 0 only with no mismatch; a mismatch prints the report of `tmc429 cosim` and
// ends the run with $fatal (status 1).
`timescale 1ns / 1ps
`default_nettype none

module tb_tmc429_dpi;
  import tmc429_pkg::*;

  logic clk = 1'b0;
  always #5 clk = ~clk;

  longint unsigned seed = 1, cycles = 50000;
  int variants = 7, profile = TMC429_PROFILE_MOTION;
  logic [2:0] done, failed;
  logic go = 1'b0;
  wire logic [2:0] vmask = variants[2:0];

  initial begin
    void'($value$plusargs("seed=%d", seed));
    void'($value$plusargs("cycles=%d", cycles));
    void'($value$plusargs("variants=%d", variants));
    void'($value$plusargs("profile=%d", profile));
    if (int'(tmc429_abi_version()) != TMC429_ABI_VERSION)
      $fatal(2, "libtmc429 has ABI %0d, tmc429_pkg.sv expects %0d", tmc429_abi_version(), TMC429_ABI_VERSION);
    go = 1'b1;
  end

  for (genvar c = 0; c < 3; c++) begin : g_chip
    tmc429_dpi_lockstep #(.CHIP(c)) u (
        .clk(clk), .start(go && variants[c]), .seed(seed), .cycles(cycles), .profile(profile),
        .done(done[c]), .failed(failed[c]));
  end

  always @(posedge clk) begin
    if (go && ((done | ~vmask) == 3'b111)) begin
      if ((failed & vmask) != 3'b000) $fatal(1, "mismatch");
      $finish;
    end
  end
endmodule

`default_nettype wire
