//! One instruction, in direct mode or from the program ([TMCL] §5.7): the check
//! (`check`), then the command. The reply value is the command's value unless the command
//! reads something (as TMCL firmware does); in a program a read value goes to the accumulator
//! ([TMCL] §5.5).

use super::*;

/// CALC and CALCX operations 0..9 ([TMCL] §5.7.16); `None` for a division by 0.
fn calc(a: i32, opn: u8, b: i32) -> Option<i32> {
    Some(match opn {
        0 => a.wrapping_add(b),
        1 => a.wrapping_sub(b),
        2 => a.wrapping_mul(b),
        3 if b != 0 => a.wrapping_div(b),
        4 if b != 0 => a.wrapping_rem(b),
        5 => a & b,
        6 => a | b,
        7 => a ^ b,
        8 => !a,
        9 => b,
        _ => return None,
    })
}

impl<C: Spi429> Module<C> {
    pub(super) fn set_accu(&mut self, v: i32) {
        self.vm.accu = v;
        self.vm.cmp = v.signum() as i8;
    }

    /// Executes one instruction; returns status code and reply value.
    pub fn execute(&mut self, ins: &Instruction, origin: Origin) -> (u8, i32) {
        let (o, t, mo, v) = (ins.op, ins.typ, ins.motor, ins.value);
        if origin == Origin::Direct && matches!(o, op::JA | op::JC | op::CSUB | op::RSUB | op::WAIT | op::STOP | op::RETI) {
            // Program flow commands are for standalone programs ([TMCL] §5.3).
            return err(Status::NotAvailable, v);
        }
        let accu = matches!(o, op::AAP | op::AGP).then_some(self.vm.accu);
        if let Err(r) = self.check(ins, accu) {
            return err(r.status, v);
        }
        let m = mo as usize;
        let r = match o {
            op::ROR => self.rotate(m, v),
            op::ROL => (self.rotate(m, v.wrapping_neg()).0, v),
            op::MST => {
                self.stop_motor(m);
                ok(v)
            }
            op::MVP => self.mvp(t, m, v),
            op::SAP => self.sap(t, m, v),
            op::AAP => (self.sap(t, m, self.vm.accu).0, v),
            op::GAP => self.gap(t, m),
            op::STAP => self.stap(t, m),
            op::RSAP => self.rsap(t, m),
            op::SGP => self.sgp(t, mo, v),
            op::AGP => (self.sgp(t, mo, self.vm.accu).0, v),
            op::GGP => self.ggp(t, mo),
            op::STGP => self.stgp(t, mo),
            op::RSGP => self.rsgp(t, mo),
            op::RFS => self.rfs(t, m, v),
            op::SIO => self.sio(t, mo, v),
            op::GIO => self.gio(t, mo),
            op::SCO => self.sco(t, mo, v),
            op::GCO => self.gco(t, mo),
            _ => self.program_op(o, t, m, v),
        };
        let reads = matches!(o, op::GAP | op::GGP | op::GIO | op::GCO) || (o == op::RFS && t == 2);
        if origin == Origin::Program && reads && r.0 == Status::Ok.code() {
            self.set_accu(r.1);
        }
        r
    }

    /// The commands on the program's state: coordinates, the accumulator, the comparison,
    /// the error flags, the interrupt vectors ([TMCL] §5); any other is not a command.
    fn program_op(&mut self, o: u8, t: u8, m: usize, v: i32) -> (u8, i32) {
        match o {
            op::CCO => {
                let x = self.actual_position(m);
                self.set_coord(m, t as usize, x);
                ok(v)
            }
            op::ACO => {
                self.set_coord(m, t as usize, self.vm.accu);
                ok(v)
            }
            op::CALC => match calc(self.vm.accu, t, v) {
                Some(r) => {
                    self.set_accu(r);
                    ok(v)
                }
                None => err(Status::InvalidValue, v),
            },
            op::CALCX => self.calcx(t, v),
            op::COMP => {
                self.vm.cmp = (self.vm.accu as i64 - v as i64).signum() as i8;
                ok(v)
            }
            op::CLE => {
                // ALL (0) and ETO (1) clear the timeout flag, ALL and EDV (3) the deviation flag.
                if t <= 1 {
                    self.vm.eto = false;
                }
                if t == 0 || t == 3 {
                    self.st[0].deviation = false;
                }
                ok(v)
            }
            op::VECT => {
                self.vm.vectors[t as usize] = Some(v as u16);
                ok(v)
            }
            op::EI | op::DI => {
                self.enable_interrupt(t, o == op::EI);
                ok(v)
            }
            _ => err(Status::InvalidCommand, v),
        }
    }

    fn calcx(&mut self, t: u8, v: i32) -> (u8, i32) {
        match t {
            8 => self.vm.x = !self.vm.x,
            9 => self.vm.x = self.vm.accu,
            10 => {
                std::mem::swap(&mut self.vm.x, &mut self.vm.accu);
                self.set_accu(self.vm.accu);
            }
            _ => match calc(self.vm.accu, t, self.vm.x) {
                Some(r) => self.set_accu(r),
                None => return err(Status::InvalidValue, v),
            },
        }
        ok(v)
    }

    /// RFS START, STOP, STATUS ([TMCL] §5.7.13). STATUS answers 0 when no search is active.
    fn rfs(&mut self, t: u8, m: usize, v: i32) -> (u8, i32) {
        match t {
            0 => (self.rfs_start(m).0, v),
            1 => {
                if self.st[m].rfs.active() {
                    self.stop_motor(m);
                }
                ok(v)
            }
            _ => ok(self.st[m].rfs.status()),
        }
    }

    /// EI / DI ([TMCL] §5.7.33, §5.7.34): 255 is the global switch. Enabling a timer starts
    /// its period; disabling drops a pending request.
    fn enable_interrupt(&mut self, n: u8, on: bool) {
        if n == 255 {
            self.vm.global_enable = on;
            return;
        }
        self.vm.enabled[n as usize] = on;
        if !on {
            self.vm.pending[n as usize] = false;
        }
        if on && n <= 2 {
            self.vm.timer_next[n as usize] = self.now_ms() + self.irq_cfg[n as usize] as u64;
        }
    }
}
