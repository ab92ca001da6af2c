//! I/O ports (SIO, GIO, [TMCL] §5.7.14, §5.7.15) and coordinates (SCO, GCO, CCO, ACO,
//! §5.7.24–§5.7.27). The check (`check`) has already refused unknown ports, banks and
//! coordinate numbers.

use super::*;

impl<C: Spi429> Module<C> {
    /// SIO: bank 2 outputs, bank 0 the TMCM-3110's pull-ups; port 255 all as a mask; value
    /// −1 the accumulator (low 8 bits at port 255, its lowest bit at a single port).
    pub(super) fn sio(&mut self, port: u8, bank: u8, v: i32) -> (u8, i32) {
        let val = if v == -1 { self.vm.accu } else { v };
        let r = if bank == 0 { &mut self.io.pullups } else { &mut self.io.outputs };
        if port == 255 {
            *r = val as u8;
        } else if val & 1 != 0 {
            *r |= 1 << port;
        } else {
            *r &= !(1 << port);
        }
        ok(v)
    }

    pub(super) fn gio(&mut self, port: u8, bank: u8) -> (u8, i32) {
        let v = match (bank, port) {
            (0, 255) => self.inputs() as i32,
            (0, _) => ((self.inputs() >> port) & 1) as i32,
            (1, 8) => self.io.supply_dv as i32,
            (1, _) => self.io.analog(port as usize) as i32,
            (_, 255) => self.io.outputs as i32,
            _ => ((self.io.outputs >> port) & 1) as i32,
        };
        ok(v)
    }

    // ----- coordinates -----

    /// SCO n, motor, v; SCO n, 255, 0 copies coordinate n (1..20) or all (0) of every axis to
    /// the EEPROM.
    pub(super) fn sco(&mut self, n: u8, motor: u8, v: i32) -> (u8, i32) {
        if motor != 255 {
            self.set_coord(motor as usize, n as usize, v);
            return ok(v);
        }
        if self.eeprom_locked() {
            return err(Status::EepromLocked, v);
        }
        for a in 0..self.kind.axes() {
            for c in Self::coord_range(n) {
                self.eeprom.coords[a][c] = self.coords[a][c];
            }
        }
        self.save_eeprom();
        ok(v)
    }

    /// Coordinate 0 (RAM only) is never copied; n = 0 means all of 1..20.
    fn coord_range(n: u8) -> std::ops::RangeInclusive<usize> {
        if n == 0 {
            1..=COORDS - 1
        } else {
            n as usize..=n as usize
        }
    }

    /// Sets a coordinate; with global parameter 84 = 1 coordinates 1..20 go to the EEPROM too.
    pub(super) fn set_coord(&mut self, m: usize, n: usize, v: i32) {
        self.coords[m][n] = v;
        if n > 0 && self.gp(84) == 1 && !self.eeprom_locked() {
            self.eeprom.coords[m][n] = v;
            self.save_eeprom();
        }
    }

    /// GCO n, motor; GCO n, 255 copies coordinate n (1..20) or all (0) back from the EEPROM.
    pub(super) fn gco(&mut self, n: u8, motor: u8) -> (u8, i32) {
        if motor != 255 {
            return ok(self.coords[motor as usize][n as usize]);
        }
        for a in 0..self.kind.axes() {
            for c in Self::coord_range(n) {
                self.coords[a][c] = self.eeprom.coords[a][c];
            }
        }
        ok(0)
    }
}
