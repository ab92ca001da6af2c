//! One host link (a TCP connection or the pseudo-terminal): the byte stream in binary mode
//! (9-byte frames, partial frames dropped after a pause) and in ASCII mode ([TMCL] §4.4).

use crate::chip::Spi429;
use crate::module::Module;
use crate::proto::{op, Instruction, Response, Status};

/// A partial binary frame is discarded when no byte follows within this time [ms].
pub const DEFAULT_FRAME_TIMEOUT_MS: u64 = 50;
/// Longest ASCII command line kept; longer lines are answered with status 2.
const MAX_LINE: usize = 128;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    Binary,
    Ascii,
}

/// State of one link.
pub struct Link {
    pub mode: Mode,
    buf: Vec<u8>,
    last_byte_ms: u64,
    line: Vec<u8>,
    /// ASCII: the line's address character matched (Some(true)) or not (Some(false)).
    addressed: Option<bool>,
    line_overflow: bool,
    /// Outstanding target-reached event (command 138): motor mask.
    event: Option<u8>,
    pub frame_timeout_ms: u64,
}

impl Link {
    /// A new link; `ascii_start` = bit 0 of global parameter 67.
    pub fn new(ascii_start: bool) -> Self {
        Link {
            mode: if ascii_start { Mode::Ascii } else { Mode::Binary },
            buf: Vec::with_capacity(9),
            last_byte_ms: 0,
            line: Vec::new(),
            addressed: None,
            line_overflow: false,
            event: None,
            frame_timeout_ms: DEFAULT_FRAME_TIMEOUT_MS,
        }
    }

    /// For a new link on a module: starts in ASCII mode when global parameter 67 says so.
    pub fn for_module<C: Spi429>(m: &Module<C>) -> Self {
        Link::new(m.ascii_config() & 1 != 0)
    }

    /// Bytes received at `now_ms` (wall-clock milliseconds of the link); returns what to send.
    pub fn feed<C: Spi429>(&mut self, m: &mut Module<C>, data: &[u8], now_ms: u64) -> Vec<u8> {
        let mut out = Vec::new();
        for &b in data {
            match self.mode {
                Mode::Binary => {
                    if !self.buf.is_empty() && now_ms.saturating_sub(self.last_byte_ms) > self.frame_timeout_ms {
                        self.buf.clear();
                    }
                    self.last_byte_ms = now_ms;
                    self.buf.push(b);
                    if self.buf.len() == 9 {
                        let mut f = [0u8; 9];
                        f.copy_from_slice(&self.buf);
                        self.buf.clear();
                        self.binary_frame(m, &f, &mut out);
                    }
                }
                Mode::Ascii => self.ascii_byte(m, b, &mut out),
            }
        }
        out
    }

    fn binary_frame<C: Spi429>(&mut self, m: &mut Module<C>, f: &[u8; 9], out: &mut Vec<u8>) {
        let resp = m.handle_bytes(f);
        out.extend_from_slice(&resp.to_bytes());
        if let Response::Normal(r) = resp {
            // In download mode the module answers 138 and 139 with status 6.
            if r.status == Status::Ok.code() {
                if r.op == op::ASCII_MODE {
                    self.mode = Mode::Ascii;
                    self.line.clear();
                    self.addressed = None;
                } else if r.op == op::TARGET_REACHED_EVENT {
                    self.event = Some(r.value as u8);
                }
            }
        }
    }

    /// Periodic work: drops a stale partial frame, sends the target-reached event.
    pub fn poll<C: Spi429>(&mut self, m: &mut Module<C>, now_ms: u64) -> Vec<u8> {
        if !self.buf.is_empty() && now_ms.saturating_sub(self.last_byte_ms) > self.frame_timeout_ms {
            self.buf.clear();
        }
        let mut out = Vec::new();
        if let Some(mask) = self.event {
            if m.arrived_mask() & mask == mask {
                self.event = None;
                let r = m.reply(Status::TargetReachedEvent.code(), op::TARGET_REACHED_EVENT, mask as i32);
                out.extend_from_slice(&r.to_bytes());
            }
        }
        out
    }

    /// Whether a target-reached event is outstanding.
    pub fn event_pending(&self) -> bool {
        self.event.is_some()
    }

    fn ascii_byte<C: Spi429>(&mut self, m: &mut Module<C>, b: u8, out: &mut Vec<u8>) {
        let (module_addr, _) = m.addresses();
        let echo = (m.ascii_config() >> 4) & 3;
        match b {
            b'\r' => {
                let addressed = self.addressed == Some(true);
                if addressed {
                    match echo {
                        0 => out.push(b'\r'),
                        1 => {
                            out.extend_from_slice(&self.line);
                            out.push(b'\r');
                        }
                        _ => {}
                    }
                    let line = String::from_utf8_lossy(&self.line).into_owned();
                    let overflow = self.line_overflow;
                    self.line.clear();
                    self.addressed = None;
                    self.line_overflow = false;
                    self.ascii_line(m, &line, overflow, out);
                } else {
                    self.line.clear();
                    self.addressed = None;
                    self.line_overflow = false;
                }
            }
            b'\n' | 0 => {}
            0x08 | 0x7f => {
                if self.addressed == Some(true) && self.line.len() > 1 {
                    self.line.pop();
                    if echo == 0 {
                        out.push(b);
                    }
                }
            }
            _ => {
                if self.addressed.is_none() {
                    if b == b' ' || b == b'\t' {
                        return;
                    }
                    self.addressed = Some(b == address_char(module_addr));
                }
                if self.addressed == Some(true) {
                    if self.line.len() < MAX_LINE {
                        self.line.push(b);
                    } else {
                        self.line_overflow = true;
                    }
                    if echo == 0 {
                        out.push(b);
                    }
                }
            }
        }
    }

    fn ascii_line<C: Spi429>(&mut self, m: &mut Module<C>, line: &str, overflow: bool, out: &mut Vec<u8>) {
        // The address character is the first one of the line (it matched).
        let body = line.get(1..).unwrap_or("").trim();
        let (status, value) = if overflow { (Status::InvalidCommand.code(), 0) } else { ascii_execute(m, body, &mut self.mode) };
        let (module_addr, host_addr) = m.addresses();
        let text = format!("{}{} {} {}\r", address_char(host_addr) as char, address_char(module_addr) as char, status, value);
        out.extend_from_slice(text.as_bytes());
    }
}

/// The ASCII address character of an address: 'A' for 1, 'B' for 2, … ([TMCL] §4.4.1).
pub fn address_char(addr: u8) -> u8 {
    b'A'.wrapping_add(addr.wrapping_sub(1))
}

/// Commands usable in ASCII mode ([TMCL] §4.4.3).
const ASCII_COMMANDS: &[u8] = &[
    op::ROL,
    op::ROR,
    op::MST,
    op::MVP,
    op::SAP,
    op::GAP,
    op::STAP,
    op::RSAP,
    op::SGP,
    op::GGP,
    op::STGP,
    op::RSGP,
    op::RFS,
    op::SIO,
    op::GIO,
    op::SCO,
    op::GCO,
    op::CCO,
    64,
    65,
    66,
    67,
    68,
    69,
    70,
    71,
];

fn ascii_execute<C: Spi429>(m: &mut Module<C>, body: &str, mode: &mut Mode) -> (u8, i32) {
    let word = body.split(|c: char| c.is_ascii_whitespace() || c == ',').next().unwrap_or("");
    let rest = body[word.len()..].trim();
    if word.eq_ignore_ascii_case("BIN") {
        *mode = Mode::Binary;
        return (Status::Ok.code(), 0);
    }
    if word.eq_ignore_ascii_case("RUN") {
        let ins = if rest.is_empty() {
            Instruction::new(op::APP_RUN, 0, 0, 0)
        } else {
            match rest.parse::<i32>() {
                Ok(a) => Instruction::new(op::APP_RUN, 1, 0, a),
                Err(_) => return (Status::InvalidValue.code(), 0),
            }
        };
        return status_of(m.handle_instruction(&ins));
    }
    if word.eq_ignore_ascii_case("STOP") {
        return status_of(m.handle_instruction(&Instruction::new(op::APP_STOP, 0, 0, 0)));
    }
    let Some(o) = crate::asm::opcode_of(word) else {
        return (Status::InvalidCommand.code(), 0);
    };
    if !ASCII_COMMANDS.contains(&o) {
        return (Status::InvalidCommand.code(), 0);
    }
    match crate::asm::parse_line(body) {
        Ok(ins) => status_of(m.handle_instruction(&ins)),
        Err(_) => (Status::InvalidValue.code(), 0),
    }
}

fn status_of(r: Response) -> (u8, i32) {
    match r {
        Response::Normal(r) => (r.status, r.value),
        _ => (Status::Ok.code(), 0),
    }
}
