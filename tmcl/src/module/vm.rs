//! The program interpreter ([TMCL] §4.3, §5.3, §11): accumulator, X register, flags, subroutine
//! stack, WAIT, return from interrupt.

use super::*;

/// Application status (global parameter 128, command 135).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AppState {
    Stop = 0,
    Run = 1,
    Step = 2,
    Reset = 3,
}

/// Condition a WAIT command blocks on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Wait {
    pub kind: u8,
    pub motor: u8,
    /// Millisecond at which the wait ends (TICKS) or times out (others); `None` = no timeout.
    pub deadline: Option<u64>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct Saved {
    pub(super) pc: u16,
    pub(super) accu: i32,
    pub(super) x: i32,
    pub(super) cmp: i8,
    pub(super) eto: bool,
    pub(super) wait: Option<Wait>,
}

/// The TMCL virtual machine: accumulator, X register, flags, stack, interrupts.
#[derive(Clone, Debug)]
pub struct Vm {
    pub state: AppState,
    pub pc: u16,
    pub accu: i32,
    pub x: i32,
    /// Result of the last comparison or load: sign of (accu − operand).
    pub cmp: i8,
    /// Timeout flag (ETO).
    pub eto: bool,
    pub stack: Vec<u16>,
    /// The program ran to its end (STOP, an empty cell): RUN without an address starts it
    /// again from address 0; after command 128 (stop) it resumes where it stopped.
    pub ended: bool,
    pub wait: Option<Wait>,
    pub vectors: [Option<u16>; 256],
    pub enabled: [bool; 256],
    pub global_enable: bool,
    pub pending: [bool; 256],
    pub(super) saved: Option<Saved>,
    pub(super) timer_next: [u64; 3],
}

impl Default for Vm {
    fn default() -> Self {
        Vm {
            state: AppState::Stop,
            pc: 0,
            accu: 0,
            x: 0,
            cmp: 0,
            eto: false,
            stack: Vec::new(),
            ended: false,
            wait: None,
            vectors: [None; 256],
            enabled: [false; 256],
            global_enable: false,
            pending: [false; 256],
            saved: None,
            timer_next: [0; 3],
        }
    }
}

impl<C: Spi429> Module<C> {
    pub(super) fn reset_vm(&mut self) {
        let vectors = self.vm.vectors;
        self.vm = Vm { vectors, ..Vm::default() };
    }

    /// Whether a WAIT is over: its condition holds, or it timed out (sets ETO,
    /// [TMCL] §5.7.22).
    fn wait_done(&mut self, w: &Wait, now: u64) -> bool {
        let m = w.motor as usize;
        let cond = match w.kind {
            0 => return w.deadline.is_some_and(|d| now >= d),
            1 => self.arrived_mask() & (1 << m) != 0,
            2 => self.home_switch(m),
            3 => self.left_switch(m) || self.right_switch(m),
            _ => !self.st[m].rfs.active(),
        };
        if !cond && w.deadline.is_some_and(|d| now >= d) {
            self.vm.eto = true;
            return true;
        }
        cond
    }

    /// The program ends (STOP, an empty cell, the end of memory).
    fn end_program(&mut self) -> bool {
        self.vm.state = AppState::Stop;
        self.vm.ended = true;
        false
    }

    /// Executes one program step. Returns false when the program cannot proceed this
    /// millisecond (stopped or waiting).
    pub fn step_program(&mut self) -> bool {
        if !matches!(self.vm.state, AppState::Run | AppState::Step) {
            return false;
        }
        self.dispatch_interrupt();
        let now = self.now_ms();
        if let Some(w) = self.vm.wait {
            if !self.wait_done(&w, now) {
                return false;
            }
            self.vm.wait = None;
            self.vm.pc = self.vm.pc.wrapping_add(1);
            return true;
        }
        let pc = self.vm.pc as usize;
        if pc >= PROGRAM_SIZE {
            return self.end_program();
        }
        let ins = self.program[pc];
        let next = match ins.op {
            op::WAIT => {
                if self.check(&ins, None).is_err() {
                    return self.end_program();
                }
                let timeout = ins.typ == 0 || ins.value > 0;
                let w = Wait { kind: ins.typ, motor: ins.motor, deadline: timeout.then(|| now + 10 * ins.value.max(0) as u64) };
                if !self.wait_done(&w, now) {
                    self.vm.wait = Some(w);
                    return false;
                }
                self.vm.pc.wrapping_add(1)
            }
            op::STOP => return self.end_program(),
            op::RETI => match self.vm.saved.take() {
                Some(s) => {
                    self.vm.accu = s.accu;
                    self.vm.x = s.x;
                    self.vm.cmp = s.cmp;
                    self.vm.eto = s.eto;
                    self.vm.wait = s.wait;
                    s.pc
                }
                None => self.vm.pc.wrapping_add(1),
            },
            o if crate::asm::is_program_opcode(o) => self.flow(&ins).unwrap_or_else(|| {
                self.execute(&ins, Origin::Program);
                self.vm.pc.wrapping_add(1)
            }),
            // An empty or invalid cell ends the program.
            _ => return self.end_program(),
        };
        self.vm.pc = next;
        self.vm.state != AppState::Stop
    }

    /// JA, JC, CSUB, RSUB: the next program counter; `None` for other commands.
    fn flow(&mut self, ins: &Instruction) -> Option<u16> {
        let next = self.vm.pc.wrapping_add(1);
        let to = ins.value as u16;
        Some(match ins.op {
            op::JA => to,
            op::JC => {
                let c = self.vm.cmp;
                let take = match ins.typ {
                    0 | 2 => c == 0,
                    1 | 3 => c != 0,
                    4 => c > 0,
                    5 => c >= 0,
                    6 => c < 0,
                    7 => c <= 0,
                    8 => self.vm.eto,
                    _ => false,
                };
                if take {
                    to
                } else {
                    next
                }
            }
            // Eight levels; a call with a full stack is ignored ([TMCL] §5.7.20).
            op::CSUB if self.vm.stack.len() < 8 => {
                self.vm.stack.push(next);
                to
            }
            op::CSUB => next,
            op::RSUB => self.vm.stack.pop().unwrap_or(next),
            _ => return None,
        })
    }
}
