//! The boundaries of the units in the current state: the probe bundle (`tmc429_top`'s
//! `probe_*` ports) and the port views of the units that test vectors are taken at
//! (`rtl/tmc429_spi_slave.v`, `rtl/tmc429_ramp.v`, `rtl/tmc429_chain.v`; docs/vectors.md). Each is
//! read from the state the units compute with; nothing here changes it.

use crate::motor_regs::sext12;
use crate::regmap::{self, f, Addr};
use crate::{chain, ramp, schedule, spi_slave, sync, Chip, MotorProbe, Probes, Tmc429};

impl Tmc429 {
    /// The probe bundle of the current state.
    pub fn probes(&self) -> Probes {
        let mut p = Probes { prescaler: self.prescaler, power_down: self.power_down as u8, status: self.status(), ..Probes::default() };
        for (mp, m) in p.motor.iter_mut().zip(self.motors.iter()) {
            *mp = MotorProbe {
                x_target: m.x_target,
                x_actual: m.x_actual,
                v_internal: m.v,
                v_target: sext12(m.v_target as u32),
                a_actual: m.a_actual,
                ustep: m.ustep as u32,
                step: m.step as u8,
                dir: m.dir as u8,
                pulse_acc: m.acc,
            };
        }
        let c = &self.chain;
        p.chain.state = c.state;
        p.chain.cell = c.cell;
        p.chain.motor = c.motor;
        p.chain.bit_count = c.bits;
        p.chain.pending = c.req as u8;
        p.chain.cover_waiting = c.cw(&self.global) as u8;
        p.chain.readback = c.readback;
        p
    }

    /// The µC SPI slave's ports in the current state ([`spi_slave::SpiPorts`]): the slave's
    /// outputs, and the status byte and read data the register file presents to it for the next
    /// edge. This is the boundary of `rtl/tmc429_spi_slave.v` (test vectors, docs/vectors.md).
    pub fn spi_ports(&self) -> spi_slave::SpiPorts {
        let mut p = self.spi.ports(&self.sync);
        p.status = self.status();
        let (d, r) = self.read_register_parts(p.rd_addr);
        p.rd_data = d & 0xFF_FFFF;
        p.rd_round = r;
        p
    }

    /// The inputs motor `m`'s ramp and pulse generator sees before the next edge: the levels of
    /// the current state ([`ramp::RampInputs`]). With [`ramp::ramp_ports`] of the state after
    /// that edge this is the boundary of `rtl/tmc429_ramp.v` (test vectors, docs/vectors.md).
    pub fn ramp_inputs(&self, m: usize) -> ramp::RampInputs {
        let mo = &self.motors[m];
        let (left, right) = self.switches();
        let (we, widx, wdata) = match self.write_of_next_edge() {
            Some((Addr::Motor(mm, idx), d)) if mm as usize == m => (true, idx, d),
            _ => (false, 0, 0),
        };
        ramp::RampInputs {
            run: !self.power_down,
            sample_tick: schedule::sample_tick(if self.power_down { self.prescaler } else { schedule::next(self.prescaler) }, m),
            cond_tick: schedule::cond_tick(self.prescaler, m),
            ramp_tick: schedule::ramp_tick(self.prescaler, m, mo.ramp_div),
            pulse_tick: schedule::pulse_tick(self.prescaler, m, mo.pulse_div),
            rm: mo.rm,
            x_target: mo.x_target,
            v_min: mo.v_min,
            a_max: mo.a_max,
            ref_conf: mo.ref_conf,
            usrs: mo.usrs,
            dx_ref_tolerance: mo.dx_ref_tolerance,
            vt: mo.vt,
            sw_l: (left >> m) & 1 != 0,
            sw_r: (right >> m) & 1 != 0,
            we,
            widx,
            wdata,
        }
    }

    /// The µC write the SPI slave executes in the next edge (C12), if any, to a register or RAM
    /// word the variant has: its address and 24 data bits.
    fn write_of_next_edge(&self) -> Option<(Addr, u32)> {
        let p = self.spi.ports(&self.sync);
        let a7 = ((p.cmd >> 25) & 0x7F) as u8;
        let write = p.exec && (p.cmd >> 24) & 1 == 0;
        regmap::lookup(self.chip, a7).filter(|_| write).map(|_| (Addr::from_a7(a7), p.cmd & 0xFF_FFFF))
    }

    /// The inputs the driver-chain master sees before the next edge: the levels of the current
    /// state ([`chain::ChainInputs`]). With the chain state after that edge and
    /// [`Tmc429::chain_step`] this is the boundary of `rtl/tmc429_chain.v` (test vectors,
    /// docs/vectors.md; rtl/README.md "Unit ports").
    pub fn chain_inputs(&self) -> chain::ChainInputs {
        let g = &self.global;
        let mut i = chain::ChainInputs {
            run: !self.power_down,
            spi_mode: self.spi_mode(),
            lsmd: g.g(f::LSMD) as u8,
            pol_ph_ab: g.g(f::POL_PH_AB) != 0,
            pol_fd_ab: g.g(f::POL_FD_AB) != 0,
            pol_dac_ab: g.g(f::POL_DAC_AB) != 0,
            cont_update: g.g(f::CONT_UPDATE) != 0,
            cw: g.cw,
            dgw: g.dgw,
            readback_clr: matches!(
                self.write_of_next_edge(),
                Some((Addr::Global(regmap::jdx::DATAGRAM_LOW_WORD | regmap::jdx::DATAGRAM_HIGH_WORD), _))
            ),
            cover_pos: g.cover_pos & 63,
            cover_len: g.cover_len & 31,
            cover_datagram: g.cover_datagram & 0xFF_FFFF,
            sdi_s: (self.sync.s2 >> sync::bit::SDI_S) & 1 != 0,
            clk2_div: g.g(f::CLK2_DIV) as u8,
            ramp_tick: schedule::ramp_ticks(self.prescaler, &self.motors),
            ..Default::default()
        };
        for (m, mo) in self.motors.iter().enumerate() {
            i.step |= (mo.step as u8) << m;
            i.dir |= (mo.dir as u8) << m;
            i.ustep[m] = mo.ustep;
            i.i_scale[m] = self.cur[m].i_scale(mo);
        }
        i
    }

    /// One edge of a copy `c` of the driver chain in the world of the current state: its global
    /// registers, RAM, motors, current scales, ramp ticks and SDI_S. This is the chain's edge of
    /// [`Tmc429::tick`] (C80–C89); nothing happens when powered down (C66). Gives the RTL's
    /// next-state outputs (`cs_pre_nx`, ...) in `c` and its handshake outputs (`take`, `ret_cw`,
    /// `ret_dgw`) for test vectors.
    pub fn chain_step(&self, c: &mut chain::Chain) -> chain::Handshake {
        if self.power_down || self.chip == Chip::Tmc4210 {
            return chain::Handshake::default();
        }
        let i = self.chain_inputs();
        c.tick(i.spi_mode, &self.ram, &self.global, &self.motors, &self.cur, i.ramp_tick, i.sdi_s)
    }
}
