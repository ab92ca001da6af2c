//! TMCL binary protocol ([TMCL] §4.1, §4.2): 9-byte commands and replies with an
//! 8-bit sum checksum, and the 7-byte form used without address and checksum.

use std::fmt;

/// Reply status codes ([TMCL] §4.2.1), plus the code of the target-reached event reply (§5.7.37).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[repr(u8)]
pub enum Status {
    /// 100: successfully executed, no error.
    Ok = 100,
    /// 101: command loaded into TMCL program EEPROM.
    Loaded = 101,
    /// 1: wrong checksum.
    WrongChecksum = 1,
    /// 2: invalid command.
    InvalidCommand = 2,
    /// 3: wrong type.
    WrongType = 3,
    /// 4: invalid value.
    InvalidValue = 4,
    /// 5: configuration EEPROM locked.
    EepromLocked = 5,
    /// 6: command not available.
    NotAvailable = 6,
    /// 128: the additional reply of command 138 (target position reached event).
    TargetReachedEvent = 128,
}

impl Status {
    pub fn code(self) -> u8 {
        self as u8
    }
    pub fn from_code(c: u8) -> Option<Status> {
        Some(match c {
            100 => Status::Ok,
            101 => Status::Loaded,
            1 => Status::WrongChecksum,
            2 => Status::InvalidCommand,
            3 => Status::WrongType,
            4 => Status::InvalidValue,
            5 => Status::EepromLocked,
            6 => Status::NotAvailable,
            128 => Status::TargetReachedEvent,
            _ => return None,
        })
    }
    /// The manual's wording (§4.2.1).
    pub fn meaning(self) -> &'static str {
        match self {
            Status::Ok => "Successfully executed, no error",
            Status::Loaded => "Command loaded into TMCL program EEPROM",
            Status::WrongChecksum => "Wrong checksum",
            Status::InvalidCommand => "Invalid command",
            Status::WrongType => "Wrong type",
            Status::InvalidValue => "Invalid value",
            Status::EepromLocked => "Configuration EEPROM locked",
            Status::NotAvailable => "Command not available",
            Status::TargetReachedEvent => "Target position reached (event)",
        }
    }
}

/// Command numbers ([TMCL] §5).
pub mod op {
    pub const ROR: u8 = 1;
    pub const ROL: u8 = 2;
    pub const MST: u8 = 3;
    pub const MVP: u8 = 4;
    pub const SAP: u8 = 5;
    pub const GAP: u8 = 6;
    pub const STAP: u8 = 7;
    pub const RSAP: u8 = 8;
    pub const SGP: u8 = 9;
    pub const GGP: u8 = 10;
    pub const STGP: u8 = 11;
    pub const RSGP: u8 = 12;
    pub const RFS: u8 = 13;
    pub const SIO: u8 = 14;
    pub const GIO: u8 = 15;
    pub const CALC: u8 = 19;
    pub const COMP: u8 = 20;
    pub const JC: u8 = 21;
    pub const JA: u8 = 22;
    pub const CSUB: u8 = 23;
    pub const RSUB: u8 = 24;
    pub const EI: u8 = 25;
    pub const DI: u8 = 26;
    pub const WAIT: u8 = 27;
    pub const STOP: u8 = 28;
    pub const SCO: u8 = 30;
    pub const GCO: u8 = 31;
    pub const CCO: u8 = 32;
    pub const CALCX: u8 = 33;
    pub const AAP: u8 = 34;
    pub const AGP: u8 = 35;
    pub const CLE: u8 = 36;
    pub const VECT: u8 = 37;
    pub const RETI: u8 = 38;
    pub const ACO: u8 = 39;
    /// UF0..UF7 are 64..71.
    pub const UF0: u8 = 64;
    pub const UF7: u8 = 71;
    pub const APP_STOP: u8 = 128;
    pub const APP_RUN: u8 = 129;
    pub const APP_STEP: u8 = 130;
    pub const APP_RESET: u8 = 131;
    pub const DOWNLOAD_START: u8 = 132;
    pub const DOWNLOAD_END: u8 = 133;
    pub const READ_MEMORY: u8 = 134;
    pub const APP_STATUS: u8 = 135;
    pub const FIRMWARE_VERSION: u8 = 136;
    pub const FACTORY_DEFAULTS: u8 = 137;
    pub const TARGET_REACHED_EVENT: u8 = 138;
    pub const ASCII_MODE: u8 = 139;
}

/// The seven fields every command has ([TMCL] §4.1): command, type, motor/bank, value.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub struct Instruction {
    pub op: u8,
    pub typ: u8,
    pub motor: u8,
    pub value: i32,
}

impl Instruction {
    pub fn new(op: u8, typ: u8, motor: u8, value: i32) -> Self {
        Instruction { op, typ, motor, value }
    }
    /// The 7-byte form (no address, no checksum; [TMCL] §4.1 "When using CAN bus").
    pub fn to_bytes7(&self) -> [u8; 7] {
        let v = self.value.to_be_bytes();
        [self.op, self.typ, self.motor, v[0], v[1], v[2], v[3]]
    }
    pub fn from_bytes7(b: &[u8; 7]) -> Self {
        Instruction { op: b[0], typ: b[1], motor: b[2], value: i32::from_be_bytes([b[3], b[4], b[5], b[6]]) }
    }
}

/// 8-bit sum of all bytes ([TMCL] §4.1.1).
pub fn checksum(bytes: &[u8]) -> u8 {
    bytes.iter().fold(0u8, |s, b| s.wrapping_add(*b))
}

/// A 9-byte command frame: module address, instruction, checksum.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Command {
    pub address: u8,
    pub ins: Instruction,
}

/// Why a 9-byte frame was not accepted.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FrameError {
    /// The received checksum byte and the sum of the first eight bytes.
    Checksum { received: u8, computed: u8 },
}

impl fmt::Display for FrameError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            FrameError::Checksum { received, computed } => {
                write!(f, "wrong checksum: received ${received:02x}, computed ${computed:02x}")
            }
        }
    }
}

impl Command {
    pub fn new(address: u8, op: u8, typ: u8, motor: u8, value: i32) -> Self {
        Command { address, ins: Instruction::new(op, typ, motor, value) }
    }
    pub fn to_bytes(&self) -> [u8; 9] {
        let s = self.ins.to_bytes7();
        let mut b = [0u8; 9];
        b[0] = self.address;
        b[1..8].copy_from_slice(&s);
        b[8] = checksum(&b[..8]);
        b
    }
    /// Decodes a 9-byte frame; a checksum mismatch is reported (the module answers it with status 1).
    pub fn from_bytes(b: &[u8; 9]) -> Result<Command, FrameError> {
        let computed = checksum(&b[..8]);
        if computed != b[8] {
            return Err(FrameError::Checksum { received: b[8], computed });
        }
        let mut s = [0u8; 7];
        s.copy_from_slice(&b[1..8]);
        Ok(Command { address: b[0], ins: Instruction::from_bytes7(&s) })
    }
}

/// A reply ([TMCL] §4.2): reply (host) address, module address, status, command number, value.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Reply {
    pub host: u8,
    pub module: u8,
    pub status: u8,
    pub op: u8,
    pub value: i32,
}

impl Reply {
    pub fn to_bytes(&self) -> [u8; 9] {
        let v = self.value.to_be_bytes();
        let mut b = [self.host, self.module, self.status, self.op, v[0], v[1], v[2], v[3], 0];
        b[8] = checksum(&b[..8]);
        b
    }
    /// The 7-byte form: the first byte (reply address) and the checksum left out.
    pub fn to_bytes7(&self) -> [u8; 7] {
        let v = self.value.to_be_bytes();
        [self.module, self.status, self.op, v[0], v[1], v[2], v[3]]
    }
    pub fn from_bytes(b: &[u8; 9]) -> Result<Reply, FrameError> {
        let computed = checksum(&b[..8]);
        if computed != b[8] {
            return Err(FrameError::Checksum { received: b[8], computed });
        }
        Ok(Reply { host: b[0], module: b[1], status: b[2], op: b[3], value: i32::from_be_bytes([b[4], b[5], b[6], b[7]]) })
    }
    pub fn status(&self) -> Option<Status> {
        Status::from_code(self.status)
    }
}

/// What the module sends back for one command.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Response {
    /// The normal 9-byte reply.
    Normal(Reply),
    /// Command 136 type 0: host address and an 8-character version string, no checksum (§5.7.39).
    Version { host: u8, text: [u8; 8] },
    /// No reply at all (command 137, frames for another address).
    None,
}

impl Response {
    pub fn to_bytes(&self) -> Vec<u8> {
        match self {
            Response::Normal(r) => r.to_bytes().to_vec(),
            Response::Version { host, text } => {
                let mut v = vec![*host];
                v.extend_from_slice(text);
                v
            }
            Response::None => Vec::new(),
        }
    }
}
