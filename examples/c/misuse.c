/*
 * misuse.c - calls every function of tmc429.h with null pointers, zero lengths, lengths above 4,
 * out-of-range arguments, and a destroyed / never-created / zero handle. Every call must return
 * its error code and nothing may crash; CI runs this under valgrind (scripts/test-capi), so an
 * invalid read or write inside the library fails the run too. Exit 0 only if all checks pass.
 */
#include <stdio.h>
#include <string.h>

#include "tmc429.h"

static int failures, checks;

#define EXPECT(call, want)                                                                     \
    do {                                                                                       \
        int got_ = (call);                                                                     \
        checks++;                                                                              \
        if (got_ != (want)) {                                                                  \
            printf("FAIL line %d: %s = %d (%s), want %d\n", __LINE__, #call, got_,             \
                   tmc429_strerror(got_), (want));                                             \
            failures++;                                                                        \
        }                                                                                      \
    } while (0)

/* Every handle-taking function with valid pointers: all must report `want`. */
static void all_calls(tmc429_handle_t h, int want)
{
    uint8_t tx[4] = {0x73, 0, 0, 0}, rx[4], u8a, u8b;
    uint32_t u32;
    uint64_t u64;
    size_t sz;
    tmc429_outputs_t o;
    tmc429_motor_probe_t p;
    tmc429_event_t ev[2];
    EXPECT(tmc429_reset(h), want);
    EXPECT(tmc429_set_sck_half(h, 4), want);
    EXPECT(tmc429_set_sck_hz(h, 1000000), want);
    EXPECT(tmc429_get_sck_half(h, &u32), want);
    EXPECT(tmc429_spi_transfer(h, tx, rx, 4), want);
    EXPECT(tmc429_advance_cycles(h, 10), want);
    EXPECT(tmc429_advance_us(h, 1), want);
    EXPECT(tmc429_get_cycle(h, &u64), want);
    EXPECT(tmc429_set_pin(h, TMC429_PIN_REF1, 0), want);
    EXPECT(tmc429_get_outputs(h, &o), want);
    EXPECT(tmc429_get_step_dir(h, &u8a, &u8b), want);
    EXPECT(tmc429_get_motor_probe(h, 0, &p), want);
    EXPECT(tmc429_get_status(h, &u8a), want);
    EXPECT(tmc429_events_enable(h, 1), want);
    EXPECT(tmc429_events_pending(h, &sz), want);
    EXPECT(tmc429_events_drain(h, ev, 2) > 0 ? 0 : tmc429_events_drain(h, ev, 2), want);
    EXPECT(tmc429_events_dropped(h, &u64), want);
    EXPECT(tmc429_peek_register(h, 0x39, &u32), want);
    EXPECT(tmc429_spi_select(h), want);
    EXPECT(tmc429_spi_transfer_byte(h, 0, &u8a), want);
    EXPECT(tmc429_spi_deselect(h), want);
}

int main(void)
{
    tmc429_handle_t h = 0, h2 = 0;
    uint8_t buf[8] = {0}, rx[8];
    char line[64];
    uint32_t w = 0;
    tmc429_event_t ev = {0};

    /* create */
    EXPECT(tmc429_create(TMC429_CHIP_TMC429, 0, NULL), TMC429_ERR_NULL);
    EXPECT(tmc429_create(3, 0, &h), TMC429_ERR_ARG);
    EXPECT(tmc429_create(-1, 0, &h), TMC429_ERR_ARG);
    EXPECT(tmc429_create(TMC429_CHIP_TMC428, 16000001, &h), TMC429_ERR_ARG);
    EXPECT(tmc429_create(TMC429_CHIP_TMC429, 32000001, &h), TMC429_ERR_ARG);
    EXPECT(tmc429_create(TMC429_CHIP_TMC429, 0, &h), TMC429_OK);

    /* a live handle: everything works, then every null pointer and bad length */
    all_calls(h, TMC429_OK);
    EXPECT(tmc429_get_sck_half(h, NULL), TMC429_ERR_NULL);
    EXPECT(tmc429_spi_transfer(h, NULL, rx, 4), TMC429_ERR_NULL);
    EXPECT(tmc429_spi_transfer(h, buf, NULL, 4), TMC429_ERR_NULL);
    EXPECT(tmc429_spi_transfer(h, NULL, NULL, 0), TMC429_ERR_NULL);
    EXPECT(tmc429_spi_transfer(h, buf, rx, 0), TMC429_ERR_LENGTH);
    EXPECT(tmc429_spi_transfer(h, buf, rx, 5), TMC429_ERR_LENGTH);
    EXPECT(tmc429_spi_transfer(h, buf, rx, 8), TMC429_ERR_LENGTH);
    EXPECT(tmc429_spi_transfer(h, buf, rx, (size_t)-1), TMC429_ERR_LENGTH);
    EXPECT(tmc429_get_cycle(h, NULL), TMC429_ERR_NULL);
    EXPECT(tmc429_get_outputs(h, NULL), TMC429_ERR_NULL);
    EXPECT(tmc429_get_step_dir(h, NULL, buf), TMC429_ERR_NULL);
    EXPECT(tmc429_get_step_dir(h, buf, NULL), TMC429_ERR_NULL);
    EXPECT(tmc429_get_motor_probe(h, 0, NULL), TMC429_ERR_NULL);
    EXPECT(tmc429_get_status(h, NULL), TMC429_ERR_NULL);
    EXPECT(tmc429_events_pending(h, NULL), TMC429_ERR_NULL);
    EXPECT(tmc429_events_drain(h, NULL, 4), TMC429_ERR_NULL);
    EXPECT(tmc429_events_drain(h, &ev, 0), TMC429_ERR_LENGTH);
    EXPECT(tmc429_events_dropped(h, NULL), TMC429_ERR_NULL);
    EXPECT(tmc429_event_format(NULL, line, sizeof line), TMC429_ERR_NULL);
    EXPECT(tmc429_event_format(&ev, NULL, sizeof line), TMC429_ERR_NULL);
    /* chip select: bytes and deselect need a select, a select or a whole frame needs none */
    EXPECT(tmc429_spi_transfer_byte(h, 0, buf), TMC429_ERR_STATE);
    EXPECT(tmc429_spi_deselect(h), TMC429_ERR_STATE);
    EXPECT(tmc429_spi_select(h), TMC429_OK);
    EXPECT(tmc429_spi_select(h), TMC429_ERR_STATE);
    EXPECT(tmc429_spi_transfer(h, buf, rx, 4), TMC429_ERR_STATE);
    EXPECT(tmc429_spi_transfer_byte(h, 0, NULL), TMC429_ERR_NULL);
    EXPECT(tmc429_spi_deselect(h), TMC429_OK);
    EXPECT(tmc429_peek_register(h, 0, NULL), TMC429_ERR_NULL);
    EXPECT(tmc429_peek_register(h, 128, &w), TMC429_ERR_ARG);
    EXPECT(tmc429_peek_register(h, 0xFFFFFFFFu, &w), TMC429_ERR_ARG);
    /* out-of-range arguments */
    EXPECT(tmc429_set_sck_half(h, 2), TMC429_ERR_ARG);
    EXPECT(tmc429_set_sck_half(h, 0), TMC429_ERR_ARG);
    EXPECT(tmc429_set_sck_hz(h, 0), TMC429_ERR_ARG);
    EXPECT(tmc429_set_sck_hz(h, 5333335), TMC429_ERR_ARG);
    EXPECT(tmc429_set_pin(h, 7, 0), TMC429_ERR_ARG);
    EXPECT(tmc429_set_pin(h, -1, 0), TMC429_ERR_ARG);
    EXPECT(tmc429_set_pin(h, TMC429_PIN_SDI_S, 2), TMC429_ERR_ARG);
    EXPECT(tmc429_get_motor_probe(h, 3, (tmc429_motor_probe_t *)(void *)line), TMC429_ERR_ARG);
    EXPECT(tmc429_events_enable(h, -1), TMC429_ERR_ARG);
    ev.kind = 7;
    EXPECT(tmc429_event_format(&ev, line, sizeof line), TMC429_ERR_ARG);
    ev.kind = TMC429_EVENT_STEP;
    ev.motor = 3;
    EXPECT(tmc429_event_format(&ev, line, sizeof line), TMC429_ERR_ARG);
    ev.motor = 2;
    ev.cycle = 99;
    EXPECT(tmc429_event_format(&ev, line, 0), TMC429_ERR_LENGTH);
    EXPECT(tmc429_event_format(&ev, line, 11), TMC429_ERR_LENGTH);
    EXPECT(tmc429_event_format(&ev, line, 12), 11);
    checks++;
    if (strcmp(line, "step 99 2 +") != 0) {
        printf("FAIL format: '%s'\n", line);
        failures++;
    }
    ev.kind = TMC429_EVENT_CHAIN;
    ev.nbits = 0xFFFFFFFFu;
    EXPECT(tmc429_event_format(&ev, line, sizeof line), TMC429_ERR_LENGTH);
    /* no failed call touched the chip: the §6.5 read still replies as after power-on */
    EXPECT(tmc429_reset(h), TMC429_OK);
    buf[0] = 0x1B;
    buf[1] = buf[2] = buf[3] = 0;
    EXPECT(tmc429_spi_transfer(h, buf, rx, 4), TMC429_OK);
    EXPECT(rx[0] << 24 | rx[1] << 16 | rx[2] << 8 | rx[3], 0x15000000);

    /* destroyed, zero and never-created handles */
    EXPECT(tmc429_destroy(h), TMC429_OK);
    EXPECT(tmc429_destroy(h), TMC429_ERR_HANDLE);
    all_calls(h, TMC429_ERR_HANDLE);
    all_calls(0, TMC429_ERR_HANDLE);
    all_calls(0xFFFFFFFFFFFFFFFFull, TMC429_ERR_HANDLE);
    EXPECT(tmc429_destroy(0), TMC429_ERR_HANDLE);
    /* a new chip never gets the old handle back */
    EXPECT(tmc429_create(TMC429_CHIP_TMC4210, 0, &h2), TMC429_OK);
    EXPECT(h2 != h, 1);
    all_calls(h, TMC429_ERR_HANDLE);
    EXPECT(tmc429_get_motor_probe(h2, 1, (tmc429_motor_probe_t *)(void *)line), TMC429_ERR_ARG);
    EXPECT(tmc429_destroy(h2), TMC429_OK);

    checks++;
    if (strcmp(tmc429_strerror(-99), "unknown error code") != 0)
        failures++;
    printf("%d checks, %d failed\n", checks, failures);
    return failures ? 1 : 0;
}
