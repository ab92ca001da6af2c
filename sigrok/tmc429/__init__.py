##
## This file is part of tmc429, the open reference of the TMC428/TMC429/TMC4210
## (MIT OR Apache-2.0).
##

'''
The µC interface of the Trinamic TMC428/TMC429/TMC4210 motion controllers, stacked on
the spi decoder (SPI mode 3: cpol=1, cpha=1; nSCS_C as CS#, SCK_C as CLK, SDI_C as
MOSI, SDOZ_C or nINT_SDO_C as MISO).

Each 32-bit datagram is shown with its register or RAM word by name, read or write,
its decoded fields and the status byte the chip answered (TMC428 §6.2, Table 6-4,
Table 7-2); frames of other lengths execute nothing and carry the status byte only.
The register table (regmap.py) is generated from the project's register map.

With the spi decoder's default word size of 8 a frame whose length is not a multiple
of 8 loses its last bits; set the spi option wordsize=1 to see every bit.
'''

from .pd import Decoder
