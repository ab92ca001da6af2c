// tmc429_dpi_lockstep: one design under test (this repository's tmc429_chip) and the golden
// model beside it through DPI-C (capi/sv/tmc429_pkg.sv), on the seeded stimulus of
// `tmc429 cosim`; every output pin compared after every CLK edge.
//
// Timing (docs/verify-your-rtl.md): at each falling CLK edge the outputs of the last rising
// edge are compared and the inputs of the next rising edge applied (C1), so no input changes
// with a rising edge. Reset: rst high for 2 rising edges with the idle inputs, then the reset
// states are compared (cycle 0) before the first edge (C2).
`timescale 1ns / 1ps
`default_nettype none

module tmc429_dpi_lockstep #(
    parameter int CHIP = 1
) (
    input  wire             clk,
    input  wire             start,
    input  longint unsigned seed,
    input  longint unsigned cycles,
    input  int              profile,
    output logic            done,
    output logic            failed
);
  import tmc429_pkg::*;

  logic rst = 1'b1;
  logic [9:0] pins_in = 10'(TMC429_IDLE_INPUTS);
  wire [10:0] pins_out;

  // A variant not started gets no clock edges and costs no simulation time.
  wire dut_clk = clk & start;

  tmc429_chip #(.CHIP(CHIP)) dut (
      .clk(dut_clk), .rst(rst),
      .nscs_c(pins_in[0]), .sck_c(pins_in[1]), .sdi_c(pins_in[2]), .sdi_s(pins_in[3]),
      .ref1(pins_in[4]), .ref2(pins_in[5]), .ref3(pins_in[6]),
      .refr1(pins_in[7]), .refr2(pins_in[8]), .refr3(pins_in[9]),
      .nint_sdo_c(pins_out[0]), .sdoz_c(pins_out[1]), .sdoz_c_oe(pins_out[2]),
      .nscs_s(pins_out[3]), .sck_s(pins_out[4]), .sdo_s(pins_out[5]),
      .sdi_s_o(pins_out[6]), .sdi_s_oe(pins_out[7]), .nscs2(pins_out[8]), .nscs3(pins_out[9]),
      .poscmp(pins_out[10]));

  localparam string VARIANT = CHIP == 0 ? "tmc428" : CHIP == 1 ? "tmc429" : "tmc4210";
  string label = $sformatf("tmc429_chip CHIP=%0d, dpi", CHIP);
  longint unsigned chip_h, stim_h, probes[TMC429_PROBE_COUNT];
  int unsigned model_out, next_in;
  longint unsigned n;
  int resets;

  // A call that fails is a broken setup, not a mismatch (the name is made only then).
  `define TMC429_OK(call) \
    begin \
      automatic int code = call; \
      if (code < 0) $fatal(2, "%s: %s", `"call`", tmc429_strerror(code)); \
    end

  initial begin
    done = 1'b0;
    failed = 1'b0;
    resets = 0;
    n = 0;
  end

  always @(negedge clk) begin
    if (start && !done) begin
      if (resets == 0) begin
        `TMC429_OK(tmc429_create(CHIP, 0, chip_h))
        `TMC429_OK(tmc429_events_enable(chip_h, 0))
        `TMC429_OK(tmc429_stim_create(CHIP, profile, seed, stim_h))
        `TMC429_OK(tmc429_output_word(chip_h, model_out))
        resets = 1;
      end else if (resets < 3) begin
        resets = resets + 1;  // rst has been high for one more rising edge
        if (resets == 3) begin
          rst <= 1'b0;
          step();
        end
      end else begin
        n = n + 1;
        step();
      end
    end
  end

  // The outputs after the last rising edge against the model's; then the next edge's inputs.
  task automatic step();
    int unsigned dut_out = {21'b0, pins_out};
    int r = tmc429_stim_check(stim_h, model_out, dut_out);
    if (r < 0) $fatal(2, "tmc429_stim_check: %s", tmc429_strerror(r));
    if (r != 0) begin
      $write("%s", tmc429_stim_report(stim_h, label));
      finish(1'b1);
    end else if (n == cycles) begin
      finish(1'b0);
    end else begin
      `TMC429_OK(tmc429_stim_next(stim_h, model_out, dut_out, next_in))
      `TMC429_OK(tmc429_tick_pins(chip_h, next_in, model_out, probes))
      pins_in <= next_in[9:0];
    end
  endtask

  task automatic finish(bit mismatch);
    longint unsigned c, f, p;
    `TMC429_OK(tmc429_stim_counts(stim_h, c, f, p))
    $display("dpi %s (%s): seed %0d", label, VARIANT, seed);
    $display("cycles:       %0d", c);
    $display("transactions: %0d SPI frames, %0d pin changes", f, p);
    $display("mismatches:   %0d", mismatch);
    `TMC429_OK(tmc429_stim_destroy(stim_h))
    `TMC429_OK(tmc429_destroy(chip_h))
    failed <= mismatch;
    done <= 1'b1;
  endtask
  `undef TMC429_OK
endmodule

`default_nettype wire
