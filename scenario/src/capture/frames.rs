//! The µC's SPI frames in a capture (TMC428 §6.2: SPI mode 3, MSB first): from nSCS_C falling
//! to nSCS_C rising, one bit per rising SCK_C edge, where the chip samples SDI_C and the µC
//! samples the data output (nINT_SDO_C or SDOZ_C).

use super::pins::{Pin, PinMap};
use super::{Capture, CaptureError};

/// One frame of a capture; sample indices.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CapFrame {
    /// nSCS_C fell.
    pub start: u64,
    /// nSCS_C rose.
    pub end: u64,
    /// Rising SCK_C edges (first sample showing SCK_C high), one per bit.
    pub rises: Vec<u64>,
    /// Bits the µC sent (first bit sent in bit `nbits − 1`; beyond 64 bits the last 64).
    pub mosi: u64,
    /// Bits the chip answered.
    pub miso: u64,
}

impl CapFrame {
    pub fn nbits(&self) -> u32 {
        self.rises.len() as u32
    }
    /// The 32-bit datagram of a 32-bit frame.
    pub fn datagram(&self) -> Option<u32> {
        (self.nbits() == 32).then_some(self.mosi as u32)
    }
}

/// The frames, and the shortest SCK_C low and high times within them (samples).
pub struct Frames {
    pub frames: Vec<CapFrame>,
    /// A frame the capture ends in (nSCS_C low at the end): its start sample (not compared).
    pub unfinished: Option<u64>,
    pub min_half: Option<u64>,
}

/// Decodes the frames. `data` is the pin the µC reads.
pub fn decode(cap: &Capture, map: &PinMap, data: Pin, file: &str) -> Result<Frames, CaptureError> {
    let ch = |p: Pin| &cap.channels[map.get(p).expect("required pins are mapped")];
    let (cs, sck, sdi, sdo) = (ch(Pin::NscsC), ch(Pin::SckC), ch(Pin::SdiC), ch(data));
    let mut frames = Vec::new();
    let mut unfinished = None;
    let mut min_half: Option<u64> = None;
    // nSCS_C low intervals
    let mut k = 0;
    let mut low_from = (!cs.initial).then_some(0u64);
    loop {
        let next = cs.edges.get(k).copied();
        k += 1;
        match (low_from, next) {
            (None, Some(e)) => low_from = Some(e),
            (Some(s), Some(e)) => {
                frames.push(frame(s, e, sck, sdi, sdo, &mut min_half));
                low_from = None;
            }
            (Some(s), None) => {
                unfinished = Some(s);
                break;
            }
            (None, None) => break,
        }
    }
    if let Some(first) = frames.first() {
        if first.start == 0 && !cs.initial {
            return Err(CaptureError(format!(
                "{file}: the capture starts inside a µC frame (nSCS_C low at sample 0): start the capture before the first frame"
            )));
        }
    }
    Ok(Frames { frames, unfinished, min_half })
}

fn frame(start: u64, end: u64, sck: &super::Channel, sdi: &super::Channel, sdo: &super::Channel, min_half: &mut Option<u64>) -> CapFrame {
    let from = sck.edges.partition_point(|&e| e <= start);
    let to = sck.edges.partition_point(|&e| e < end);
    let mut rises = Vec::new();
    let (mut mosi, mut miso) = (0u64, 0u64);
    let mut prev: Option<u64> = None;
    for &e in &sck.edges[from..to] {
        if let Some(p) = prev {
            let h = e - p;
            *min_half = Some(min_half.map_or(h, |m: u64| m.min(h)));
        }
        prev = Some(e);
        if sck.level(e) {
            rises.push(e);
            mosi = (mosi << 1) | sdi.level(e) as u64;
            miso = (miso << 1) | sdo.level(e) as u64;
        }
    }
    CapFrame { start, end, rises, mosi, miso }
}
