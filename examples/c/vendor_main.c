/*
 * vendor_main.c - runs the vendor-style driver of vendor_api.c against the virtual TMC429 and
 * checks its own results (exit 0 only if all hold): the version word, the §12.1 start-up, frames
 * of 1, 2 and 3 bytes, a move of three motors waited for through the status byte with a firmware
 * millisecond tick taken from the chip's cycle count, and the registers asserted with
 * tmc429_peek_register (no SPI traffic, no chip time).
 *
 * The board functions below are the only place that knows the chip is virtual.
 */
#include <stdio.h>

#include "tmc429.h"
#include "check.h"
#include "tmc429_drv.h"
#include "vendor_api.h"

#define FCLK 32000000u

static tmc429_handle_t chip;

/* ---- the board ---- */

/* One byte, chip select from the first byte of a datagram until last = 1; the reply at once. */
uint8_t ReadWriteSPI(uint8_t byte, uint8_t last)
{
    static int selected;
    uint8_t rx = 0;
    if (!selected) {
        CHECK_EQ("select", tmc429_spi_select(chip), TMC429_OK);
        selected = 1;
    }
    CHECK_EQ("byte", tmc429_spi_transfer_byte(chip, byte, &rx), TMC429_OK);
    if (last) {
        CHECK_EQ("deselect", tmc429_spi_deselect(chip), TMC429_OK);
        selected = 0;
    }
    return rx;
}

/* The firmware's millisecond tick: the chip's CLK edges / (fclk / 1000). Time passes only inside
 * library calls, so a loop that waits on this tick must also let time pass (board_delay_ms). */
static uint32_t board_millis(void)
{
    uint64_t c = 0;
    tmc429_get_cycle(chip, &c);
    return (uint32_t)(c / (FCLK / 1000));
}

static void board_delay_ms(uint32_t ms)
{
    tmc429_advance_us(chip, 1000u * ms);
}

static uint32_t peek(uint8_t address)
{
    uint32_t d = 0;
    CHECK_EQ("peek", tmc429_peek_register(chip, address, &d), TMC429_OK);
    return d;
}

/* A frame of n bytes through ReadWriteSPI: the replies. */
static void frame(const uint8_t *tx, uint8_t *rx, int n)
{
    int i;
    for (i = 0; i < n; i++)
        rx[i] = ReadWriteSPI(tx[i], i == n - 1);
}

int main(void)
{
    static const int32_t target[3] = {1200, -800, 400};
    const uint8_t dx = DRV429_MOTOR(1, 0xD); /* dx_ref_tolerance of motor 1 */
    uint8_t rx[4];
    uint64_t c0, c1;
    uint32_t t0;
    int m;

    if (tmc429_abi_version() < 3) {
        printf("FAIL library ABI %u: byte-wise SPI needs 3\n", tmc429_abi_version());
        return 1;
    }
    if (tmc429_create(TMC429_CHIP_TMC429, FCLK, &chip) != TMC429_OK)
        return 1;
    tmc429_set_sck_hz(chip, 4000000);

    /* The version word (TMC429 §8.2.4.4), the status byte first ($15: INT 0, every xEQt 1). */
    CHECK_EQ("type_version", TMC429_ReadInt(DRV429_TYPE_VERSION), 0x429101);
    CHECK_EQ("status byte of the read", TMC429_Status, 0x15);
    CHECK_EQ("status-only frame", TMC429_ReadStatus(), 0x15);

    /* Frames of 2 and 3 bytes execute nothing (TMC429 §6.2: a datagram is 32 bits). */
    TMC429_WriteInt(dx, 0x123);
    {
        static const uint8_t w3[3] = {0x1A, 0x00, 0x07}, w2[2] = {0x1A, 0x00};
        frame(w3, rx, 3);
        CHECK_EQ("3-byte frame: status", rx[0], 0x15);
        frame(w2, rx, 2);
        CHECK_EQ("2-byte frame: status", rx[0], 0x15);
    }
    tmc429_get_cycle(chip, &c0);
    CHECK_EQ("dx_ref_tolerance unchanged by short frames", peek(dx), 0x123);
    tmc429_get_cycle(chip, &c1);
    CHECK_EQ("a peek takes no chip time", c1 - c0, 0);

    /* TMC429 §12.1 start-up, checked register by register with peeks. */
    CHECK_EQ("init", TMC429_Init(drv429_table_11_2, 1000, 100, 3, 7, 6), 0);
    for (m = 0; m < 18; m++)
        CHECK_EQ("driver RAM", peek(DRV429_RAM(m)), drv429_table_11_2[2 * m + 1] << 8 | drv429_table_11_2[2 * m]);
    CHECK_EQ("LUT word 31", peek(DRV429_RAM(63)), 0x3F3F);
    CHECK_EQ("global parameters", peek(DRV429_GLOBAL_PARAMETERS), 0x000F02);
    for (m = 0; m < 3; m++) {
        CHECK_EQ("v_max", peek(DRV429_MOTOR(m, DRV429_V_MAX)), 1000);
        CHECK_EQ("a_max", peek(DRV429_MOTOR(m, DRV429_A_MAX)), 100);
        CHECK_EQ("pmul_pdiv", peek(DRV429_MOTOR(m, DRV429_PMUL_PDIV)), 0xBD09);
        CHECK_EQ("clk_config", peek(DRV429_MOTOR(m, DRV429_CLK_CONFIG)), 0x3706);
    }

    /* §12.1 step 10: the moves, waited for through the status byte (xEQt1..3), 5 s at most. */
    for (m = 0; m < 3; m++)
        TMC429_MoveTo((uint8_t)m, target[m]);
    t0 = board_millis();
    while ((TMC429_ReadStatus() & 0x15) != 0x15 && board_millis() - t0 < 5000)
        board_delay_ms(1);
    CHECK_EQ("all motors at their targets (xEQt)", TMC429_Status & 0x15, 0x15);
    printf("  moves done after %u ms of firmware tick\n", (unsigned)(board_millis() - t0));
    for (m = 0; m < 3; m++) {
        CHECK_EQ("x_actual read", TMC429_ReadInt(DRV429_MOTOR(m, DRV429_X_ACTUAL)), target[m]);
        CHECK_EQ("x_actual peek", peek(DRV429_MOTOR(m, DRV429_X_ACTUAL)), (uint32_t)target[m] & 0xFFFFFFu);
    }
    CHECK_EQ("INT after POS_END", TMC429_ReadStatus() & DRV429_ST_INT, DRV429_ST_INT);
    tmc429_destroy(chip);
    if (failures) {
        printf("%d check(s) failed\n", failures);
        return 1;
    }
    printf("ok: byte-wise driver: version, start-up, short frames and moves to (%d, %d, %d) checked\n",
           target[0], target[1], target[2]);
    return 0;
}
