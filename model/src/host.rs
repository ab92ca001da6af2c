//! A virtual microcontroller: drives the chip's µC SPI pins as firmware would (TMC428 §6.2,
//! Table 6-1) and keeps the other input pins.

use crate::regmap;
use crate::{Chip, Inputs, Outputs, Tmc429};

/// Smallest SCK_C half period in CLK cycles that meets TMC428 Table 6-1 (contract C11).
pub const MIN_SCK_HALF: u32 = 3;

/// Called after every CLK edge with the chip, the pins applied and the outputs.
pub type Observer = Box<dyn FnMut(&Tmc429, &Inputs, &Outputs) + Send>;

/// What went wrong configuring the host.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct HostError(pub String);

impl std::fmt::Display for HostError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}
impl std::error::Error for HostError {}

/// The virtual µC with the chip it is wired to.
pub struct Host {
    chip: Tmc429,
    pins: Inputs,
    sck_half: u32,
    last_out: Outputs,
    observer: Option<Observer>,
    /// The observer watches only the edges that may change something ([`Host::set_change_observer`])
    /// once it has seen one edge.
    changes_only: bool,
    /// The observer has seen an edge since it was set.
    observed: bool,
    /// Cycle index at which nSCS_C rose at the end of the last frame.
    last_frame_end: u64,
}

impl Host {
    pub fn new(chip: Chip) -> Self {
        Self::from_chip(Tmc429::new(chip))
    }

    /// A host driving `c` (e.g. [`Tmc429::with_package`]).
    pub fn from_chip(c: Tmc429) -> Self {
        let last_out = c.outputs();
        Host {
            chip: c,
            pins: Inputs::default(),
            sck_half: 4,
            last_out,
            observer: None,
            changes_only: false,
            observed: false,
            last_frame_end: 0,
        }
    }

    /// CLK cycles per SCK_C half period (≥ [`MIN_SCK_HALF`]).
    pub fn set_sck_half(&mut self, half: u32) -> Result<(), HostError> {
        if half < MIN_SCK_HALF {
            return Err(HostError(format!(
                "SCK_C half period of {half} CLK is below the minimum of {MIN_SCK_HALF} CLK (TMC428 Table 6-1)"
            )));
        }
        self.sck_half = half;
        Ok(())
    }

    pub fn sck_half(&self) -> u32 {
        self.sck_half
    }

    /// `obs` is called after every edge.
    pub fn set_observer(&mut self, obs: Observer) {
        self.observer = Some(obs);
        self.changes_only = false;
        self.observed = false;
    }

    /// `obs` is called after the next edge and then after the edges that may change something
    /// it sees; [`Host::wait`] runs the fast path's edges, which change no pin, no INT and no
    /// register ([`Tmc429::tick_changes`] `None`), at once without it. For a watcher of the
    /// pins such as the [`crate::events::EventDecoder`], which learns the levels at its first
    /// edge.
    pub fn set_change_observer(&mut self, obs: Observer) {
        self.observer = Some(obs);
        self.changes_only = true;
        self.observed = false;
    }

    pub fn take_observer(&mut self) -> Option<Observer> {
        self.observer.take()
    }

    pub fn chip(&self) -> &Tmc429 {
        &self.chip
    }

    pub fn chip_mut(&mut self) -> &mut Tmc429 {
        &mut self.chip
    }

    pub fn into_chip(self) -> Tmc429 {
        self.chip
    }

    /// The input pins as they are applied now.
    pub fn pins(&self) -> Inputs {
        self.pins
    }

    /// Changes the non-SPI input pins (REF, REFR, SDI_S) from the next edge on.
    pub fn pins_mut(&mut self) -> &mut Inputs {
        &mut self.pins
    }

    /// Outputs after the last edge.
    pub fn outputs(&self) -> Outputs {
        self.last_out
    }

    /// CLK edges so far.
    pub fn cycle(&self) -> u64 {
        self.chip.cycle()
    }

    /// Index of the CLK edge at which nSCS_C rose at the end of the last frame.
    pub fn last_frame_end(&self) -> u64 {
        self.last_frame_end
    }

    #[inline]
    fn tick(&mut self) {
        self.last_out = self.chip.tick(&self.pins);
        self.observe();
    }

    /// The observer, if any, after an edge.
    #[inline]
    fn observe(&mut self) {
        if let Some(obs) = self.observer.as_mut() {
            obs(&self.chip, &self.pins, &self.last_out);
            self.observed = true;
        }
    }

    /// Advances `cycles` CLK edges with the pins as they are.
    pub fn wait(&mut self, cycles: u64) {
        if self.observer.is_some() && !self.changes_only {
            for _ in 0..cycles {
                self.tick();
            }
            return;
        }
        let mut left = cycles;
        if self.observer.is_some() && !self.observed && left > 0 {
            self.tick();
            left -= 1;
        }
        // The fast path's edges change no pin: they run at once (Tmc429::skip_quiet).
        let pins = crate::sync::pack(&self.pins);
        while left > 0 {
            left -= self.chip.skip_quiet(pins, left);
            if left > 0 {
                self.last_out = self.chip.tick_full(pins);
                self.observe();
                left -= 1;
            }
        }
    }

    fn hold(&mut self) {
        for _ in 0..self.sck_half {
            self.tick();
        }
    }

    /// The data output the µC reads: SDOZ_C while it is enabled, else nINT_SDO_C.
    fn miso(&self) -> bool {
        if self.last_out.sdoz_c_oe {
            self.last_out.sdoz_c
        } else {
            self.last_out.nint_sdo_c
        }
    }

    /// One SPI frame of `nbits` (1..=32) bits, MSB first: nSCS_C low, data set on falling SCK_C,
    /// sampled by the chip on rising SCK_C; the µC samples SDO_C just before each rising edge.
    /// Returns the `nbits` bits received. The same as [`Host::select`], [`Host::shift`],
    /// [`Host::deselect`].
    pub fn frame(&mut self, value: u32, nbits: u32) -> u32 {
        self.select();
        let rx = self.shift(value, nbits);
        self.deselect();
        rx
    }

    /// nSCS_C falls (chip select under the caller's control, as byte-wise drivers hold it across
    /// several transfers), then one SCK_C half period passes.
    pub fn select(&mut self) {
        self.pins.nscs_c = false;
        self.hold();
    }

    /// Whether nSCS_C is low.
    pub fn selected(&self) -> bool {
        !self.pins.nscs_c
    }

    /// `nbits` (1..=32) SCK_C periods with nSCS_C as it is, MSB first; returns the bits received.
    /// With nSCS_C high the chip ignores the clock and the bits read are nINT.
    pub fn shift(&mut self, value: u32, nbits: u32) -> u32 {
        let nbits = nbits.clamp(1, 32);
        let mut rx = 0u32;
        for i in (0..nbits).rev() {
            self.pins.sck_c = false;
            self.pins.sdi_c = (value >> i) & 1 != 0;
            self.hold();
            rx = (rx << 1) | self.miso() as u32;
            self.pins.sck_c = true;
            self.hold();
        }
        rx
    }

    /// nSCS_C rises: the chip executes the frame if it was a whole 32-bit datagram (TMC429 §6.2,
    /// contract C12); then one SCK_C half period passes.
    pub fn deselect(&mut self) {
        self.pins.nscs_c = true;
        self.last_frame_end = self.chip.cycle();
        self.hold();
    }

    /// A 32-bit datagram; returns the 32-bit reply.
    pub fn datagram(&mut self, d: u32) -> u32 {
        self.frame(d, 32)
    }

    /// Writes `data` to the register at `a7`; returns the status byte.
    pub fn write(&mut self, a7: u8, data: u32) -> u8 {
        (self.datagram(regmap::datagram(a7, false, data)) >> 24) as u8
    }

    /// Reads the register at `a7`; returns the 24-bit data.
    pub fn read(&mut self, a7: u8) -> u32 {
        self.datagram(regmap::datagram(a7, true, 0)) & 0xFF_FFFF
    }

    /// Status byte by an 8-bit frame, as vendor drivers read it.
    pub fn status(&mut self) -> u8 {
        self.frame(0, 8) as u8
    }
}
