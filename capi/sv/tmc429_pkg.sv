// tmc429_pkg: the tmc429 golden model in a SystemVerilog testbench, through DPI-C.
//
// Imports the pin-level entry of the C library libtmc429 (capi/include/tmc429.h, "Pin level"):
// a chip handle ticked once per CLK edge with the input pins in one word, its output pins (and
// probes) out; and the seeded stimulus of `tmc429 cosim` with its check and first-mismatch
// report. Link libtmc429 into the simulation (docs/verify-your-rtl.md, docs/c-api.md).
// The constants mirror tmc429.h; capi/tests/sv_package.rs checks them and every import.
//
// Words: input bit 0..9 = nSCS_C, SCK_C, SDI_C, SDI_S, REF1, REF2, REF3, REFR1, REFR2, REFR3;
// output bit 0..10 = nINT_SDO_C, SDOZ_C, SDOZ_C enable, nSCS_S, SCK_S, SDO_S, SDI_S out,
// SDI_S enable, nSCS2, nSCS3, POSCMP.
`timescale 1ns / 1ps
package tmc429_pkg;
  // the constants of tmc429.h: a testbench uses some of them (no unused-parameter lint for the rest)
  /* verilator lint_off UNUSEDPARAM */
  localparam int TMC429_ABI_VERSION = 3;
  localparam int TMC429_OK = 0;
  localparam int TMC429_CHIP_TMC428 = 0;
  localparam int TMC429_CHIP_TMC429 = 1;
  localparam int TMC429_CHIP_TMC4210 = 2;
  localparam int TMC429_INPUT_PINS = 10;
  localparam int TMC429_OUTPUT_PINS = 11;
  localparam int TMC429_PROBE_COUNT = 37;
  localparam int TMC429_IDLE_INPUTS = 'h383;
  localparam int TMC429_PROFILE_MOTION = 0;
  localparam int TMC429_PROFILE_MOTION_CORE = 1;
  localparam int TMC429_PROFILE_DRIVERS = 2;
  localparam int TMC429_PROFILE_REGISTERS = 3;
  localparam int TMC429_PROFILE_FULL = 4;
  /* verilator lint_on UNUSEDPARAM */

  import "DPI-C" function int unsigned tmc429_abi_version();
  import "DPI-C" function string tmc429_strerror(input int code);
  import "DPI-C" function int tmc429_create(input int variant, input int unsigned fclk_hz, output longint unsigned out);
  import "DPI-C" function int tmc429_destroy(input longint unsigned h);
  import "DPI-C" function int tmc429_reset(input longint unsigned h);
  import "DPI-C" function int tmc429_events_enable(input longint unsigned h, input int on);
  import "DPI-C" function int tmc429_tick_pins(input longint unsigned h, input int unsigned inputs,
                                               output int unsigned outputs,
                                               output longint unsigned probes[TMC429_PROBE_COUNT]);
  import "DPI-C" function int tmc429_output_word(input longint unsigned h, output int unsigned outputs);
  import "DPI-C" function string tmc429_probe_name(input int unsigned index);
  import "DPI-C" function int tmc429_stim_create(input int variant, input int profile, input longint unsigned seed,
                                                 output longint unsigned out);
  import "DPI-C" function int tmc429_stim_destroy(input longint unsigned h);
  import "DPI-C" function int tmc429_stim_next(input longint unsigned h, input int unsigned model_outputs,
                                               input int unsigned dut_outputs, output int unsigned inputs);
  import "DPI-C" function int tmc429_stim_check(input longint unsigned h, input int unsigned model_outputs,
                                                input int unsigned dut_outputs);
  import "DPI-C" function int tmc429_stim_counts(input longint unsigned h, output longint unsigned cycles,
                                                 output longint unsigned frames, output longint unsigned pin_changes);
  import "DPI-C" function string tmc429_stim_report(input longint unsigned h, input string label);
endpackage
