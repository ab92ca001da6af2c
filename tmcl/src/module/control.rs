//! Frames from the host, download mode and the control commands 128..139 ([TMCL] §4, §5.7.37,
//! §5.7.39, §10.1 parameter 81).

use super::*;

impl<C: Spi429> Module<C> {
    /// Handles one frame from the host (9-byte form) and returns what the module sends back.
    pub fn handle_bytes(&mut self, b: &[u8; 9]) -> Response {
        if b[0] != self.gp(66) as u8 {
            return Response::None;
        }
        match Command::from_bytes(b) {
            Ok(c) => self.handle_instruction(&c.ins),
            Err(_) => {
                self.last_cmd_ms = self.now_ms();
                // Wrong checksum: status 1, command and value 0 (as TMCL firmware replies).
                Response::Normal(self.reply(Status::WrongChecksum.code(), 0, 0))
            }
        }
    }

    pub fn reply(&self, status: u8, op: u8, value: i32) -> Reply {
        let (module, host) = self.addresses();
        Reply { host, module, status, op, value }
    }

    /// Module address (global parameter 66) and host address (76).
    pub fn addresses(&self) -> (u8, u8) {
        (self.gp(66) as u8, self.gp(76) as u8)
    }

    /// Global parameter 67 (ASCII interface configuration).
    pub fn ascii_config(&self) -> i32 {
        self.gp(67)
    }

    /// Handles one command in direct mode (with download mode and the control commands).
    pub fn handle_instruction(&mut self, ins: &Instruction) -> Response {
        self.last_cmd_ms = self.now_ms();
        self.heartbeat_tripped = false;
        let (o, v) = (ins.op, ins.value);
        if let Some(addr) = self.download {
            if o < 128 {
                return Response::Normal(self.download_one(addr, ins));
            }
            if matches!(o, op::TARGET_REACHED_EVENT | op::ASCII_MODE) {
                // Download mode takes program instructions and the control commands 128..137.
                return Response::Normal(self.reply(Status::NotAvailable.code(), o, v));
            }
        }
        let (st, val) = match o {
            op::APP_STOP => {
                self.vm.state = AppState::Stop;
                ok(v)
            }
            op::APP_RUN => self.run_command(ins),
            op::APP_STEP => {
                self.vm.state = AppState::Step;
                self.step_program();
                if self.vm.state == AppState::Run {
                    self.vm.state = AppState::Step;
                }
                ok(v)
            }
            op::APP_RESET => {
                self.reset_vm();
                self.vm.state = AppState::Reset;
                ok(v)
            }
            op::DOWNLOAD_START => self.download_start(v),
            op::DOWNLOAD_END => {
                if self.download.take().is_some() {
                    self.save_eeprom();
                }
                ok(v)
            }
            op::READ_MEMORY => self.read_memory(ins.typ, v),
            op::APP_STATUS => ok(self.vm.state as i32),
            op::FIRMWARE_VERSION => match ins.typ {
                0 => return self.version_string(),
                1 => ok(((self.kind.number() as i32) << 16) | ((VERSION.0 as i32) << 8) | VERSION.1 as i32),
                _ => err(Status::WrongType, v),
            },
            op::FACTORY_DEFAULTS => {
                if v == 1234 && !self.eeprom_locked() {
                    self.factory_reset();
                }
                // This command sends no reply ([TMCL] §5.7.39).
                return Response::None;
            }
            // The event reply itself is sent by the link that asked (see `link`).
            op::TARGET_REACHED_EVENT => ok(self.event_mask(v) as i32),
            op::ASCII_MODE => ok(v),
            _ => self.execute(ins, Origin::Direct),
        };
        Response::Normal(self.reply(st, o, val))
    }

    /// One instruction in download mode: checked, stored at `addr`, status 101; a refused one
    /// is not stored (the address stays) and answers its status.
    fn download_one(&mut self, addr: usize, ins: &Instruction) -> Reply {
        if addr >= PROGRAM_SIZE {
            return self.reply(Status::InvalidValue.code(), ins.op, ins.value);
        }
        if let Err(r) = self.check(ins, None) {
            return self.reply(r.status.code(), ins.op, ins.value);
        }
        self.program[addr] = *ins;
        self.download = Some(addr + 1);
        self.prog_len = self.prog_len.max(addr + 1);
        self.reply(Status::Loaded.code(), ins.op, ins.value)
    }

    /// Command 132: download mode from address `v`. Not while the EEPROM is locked or the
    /// program is protected against overwriting (global parameter 81 bit 1).
    fn download_start(&mut self, v: i32) -> (u8, i32) {
        if self.eeprom_locked() {
            err(Status::EepromLocked, v)
        } else if self.gp(81) & 2 != 0 {
            err(Status::NotAvailable, v)
        } else if !(0..PROGRAM_SIZE as i32).contains(&v) {
            err(Status::InvalidValue, v)
        } else {
            self.vm.state = AppState::Stop;
            self.download = Some(v as usize);
            ok(v)
        }
    }

    /// Command 129: type 0 continues a stopped program where it stopped, or starts one that
    /// ran to its end again from address 0; type 1 starts at the address in the value.
    fn run_command(&mut self, ins: &Instruction) -> (u8, i32) {
        let v = ins.value;
        if ins.typ == 1 {
            if !(0..PROGRAM_SIZE as i32).contains(&v) {
                return err(Status::InvalidValue, v);
            }
            self.vm.pc = v as u16;
            self.vm.wait = None;
        } else if self.vm.ended {
            self.reset_vm();
        }
        self.vm.ended = false;
        self.vm.state = AppState::Run;
        ok(v)
    }

    /// Command 134 (its reply is not defined in the manual): type 0 returns
    /// `opcode<<24 | type<<16 | motor<<8`, type 1 the value. Not with global parameter 81
    /// bit 0 (protection against disassembling).
    fn read_memory(&mut self, typ: u8, v: i32) -> (u8, i32) {
        if self.gp(81) & 1 != 0 {
            return err(Status::NotAvailable, v);
        }
        if !(0..PROGRAM_SIZE as i32).contains(&v) {
            return err(Status::InvalidValue, v);
        }
        let p = self.program[v as usize];
        match typ {
            0 => ok(((p.op as i32) << 24) | ((p.typ as i32) << 16) | ((p.motor as i32) << 8)),
            1 => ok(p.value),
            _ => err(Status::WrongType, v),
        }
    }

    /// Command 136 type 0: host address and 8 characters, e.g. `1311V100` ([TMCL] §5.7.39).
    fn version_string(&self) -> Response {
        let s = format!("{:04}V{}{:02}", self.kind.number(), VERSION.0, VERSION.1);
        let mut text = [b'0'; 8];
        text.copy_from_slice(&s.as_bytes()[..8]);
        Response::Version { host: self.gp(76) as u8, text }
    }

    /// Motors selected by the value of command 138: a bit mask of this module's axes; 0 means
    /// motor 0.
    pub fn event_mask(&self, v: i32) -> u8 {
        let m = (v & ((1 << self.kind.axes()) - 1)) as u8;
        if m == 0 {
            1
        } else {
            m
        }
    }
}
