/*
 * vendor_api.h - a TMC429 driver in the style of the vendors' APIs: it reaches the chip through a
 * single board function that moves one byte, ReadWriteSPI(byte, last). Chip select goes low with
 * the first byte of a datagram and stays low until the byte sent with last = 1; each call returns
 * the byte the chip sent meanwhile, and the driver uses it at once (the status byte of a read
 * before it sends the next byte). Bound to libtmc429 by vendor_main.c through tmc429_spi_select,
 * tmc429_spi_transfer_byte and tmc429_spi_deselect, without any look-ahead.
 *
 * Sources: TMC429 datasheet rev 2.06 §6.2 (datagram: RRS, ADDRESS, RW, 24 data bits; status byte),
 * §12.1 (getting started).
 */
#ifndef VENDOR_API_H
#define VENDOR_API_H

#include <stdint.h>

/* The board's SPI byte transfer (the firmware's HAL provides it). */
uint8_t ReadWriteSPI(uint8_t byte, uint8_t last);

/* The status byte the chip sent first in the last datagram. */
extern uint8_t TMC429_Status;

/* Write datagram: address = RRS|ADDRESS (7 bits, datagram bits 31..25), 24 data bits. */
void TMC429_WriteInt(uint8_t address, int32_t value);
/* Read datagram: the 24 data bits, sign-extended. */
int32_t TMC429_ReadInt(uint8_t address);
/* One byte: the status byte alone. */
uint8_t TMC429_ReadStatus(void);

/* TMC429 §12.1 steps 1-9 in SPI mode for three motors: driver-chain RAM (36 cells), the
 * quarter-wave table, LSMD, then per motor v_min, v_max, clk_config, a_max, pmul/pdiv, RAMP_MODE
 * with the reference switches' stops off, interrupt mask POS_END. Returns 0, or -1 when a_max has
 * no pmul/pdiv. */
int TMC429_Init(const uint8_t cells[36], uint16_t v_max, uint16_t a_max, uint8_t pulse_div,
                uint8_t ramp_div, uint8_t usrs);
/* §12.1 step 10: a RAMP_MODE move. */
void TMC429_MoveTo(uint8_t motor, int32_t x);

#endif
