// TMC428/TMC429/TMC4210 frame schedule for the RTL: the phase (prescaler[4:0]) of each motor's
// slots in the 32-cycle frame (TMC428 §8.7, §8.13; TMC429 §8.1.7; docs/model-contract.md C41).
// Generated from model/src/schedule.rs; do not edit. Regenerate with
//   tmc429 regmap --format verilog-schedule > rtl/tmc429_schedule.vh
`ifndef TMC429_SCHEDULE_VH
`define TMC429_SCHEDULE_VH

`define TMC429_PH_SNAPSHOT(m) ((m) == 0 ? 5'd0 : (m) == 1 ? 5'd7 : 5'd14) // motor m's registers into the target-velocity unit
`define TMC429_PH_COMMIT(m) ((m) == 0 ? 5'd14 : (m) == 1 ? 5'd21 : 5'd28) // motor m's target velocity committed in this edge
`define TMC429_PH_RAMP(m) ((m) == 0 ? 5'd16 : (m) == 1 ? 5'd23 : 5'd30) // motor m's ramp tick in a ramp frame
`define TMC429_PH_PULSE(m) ((m) == 0 ? 5'd17 : (m) == 1 ? 5'd24 : 5'd31) // motor m's pulse tick in a pulse frame
`define TMC429_PH_STEPDIR(m) ((m) == 0 ? 5'd19 : (m) == 1 ? 5'd26 : 5'd1) // motor m's Step/Dir slot (and 16 after it)

`endif // TMC429_SCHEDULE_VH
