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
/* The guard is this library's own: vendor drivers' TMC429.h use TMC429_H, and both headers may be
 * included in one test. */
#ifndef TMC429_CAPI_H_INCLUDED
#define TMC429_CAPI_H_INCLUDED

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define TMC429_ABI_VERSION 3

/* Return codes. */
#define TMC429_OK 0
#define TMC429_ERR_NULL (-1)     /* a pointer argument is NULL */
#define TMC429_ERR_HANDLE (-2)   /* handle zero, never created, or destroyed */
#define TMC429_ERR_LENGTH (-3)   /* SPI length 0 or > 4, zero capacity, buffer too small */
#define TMC429_ERR_ARG (-4)      /* argument out of range (variant, fclk, SCK, pin, level, motor, kind) */
#define TMC429_ERR_INTERNAL (-5) /* internal error caught; the handle is retired */
#define TMC429_ERR_STATE (-6)    /* chip select: byte/deselect while not selected, select/frame while selected */

/* Chip variants (the RTL's CHIP parameter). */
#define TMC429_CHIP_TMC428 0
#define TMC429_CHIP_TMC429 1
#define TMC429_CHIP_TMC4210 2

/* Input pins for tmc429_set_pin. TMC4210: REF1 = REF_L, REF2 = GP_IN, REF3 = REF_R. */
#define TMC429_PIN_REF1 0
#define TMC429_PIN_REF2 1
#define TMC429_PIN_REF3 2
#define TMC429_PIN_REFR1 3 /* TMC429 only; pulled up: 1 (switch active) after create, see docs */
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
 * datagram the chip executes; a 1-byte frame reads the status byte, 2- and 3-byte frames return
 * the status byte and the first data bytes and execute nothing. The time the frame takes
 * (2 + 16*len half periods) passes on the chip. While tmc429_spi_select holds nSCS_C low:
 * TMC429_ERR_STATE. */
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

/* ---- Byte-wise SPI and register peek (ABI 3) -------------------------------------------------
 * For drivers that send one byte per SPI call with chip select held across calls and need each
 * reply byte at once (Trinamic's ReadWriteSPI(byte, last), examples/c/vendor_api.c). */

/* Pulls nSCS_C low; one SCK_C half period passes. TMC429_ERR_STATE if it is low already. */
int tmc429_spi_select(tmc429_handle_t h);

/* 8 SCK_C periods with nSCS_C low, MSB first; *rx receives the byte the chip sent meanwhile
 * (status byte first, then data bits 23..0). TMC429_ERR_STATE unless selected. */
int tmc429_spi_transfer_byte(tmc429_handle_t h, uint8_t tx, uint8_t *rx);

/* Raises nSCS_C: the chip executes the datagram at this rising edge if exactly 32 bits were
 * shifted since the select (fewer or more: nothing); one SCK_C half period passes.
 * TMC429_ERR_STATE unless selected. */
int tmc429_spi_deselect(tmc429_handle_t h);

/* The 24 data bits a read datagram of address (RRS and the 6 address bits, datagram bits 31..25:
 * SMDA<<4 | IDX, $30 | JDX, $40 | RAM address) would return now, without SPI traffic and without
 * CLK time (for test assertions). Unused addresses read 0; address > 127 is TMC429_ERR_ARG. */
int tmc429_peek_register(tmc429_handle_t h, uint32_t address, uint32_t *data);

/* ---------------------------------------------------------------------------------------------
 * Pin level (capi/src/pins.rs): one call per CLK edge, for SystemVerilog DPI-C (capi/sv/
 * tmc429_pkg.sv) and other cycle-based testbenches; and the seeded stimulus of `tmc429 cosim`
 * with its transaction log and first-mismatch report. docs/c-api.md, docs/verify-your-rtl.md.
 *
 * Input word, bit 0..9: nSCS_C, SCK_C, SDI_C, SDI_S, REF1, REF2, REF3, REFR1, REFR2, REFR3.
 * Output word, bit 0..10: nINT_SDO_C, SDOZ_C, SDOZ_C enable, nSCS_S, SCK_S, SDO_S, SDI_S out,
 * SDI_S enable, nSCS2, nSCS3, POSCMP.
 */
#define TMC429_INPUT_PINS 10
#define TMC429_OUTPUT_PINS 11
#define TMC429_PROBE_COUNT 37 /* probes of tmc429_tick_pins; names: tmc429_probe_name */
#define TMC429_IDLE_INPUTS 0x383 /* idle bus, switches open: nSCS_C, SCK_C, REFR1..3 high */

/* Stimulus profiles (`tmc429 cosim --profile`). */
#define TMC429_PROFILE_MOTION 0
#define TMC429_PROFILE_MOTION_CORE 1
#define TMC429_PROFILE_DRIVERS 2
#define TMC429_PROFILE_REGISTERS 3
#define TMC429_PROFILE_FULL 4

/* One rising CLK edge with the input pins of `inputs` (bits above 9 must be 0, else
 * TMC429_ERR_ARG); the output word after it in *outputs and, unless probes is NULL, the
 * TMC429_PROBE_COUNT probes (signed ones as two's complement of their width). The pins stay as
 * given until the next call or an SPI transfer. Turn events off for speed (tmc429_events_enable). */
int tmc429_tick_pins(tmc429_handle_t h, uint32_t inputs, uint32_t *outputs, uint64_t *probes);

/* The output word after the last edge (after create or reset: the reset state). */
int tmc429_output_word(tmc429_handle_t h, uint32_t *outputs);

/* Name of probe `index` as the co-simulation's VCD scopes it ("motor0.x_target", "top.status");
 * "" for an index >= TMC429_PROBE_COUNT. Static, never NULL. */
const char *tmc429_probe_name(uint32_t index);

/* The stimulus of `tmc429 cosim --chip VARIANT --profile PROFILE --seed SEED`: the same seed, the
 * same pins edge for edge. Its handles are distinct from chip handles. */
int tmc429_stim_create(int variant, int profile, uint64_t seed, tmc429_handle_t *out);

int tmc429_stim_destroy(tmc429_handle_t h);

/* The input word of the next edge. model_outputs, dut_outputs: both sides' output words after
 * the last edge (before the first: the reset states), for the replies in the transaction log.
 * An output word above bit 10 is TMC429_ERR_ARG. */
int tmc429_stim_next(tmc429_handle_t h, uint32_t model_outputs, uint32_t dut_outputs, uint32_t *inputs);

/* Compares the design's output word after the last edge with the model's (SDOZ_C and SDI_S data
 * only while both enable them): 0 = equal, 1 = the first mismatch or any check after it. */
int tmc429_stim_check(tmc429_handle_t h, uint32_t model_outputs, uint32_t dut_outputs);

/* Edges, SPI frames and pin-change transactions so far. */
int tmc429_stim_counts(tmc429_handle_t h, uint64_t *cycles, uint64_t *frames, uint64_t *pin_changes);

/* The first mismatch's report as `tmc429 cosim` prints it, `label` (NULL: "dut") naming the
 * design; "" without a mismatch or for an invalid handle. Owned by the handle, valid until the
 * next call on it, never NULL. */
const char *tmc429_stim_report(tmc429_handle_t h, const char *label);

#ifdef __cplusplus
}
#endif

#endif /* TMC429_CAPI_H_INCLUDED */
