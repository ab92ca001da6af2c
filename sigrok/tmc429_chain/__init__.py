##
## This file is part of tmc429, the open reference of the TMC428/TMC429/TMC4210
## (MIT OR Apache-2.0).
##

'''
The driver chain of the Trinamic TMC428/TMC429 in SPI mode (TMC428 §6.3, §9-§11;
TMC429 §8.2.1-§8.2.5): the datagrams the chip sends to its stepper motor drivers on
nSCS_S, SCK_S and SDO_S, and what the drivers answer on SDI_S (the readback of
DATAGRAM_LOW_WORD / DATAGRAM_HIGH_WORD).

A datagram is shown with its length and bits (first bit sent as MSB), split into its
NxM groups (the pause the chip makes after a bit whose configuration cell has NxM set,
TMC428 §11), with the readback bits. Name the drivers to see their bits by name:
tmc23x-24x (TMC236/TMC239/TMC246/TMC249, 12-bit groups, TMC428 Table 11-2; readback as
TMC246/TMC249 status bits, TMC429 Figure 8.5) or tmc26x (TMC26x in SPI mode, 20-bit
groups). cover_pos and cover_len mark the bits a cover datagram replaces (TMC429
§8.2.2, §8.2.3) and show its value. Set the polarities as in the global parameter
register: polarity_nscs_s (cs_polarity) and polarity_sck_s (clk_polarity).
'''

from .pd import Decoder
