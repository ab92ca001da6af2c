/*
 * tmc429.h - a virtual TMC428/TMC429/TMC4210 for firmware unit tests.
 *
 * The C ABI of the tmc429 golden model (crate tmc429-capi, library libtmc429). The chip is
 * cycle-accurate and pin-level: an SPI transfer bit-bangs the chip's SCK_C/SDI_C/nSCS_C pins
 * and samples SDO_C, so the bytes returned are exactly what the chip sends.
 * Documentation: docs/c-api.md. The test capi/tests/header.rs checks every declaration here
 * against the Rust signatures in capi/src/lib.rs.
 *
 * Conventions
 *  - Every function returns int: TMC429_OK (0), or a non-negative count where documented, on
 *    success; a negative TMC429_ERR_* code on failure. tmc429_abi_version and tmc429_strerror
 *    cannot fail.
 *  - Every pointer argument must be non-NULL (else TMC429_ERR_NULL) and valid for the documented
 *    number of elements.
 *  - Nothing unwinds or aborts across the boundary: an internal panic (a bug, never an input)
 *    returns TMC429_ERR_INTERNAL and retires the handle (only tmc429_destroy works on it then).
 *  - A handle is a number, not a pointer. Handles are never reused within a process, so a zero,
 *    never-created or destroyed handle is detected: TMC429_ERR_HANDLE, no memory is touched.
 *    Different handles may be used from different threads concurrently; calls on one handle
 *    from several threads are serialized.
 */
#ifndef TMC429_H
#define TMC429_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define TMC429_ABI_VERSION 1

/* Return codes. */
#define TMC429_OK 0
#define TMC429_ERR_NULL (-1)     /* a pointer argument is NULL */
#define TMC429_ERR_HANDLE (-2)   /* handle zero, never created, or destroyed */
#define TMC429_ERR_LENGTH (-3)   /* SPI length 0 or > 4, zero capacity, buffer too small */
#define TMC429_ERR_ARG (-4)      /* argument out of range (variant, fclk, SCK, pin, level, motor, kind) */
#define TMC429_ERR_INTERNAL (-5) /* internal error caught; the handle is retired */

/* Chip variants (the RTL's CHIP parameter). */
#define TMC429_CHIP_TMC428 0
#define TMC429_CHIP_TMC429 1
#define TMC429_CHIP_TMC4210 2

/* Input pins for tmc429_set_pin. TMC4210: REF1 = REF_L, REF2 = GP_IN, REF3 = REF_R. */
#define TMC429_PIN_REF1 0
#define TMC429_PIN_REF2 1
#define TMC429_PIN_REF3 2
#define TMC429_PIN_REFR1 3 /* TMC429 only; pulled up: 1 after create */
#define TMC429_PIN_REFR2 4
#define TMC429_PIN_REFR3 5
#define TMC429_PIN_SDI_S 6 /* serial data from the driver chain */

/* Event kinds. */
#define TMC429_EVENT_CHAIN 0 /* a datagram on the driver chain (SPI mode) */
#define TMC429_EVENT_STEP 1  /* a step pulse on a Step/Dir output */
#define TMC429_EVENT_INT 2   /* INT changed */

/* Events kept at most; later ones are counted by tmc429_events_dropped and lost. */
#define TMC429_EVENT_QUEUE_CAPACITY 1048576

typedef uint64_t tmc429_handle_t;

/* One decoded pin event; kind says which fields are meaningful. */
typedef struct tmc429_event_t {
    uint64_t cycle;   /* CLK edge the event was seen at (as tmc429_get_cycle) */
    uint64_t bits;    /* CHAIN: datagram, first bit sent in bit nbits-1 (last 64 bits if longer) */
    uint32_t kind;    /* TMC429_EVENT_* */
    uint32_t nbits;   /* CHAIN: number of bits */
    uint8_t motor;    /* STEP: motor 0..2 */
    uint8_t negative; /* STEP: 1 = negative direction */
    uint8_t level;    /* INT: new level (1 = interrupt active, nINT low) */
    uint8_t reserved;
} tmc429_event_t;

/* Output pins after the last CLK edge, 0 or 1 each. */
typedef struct tmc429_outputs_t {
    uint8_t nint_sdo_c; /* nINT_SDO_C: SDO while nSCS_C is low, else nINT */
    uint8_t sdoz_c;     /* SDOZ_C data (TMC429), valid when sdoz_c_oe */
    uint8_t sdoz_c_oe;
    uint8_t nscs_s;     /* STEP2 in Step/Dir mode */
    uint8_t sck_s;      /* DIR1 */
    uint8_t sdo_s;      /* STEP1 */
    uint8_t sdi_s_o;    /* DIR2, valid when sdi_s_oe */
    uint8_t sdi_s_oe;
    uint8_t nscs2;      /* STEP3 */
    uint8_t nscs3;      /* DIR3 */
    uint8_t poscmp;     /* position compare (TMC429) */
    uint8_t reserved;
} tmc429_outputs_t;

/* Internal state of one motor (the model's probes). */
typedef struct tmc429_motor_probe_t {
    int32_t x_target;   /* sign-extended from 24 bits */
    int32_t x_actual;   /* sign-extended from 24 bits */
    int32_t v_internal; /* internal velocity in 1/256 units of v */
    int32_t v_actual;   /* the v_actual register (12-bit signed) */
    int32_t v_target;   /* the v_target register (12-bit signed) */
    int32_t a_actual;   /* the a_actual register (12-bit signed) */
    uint32_t ustep;     /* microstep index 0..255 */
    uint8_t step;       /* 1 in the cycle the motor stepped */
    uint8_t dir;        /* direction of the last step, 1 = negative */
    uint16_t reserved;
} tmc429_motor_probe_t;

/* The ABI version of the library (compare with TMC429_ABI_VERSION). */
uint32_t tmc429_abi_version(void);

/* A static NUL-terminated description of a return code (never NULL). */
const char *tmc429_strerror(int code);

/* Creates a chip in its power-on state. variant: TMC429_CHIP_*. fclk_hz: CLK frequency, 0 = the
 * variant's maximum (16 MHz TMC428, 32 MHz TMC429/TMC4210); above the maximum is
 * TMC429_ERR_ARG. SCK starts at 4 CLK cycles per half period; event decoding is on. */
int tmc429_create(int variant, uint32_t fclk_hz, tmc429_handle_t *out);

/* Destroys a chip; the handle is invalid afterwards (a second destroy: TMC429_ERR_HANDLE). */
int tmc429_destroy(tmc429_handle_t h);

/* Power-on reset: registers, RAM, pins and cycle counter as after create; events cleared.
 * fclk, SCK rate and the event on/off setting are kept. */
int tmc429_reset(tmc429_handle_t h);

/* SCK_C half period in CLK cycles, at least 3 (TMC428 Table 6-1). */
int tmc429_set_sck_half(tmc429_handle_t h, uint32_t clk_cycles);

/* SCK_C rate in Hz: half period = ceil(fclk / (2*hz)) CLK cycles (the rate used is the one
 * asked or the next lower). 0, or above fclk/6 rounded up to a whole Hz (which gives 3), is
 * TMC429_ERR_ARG. */
int tmc429_set_sck_hz(tmc429_handle_t h, uint32_t hz);

/* The SCK_C half period in use, in CLK cycles. */
int tmc429_get_sck_half(tmc429_handle_t h, uint32_t *out);

/* One SPI frame of len (1..4) bytes, MSB first (SPI mode 3): nSCS_C low for 8*len SCK_C periods,
 * then high. rx receives the len bytes the chip sent (rx may equal tx). Only a 4-byte frame is a
 * datagram the chip executes; a 1-byte frame reads the status byte. The time the frame takes
 * (2 + 16*len half periods) passes on the chip. */
int tmc429_spi_transfer(tmc429_handle_t h, const uint8_t *tx, uint8_t *rx, size_t len);

/* Advances CLK edges with the input pins as they are. */
int tmc429_advance_cycles(tmc429_handle_t h, uint64_t cycles);

/* Advances floor((us*fclk + r) / 1e6) CLK edges; the remainder r is carried between calls. */
int tmc429_advance_us(tmc429_handle_t h, uint64_t us);

/* CLK edges since create or reset. */
int tmc429_get_cycle(tmc429_handle_t h, uint64_t *out);

/* Sets input pin TMC429_PIN_* to level 0 or 1 from the next CLK edge on (the chip synchronizes
 * it: acted on two edges later). A pin the variant lacks is accepted and has no effect. */
int tmc429_set_pin(tmc429_handle_t h, int pin, int level);

/* All output pins after the last CLK edge. */
int tmc429_get_outputs(tmc429_handle_t h, tmc429_outputs_t *out);

/* STEP and DIR pin levels, bit m = motor m (TMC429 §10: STEP1..3 = SDO_S, nSCS_S, nSCS2;
 * DIR1..3 = SCK_S, SDI_S, nSCS3). Meaningful in Step/Dir mode (en_sd = 1, TMC4210). */
int tmc429_get_step_dir(tmc429_handle_t h, uint8_t *step, uint8_t *dir);

/* Probes of motor 0..2 (TMC4210: 0 only; others TMC429_ERR_ARG). */
int tmc429_get_motor_probe(tmc429_handle_t h, unsigned int motor, tmc429_motor_probe_t *out);

/* The status byte INT CDGW RS3 xEQt3 RS2 xEQt2 RS1 xEQt1 of the current state, without SPI. */
int tmc429_get_status(tmc429_handle_t h, uint8_t *out);

/* Event decoding on (1) or off (0, faster). Turning it on restarts the decoder, which then
 * reports an INT that is already high at the next edge. The queue is kept. */
int tmc429_events_enable(tmc429_handle_t h, int on);

/* Number of events waiting. */
int tmc429_events_pending(tmc429_handle_t h, size_t *out);

/* Moves up to cap (>= 1) oldest events into buf, oldest first; returns how many (>= 0). */
int tmc429_events_drain(tmc429_handle_t h, tmc429_event_t *buf, size_t cap);

/* Events lost because the queue was full. */
int tmc429_events_dropped(tmc429_handle_t h, uint64_t *out);

/* The event as one line of `tmc429 spi --events` ("int 1234 1", "step 99 0 +",
 * "chain 4567 36 87F87F87F"), NUL-terminated, no newline; returns its length. 64 bytes suffice
 * when nbits <= 64; a buffer the line does not fit is TMC429_ERR_LENGTH. An unknown kind, a motor
 * above 2, or negative/level other than 0/1 is TMC429_ERR_ARG. */
int tmc429_event_format(const tmc429_event_t *ev, char *buf, size_t cap);

#ifdef __cplusplus
}
#endif

#endif /* TMC429_H */
