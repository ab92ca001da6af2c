##
## This file is part of tmc429, the open reference of the TMC428/TMC429/TMC4210
## (MIT OR Apache-2.0).
##

'''
The interrupt output of the Trinamic TMC428/TMC429/TMC4210: nINT_SDO_C carries serial
data while nSCS_C is low and nINT (low active) while it is high (TMC428 §6.2); with
sdo_int = 1 it is nINT all the time and the data goes out on SDOZ_C (TMC429 §8.2.4).
The spi-stacked tmc429 decoder sees only frames, so nINT outside them is decoded here
from the pins: give nSCS_C too unless sdo_int is set.
'''

from .pd import Decoder
