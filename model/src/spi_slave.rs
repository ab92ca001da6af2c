//! µC SPI slave (TMC428 §6.2, TMC429 §6.2; contract C10–C13).

use crate::sync::{bit, SyncBank};

/// What the slave asks of the chip in one cycle.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SpiEvent {
    None,
    /// nSCS_C fell: load the status byte (and wake from power down).
    Select,
    /// The 8th bit of a read arrived: load the read data of this address.
    ReadAddress(u8),
    /// nSCS_C rose after exactly 32 bits: execute this datagram.
    Execute(u32),
    /// nSCS_C rose after a frame that was not 32 bits: nothing executes.
    Deselect,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SpiSlave {
    /// Input shift register (bits shifted in so far, last one in bit 0).
    pub shift_in: u32,
    /// Output shift register; bit 31 is on the data output.
    pub shift_out: u32,
    /// Bits received in this frame (saturates at 63).
    pub count: u8,
    /// Synchronized nSCS_C is low (frame in progress).
    pub active: bool,
    /// The read value loaded in the last edge is 1 more in its bits 11..0 (v_actual of a
    /// negative V with a nonzero low byte, C42): added in this edge, before a shift.
    pub round: bool,
}

impl SpiSlave {
    pub fn reset() -> Self {
        SpiSlave { shift_in: 0, shift_out: 0, count: 0, active: false, round: false }
    }

    /// One CLK edge, from the synchronizer state before the edge (`s`). Returns what the chip must
    /// do this cycle; the caller loads the status byte or read data with [`SpiSlave::load_status`]
    /// and [`SpiSlave::load_data`].
    #[inline]
    pub fn step(&mut self, s: &SyncBank) -> SpiEvent {
        if self.round {
            // the read value's bits 11..0 sit at bits 18..7; a new status byte replaces them
            let f = (self.shift_out >> 7).wrapping_add(1) & 0xFFF;
            self.shift_out = (self.shift_out & !(0xFFF << 7)) | f << 7;
            self.round = false;
        }
        self.active = !s.level(bit::NSCS_C);
        if s.fell(bit::NSCS_C) {
            self.count = 0;
            return SpiEvent::Select; // C13: a coinciding SCK_C edge is ignored
        }
        if s.rose(bit::NSCS_C) {
            let ev = if self.count == 32 { SpiEvent::Execute(self.shift_in) } else { SpiEvent::Deselect };
            return ev;
        }
        if !self.active {
            return SpiEvent::None;
        }
        if s.rose(bit::SCK_C) {
            self.shift_in = (self.shift_in << 1) | s.level(bit::SDI_C) as u32;
            if self.count < 63 {
                self.count += 1;
            }
            if self.count == 8 && self.shift_in & 1 == 1 {
                return SpiEvent::ReadAddress(((self.shift_in >> 1) & 0x7F) as u8);
            }
        } else if s.fell(bit::SCK_C) && self.count > 0 {
            // The first falling edge presents bit 31, which is already out (SPI mode 3).
            self.shift_out <<= 1;
        }
        SpiEvent::None
    }

    pub fn load_status(&mut self, status: u8) {
        self.shift_out = (status as u32) << 24;
    }

    /// Loads read data after the 8th rising SCK_C edge: seven falling edges have shifted the
    /// register by then, so data bit 23 goes to bit 30 and leaves on the 8th falling edge.
    /// `round`: the read value is `data` plus 1 in bits 11..0, added in the next edge (its bits
    /// leave twelve falling edges later at the earliest), so that the register file's read
    /// multiplexer has no incrementer.
    pub fn load_data(&mut self, data: u32, round: bool) {
        self.shift_out = (self.shift_out & 0x8000_0000) | ((data & 0xFF_FFFF) << 7);
        self.round = round;
    }

    /// The data output bit.
    #[inline]
    pub fn sdo(&self) -> bool {
        self.shift_out >> 31 != 0
    }
}

/// The µC SPI slave's ports as `rtl/tmc429_spi_slave.v` has them, for one CLK edge (the unit
/// boundary of the test vectors, docs/vectors.md). Inputs besides the three pins: `status`,
/// `rd_data` and `rd_round`, driven by the register file from the old state. Outputs:
/// combinational functions of the slave's registers (the synchronizer flops, the shift
/// registers and the bit counter).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SpiPorts {
    /// Status byte the register file presents (loaded at `frame_start`, C10).
    pub status: u8,
    /// Read data of `rd_addr` the register file presents (loaded after the 8th bit of a read),
    /// v_actual without its rounding toward 0.
    pub rd_data: u32,
    /// v_actual's rounding toward 0: the read value is `rd_data` plus 1 in bits 11..0.
    pub rd_round: bool,
    /// Address of the frame being received: bits 7..1 of the input register after the next shift.
    pub rd_addr: u8,
    /// Synchronized nSCS_C falling edge (acted on at the next CLK edge).
    pub frame_start: bool,
    /// Synchronized nSCS_C rising edge after exactly 32 bits: execute `cmd` (C12).
    pub exec: bool,
    /// Input shift register.
    pub cmd: u32,
    /// The output register drives the data pin (the history flop of nSCS_C is low).
    pub active: bool,
    /// Current data bit: bit 31 of the output register.
    pub sdo: bool,
}

impl SpiSlave {
    /// The outputs of the slave's ports for the register state `self` and the synchronizer
    /// state `s`; `status`, `rd_data` and `rd_round` are left 0 (the register file fills them in).
    pub fn ports(&self, s: &SyncBank) -> SpiPorts {
        let in_next = (self.shift_in << 1) | s.level(bit::SDI_C) as u32;
        SpiPorts {
            status: 0,
            rd_data: 0,
            rd_round: false,
            rd_addr: ((in_next >> 1) & 0x7F) as u8,
            frame_start: s.fell(bit::NSCS_C),
            exec: s.rose(bit::NSCS_C) && self.count == 32,
            cmd: self.shift_in,
            active: (s.s3 >> bit::NSCS_C) & 1 == 0,
            sdo: self.sdo(),
        }
    }
}
