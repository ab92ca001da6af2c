// TMC428/TMC429/TMC4210 register map for the RTL (TMC428 Table 7-2, §8-§10; TMC429 §8; TMC4210 §5).
// Generated from model/src/regmap.rs; do not edit. Regenerate with
//   tmc429 regmap --format verilog > rtl/tmc429_regmap.vh
// Names: TMC429_IDX_* / TMC429_JDX_* / TMC429_ADDR_* index of a motor register, a global register,
// the first RAM word; TMC429_CHIPS_* the variants that have it (bit CHIP); TMC429_RESET_* its
// power-on read value; TMC429_WMASK_* the bits a write stores (TMC4210_*: that variant's own
// layout). TMC429_F_* a field's bits (msb:lsb, or the bit), with _LSB, _MSB and _W.
`ifndef TMC429_REGMAP_VH
`define TMC429_REGMAP_VH

// ---- the datagram (TMC428 §6.2, §7.1): {A7, RW, data}; A7 = {RRS, SMDA, IDX} --------
`define TMC429_DG_A7 31:25                       // address A7
`define TMC429_DG_RW 24                          // 1: read
`define TMC429_DG_DATA 23:0                      // data word
`define TMC429_A7_RRS 6                          // 1: RAM word (ADDR in TMC429_A7_ADDR)
`define TMC429_A7_SMDA 5:4                       // motor 0..2, or TMC429_SMDA_GLOBAL
`define TMC429_A7_IDX 3:0                        // IDX of a motor register, JDX of a global one
`define TMC429_A7_REG 5:0                        // {SMDA, IDX}: one of the 64 register addresses
`define TMC429_A7_ADDR 5:0                       // ADDR of a RAM word
`define TMC429_SMDA_GLOBAL 2'd3                  // SMDA of the global registers

// ---- the variants (CHIP 0 TMC428, 1 TMC429, 2 TMC4210); a register a variant lacks reads 0
//      and ignores writes (contract C21) ---------------------------------------------------
`define TMC429_HAS(chips, chip) ((((chips) >> (chip)) & 3'd1) != 3'd0) // a TMC429_CHIPS_* set holds CHIP
`define TMC429_MOTORS(chip) ((chip) == 0 ? 3 : (chip) == 1 ? 3 : 1) // motors (SMDA 0..)
`define TMC429_IDX_PRESENT(chip) ((chip) == 0 ? 16'h7FFF : (chip) == 1 ? 16'hFFFF : 16'hFEFF) // bit IDX: the variant has it
`define TMC429_JDX_PRESENT(chip) ((chip) == 0 ? 16'hC10F : (chip) == 1 ? 16'hC37F : 16'hC370) // bit JDX: the variant has it

// x_target — TMC428 §8.1 (TMC428, TMC429, TMC4210)
`define TMC429_IDX_X_TARGET 4'd0
`define TMC429_CHIPS_X_TARGET 3'b111
`define TMC429_RESET_X_TARGET 24'h000000
`define TMC429_WMASK_X_TARGET 24'hFFFFFF
`define TMC429_F_X_TARGET 23:0                   // target position
`define TMC429_F_X_TARGET_LSB 0
`define TMC429_F_X_TARGET_MSB 23
`define TMC429_F_X_TARGET_W 24

// x_actual — TMC428 §8.2 (TMC428, TMC429, TMC4210)
`define TMC429_IDX_X_ACTUAL 4'd1
`define TMC429_CHIPS_X_ACTUAL 3'b111
`define TMC429_RESET_X_ACTUAL 24'h000000
`define TMC429_WMASK_X_ACTUAL 24'hFFFFFF
`define TMC429_F_X_ACTUAL 23:0                   // actual position
`define TMC429_F_X_ACTUAL_LSB 0
`define TMC429_F_X_ACTUAL_MSB 23
`define TMC429_F_X_ACTUAL_W 24

// v_min — TMC428 §8.3 (TMC428, TMC429, TMC4210)
`define TMC429_IDX_V_MIN 4'd2
`define TMC429_CHIPS_V_MIN 3'b111
`define TMC429_RESET_V_MIN 24'h000000
`define TMC429_WMASK_V_MIN 24'h0007FF
`define TMC429_F_V_MIN 10:0                      // minimum velocity (RAMP, SOFT)
`define TMC429_F_V_MIN_LSB 0
`define TMC429_F_V_MIN_MSB 10
`define TMC429_F_V_MIN_W 11

// v_max — TMC428 §8.4 (TMC428, TMC429, TMC4210)
`define TMC429_IDX_V_MAX 4'd3
`define TMC429_CHIPS_V_MAX 3'b111
`define TMC429_RESET_V_MAX 24'h000000
`define TMC429_WMASK_V_MAX 24'h0007FF
`define TMC429_F_V_MAX 10:0                      // maximum velocity
`define TMC429_F_V_MAX_LSB 0
`define TMC429_F_V_MAX_MSB 10
`define TMC429_F_V_MAX_W 11

// v_target — TMC428 §8.5 (TMC428, TMC429, TMC4210)
`define TMC429_IDX_V_TARGET 4'd4
`define TMC429_CHIPS_V_TARGET 3'b111
`define TMC429_RESET_V_TARGET 24'h000000
`define TMC429_WMASK_V_TARGET 24'h000FFF
`define TMC429_F_V_TARGET 11:0                   // target velocity (VELOCITY mode input; computed in RAMP, SOFT)
`define TMC429_F_V_TARGET_LSB 0
`define TMC429_F_V_TARGET_MSB 11
`define TMC429_F_V_TARGET_W 12

// v_actual — TMC428 §8.6 (TMC428, TMC429, TMC4210)
`define TMC429_IDX_V_ACTUAL 4'd5
`define TMC429_CHIPS_V_ACTUAL 3'b111
`define TMC429_RESET_V_ACTUAL 24'h000000
`define TMC429_WMASK_V_ACTUAL 24'h000FFF
`define TMC429_F_V_ACTUAL 11:0                   // actual velocity: sign and 11 MSBs of the internal velocity
`define TMC429_F_V_ACTUAL_LSB 0
`define TMC429_F_V_ACTUAL_MSB 11
`define TMC429_F_V_ACTUAL_W 12

// a_max — TMC428 §8.7 (TMC428, TMC429, TMC4210)
`define TMC429_IDX_A_MAX 4'd6
`define TMC429_CHIPS_A_MAX 3'b111
`define TMC429_RESET_A_MAX 24'h000000
`define TMC429_WMASK_A_MAX 24'h0007FF
`define TMC429_F_A_MAX 10:0                      // maximum acceleration
`define TMC429_F_A_MAX_LSB 0
`define TMC429_F_A_MAX_MSB 10
`define TMC429_F_A_MAX_W 11

// a_actual — TMC428 §8.8 (TMC428, TMC429, TMC4210)
`define TMC429_IDX_A_ACTUAL 4'd7
`define TMC429_CHIPS_A_ACTUAL 3'b111
`define TMC429_RESET_A_ACTUAL 24'h000000
`define TMC429_WMASK_A_ACTUAL 24'h000000
`define TMC429_F_A_ACTUAL 11:0                   // velocity change of the last ramp tick
`define TMC429_F_A_ACTUAL_LSB 0
`define TMC429_F_A_ACTUAL_MSB 11
`define TMC429_F_A_ACTUAL_W 12

// current_scaling — TMC428 §8.9 (TMC428, TMC429)
`define TMC429_IDX_CURRENT_SCALING 4'd8
`define TMC429_CHIPS_CURRENT_SCALING 3'b011
`define TMC429_RESET_CURRENT_SCALING 24'h000000
`define TMC429_WMASK_CURRENT_SCALING 24'h7777FF
`define TMC429_F_IS_AGTAT 22:20                  // current scale while |a| > a_threshold
`define TMC429_F_IS_AGTAT_LSB 20
`define TMC429_F_IS_AGTAT_MSB 22
`define TMC429_F_IS_AGTAT_W 3
`define TMC429_F_IS_ALEAT 18:16                  // current scale while |a| <= a_threshold
`define TMC429_F_IS_ALEAT_LSB 16
`define TMC429_F_IS_ALEAT_MSB 18
`define TMC429_F_IS_ALEAT_W 3
`define TMC429_F_IS_V0 14:12                     // current scale at rest
`define TMC429_F_IS_V0_LSB 12
`define TMC429_F_IS_V0_MSB 14
`define TMC429_F_IS_V0_W 3
`define TMC429_F_A_THRESHOLD 10:0                // acceleration threshold of current scaling
`define TMC429_F_A_THRESHOLD_LSB 0
`define TMC429_F_A_THRESHOLD_MSB 10
`define TMC429_F_A_THRESHOLD_W 11

// pmul_pdiv — TMC428 §8.10 (TMC428, TMC429, TMC4210)
`define TMC429_IDX_PMUL_PDIV 4'd9
`define TMC429_CHIPS_PMUL_PDIV 3'b111
`define TMC429_RESET_PMUL_PDIV 24'h008000
`define TMC429_WMASK_PMUL_PDIV 24'h00FF0F
`define TMC429_F_PMUL 15:8                       // p_mul = 128 + bits 14..8; bit 15 reads 1
`define TMC429_F_PMUL_LSB 8
`define TMC429_F_PMUL_MSB 15
`define TMC429_F_PMUL_W 8
`define TMC429_F_PDIV 3:0                        // p_div exponent (valid 0..13)
`define TMC429_F_PDIV_LSB 0
`define TMC429_F_PDIV_MSB 3
`define TMC429_F_PDIV_W 4

// ref_conf_rm — TMC428 §8.11, §8.12 (TMC428, TMC429, TMC4210)
`define TMC429_IDX_REF_CONF_RM 4'd10
`define TMC429_CHIPS_REF_CONF_RM 3'b111
`define TMC429_RESET_REF_CONF_RM 24'h000000
`define TMC429_WMASK_REF_CONF_RM 24'h000F03
`define TMC429_F_LP 16                           // latch pending
`define TMC429_F_LP_LSB 16
`define TMC429_F_LP_MSB 16
`define TMC429_F_LP_W 1
`define TMC429_F_REF_RNL 11                      // 1: right switch is the reference switch
`define TMC429_F_REF_RNL_LSB 11
`define TMC429_F_REF_RNL_MSB 11
`define TMC429_F_REF_RNL_W 1
`define TMC429_F_SOFT_STOP 10                    // 1: switch stop with a linear ramp
`define TMC429_F_SOFT_STOP_LSB 10
`define TMC429_F_SOFT_STOP_MSB 10
`define TMC429_F_SOFT_STOP_W 1
`define TMC429_F_DISABLE_STOP_R 9                // 1: right switch does not stop
`define TMC429_F_DISABLE_STOP_R_LSB 9
`define TMC429_F_DISABLE_STOP_R_MSB 9
`define TMC429_F_DISABLE_STOP_R_W 1
`define TMC429_F_DISABLE_STOP_L 8                // 1: left switch does not stop
`define TMC429_F_DISABLE_STOP_L_LSB 8
`define TMC429_F_DISABLE_STOP_L_MSB 8
`define TMC429_F_DISABLE_STOP_L_W 1
`define TMC429_F_RM 1:0                          // ramp mode: 0 RAMP, 1 SOFT, 2 VELOCITY, 3 HOLD
`define TMC429_F_RM_LSB 0
`define TMC429_F_RM_MSB 1
`define TMC429_F_RM_W 2

// interrupt — TMC428 §8.13 (TMC428, TMC429, TMC4210)
`define TMC429_IDX_INTERRUPT 4'd11
`define TMC429_CHIPS_INTERRUPT 3'b111
`define TMC429_RESET_INTERRUPT 24'h000000
`define TMC429_WMASK_INTERRUPT 24'h00FF00
`define TMC429_F_INTERRUPT_MASK 15:8             // interrupt mask
`define TMC429_F_INTERRUPT_MASK_LSB 8
`define TMC429_F_INTERRUPT_MASK_MSB 15
`define TMC429_F_INTERRUPT_MASK_W 8
`define TMC429_F_INTERRUPT_FLAGS 7:0             // interrupt flags (write 1 to clear)
`define TMC429_F_INTERRUPT_FLAGS_LSB 0
`define TMC429_F_INTERRUPT_FLAGS_MSB 7
`define TMC429_F_INTERRUPT_FLAGS_W 8

// clk_config — TMC428 §8.14, §8.15 (TMC428, TMC429, TMC4210)
`define TMC429_IDX_CLK_CONFIG 4'd12
`define TMC429_CHIPS_CLK_CONFIG 3'b111
`define TMC429_RESET_CLK_CONFIG 24'h000000
`define TMC429_WMASK_CLK_CONFIG 24'h00FF07
`define TMC429_F_PULSE_DIV 15:12                 // pulse clock divider exponent
`define TMC429_F_PULSE_DIV_LSB 12
`define TMC429_F_PULSE_DIV_MSB 15
`define TMC429_F_PULSE_DIV_W 4
`define TMC429_F_RAMP_DIV 11:8                   // ramp clock divider exponent
`define TMC429_F_RAMP_DIV_LSB 8
`define TMC429_F_RAMP_DIV_MSB 11
`define TMC429_F_RAMP_DIV_W 4
`define TMC429_F_USRS 2:0                        // microstep resolution: 2^usrs per full step
`define TMC429_F_USRS_LSB 0
`define TMC429_F_USRS_MSB 2
`define TMC429_F_USRS_W 3

// dx_ref_tolerance — TMC428 §8.15 (TMC428, TMC429, TMC4210)
`define TMC429_IDX_DX_REF_TOLERANCE 4'd13
`define TMC429_CHIPS_DX_REF_TOLERANCE 3'b111
`define TMC429_RESET_DX_REF_TOLERANCE 24'h000000
`define TMC429_WMASK_DX_REF_TOLERANCE 24'h000FFF
`define TMC429_F_DX_REF_TOLERANCE 11:0           // reference switch tolerance window
`define TMC429_F_DX_REF_TOLERANCE_LSB 0
`define TMC429_F_DX_REF_TOLERANCE_MSB 11
`define TMC429_F_DX_REF_TOLERANCE_W 12

// x_latched — TMC428 §8.16 (TMC428, TMC429, TMC4210)
`define TMC429_IDX_X_LATCHED 4'd14
`define TMC429_CHIPS_X_LATCHED 3'b111
`define TMC429_RESET_X_LATCHED 24'h000000
`define TMC429_WMASK_X_LATCHED 24'h000000
`define TMC429_F_X_LATCHED 23:0                  // latched position; a write arms the latch
`define TMC429_F_X_LATCHED_LSB 0
`define TMC429_F_X_LATCHED_MSB 23
`define TMC429_F_X_LATCHED_W 24

// ustep_count — TMC429 §8.1.16 (TMC429, TMC4210)
`define TMC429_IDX_USTEP_COUNT 4'd15
`define TMC429_CHIPS_USTEP_COUNT 3'b110
`define TMC429_RESET_USTEP_COUNT 24'h000000
`define TMC429_WMASK_USTEP_COUNT 24'h0000FF
`define TMC429_F_USTEP_COUNT 7:0                 // full-wave microstep index
`define TMC429_F_USTEP_COUNT_LSB 0
`define TMC429_F_USTEP_COUNT_MSB 7
`define TMC429_F_USTEP_COUNT_W 8

// datagram_low_word — TMC428 §9.1 (TMC428, TMC429)
`define TMC429_JDX_DATAGRAM_LOW_WORD 4'd0
`define TMC429_CHIPS_DATAGRAM_LOW_WORD 3'b011
`define TMC429_RESET_DATAGRAM_LOW_WORD 24'h000000
`define TMC429_WMASK_DATAGRAM_LOW_WORD 24'h000000
`define TMC429_F_DATAGRAM_LOW_WORD 23:0          // bits 23..0 of the driver-chain readback; a write arms CDGW
`define TMC429_F_DATAGRAM_LOW_WORD_LSB 0
`define TMC429_F_DATAGRAM_LOW_WORD_MSB 23
`define TMC429_F_DATAGRAM_LOW_WORD_W 24

// datagram_high_word — TMC428 §9.1 (TMC428, TMC429)
`define TMC429_JDX_DATAGRAM_HIGH_WORD 4'd1
`define TMC429_CHIPS_DATAGRAM_HIGH_WORD 3'b011
`define TMC429_RESET_DATAGRAM_HIGH_WORD 24'h000000
`define TMC429_WMASK_DATAGRAM_HIGH_WORD 24'h000000
`define TMC429_F_DATAGRAM_HIGH_WORD 23:0         // bits 47..24 of the driver-chain readback; a write arms CDGW
`define TMC429_F_DATAGRAM_HIGH_WORD_LSB 0
`define TMC429_F_DATAGRAM_HIGH_WORD_MSB 23
`define TMC429_F_DATAGRAM_HIGH_WORD_W 24

// cover_pos_len — TMC428 §9.2 (TMC428, TMC429)
`define TMC429_JDX_COVER_POS_LEN 4'd2
`define TMC429_CHIPS_COVER_POS_LEN 3'b011
`define TMC429_RESET_COVER_POS_LEN 24'h000000
`define TMC429_WMASK_COVER_POS_LEN 24'h003F1F
`define TMC429_F_CW 23                           // cover datagram waiting
`define TMC429_F_CW_LSB 23
`define TMC429_F_CW_MSB 23
`define TMC429_F_CW_W 1
`define TMC429_F_COVER_POS 13:8                  // first bit position of the cover datagram (reads back +1)
`define TMC429_F_COVER_POS_LSB 8
`define TMC429_F_COVER_POS_MSB 13
`define TMC429_F_COVER_POS_W 6
`define TMC429_F_COVER_LEN 4:0                   // cover datagram length (0..24)
`define TMC429_F_COVER_LEN_LSB 0
`define TMC429_F_COVER_LEN_MSB 4
`define TMC429_F_COVER_LEN_W 5

// cover_datagram — TMC428 §9.3 (TMC428, TMC429)
`define TMC429_JDX_COVER_DATAGRAM 4'd3
`define TMC429_CHIPS_COVER_DATAGRAM 3'b011
`define TMC429_RESET_COVER_DATAGRAM 24'h000000
`define TMC429_WMASK_COVER_DATAGRAM 24'hFFFFFF
`define TMC429_F_COVER_DATAGRAM 23:0             // cover datagram; a write requests it
`define TMC429_F_COVER_DATAGRAM_LSB 0
`define TMC429_F_COVER_DATAGRAM_MSB 23
`define TMC429_F_COVER_DATAGRAM_W 24

// if_configuration — TMC429 §8.2.4 (TMC429, TMC4210)
`define TMC429_JDX_IF_CONFIGURATION 4'd4
`define TMC429_CHIPS_IF_CONFIGURATION 3'b110
`define TMC429_RESET_IF_CONFIGURATION 24'h000000
`define TMC429_WMASK_IF_CONFIGURATION 24'h0001FF
`define TMC429_F_INV_REF 0                       // invert all reference inputs
`define TMC429_F_INV_REF_LSB 0
`define TMC429_F_INV_REF_MSB 0
`define TMC429_F_INV_REF_W 1
`define TMC429_F_SDO_INT 1                       // nINT_SDO_C is a plain nINT output
`define TMC429_F_SDO_INT_LSB 1
`define TMC429_F_SDO_INT_MSB 1
`define TMC429_F_SDO_INT_W 1
`define TMC429_F_STEP_HALF 2                     // STEP toggles once per step
`define TMC429_F_STEP_HALF_LSB 2
`define TMC429_F_STEP_HALF_MSB 2
`define TMC429_F_STEP_HALF_W 1
`define TMC429_F_INV_STP 3                       // invert STEP
`define TMC429_F_INV_STP_LSB 3
`define TMC429_F_INV_STP_MSB 3
`define TMC429_F_INV_STP_W 1
`define TMC429_F_INV_DIR 4                       // invert DIR
`define TMC429_F_INV_DIR_LSB 4
`define TMC429_F_INV_DIR_MSB 4
`define TMC429_F_INV_DIR_W 1
`define TMC429_F_EN_SD 5                         // Step/Dir mode
`define TMC429_F_EN_SD_LSB 5
`define TMC429_F_EN_SD_MSB 5
`define TMC429_F_EN_SD_W 1
`define TMC429_F_POS_COMP_SEL 7:6                // motor compared with pos_comp
`define TMC429_F_POS_COMP_SEL_LSB 6
`define TMC429_F_POS_COMP_SEL_MSB 7
`define TMC429_F_POS_COMP_SEL_W 2
`define TMC429_F_EN_REFR 8                       // enable REFR1..3
`define TMC429_F_EN_REFR_LSB 8
`define TMC429_F_EN_REFR_MSB 8
`define TMC429_F_EN_REFR_W 1

// pos_comp — TMC429 §8.2.4.1 (TMC429, TMC4210)
`define TMC429_JDX_POS_COMP 4'd5
`define TMC429_CHIPS_POS_COMP 3'b110
`define TMC429_RESET_POS_COMP 24'h000000
`define TMC429_WMASK_POS_COMP 24'hFFFFFF
`define TMC429_F_POS_COMP 23:0                   // position compared with x_actual of the selected motor
`define TMC429_F_POS_COMP_LSB 0
`define TMC429_F_POS_COMP_MSB 23
`define TMC429_F_POS_COMP_W 24

// pos_comp_int — TMC429 §8.2.4.2 (TMC429, TMC4210)
`define TMC429_JDX_POS_COMP_INT 4'd6
`define TMC429_CHIPS_POS_COMP_INT 3'b110
`define TMC429_RESET_POS_COMP_INT 24'h000000
`define TMC429_WMASK_POS_COMP_INT 24'h000100
`define TMC429_F_POS_COMP_INT_M 8                // position compare interrupt mask
`define TMC429_F_POS_COMP_INT_M_LSB 8
`define TMC429_F_POS_COMP_INT_M_MSB 8
`define TMC429_F_POS_COMP_INT_M_W 1
`define TMC429_F_POS_COMP_INT_I 0                // position compare interrupt flag
`define TMC429_F_POS_COMP_INT_I_LSB 0
`define TMC429_F_POS_COMP_INT_I_MSB 0
`define TMC429_F_POS_COMP_INT_I_W 1

// power_down — TMC428 §9.5 (TMC428, TMC429, TMC4210)
`define TMC429_JDX_POWER_DOWN 4'd8
`define TMC429_CHIPS_POWER_DOWN 3'b111
`define TMC429_RESET_POWER_DOWN 24'h000000
`define TMC429_WMASK_POWER_DOWN 24'h000000
`define TMC429_F_POWER_DOWN 23:0                 // a write powers down until nSCS_C falls
`define TMC429_F_POWER_DOWN_LSB 0
`define TMC429_F_POWER_DOWN_MSB 23
`define TMC429_F_POWER_DOWN_W 24

// type_version — TMC429 §8.2.4.4 (TMC429, TMC4210)
`define TMC429_JDX_TYPE_VERSION 4'd9
`define TMC429_CHIPS_TYPE_VERSION 3'b110
`define TMC429_RESET_TYPE_VERSION 24'h429101
`define TMC429_WMASK_TYPE_VERSION 24'h000000
`define TMC429_F_TYPE_VERSION 23:0               // $429101
`define TMC429_F_TYPE_VERSION_LSB 0
`define TMC429_F_TYPE_VERSION_MSB 23
`define TMC429_F_TYPE_VERSION_W 24

// ref_switches — TMC428 §9.6, TMC429 §8.2.4.5 (TMC428, TMC429, TMC4210)
`define TMC429_JDX_REF_SWITCHES 4'd14
`define TMC429_CHIPS_REF_SWITCHES 3'b111
`define TMC429_RESET_REF_SWITCHES 24'h000000
`define TMC429_WMASK_REF_SWITCHES 24'h000000
`define TMC429_F_R1 0                            // right switch motor 1 (TMC4210: REF_R)
`define TMC429_F_R1_LSB 0
`define TMC429_F_R1_MSB 0
`define TMC429_F_R1_W 1
`define TMC429_F_L1 1                            // left switch motor 1 (TMC4210: REF_L)
`define TMC429_F_L1_LSB 1
`define TMC429_F_L1_MSB 1
`define TMC429_F_L1_W 1
`define TMC429_F_R2 2                            // right switch motor 2
`define TMC429_F_R2_LSB 2
`define TMC429_F_R2_MSB 2
`define TMC429_F_R2_W 1
`define TMC429_F_L2 3                            // left switch motor 2 (TMC4210: GP_IN)
`define TMC429_F_L2_LSB 3
`define TMC429_F_L2_MSB 3
`define TMC429_F_L2_W 1
`define TMC429_F_R3 4                            // right switch motor 3
`define TMC429_F_R3_LSB 4
`define TMC429_F_R3_MSB 4
`define TMC429_F_R3_W 1
`define TMC429_F_L3 5                            // left switch motor 3
`define TMC429_F_L3_LSB 5
`define TMC429_F_L3_MSB 5
`define TMC429_F_L3_W 1

// global_parameters — TMC428 §9.7, TMC429 §8.2.5 (TMC428, TMC429)
`define TMC429_JDX_GLOBAL_PARAMETERS 4'd15
`define TMC429_CHIPS_GLOBAL_PARAMETERS 3'b011
`define TMC429_RESET_GLOBAL_PARAMETERS 24'h000F00
`define TMC429_WMASK_GLOBAL_PARAMETERS 24'h31FFFF
`define TMC429_F_LSMD 1:0                        // last stepper motor driver (0..2)
`define TMC429_F_LSMD_LSB 0
`define TMC429_F_LSMD_MSB 1
`define TMC429_F_LSMD_W 2
`define TMC429_F_POLARITY_NSCS_S 2               // nSCS_S high active
`define TMC429_F_POLARITY_NSCS_S_LSB 2
`define TMC429_F_POLARITY_NSCS_S_MSB 2
`define TMC429_F_POLARITY_NSCS_S_W 1
`define TMC429_F_POLARITY_SCK_S 3                // invert SCK_S
`define TMC429_F_POLARITY_SCK_S_LSB 3
`define TMC429_F_POLARITY_SCK_S_MSB 3
`define TMC429_F_POLARITY_SCK_S_W 1
`define TMC429_F_POLARITY_PH_AB 4                // invert PH_A, PH_B
`define TMC429_F_POLARITY_PH_AB_LSB 4
`define TMC429_F_POLARITY_PH_AB_MSB 4
`define TMC429_F_POLARITY_PH_AB_W 1
`define TMC429_F_POLARITY_FD_AB 5                // FD low active
`define TMC429_F_POLARITY_FD_AB_LSB 5
`define TMC429_F_POLARITY_FD_AB_MSB 5
`define TMC429_F_POLARITY_FD_AB_W 1
`define TMC429_F_POLARITY_DAC_AB 6               // invert all DAC bits
`define TMC429_F_POLARITY_DAC_AB_LSB 6
`define TMC429_F_POLARITY_DAC_AB_MSB 6
`define TMC429_F_POLARITY_DAC_AB_W 1
`define TMC429_F_CS_COM_IND 7                    // individual nSCS_S, nSCS2, nSCS3
`define TMC429_F_CS_COM_IND_LSB 7
`define TMC429_F_CS_COM_IND_MSB 7
`define TMC429_F_CS_COM_IND_W 1
`define TMC429_F_CLK2_DIV 15:8                   // SCK_S divider: f = fCLK/(2(clk2_div+1)); Step/Dir: bits 11..8 = STPDIV
`define TMC429_F_CLK2_DIV_LSB 8
`define TMC429_F_CLK2_DIV_MSB 15
`define TMC429_F_CLK2_DIV_W 8
`define TMC429_F_CONT_UPDATE 16                  // periodic driver-chain datagrams
`define TMC429_F_CONT_UPDATE_LSB 16
`define TMC429_F_CONT_UPDATE_MSB 16
`define TMC429_F_CONT_UPDATE_W 1
`define TMC429_F_REFMUX 20                       // reference switches multiplexed by a 74HC157 on nSCS_S
`define TMC429_F_REFMUX_LSB 20
`define TMC429_F_REFMUX_MSB 20
`define TMC429_F_REFMUX_W 1
`define TMC429_F_MOT1R 21                        // REF3 is the right switch of motor 1
`define TMC429_F_MOT1R_LSB 21
`define TMC429_F_MOT1R_MSB 21
`define TMC429_F_MOT1R_W 1

// global_parameters — TMC4210 §5.3 (TMC4210)
`define TMC4210_CHIPS_GLOBAL_PARAMETERS 3'b100
`define TMC4210_RESET_GLOBAL_PARAMETERS 24'h000F00
`define TMC4210_WMASK_GLOBAL_PARAMETERS 24'h200F00
`define TMC429_F_STPDIV 11:8                     // step pulse length 16(1+STPDIV) CLK
`define TMC429_F_STPDIV_LSB 8
`define TMC429_F_STPDIV_MSB 11
`define TMC429_F_STPDIV_W 4

// ram_driver_config — TMC428 §10, §11; TMC4210 §1.3, §5.2.3 (TMC428, TMC429, TMC4210)
`define TMC429_ADDR_RAM_DRIVER_CONFIG 6'd0
`define TMC429_CHIPS_RAM_DRIVER_CONFIG 3'b111
`define TMC429_RESET_RAM_DRIVER_CONFIG 24'h000000
`define TMC429_WMASK_RAM_DRIVER_CONFIG 24'h003F3F
`define TMC429_F_RAM_ODD 13:8                    // cell 2*ADDR+1
`define TMC429_F_RAM_ODD_LSB 8
`define TMC429_F_RAM_ODD_MSB 13
`define TMC429_F_RAM_ODD_W 6
`define TMC429_F_RAM_EVEN 5:0                    // cell 2*ADDR
`define TMC429_F_RAM_EVEN_LSB 0
`define TMC429_F_RAM_EVEN_MSB 5
`define TMC429_F_RAM_EVEN_W 6

// ram_microstep_table — TMC428 §10, §12; TMC4210 §1.3, §5.2.3 (TMC428, TMC429, TMC4210)
`define TMC429_ADDR_RAM_MICROSTEP_TABLE 6'd32
`define TMC429_CHIPS_RAM_MICROSTEP_TABLE 3'b111
`define TMC429_RESET_RAM_MICROSTEP_TABLE 24'h000000
`define TMC429_WMASK_RAM_MICROSTEP_TABLE 24'h003F3F

`endif // TMC429_REGMAP_VH
