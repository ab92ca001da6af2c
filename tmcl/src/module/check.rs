//! Whether an instruction can run on this module type, judged from its fields alone: motor and
//! bank numbers, parameter numbers and access, value ranges, features this module does not
//! model. Every command runs this check first (its status is the reply's); program
//! instructions meet it at download, so a program never holds one that would be refused for
//! such a reason ([TMCL] §4.2.1 status codes 2, 3, 4, 6).

use super::*;
use crate::personality::Param;

/// Why an instruction cannot run: the reply's status and the reason in words.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Refusal {
    pub status: Status,
    pub reason: String,
}

fn no<T>(status: Status, reason: String) -> Result<T, Refusal> {
    Err(Refusal { status, reason })
}

/// Interrupt sources configured in bank 3 ([TMCL] §10.4): timers, stop switches, inputs.
fn bank3(kind: ModuleType, p: u8) -> bool {
    matches!(p, 0..=2 | 39..=46) || (27..27 + 2 * kind.axes() as u8).contains(&p)
}

impl<C: Spi429> Module<C> {
    /// The check of a program instruction at download: `Err` names the reason and the status.
    pub fn check_instruction(&self, ins: &Instruction) -> Result<(), String> {
        self.check(ins, None).map_err(|r| format!("{} (status {})", r.reason, r.status.code()))
    }

    /// The check of `ins`; `value` is the value AAP and AGP take from the accumulator (`None`:
    /// not known yet, at download).
    pub(super) fn check(&self, ins: &Instruction, value: Option<i32>) -> Result<(), Refusal> {
        let (t, mo, v) = (ins.typ, ins.motor, ins.value);
        let coord = |n: u8| match n as usize {
            0..COORDS => Ok(()),
            _ => no(Status::WrongType, format!("coordinate {n}: expected 0..20")),
        };
        match ins.op {
            op::ROR | op::ROL => self.check_axis(mo).and_then(|_| self.check_speed(v as i64)),
            op::MST => self.check_axis(mo),
            op::MVP => self.check_axis(mo).and_then(|_| match t {
                0 => self.check_position(v as i64),
                1 => Ok(()),
                2 if (0..COORDS as i32).contains(&v) => Ok(()),
                2 => no(Status::InvalidValue, format!("coordinate {v}: expected 0..20")),
                _ => no(Status::WrongType, format!("MVP type {t}: expected ABS (0), REL (1) or COORD (2)")),
            }),
            op::SAP => self.check_axis(mo).and_then(|_| self.check_sap(t, Some(v))),
            op::AAP => self.check_axis(mo).and_then(|_| self.check_sap(t, value)),
            op::GAP => self.check_axis(mo).and_then(|_| self.axis_entry(t).map(|_| ())),
            op::STAP | op::RSAP => self.check_axis(mo).and_then(|_| self.check_stored(t)),
            op::SGP => self.check_sgp(t, mo, Some(v)),
            op::AGP => self.check_sgp(t, mo, value),
            op::GGP => self.check_ggp(t, mo),
            op::STGP | op::RSGP => self.check_stgp(t, mo),
            op::RFS if t > 2 => no(Status::WrongType, format!("RFS type {t}: expected START (0), STOP (1) or STATUS (2)")),
            op::RFS => self.check_axis(mo),
            op::SIO => self.check_sio(t, mo, v),
            op::GIO => self.check_gio(t, mo),
            op::SCO | op::GCO if mo == 255 => coord(t),
            op::SCO | op::GCO | op::CCO | op::ACO => self.check_axis(mo).and_then(|_| coord(t)),
            op::CALC if t > 9 => no(Status::WrongType, format!("CALC operation {t}: expected 0..9")),
            op::CALCX if t > 10 => no(Status::WrongType, format!("CALCX operation {t}: expected 0..10")),
            op::JC if t > 8 => no(Status::WrongType, format!("JC condition {t}: expected 0..8")),
            op::JA | op::JC | op::CSUB => check_address(v),
            op::WAIT if t > 4 => no(Status::WrongType, format!("WAIT condition {t}: expected TICKS, POS, REFSW, LIMSW or RFS (0..4)")),
            op::WAIT if v < 0 => no(Status::InvalidValue, format!("WAIT {v} ticks: expected 0 or more")),
            op::WAIT if t > 0 => self.check_axis(mo),
            op::CLE if t > 4 => no(Status::WrongType, format!("CLE flag {t}: expected ALL, ETO, EAL, EDV or EPO (0..4)")),
            op::VECT if t == 255 || !self.kind.interrupt_exists(t) => self.no_interrupt(t),
            op::VECT => check_address(v),
            op::EI | op::DI if !self.kind.interrupt_exists(t) => self.no_interrupt(t),
            op::UF0..=op::UF7 => no(Status::NotAvailable, "the user functions UF0..UF7 are not available on this module".into()),
            o if crate::asm::is_program_opcode(o) => Ok(()),
            o => no(Status::InvalidCommand, format!("command {o} is not a TMCL command of this module")),
        }
    }

    fn check_axis(&self, motor: u8) -> Result<(), Refusal> {
        match self.axis(motor) {
            Some(_) => Ok(()),
            None => no(Status::InvalidValue, format!("motor {motor}: the {} has axes 0..{}", self.kind.name(), self.kind.axes() - 1)),
        }
    }

    fn no_interrupt(&self, n: u8) -> Result<(), Refusal> {
        no(Status::WrongType, format!("interrupt {n} is not an interrupt vector of the {}", self.kind.name()))
    }

    /// A velocity in the module's units: TMC429 units (TMCM-3110), pps up to the TMC429's
    /// fastest rate (TMCM-1311).
    fn check_speed(&self, v: i64) -> Result<(), Refusal> {
        let max = match self.kind {
            ModuleType::Tmcm3110 => 2047,
            ModuleType::Tmcm1311 => crate::units::max_pps(self.chip.fclk()),
        };
        if v.abs() <= max {
            return Ok(());
        }
        let unit = match self.kind {
            ModuleType::Tmcm3110 => "TMC429 units; --module tmcm-1311 takes pps",
            ModuleType::Tmcm1311 => "pps: the fastest rate of the TMC429 at this clock",
        };
        no(Status::InvalidValue, format!("velocity {v} is outside −{max}..{max} ({unit})"))
    }

    fn check_position(&self, v: i64) -> Result<(), Refusal> {
        if self.kind == ModuleType::Tmcm3110 && !(-(1 << 23)..(1 << 23)).contains(&v) {
            return no(Status::InvalidValue, format!("position {v} is outside the TMC429's 24 bits −8388608..8388607"));
        }
        Ok(())
    }

    fn axis_entry(&self, p: u8) -> Result<&'static Param, Refusal> {
        match self.kind.axis_param(p) {
            Some(e) => Ok(e),
            None => no(Status::WrongType, format!("axis parameter {p}: {}", self.kind.axis_absent(p))),
        }
    }

    fn check_sap(&self, p: u8, value: Option<i32>) -> Result<(), Refusal> {
        let e = self.axis_entry(p)?;
        if !e.access.writable() {
            return no(Status::WrongType, format!("axis parameter {p} ({}) is read-only", e.name));
        }
        let Some(v) = value else { return Ok(()) };
        if !crate::config::valid(e, v) {
            return no(Status::InvalidValue, format!("value {v} of axis parameter {p} ({}): expected {}..{}", e.name, e.min, e.max));
        }
        if self.kind == ModuleType::Tmcm1311 {
            if let Some(why) = tmcm1311_refused(p, v) {
                return no(Status::InvalidValue, format!("axis parameter {p} = {v}: {why}"));
            }
            if matches!(p, 2 | 3 | 4 | 130 | 194 | 195) {
                return self.check_speed(v as i64);
            }
        }
        Ok(())
    }

    fn check_stored(&self, p: u8) -> Result<(), Refusal> {
        let e = self.axis_entry(p)?;
        if e.live || e.access != crate::personality::Access::RWE {
            return no(Status::WrongType, format!("axis parameter {p} ({}) is not stored in the EEPROM", e.name));
        }
        Ok(())
    }

    fn check_bank0(&self, p: u8) -> Result<&'static Param, Refusal> {
        match self.kind.global_param(p) {
            Some(e) => Ok(e),
            None => no(Status::WrongType, format!("global parameter {p}: {}", self.kind.global_absent(p))),
        }
    }

    fn check_sgp(&self, p: u8, bank: u8, value: Option<i32>) -> Result<(), Refusal> {
        match bank {
            0 => {
                let e = self.check_bank0(p)?;
                if !e.access.writable() {
                    return no(Status::WrongType, format!("global parameter {p} ({}) is read-only", e.name));
                }
                match value {
                    Some(v) if p == 73 && v != 1234 && v != 4321 => {
                        no(Status::InvalidValue, format!("global parameter 73 = {v}: expected 1234 (lock) or 4321 (unlock)"))
                    }
                    Some(v) if p != 73 && !crate::config::valid(e, v) => {
                        no(Status::InvalidValue, format!("value {v} of global parameter {p} ({}): expected {}..{}", e.name, e.min, e.max))
                    }
                    _ => Ok(()),
                }
            }
            2 => Ok(()),
            3 if !bank3(self.kind, p) => no(Status::WrongType, format!("bank 3 parameter {p}: no such interrupt setting")),
            3 => match value {
                Some(v) if p <= 2 && v < 0 => no(Status::InvalidValue, format!("timer period {v} ms: expected 0 or more")),
                Some(v) if p > 2 && !(0..=3).contains(&v) => {
                    no(Status::InvalidValue, format!("transition {v}: expected 0 off, 1 rising, 2 falling, 3 both"))
                }
                _ => Ok(()),
            },
            _ => no(Status::InvalidValue, format!("bank {bank}: expected 0, 2 or 3")),
        }
    }

    fn check_ggp(&self, p: u8, bank: u8) -> Result<(), Refusal> {
        match bank {
            0 => self.check_bank0(p).map(|_| ()),
            2 => Ok(()),
            3 if bank3(self.kind, p) => Ok(()),
            3 => no(Status::WrongType, format!("bank 3 parameter {p}: no such interrupt setting")),
            _ => no(Status::InvalidValue, format!("bank {bank}: expected 0, 2 or 3")),
        }
    }

    fn check_stgp(&self, p: u8, bank: u8) -> Result<(), Refusal> {
        match bank {
            0 => match self.check_bank0(p)? {
                e if e.live => no(Status::WrongType, format!("global parameter {p} ({}) is not stored", e.name)),
                _ => Ok(()),
            },
            2 if (p as usize) < STORED_USER_VARS => Ok(()),
            2 => no(Status::WrongType, format!("user variable {p}: only 0..55 are stored")),
            3 => no(Status::WrongType, "bank 3 is not stored".into()),
            _ => no(Status::InvalidValue, format!("bank {bank}: expected 0 or 2")),
        }
    }

    /// SIO: outputs OUT0..7 (bank 2); the TMCM-3110's pull-ups of IN0..7 (bank 0); 255 = all
    /// as a mask, −1 = the accumulator's low 8 bits ([TMCL] §5.7.14).
    fn check_sio(&self, port: u8, bank: u8, v: i32) -> Result<(), Refusal> {
        let banks: &[u8] = if self.kind == ModuleType::Tmcm3110 { &[0, 2] } else { &[2] };
        if !banks.contains(&bank) {
            return no(Status::InvalidValue, format!("SIO bank {bank}: expected {}", if banks.len() == 2 { "0 or 2" } else { "2" }));
        }
        match port {
            0..=7 if v == 0 || v == 1 || v == -1 => Ok(()),
            255 if (-1..=255).contains(&v) => Ok(()),
            0..=7 | 255 => no(Status::InvalidValue, format!("SIO value {v}: expected 0 or 1 (port 255: 0..255 or −1)")),
            _ => no(Status::WrongType, format!("SIO port {port}: expected 0..7 or 255")),
        }
    }

    /// GIO: inputs (bank 0), analog channels and supply (bank 1), outputs (bank 2)
    /// ([TMCL] §5.7.15).
    fn check_gio(&self, port: u8, bank: u8) -> Result<(), Refusal> {
        match (bank, port) {
            (0 | 2, 0..=7 | 255) | (1, 0 | 4 | 8) => Ok(()),
            (1, 9..=12) => no(Status::WrongType, format!("GIO {port}, 1: temperature and current readings are not modelled")),
            (0..=2, _) => no(Status::WrongType, format!("GIO port {port} of bank {bank} does not exist")),
            _ => no(Status::InvalidValue, format!("GIO bank {bank}: expected 0, 1 or 2")),
        }
    }
}

fn check_address(a: i32) -> Result<(), Refusal> {
    if (0..PROGRAM_SIZE as i32).contains(&a) {
        Ok(())
    } else {
        no(Status::InvalidValue, format!("address {a}: program memory is 0..{}", PROGRAM_SIZE - 1))
    }
}

/// TMCM-1311 values that would start a function needing a motor model this module does not
/// have (closed loop, torque mode, stallGuard2, coolStep).
fn tmcm1311_refused(p: u8, v: i32) -> Option<&'static str> {
    match (p, v) {
        (14 | 19, _) | (128, 2) => Some("torque mode needs closed-loop control, which this module does not model"),
        (129, 1) => Some("closed-loop operation needs a motor model this module does not have"),
        (132, 1) => Some("encoder initialization prepares closed-loop operation, which this module does not model"),
        (172, 1..) => Some("a hysteresis start above 0 enables coolStep, which needs a motor model"),
        (181, 1..) => Some("a stop-on-stall speed enables the stallGuard2 stop, which needs a motor load model"),
        _ => None,
    }
}
