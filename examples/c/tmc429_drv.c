/* tmc429_drv.c - see tmc429_drv.h. */
#include "tmc429_drv.h"

#include <math.h>

const uint8_t drv429_table_11_2[36] = {
    0x10, 0x05, 0x04, 0x03, 0x02, 0x06, 0x10, 0x0D, 0x0C, 0x0B, 0x0A, 0x2E,
    0x10, 0x05, 0x04, 0x03, 0x02, 0x06, 0x10, 0x0D, 0x0C, 0x0B, 0x0A, 0x2E,
    0x07, 0x05, 0x04, 0x03, 0x02, 0x06, 0x0F, 0x0D, 0x0C, 0x0B, 0x0A, 0x2E,
};

uint32_t drv429_datagram(drv429_t *d, uint32_t dg)
{
    uint8_t b[4] = {(uint8_t)(dg >> 24), (uint8_t)(dg >> 16), (uint8_t)(dg >> 8), (uint8_t)dg};
    if (d->bus.spi(d->bus.ctx, b, b, 4) != 0) {
        d->error = 1;
        return 0;
    }
    d->last_status = b[0];
    return (uint32_t)b[0] << 24 | (uint32_t)b[1] << 16 | (uint32_t)b[2] << 8 | b[3];
}

/* Datagram (TMC429 §6.2): RRS+ADDRESS (7 bit) | RW | 24 data bits. */
void drv429_write(drv429_t *d, uint8_t a7, uint32_t data)
{
    drv429_datagram(d, (uint32_t)a7 << 25 | (data & 0xFFFFFFu));
}

uint32_t drv429_read(drv429_t *d, uint8_t a7)
{
    return drv429_datagram(d, (uint32_t)a7 << 25 | 1u << 24) & 0xFFFFFFu;
}

int32_t drv429_read_signed(drv429_t *d, uint8_t a7)
{
    uint32_t v = drv429_read(d, a7);
    return (v & 0x800000u) ? (int32_t)v - 0x1000000 : (int32_t)v;
}

uint8_t drv429_status(drv429_t *d)
{
    uint8_t b = 0;
    if (d->bus.spi(d->bus.ctx, &b, &b, 1) != 0) {
        d->error = 1;
        return 0;
    }
    return b;
}

void drv429_calc_pmul_pdiv(int a_max, int ramp_div, int pulse_div, float p_reduction, int *p_mul,
                           int *p_div)
{
    int pdiv, pmul, pm = -1, pd = -1;
    double p = a_max / (128.0 * pow(2, ramp_div - pulse_div));
    double p_reduced = p * (1.0 - p_reduction);
    for (pdiv = 0; pdiv <= 13; pdiv++) {
        pmul = (int)(p_reduced * 8.0 * pow(2, pdiv)) - 128;
        if (0 <= pmul && pmul <= 127) {
            pm = pmul + 128;
            pd = pdiv;
        }
    }
    *p_mul = pm;
    *p_div = pd;
}

uint8_t drv429_lut(int i)
{
    int y = (int)(0.5 + 64.0 * sin(3.14159265358979323846 * i / 128.0));
    return (uint8_t)(y > 63 ? 63 : y);
}

void drv429_init_chain(drv429_t *d, const uint8_t cells[36], uint8_t lsmd)
{
    int a, k;
    /* 1. Driver datagram configuration: cells 2a, 2a+1 in RAM word a (TMC429 §11.3). */
    for (a = 0; a < 18; a++)
        drv429_write(d, DRV429_RAM(a), (uint32_t)(cells[2 * a + 1] & 0x3F) << 8 | (cells[2 * a] & 0x3F));
    /* 2. Quarter-wave microstep table, RAM words 32..63 (TMC429 §11.5, Table 12-2). */
    for (k = 0; k < 32; k++)
        drv429_write(d, DRV429_RAM(32 + k), (uint32_t)drv429_lut(2 * k + 1) << 8 | drv429_lut(2 * k));
    /* 3. LSMD in the global parameter register; clk2_div kept at its power-on 15. */
    drv429_write(d, DRV429_GLOBAL_PARAMETERS, 15u << 8 | (lsmd & 3u));
}

int32_t drv429_init_motor(drv429_t *d, int m, const drv429_motor_cfg_t *c)
{
    int p_mul, p_div;
    drv429_calc_pmul_pdiv(c->a_max, c->ramp_div, c->pulse_div, 0.05f, &p_mul, &p_div);
    if (p_mul < 0)
        return -1;
    /* 4. v_min, v_max. 5.-6. pulse_div, ramp_div, usrs. */
    drv429_write(d, DRV429_MOTOR(m, DRV429_V_MIN), c->v_min);
    drv429_write(d, DRV429_MOTOR(m, DRV429_V_MAX), c->v_max);
    drv429_write(d, DRV429_MOTOR(m, DRV429_CLK_CONFIG),
                 (uint32_t)c->pulse_div << 12 | (uint32_t)c->ramp_div << 8 | c->usrs);
    /* 7. a_max with a valid pmul/pdiv pair. */
    drv429_write(d, DRV429_MOTOR(m, DRV429_A_MAX), c->a_max);
    drv429_write(d, DRV429_MOTOR(m, DRV429_PMUL_PDIV), (uint32_t)p_mul << 8 | (uint32_t)p_div);
    /* 8.-9. ramp mode and reference switch configuration; interrupt mask. */
    drv429_write(d, DRV429_MOTOR(m, DRV429_REFCONF_RM), (uint32_t)(c->ref_conf & 0xF) << 8 | DRV429_RAMP_MODE);
    drv429_write(d, DRV429_MOTOR(m, DRV429_INTERRUPT), (uint32_t)c->int_mask << 8);
    return (int32_t)((uint32_t)p_mul << 8 | (uint32_t)p_div);
}

void drv429_move_to(drv429_t *d, int m, int32_t x)
{
    drv429_write(d, DRV429_MOTOR(m, DRV429_X_TARGET), (uint32_t)x & 0xFFFFFFu);
}

int drv429_wait_reached(drv429_t *d, unsigned motor_mask, uint32_t poll_us, uint32_t timeout_us)
{
    uint32_t t, want = 0;
    int m;
    for (m = 0; m < 3; m++)
        if (motor_mask & (1u << m))
            want |= DRV429_ST_XEQT(m);
    for (t = 0; t <= timeout_us; t += poll_us) {
        if ((drv429_status(d) & want) == want && !d->error)
            return 0;
        d->bus.delay_us(d->bus.ctx, poll_us);
    }
    return -1;
}
