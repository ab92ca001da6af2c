/* vendor_api.c - see vendor_api.h. */
#include "vendor_api.h"

#include "tmc429_drv.h" /* drv429_lut, drv429_calc_pmul_pdiv: the datasheet's formulas */

uint8_t TMC429_Status;

static void datagram(uint8_t address, int rw, uint32_t data, uint8_t rx[3])
{
    /* the status byte comes back while the address byte goes out */
    TMC429_Status = ReadWriteSPI((uint8_t)(address << 1 | (rw & 1)), 0);
    rx[0] = ReadWriteSPI((uint8_t)(data >> 16), 0);
    rx[1] = ReadWriteSPI((uint8_t)(data >> 8), 0);
    rx[2] = ReadWriteSPI((uint8_t)data, 1);
}

void TMC429_WriteInt(uint8_t address, int32_t value)
{
    uint8_t rx[3];
    datagram(address, 0, (uint32_t)value & 0xFFFFFFu, rx);
}

int32_t TMC429_ReadInt(uint8_t address)
{
    uint8_t rx[3];
    uint32_t v;
    datagram(address, 1, 0, rx);
    v = (uint32_t)rx[0] << 16 | (uint32_t)rx[1] << 8 | rx[2];
    return (v & 0x800000u) ? (int32_t)v - 0x1000000 : (int32_t)v;
}

uint8_t TMC429_ReadStatus(void)
{
    TMC429_Status = ReadWriteSPI(0, 1);
    return TMC429_Status;
}

int TMC429_Init(const uint8_t cells[36], uint16_t v_max, uint16_t a_max, uint8_t pulse_div,
                uint8_t ramp_div, uint8_t usrs)
{
    int a, m, p_mul, p_div;
    for (a = 0; a < 18; a++) /* 1. driver datagram configuration, RAM words 0..17 */
        TMC429_WriteInt(DRV429_RAM(a), (cells[2 * a + 1] & 0x3F) << 8 | (cells[2 * a] & 0x3F));
    for (a = 0; a < 32; a++) /* 2. quarter-wave table, RAM words 32..63 */
        TMC429_WriteInt(DRV429_RAM(32 + a), drv429_lut(2 * a + 1) << 8 | drv429_lut(2 * a));
    TMC429_WriteInt(DRV429_GLOBAL_PARAMETERS, 15 << 8 | 2); /* 3. LSMD 2, clk2_div 15 */
    drv429_calc_pmul_pdiv(a_max, ramp_div, pulse_div, 0.05f, &p_mul, &p_div);
    if (p_mul < 0)
        return -1;
    for (m = 0; m < 3; m++) { /* 4.-9. */
        TMC429_WriteInt(DRV429_MOTOR(m, DRV429_V_MIN), 1);
        TMC429_WriteInt(DRV429_MOTOR(m, DRV429_V_MAX), v_max);
        TMC429_WriteInt(DRV429_MOTOR(m, DRV429_CLK_CONFIG), pulse_div << 12 | ramp_div << 8 | usrs);
        TMC429_WriteInt(DRV429_MOTOR(m, DRV429_A_MAX), a_max);
        TMC429_WriteInt(DRV429_MOTOR(m, DRV429_PMUL_PDIV), p_mul << 8 | p_div);
        TMC429_WriteInt(DRV429_MOTOR(m, DRV429_REFCONF_RM), 0x3 << 8 | DRV429_RAMP_MODE);
        TMC429_WriteInt(DRV429_MOTOR(m, DRV429_INTERRUPT), DRV429_INT_POS_END << 8);
    }
    return 0;
}

void TMC429_MoveTo(uint8_t motor, int32_t x)
{
    TMC429_WriteInt(DRV429_MOTOR(motor, DRV429_X_TARGET), x);
}
