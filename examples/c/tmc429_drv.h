/*
 * tmc429_drv.h - a small TMC429 driver written the way microcontroller firmware is: it knows
 * nothing of the virtual chip. It talks to the chip through two board functions (an SPI
 * transfer with chip select, a delay), as it would on a board.
 *
 * Sources: TMC429 datasheet rev 2.06 §6.2 (datagram), §7 (address map), §8 (registers),
 * §8.1.10.2.3 (pmulpdiv.c), §11.3-§11.5 (driver RAM, LUT), §12.1 (getting started).
 */
#ifndef TMC429_DRV_H
#define TMC429_DRV_H

#include <stddef.h>
#include <stdint.h>

/* The board: full-duplex SPI with nSCS_C low for the whole transfer; a delay. */
typedef struct {
    int (*spi)(void *ctx, const uint8_t *tx, uint8_t *rx, size_t len); /* 0 = ok */
    void (*delay_us)(void *ctx, uint32_t us);
    void *ctx;
} drv429_bus_t;

typedef struct {
    drv429_bus_t bus;
    uint8_t last_status; /* status byte of the last datagram */
    int error;           /* nonzero once an SPI transfer failed */
} drv429_t;

/* Per-motor register index IDX (TMC429 §7.3): A7 = SMDA<<4 | IDX. */
enum {
    DRV429_X_TARGET = 0x0, DRV429_X_ACTUAL = 0x1, DRV429_V_MIN = 0x2, DRV429_V_MAX = 0x3,
    DRV429_V_TARGET = 0x4, DRV429_V_ACTUAL = 0x5, DRV429_A_MAX = 0x6, DRV429_A_ACTUAL = 0x7,
    DRV429_PMUL_PDIV = 0x9, DRV429_REFCONF_RM = 0xA, DRV429_INTERRUPT = 0xB,
    DRV429_CLK_CONFIG = 0xC
};
/* Global registers: A7 = $30 | JDX. */
enum { DRV429_IF_CONFIGURATION = 0x34, DRV429_TYPE_VERSION = 0x39, DRV429_GLOBAL_PARAMETERS = 0x3F };
/* RAM: A7 = $40 | ADDR (two 6-bit cells per word). */
#define DRV429_RAM(addr) ((uint8_t)(0x40 | (addr)))
#define DRV429_MOTOR(m, idx) ((uint8_t)(((m) << 4) | (idx)))

/* Status byte bits (TMC429 §6.2.1): INT CDGW RS3 xEQt3 RS2 xEQt2 RS1 xEQt1. */
#define DRV429_ST_XEQT(m) (1u << (2 * (m)))
#define DRV429_ST_INT 0x80u

#define DRV429_RAMP_MODE 0
#define DRV429_INT_POS_END 0x01u

/* Register access. */
uint32_t drv429_datagram(drv429_t *d, uint32_t dg);
void drv429_write(drv429_t *d, uint8_t a7, uint32_t data);
uint32_t drv429_read(drv429_t *d, uint8_t a7);
int32_t drv429_read_signed(drv429_t *d, uint8_t a7);
uint8_t drv429_status(drv429_t *d); /* 8-bit status-only frame */

/* pmulpdiv.c (TMC429 §8.1.10.2.3): p_mul 128..255 and p_div 0..13, or -1 / -1. */
void drv429_calc_pmul_pdiv(int a_max, int ramp_div, int pulse_div, float p_reduction, int *p_mul,
                           int *p_div);

/* Motion parameters of one motor. */
typedef struct {
    uint16_t v_min, v_max, a_max;
    uint8_t pulse_div, ramp_div, usrs;
    uint8_t ref_conf; /* 4 bits: disable_stop_l/r, soft_stop, ref_rnl */
    uint8_t int_mask;
} drv429_motor_cfg_t;

/* TMC429 §12.1 steps 1-3 (SPI mode): driver-chain RAM, microstep table, LSMD. */
void drv429_init_chain(drv429_t *d, const uint8_t cells[36], uint8_t lsmd);
/* TMC429 §12.1 steps 4-9 for one motor. Returns the pmul/pdiv register value or -1. */
int32_t drv429_init_motor(drv429_t *d, int motor, const drv429_motor_cfg_t *cfg);
/* Step 10 in RAMP_MODE: start a move. */
void drv429_move_to(drv429_t *d, int motor, int32_t x);
/* Polls the status byte until xEQt of every motor in mask is set; returns 0, or -1 on timeout. */
int drv429_wait_reached(drv429_t *d, unsigned motor_mask, uint32_t poll_us, uint32_t timeout_us);

/* TMC428 Table 11-2: driver-chain RAM cells for three TMC236 drivers (the TMC429 §11.4 example). */
extern const uint8_t drv429_table_11_2[36];

/* Table 12-2 microstep value y(i) = int(1/2 + 64 sin(pi i/128)), 63 where that is 64. */
uint8_t drv429_lut(int i);

#endif
