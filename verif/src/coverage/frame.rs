//! The bins of the µC's frames: their shapes, and the register and RAM accesses they make.

use tmc429_model::regmap;
use tmc429_model::{Chip, Global, Tmc429};

use super::{reg_name, Coverage, FLAG_NAMES};
use crate::stimulus::{Frame, MIN_HALF};

impl Coverage {
    /// A frame ended; `reply` is what the model sent back (bit 31 first, `nbits` bits).
    pub fn frame(&mut self, chip: Chip, f: &Frame, reply: u64, model: &Tmc429) {
        let g = model.global();
        self.frame_shape(chip, f, reply, g);
        if f.executes() {
            self.register_access(chip, f, reply, g);
        }
    }

    /// The frame's length and timing, and the status byte it brought back.
    fn frame_shape(&mut self, chip: Chip, f: &Frame, reply: u64, g: &Global) {
        if f.nbits < 32 {
            self.hit("frame short (1..31 bits, not executed)");
        }
        if f.nbits == 8 {
            self.hit("frame 8 bits (status byte only)");
        }
        if f.nbits > 32 {
            self.hit("frame long (33..64 bits, not executed)");
        }
        if f.gap == MIN_HALF {
            self.hit("frame back-to-back (nSCS_C high 3 CLK)");
        }
        if f.half == MIN_HALF {
            self.hit("frame SCK_C half period 3 CLK (fastest)");
        }
        if f.half >= 32 {
            self.hit("frame SCK_C half period >= 32 CLK (slow)");
        }
        if f.nbits >= 8 {
            let status = (reply >> (f.nbits as u32 - 8)) as u8;
            if status & 0x80 != 0 {
                self.hit("INT in status byte");
            }
            if status & 0x40 != 0 {
                self.hit("CDGW armed by a datagram_low/high write");
            }
        }
        if f.nbits == 32 && chip == Chip::Tmc429 && g.ifconf & 2 != 0 {
            self.hit("sdo_int: frame with data on SDOZ_C only");
        }
    }

    /// An executed frame: a read or write of a register or RAM word.
    fn register_access(&mut self, chip: Chip, f: &Frame, reply: u64, g: &Global) {
        let a7 = f.a7();
        let present = regmap::lookup(chip, a7).is_some();
        let data = (reply & 0xFF_FFFF) as u32;
        if a7 >= 0x40 {
            if present {
                let w = a7 & 0x3F;
                let n = if f.is_read() { format!("ram read word {w}") } else { format!("ram write word {w}") };
                self.hit(&n);
            }
            return;
        }
        if !present {
            self.hit(if f.is_read() { "read unused address" } else { "write unused address" });
            return;
        }
        let name = reg_name(chip, a7);
        self.hit(&format!("{} {}", if f.is_read() { "read" } else { "write" }, name));
        if f.is_read() {
            self.register_read(chip, a7, data, g);
        } else {
            self.register_write(a7, f.data());
        }
    }

    /// What a register read shows: pmul bit 15, lp, interrupt flags, cover_pos, pos_comp's I,
    /// type_version, the reference switches.
    fn register_read(&mut self, chip: Chip, a7: u8, data: u32, g: &Global) {
        let motor = (a7 >> 4) as usize;
        let idx = a7 & 0xF;
        match (a7 < 0x30, idx) {
            (true, 9) if data & 0x8000 != 0 => self.hit("pmul bit 15 reads 1"),
            (true, 10) if data & 0x1_0000 != 0 => self.hit("x_latched write arms lp"),
            (true, 11) => {
                self.last_flags[motor] = data as u8;
                for (k, fl) in FLAG_NAMES.iter().enumerate() {
                    if data >> k & 1 == 1 {
                        self.hit(&format!("interrupt flag {fl} set"));
                    }
                }
            }
            (false, 2) if self.last_cover_pos == 63 && (data >> 8) & 63 == 0 => self.hit("cover_pos 63 reads back 0"),
            (false, 6) if data & 1 == 1 => self.hit("pos_comp match sets I"),
            (false, 9) if data == 0x429101 => self.hit("type_version reads $429101"),
            (false, 14) => {
                let names: &[(u32, &str)] = match chip {
                    Chip::Tmc4210 => &[(0, "r1 (REF_R)"), (1, "l1 (REF_L)"), (3, "l2 (GP_IN)")],
                    _ => &[(0, "r1"), (1, "l1"), (2, "r2"), (3, "l2"), (4, "r3"), (5, "l3")],
                };
                for (b, n) in names {
                    if data >> b & 1 == 1 {
                        self.hit(&format!("ref_switches {n} active"));
                    }
                }
                if chip != Chip::Tmc428 && g.ifconf & 1 != 0 {
                    self.hit("inv_ref inverts the switches");
                }
                if chip == Chip::Tmc429 && g.ifconf & 0x100 != 0 && g.gconf & (1 << 21 | 1 << 20) == 0 {
                    self.hit("en_refr: REFR switches read");
                }
            }
            _ => {}
        }
    }

    /// What a register write does to the flags and cover_pos the next read shows.
    fn register_write(&mut self, a7: u8, wdata: u32) {
        let motor = (a7 >> 4) as usize;
        let idx = a7 & 0xF;
        match (a7 < 0x30, idx) {
            (true, 11) => {
                let flags = self.last_flags[motor];
                if flags & wdata as u8 != 0 {
                    self.hit("interrupt flags cleared by writing 1");
                }
                if flags & !((wdata >> 8) as u8) != 0 {
                    self.hit("interrupt flags forced 0 by the mask");
                }
            }
            (false, 2) => self.last_cover_pos = ((wdata >> 8) & 63) as u8,
            _ => {}
        }
    }
}
