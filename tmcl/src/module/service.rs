//! The firmware's millisecond: switch pins, the serial heartbeat, reference searches, the
//! TMCM-1311's position tracking and encoder, interrupt sources and the program
//! ([TMCL] §5.6, §10.1 parameter 68, §10.4).

use super::*;

impl<C: Spi429> Module<C> {
    pub(super) fn service(&mut self) {
        self.update_pins();
        let now = self.now_ms();
        let hb = self.gp(68);
        if hb > 0 && !self.heartbeat_tripped && now.saturating_sub(self.last_cmd_ms) > hb as u64 {
            // Serial heartbeat expired: stop all motors.
            self.heartbeat_tripped = true;
            for m in 0..self.kind.axes() {
                self.stop_motor(m);
            }
        }
        for m in 0..self.kind.axes() {
            self.rfs_service(m);
            if self.kind == ModuleType::Tmcm1311 {
                // The 32-bit position needs x_actual read at least every 2^23 steps.
                self.track(m);
                self.encoder_service(m);
            }
        }
        self.detect_interrupts(now);
        if self.vm.state == AppState::Run {
            for _ in 0..self.instructions_per_ms {
                if !self.step_program() {
                    break;
                }
            }
        }
    }

    /// Raises the interrupts whose source changed this millisecond: timers (period in bank 3,
    /// 0..2), target reached (on its target at rest: a pass through the target while braking
    /// does not count), stop switch and input edges (transition in bank 3: 1 rising, 2
    /// falling, 3 both), encoder deviation. The sources are followed whether or not an
    /// interrupt is enabled, so EI never fires on an older edge.
    fn detect_interrupts(&mut self, now: u64) {
        let kind = self.kind;
        for t in 0..3 {
            let p = self.irq_cfg[t] as u64;
            if p > 0 && self.vm.enabled[t] && now >= self.vm.timer_next[t] {
                self.vm.pending[t] = true;
                self.vm.timer_next[t] = now + p;
            }
        }
        let r = self.arrived_mask();
        let rising = r & !self.edges.reached;
        self.edges.reached = r;
        for m in 0..kind.axes() {
            if rising & (1 << m) != 0 {
                self.raise(kind.target_irq(m));
            }
        }
        let s = self.switch_register();
        let changed = s ^ self.edges.switches;
        self.edges.switches = s;
        for m in 0..kind.axes() {
            for (n, bit) in [(kind.stop_left_irq(m), 2u8 << (2 * m)), (kind.stop_left_irq(m) + 1, 1u8 << (2 * m))] {
                self.edge(n, changed & bit != 0, s & bit != 0);
            }
        }
        let inp = self.inputs();
        let changed = inp ^ self.edges.inputs;
        self.edges.inputs = inp;
        for i in 0..8u8 {
            self.edge(39 + i, changed & (1 << i) != 0, inp & (1 << i) != 0);
        }
        let dev = self.st[0].deviation;
        if dev && !self.edges.deviation {
            self.raise(21);
        }
        self.edges.deviation = dev;
    }

    /// An edge of a switch or input: raises interrupt `n` when bank 3 asks for it.
    fn edge(&mut self, n: u8, changed: bool, high: bool) {
        let cfg = self.irq_cfg[n as usize];
        if changed && ((high && cfg & 1 != 0) || (!high && cfg & 2 != 0)) {
            self.raise(n);
        }
    }

    fn raise(&mut self, n: u8) {
        if self.kind.interrupt_exists(n) && self.vm.enabled[n as usize] {
            self.vm.pending[n as usize] = true;
        }
    }

    /// Calls the handler of the pending interrupt with the lowest number (the highest
    /// priority, [TMCL] §10.4); none while a handler runs (no nesting, §5.6.2).
    pub(super) fn dispatch_interrupt(&mut self) -> bool {
        if !self.vm.global_enable || self.vm.saved.is_some() {
            return false;
        }
        for n in 0..255usize {
            if self.vm.pending[n] && self.vm.enabled[n] {
                if let Some(addr) = self.vm.vectors[n] {
                    self.vm.pending[n] = false;
                    self.vm.saved = Some(vm::Saved {
                        pc: self.vm.pc,
                        accu: self.vm.accu,
                        x: self.vm.x,
                        cmp: self.vm.cmp,
                        eto: self.vm.eto,
                        wait: self.vm.wait.take(),
                    });
                    self.vm.pc = addr;
                    return true;
                }
            }
        }
        false
    }
}
