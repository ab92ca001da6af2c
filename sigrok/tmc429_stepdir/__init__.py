##
## This file is part of tmc429, the open reference of the TMC428/TMC429/TMC4210
## (MIT OR Apache-2.0).
##

'''
The Step/Dir outputs of the Trinamic TMC429 (en_sd = 1, TMC429 §10) and TMC4210: the
steps and directions of each motor with its running position. The TMC429 puts STEP1/DIR1
on SDO_S/SCK_S, STEP2/DIR2 on nSCS_S/SDI_S and STEP3/DIR3 on nSCS2/nSCS3; the TMC4210's
STEP and DIR are SDO_S and SCK_S (TMC4210 §1.5). A step is the active edge of STEP
(rising; falling with inv_stp; both with step_half) and goes the negative way while DIR
is high (low with inv_dir), as the if_configuration register sets them (TMC429 §8.2.4).
'''

from .pd import Decoder
