/*
 * main.c - runs the firmware driver of tmc429_drv.c against the virtual TMC429 (libtmc429) and
 * checks its own results: exit 0 only if every register read-back matched and every motor
 * reached its target.
 *
 * The board functions below are the only place that knows the chip is virtual.
 */
#include <stdio.h>
#include <string.h>

#include "tmc429.h"
#include "check.h"
#include "tmc429_drv.h"

/* ---- the board: SPI and delay on the virtual chip ---- */
static int board_spi(void *ctx, const uint8_t *tx, uint8_t *rx, size_t len)
{
    int rc = tmc429_spi_transfer(*(tmc429_handle_t *)ctx, tx, rx, len);
    if (rc != TMC429_OK)
        printf("spi: %s\n", tmc429_strerror(rc));
    return rc;
}

static void board_delay_us(void *ctx, uint32_t us)
{
    tmc429_advance_us(*(tmc429_handle_t *)ctx, us);
}

int main(void)
{
    tmc429_handle_t chip;
    drv429_t d;
    int m, rc;
    static const int32_t target[3] = {2000, -1500, 700};
    drv429_motor_cfg_t cfg = {
        .v_min = 1, .v_max = 1000, .a_max = 100,
        .pulse_div = 3, .ramp_div = 7, .usrs = 6,
        .ref_conf = 0x3, /* no reference switches on this bench: stops disabled */
        .int_mask = DRV429_INT_POS_END,
    };

    _Static_assert(sizeof(tmc429_event_t) == 32, "tmc429_event_t layout");
    if (tmc429_abi_version() != TMC429_ABI_VERSION) {
        printf("FAIL library ABI %u, header %d\n", tmc429_abi_version(), TMC429_ABI_VERSION);
        return 1;
    }
    rc = tmc429_create(TMC429_CHIP_TMC429, 32000000, &chip);
    if (rc != TMC429_OK) {
        printf("FAIL create: %s\n", tmc429_strerror(rc));
        return 1;
    }
    tmc429_set_sck_hz(chip, 4000000); /* 4 MHz SPI: 4 CLK per half period at 32 MHz */

    memset(&d, 0, sizeof d);
    d.bus.spi = board_spi;
    d.bus.delay_us = board_delay_us;
    d.bus.ctx = &chip;

    /* TMC428 §6.5 / TMC429 §6.2.3 datagram examples (status $15: INT 0, all xEQt 1). */
    CHECK_EQ("§6.5 write reply", drv429_datagram(&d, 0x1A000123u), 0x15000000u);
    CHECK_EQ("§6.5 read reply", drv429_datagram(&d, 0x1B000000u), 0x15000123u);
    CHECK_EQ("status-only 8-bit read", drv429_status(&d), 0x15);
    CHECK_EQ("type_version", drv429_read(&d, DRV429_TYPE_VERSION), 0x429101u);

    /* TMC429 §12.1: start-up sequence. */
    drv429_init_chain(&d, drv429_table_11_2, 2);
    for (m = 0; m < 3; m++) {
        int32_t pp = drv429_init_motor(&d, m, &cfg);
        CHECK_EQ("pmul/pdiv of a_max 100, ramp_div 7, pulse_div 3", pp, 0xBD09);
    }

    /* Read-backs. */
    for (m = 0; m < 18; m++) {
        uint32_t want = (uint32_t)(drv429_table_11_2[2 * m + 1]) << 8 | drv429_table_11_2[2 * m];
        CHECK_EQ("driver RAM word", drv429_read(&d, DRV429_RAM(m)), want);
    }
    CHECK_EQ("LUT word 0", drv429_read(&d, DRV429_RAM(32)), 0x0200);   /* y(1)=2, y(0)=0 */
    CHECK_EQ("LUT word 31", drv429_read(&d, DRV429_RAM(63)), 0x3F3F);  /* y(63)=y(62)=63 */
    CHECK_EQ("global parameters", drv429_read(&d, DRV429_GLOBAL_PARAMETERS), 0x000F02);
    for (m = 0; m < 3; m++) {
        CHECK_EQ("v_min", drv429_read(&d, DRV429_MOTOR(m, DRV429_V_MIN)), 1);
        CHECK_EQ("v_max", drv429_read(&d, DRV429_MOTOR(m, DRV429_V_MAX)), 1000);
        CHECK_EQ("a_max", drv429_read(&d, DRV429_MOTOR(m, DRV429_A_MAX)), 100);
        CHECK_EQ("pmul_pdiv", drv429_read(&d, DRV429_MOTOR(m, DRV429_PMUL_PDIV)), 0xBD09);
        CHECK_EQ("clk_config", drv429_read(&d, DRV429_MOTOR(m, DRV429_CLK_CONFIG)), 0x3706);
        CHECK_EQ("ref_conf/rm", drv429_read(&d, DRV429_MOTOR(m, DRV429_REFCONF_RM)), 0x0300);
        CHECK_EQ("interrupt mask", drv429_read(&d, DRV429_MOTOR(m, DRV429_INTERRUPT)) >> 8, DRV429_INT_POS_END);
    }
    if (d.error) {
        printf("FAIL SPI errors during start-up\n");
        return 1;
    }

    /* §12.1 step 10: move, and wait for position reached through the status byte. */
    for (m = 0; m < 3; m++)
        drv429_move_to(&d, m, target[m]);
    CHECK_EQ("xEQt clear while moving", drv429_status(&d) & 0x15, 0);
    if (drv429_wait_reached(&d, 7, 1000, 5000000) != 0) {
        printf("FAIL timeout waiting for position reached\n");
        failures++;
    }
    for (m = 0; m < 3; m++) {
        tmc429_motor_probe_t p;
        CHECK_EQ("x_actual", drv429_read_signed(&d, DRV429_MOTOR(m, DRV429_X_ACTUAL)), target[m]);
        CHECK_EQ("v_actual", drv429_read(&d, DRV429_MOTOR(m, DRV429_V_ACTUAL)), 0);
        CHECK_EQ("probe", tmc429_get_motor_probe(chip, (unsigned)m, &p), TMC429_OK);
        CHECK_EQ("probe x_actual", p.x_actual, target[m]);
    }
    /* POS_END interrupts: INT in the status byte and on the nINT pin. */
    {
        tmc429_outputs_t o;
        uint8_t st = drv429_status(&d);
        CHECK_EQ("status after the move", st, 0x95);
        tmc429_get_outputs(chip, &o);
        CHECK_EQ("nINT pin", o.nint_sdo_c, 0);
        for (m = 0; m < 3; m++) /* clear the flags (write 1), keep the mask */
            drv429_write(&d, DRV429_MOTOR(m, DRV429_INTERRUPT), (uint32_t)DRV429_INT_POS_END << 8 | DRV429_INT_POS_END);
        CHECK_EQ("status after clearing", drv429_status(&d), 0x15);
    }
    /* The event queue: the INT rise and fall, as `tmc429 spi --events` prints them. */
    {
        tmc429_event_t ev[64];
        char line[64];
        int i, n, rises = 0, falls = 0;
        uint64_t cyc;
        long chain = 0;
        /* The queue also holds every driver-chain datagram of the moves: drain it all. */
        while ((n = tmc429_events_drain(chip, ev, 64)) > 0) {
            for (i = 0; i < n; i++) {
                if (ev[i].kind == TMC429_EVENT_CHAIN)
                    chain++;
                if (ev[i].kind != TMC429_EVENT_INT)
                    continue;
                if (tmc429_event_format(&ev[i], line, sizeof line) > 0)
                    printf("  %s\n", line);
                ev[i].level ? rises++ : falls++;
            }
        }
        CHECK_EQ("no error draining", n, 0);
        printf("  %ld driver-chain datagrams\n", chain);
        CHECK_EQ("the moves reached the driver chain", chain > 0, 1);
        CHECK_EQ("INT rises", rises, 1);
        CHECK_EQ("INT falls", falls, 1);
        tmc429_get_cycle(chip, &cyc);
        printf("  %llu CLK cycles simulated (%.1f ms at 32 MHz)\n", (unsigned long long)cyc, cyc / 32000.0);
    }
    tmc429_destroy(chip);
    if (failures) {
        printf("%d check(s) failed\n", failures);
        return 1;
    }
    printf("ok: start-up, read-backs and moves to (%d, %d, %d) checked\n", target[0], target[1], target[2]);
    return 0;
}
