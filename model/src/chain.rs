//! Driver-chain SPI master (TMC428 §6.3, §9.1–§9.3, §9.7, §10, §11; TMC429 §8.2.1–§8.2.5, §11;
//! contract C80–C89).
//!
//! A synchronous state machine with one down-counter. Every edge computes the new state from
//! the old state (C1): the motors' step flags, microstep indices and velocities, the RAM, the
//! global registers and the synchronized SDI_S of the previous edge.
//!
//! Frame of one datagram (C82), with LO/HI the SCK_S low/high half periods and P = LO + HI:
//!
//! RAM reads (C80): the state before a bit's LOW entry (SETUP, HIGH or GAP) is at least 8 edges
//! long; at its edge with 4 edges left the bit's configuration cell is read, at the edge with 3
//! left the LUT cell its code needs, each from that edge's old state (one read per edge, so the
//! RTL's synchronous RAM read port needs no write forwarding, and the RTL has two more edges to
//! scale the LUT value and form the bit).
//! ```text
//! IDLE ──request──► SETUP (CS active, SCK high, HI edges: t_HDSCSdrv)
//!   ► LOW (bit on SDO_S, SCK low, LO edges) ► HIGH (SCK high, SDI_S sampled at its first edge,
//!     HI edges) ► next bit, or GAP (NxM with motor < LSMD, G edges) ► next bit,
//!     or HOLD (NxM with motor = LSMD, CS active, SCK high, HI edges)
//!   ► CSOFF (CS inactive, SDO_S high, P edges: twice t_SUSCSdrv) ► next datagram or IDLE
//! ```
//! A datagram of n bits thus lasts (n + 2)·P plus its gaps, the sum of TMC429 Table 11.2
//! (8 + 8 + 1·16 + 8 + 8 = 48 CLK for one bit at clk2_div 7, C82).

use crate::current::CurrentScale;
use crate::microstep::{self, Polarity};
use crate::motor_regs::Motor;
use crate::regmap::f;
use crate::Global;

/// Sequencer states (the `state` field of [`crate::ChainProbe`]).
pub const IDLE: u8 = 0;
pub const SETUP: u8 = 1;
pub const LOW: u8 = 2;
pub const HIGH: u8 = 3;
pub const GAP: u8 = 4;
pub const HOLD: u8 = 5;
pub const CSOFF: u8 = 6;

const MASK48: u64 = (1 << 48) - 1;
/// Ramp ticks per continuous-update request of a motor: 2^(15+ramp_div) CLK / (32·2^ramp_div).
pub const CUPD_RAMP_TICKS: u16 = 1024;
/// Reset values of the continuous-update counters: a third of the period apart, so that
/// motors with equal ramp_div never request in the same frame (C83).
pub const CUPD_RESET: [u16; 3] = [0, 341, 682];
/// The datagram bit position counter saturates here (cover positions end at 63 + 24).
const BITS_MAX: u8 = 127;

/// SCK_S timing of a clk2_div value (C81): (LO, HI, P, G) in CLK edges.
/// LO = clk2_div + 1; HI = LO for clk2_div ≥ 7, else 15 − clk2_div (the period stays 16 CLK,
/// the duty cycle becomes asymmetric, TMC428 §9.7); G, the NxM processing gap, is one period for
/// clk2_div ≤ 7 and 1.5 periods above (TMC428 §9.7).
#[inline]
pub fn timing(clk2_div: u32) -> (u16, u16, u16, u16) {
    let c = (clk2_div & 0xFF) as u16;
    let lo = c + 1;
    let hi = if c >= 7 { c + 1 } else { 15 - c };
    let p = lo + hi;
    let g = if c <= 7 { p } else { 3 * (c + 1) };
    (lo, hi, p, g)
}

/// The inputs of the driver-chain master at its RTL boundary (`tmc429_chain`, rtl/README.md
/// "Unit ports"): levels of the old state, presented before a CLK edge (C70). Bit m / element m
/// is motor m. `clk2_div` is the register of the state (the RTL's SCK_S timing registers load
/// it in the edge that writes it: `clk2_div_we`, `clk2_div_wd` of the line before).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ChainInputs {
    pub run: bool,
    pub spi_mode: bool,
    pub step: u8,
    pub dir: u8,
    pub ustep: [u8; 3],
    pub i_scale: [u8; 3],
    pub ramp_tick: u8,
    pub clk2_div: u8,
    pub lsmd: u8,
    pub pol_ph_ab: bool,
    pub pol_fd_ab: bool,
    pub pol_dac_ab: bool,
    pub cont_update: bool,
    pub cw: bool,
    pub dgw: bool,
    /// A µC write of datagram_low_word or datagram_high_word executes in this edge: the
    /// readback register is cleared (C87).
    pub readback_clr: bool,
    pub cover_pos: u8,
    pub cover_len: u8,
    pub cover_datagram: u32,
    pub sdi_s: bool,
}

/// The RAM read of the state `c` (C80): `Some((cell, is_cfg))` at the edge with cnt = 4 (the
/// bit's configuration cell) or cnt = 3 (its LUT cell; the cell then depends on the value the
/// read port holds, bit 3 = coil B) of SETUP, HIGH or GAP.
pub fn ram_read(c: &Chain, ram_q: u8) -> Option<(u8, bool)> {
    if !matches!(c.state, SETUP | HIGH | GAP) {
        return None;
    }
    match c.cnt {
        4 => Some((if c.state == HIGH { (c.cell + 1) & 63 } else { c.cell & 63 }, true)),
        3 => Some((microstep::lut_cell(c.snap_w[(c.motor as usize).min(2)], ram_q) as u8, false)),
        _ => None,
    }
}

/// Driver-chain state.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Chain {
    pub state: u8,
    /// Edges left in the current state (≥ 1 while not IDLE).
    pub cnt: u16,
    /// Configuration RAM cell of the current bit (0..63).
    pub cell: u8,
    /// Motor (SMDA) of the current bit.
    pub motor: u8,
    /// Datagram bits sent so far (position of the current bit; saturates at 127).
    pub bits: u8,
    /// A request arrived and no datagram has started since (requests collapse).
    pub req: bool,
    /// Bit m: a step of motor m since its last snapshot (code $13, C84).
    pub stepped: u8,
    /// Snapshot taken at the start of the datagram (C80): per motor the full-wave index, the
    /// selected current scale, the direction (bit m) and the step flag (bit m); the polarities.
    pub snap_w: [u8; 3],
    pub snap_i_scale: [u8; 3],
    pub snap_dir: u8,
    pub snap_step: u8,
    pub snap_pol: Polarity,
    /// Configuration cell of the next bit, read 4 edges before its LOW entry (C80).
    pub cfg: u8,
    /// LUT cell the next bit's code needs, read 3 edges before its LOW entry (C80).
    pub lut: u8,
    /// NxM bit of the cell of the bit being sent (from `cfg`, taken at its LOW entry).
    pub nxm: bool,
    /// The datagram in progress carries the cover datagram (cw taken at its start).
    pub cover_busy: bool,
    /// A datagram_low/high_word write was pending at the start of the datagram in progress.
    pub dgw_busy: bool,
    /// Cover position, end (position + length, the length at most 24) and data latched at the
    /// start (C85).
    pub cov_pos: u8,
    pub cov_end: u8,
    pub cov_data: u32,
    /// Ramp ticks per motor for continuous update (mod 1024, C83).
    pub cupd: [u16; 3],
    /// Chip select active (before polarity), SCK_S level (before polarity), SDO_S level (high
    /// from reset and whenever the chip select is inactive, C2, C81).
    pub cs: bool,
    pub sck: bool,
    pub sdo: bool,
    /// SDI_S readback register (C87): R := R << 1 | SDI_S at each rising SCK_S; 0 after a
    /// datagram_low/high_word write ([`Chain::clear_readback`]). It survives an en_sd abort.
    pub readback: u64,
}

/// The take/return handshake of one chain edge with the register file, which holds the cover
/// flag cw and the datagram-word flag (C85, C88, C89; the `take`, `ret_cw`, `ret_dgw` outputs of
/// `rtl/tmc429_chain.v`). `changed`: a pin-relevant chain state changed.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Handshake {
    pub changed: bool,
    /// A datagram starts: cw and the datagram-word flag are taken (the register file clears them).
    pub take: bool,
    /// En_sd abort (C89): a taken cover / datagram-word flag returns to waiting.
    pub ret_cw: bool,
    pub ret_dgw: bool,
}

impl Default for Chain {
    fn default() -> Self {
        Self::reset()
    }
}

impl Chain {
    pub fn reset() -> Self {
        Chain {
            state: IDLE,
            cnt: 0,
            cell: 0,
            motor: 0,
            bits: 0,
            req: false,
            stepped: 0,
            snap_w: [0; 3],
            snap_i_scale: [0; 3],
            snap_dir: 0,
            snap_step: 0,
            snap_pol: Polarity::default(),
            cfg: 0,
            lut: 0,
            nxm: false,
            cover_busy: false,
            dgw_busy: false,
            cov_pos: 0,
            cov_end: 0,
            cov_data: 0,
            cupd: CUPD_RESET,
            cs: false,
            sck: true,
            sdo: true,
            readback: 0,
        }
    }

    /// One CLK edge of the SPI chain (C80–C89). `enabled`: the chip is in SPI mode (TMC428,
    /// TMC429 with en_sd = 0). `g`: the global registers of the old state, with the register
    /// file's cw and datagram-word flags. `ramp_ticks`: bit m = motor m has a ramp tick this
    /// cycle. `sdi_s`: the synchronized SDI_S (C4). Returns the handshake with the register file;
    /// the chain changes no state but its own.
    #[allow(clippy::too_many_arguments)]
    #[inline]
    pub fn tick(
        &mut self,
        enabled: bool,
        ram: &[u8; 128],
        g: &Global,
        motors: &[Motor; 3],
        cur: &[CurrentScale; 3],
        ramp_ticks: u8,
        sdi_s: bool,
    ) -> Handshake {
        if !enabled {
            if self.state != IDLE || self.cs || self.req || self.stepped != 0 {
                return self.abort();
            }
            return Handshake::default();
        }
        // Requests (C83): a step of any motor, cw, the continuous-update timer.
        let steps = motors[0].step as u8 | (motors[1].step as u8) << 1 | (motors[2].step as u8) << 2;
        let cont = g.g(f::CONT_UPDATE) != 0;
        // Fast path: counting down inside a state, no RAM read at this edge.
        if self.counting_only() && (ramp_ticks == 0 || !cont) {
            self.cnt -= 1;
            self.req |= steps != 0 || g.cw;
            self.stepped |= steps;
            return Handshake::default();
        }
        // the counters advance with every ramp tick, whatever else requests
        let wrap = cont && self.count_ramp_ticks(ramp_ticks);
        let request = self.req || steps != 0 || g.cw || wrap;
        let (start, changed) = self.advance(ram, g, sdi_s, request);
        if start {
            self.start(g, motors, cur);
        } else {
            // In IDLE without a start no request is pending; elsewhere requests collapse.
            self.req = request;
            self.stepped |= steps;
        }
        Handshake { changed, take: start, ret_cw: false, ret_dgw: false }
    }

    /// The continuous-update counters (C83): each motor with a ramp tick in this edge counts;
    /// true when one of them wraps (a request).
    #[inline]
    fn count_ramp_ticks(&mut self, ramp_ticks: u8) -> bool {
        let mut wrap = false;
        for m in 0..3 {
            if (ramp_ticks >> m) & 1 != 0 {
                wrap |= self.cupd[m] == CUPD_RAMP_TICKS - 1;
                self.cupd[m] = (self.cupd[m] + 1) & (CUPD_RAMP_TICKS - 1);
            }
        }
        wrap
    }

    /// The datagram state machine's edge (C80–C82, C84–C87): `(start, changed)`, whether a
    /// datagram starts in this edge (`request` in IDLE or at the end of CSOFF) and whether the
    /// pins may change.
    #[inline]
    fn advance(&mut self, ram: &[u8; 128], g: &Global, sdi_s: bool, request: bool) -> (bool, bool) {
        match self.state {
            IDLE => (request, request),
            _ if self.cnt > 1 => {
                self.fetch(ram);
                self.cnt -= 1;
                (false, false)
            }
            SETUP | GAP => {
                self.next_bit(g);
                (false, true)
            }
            LOW => {
                // Rising SCK_S: the driver samples SDO_S; SDI_S shifts into the readback (C87).
                self.sck = true;
                self.readback = ((self.readback << 1) | sdi_s as u64) & MASK48;
                self.bits = (self.bits + 1).min(BITS_MAX);
                self.state = HIGH;
                self.cnt = timing(g.g(f::CLK2_DIV)).1;
                (false, true)
            }
            HIGH => {
                self.after_high(g);
                (false, true)
            }
            HOLD => {
                // End of the datagram: CS inactive, SDO_S back high (C81), CDGW handshake
                // done (C87, C88).
                self.cs = false;
                self.sdo = true;
                self.cover_busy = false;
                self.dgw_busy = false;
                self.state = CSOFF;
                self.cnt = timing(g.g(f::CLK2_DIV)).2;
                (false, true)
            }
            _ => {
                // CSOFF over: the next datagram starts at once if one is requested.
                self.state = IDLE;
                (request, true)
            }
        }
    }

    /// The end of a HIGH phase: the next cell's bit, or with NxM (C86) the next motor's
    /// datagram after the gap, or the hold before CS goes inactive after the last motor (C82).
    #[inline]
    fn after_high(&mut self, g: &Global) {
        if !self.nxm {
            self.cell = (self.cell + 1) & 63;
            self.next_bit(g);
            return;
        }
        let (_, hi, _, gap) = timing(g.g(f::CLK2_DIV));
        // NxM (C86): LSMD 3 acts as 2.
        let lsmd = (g.g(f::LSMD) as u8).min(2);
        if self.motor >= lsmd {
            // t_HDSCSdrv after the last bit (C82).
            self.state = HOLD;
            self.cnt = hi;
        } else {
            self.motor += 1;
            self.cell = (self.cell + 1) & 63;
            self.state = GAP;
            self.cnt = gap;
        }
    }

    /// The `readback_clr` input: a µC write of datagram_low_word or datagram_high_word executes
    /// in this edge, after the chain's edge, so it wins over a shift of the same edge (C3, C87).
    #[inline]
    pub fn clear_readback(&mut self) {
        self.readback = 0;
    }

    /// True when the chain only counts down at the coming edge: inside a state with more than
    /// one edge left and no RAM read due (C80).
    #[inline]
    pub fn counting_only(&self) -> bool {
        self.counting_edges() > 0
    }

    /// How many coming edges only count down: those before the state's last edge and, in a
    /// state ahead of a bit, before its RAM reads (C80, cnt = 4 and 3); 0 while idle.
    #[inline]
    pub fn counting_edges(&self) -> u64 {
        let last = if matches!(self.state, SETUP | HIGH | GAP) { 4 } else { 1 };
        if self.state == IDLE {
            0
        } else {
            u64::from(self.cnt.saturating_sub(last))
        }
    }

    /// `n` edges of a busy chain that only count (fast path of `Tmc429::tick`; the caller has
    /// checked [`Chain::counting_edges`], SPI mode, no step, no counting ramp tick).
    #[inline]
    pub fn count_down(&mut self, n: u16) {
        if self.state != IDLE {
            self.cnt -= n;
        }
    }

    /// The RAM reads ahead of a bit (C80), in SETUP, HIGH and GAP: 4 edges before the LOW
    /// entry the configuration cell of the next bit (the current cell in SETUP and GAP, the
    /// following one in HIGH), 3 edges before it the LUT cell that cell's code needs for the
    /// current motor. Each reads the RAM of the edge's old state.
    #[inline]
    fn fetch(&mut self, ram: &[u8; 128]) {
        match (self.state, self.cnt) {
            (SETUP | GAP, 4) => self.cfg = ram[self.cell as usize & 63],
            (HIGH, 4) => self.cfg = ram[(self.cell as usize + 1) & 63],
            (SETUP | HIGH | GAP, 3) => {
                let m = (self.motor as usize).min(2);
                self.lut = ram[microstep::lut_cell(self.snap_w[m], self.cfg)];
            }
            _ => {}
        }
    }

    /// Starts a datagram (C80): snapshot of the index, current scale, direction and step flag of
    /// every motor and of the polarities; cover and dgw taken (the caller clears the register
    /// file's flags on the returned `take`).
    fn start(&mut self, g: &Global, motors: &[Motor; 3], cur: &[CurrentScale; 3]) {
        self.snap_pol = Polarity { ph_ab: g.g(f::POL_PH_AB) != 0, fd_ab: g.g(f::POL_FD_AB) != 0, dac_ab: g.g(f::POL_DAC_AB) != 0 };
        let mut dir = 0;
        let mut step = 0;
        for m in 0..3 {
            let mo = &motors[m];
            self.snap_w[m] = mo.ustep;
            self.snap_i_scale[m] = cur[m].i_scale(mo);
            dir |= (mo.dir as u8) << m;
            step |= (((self.stepped >> m) & 1 != 0 || mo.step) as u8) << m;
        }
        self.snap_dir = dir;
        self.snap_step = step;
        self.stepped = 0;
        self.cover_busy = g.cw;
        self.cov_pos = g.cover_pos & 63;
        self.cov_end = self.cov_pos + g.cover_len.min(24);
        self.cov_data = g.cover_datagram & 0xFF_FFFF;
        self.dgw_busy = g.dgw;
        self.req = false;
        self.cell = 0;
        self.motor = 0;
        self.bits = 0;
        self.cs = true;
        self.sck = true;
        // t_HDSCSdrv: the chip select leads the first falling SCK_S edge by HI (C82).
        self.state = SETUP;
        self.cnt = timing(g.g(f::CLK2_DIV)).1;
    }

    /// Falling SCK_S: the bit of the current cell goes out on SDO_S (C84, C85), from the cells
    /// fetched ahead of it.
    #[inline]
    fn next_bit(&mut self, g: &Global) {
        let code = self.cfg & 0x1F;
        self.nxm = self.cfg & 0x20 != 0;
        let m = (self.motor as usize).min(2);
        let mut b = microstep::signal_bit(
            code,
            self.snap_w[m],
            self.lut,
            self.snap_i_scale[m],
            (self.snap_dir >> m) & 1 != 0,
            (self.snap_step >> m) & 1 != 0,
            self.snap_pol,
        );
        // positions pos ≤ k < end carry data bit len - 1 - (k - pos) = end - 1 - k
        if self.cover_busy && self.bits >= self.cov_pos && self.bits < self.cov_end {
            let i = self.cov_end - 1 - self.bits;
            b = (self.cov_data >> i) & 1 != 0;
        }
        self.sdo = b;
        self.sck = false;
        self.state = LOW;
        self.cnt = timing(g.g(f::CLK2_DIV)).0;
    }

    /// Leaving SPI mode (en_sd := 1, C89): back to IDLE; a cover or readback request in
    /// progress returns to waiting (`ret_cw`, `ret_dgw`). The continuous-update counters and
    /// the readback register keep their values.
    fn abort(&mut self) -> Handshake {
        let hs = Handshake { changed: true, take: false, ret_cw: self.cover_busy, ret_dgw: self.dgw_busy };
        let (cupd, readback) = (self.cupd, self.readback);
        *self = Chain::reset();
        self.cupd = cupd;
        self.readback = readback;
        hs
    }

    /// The signal vectors (C73) of the snapshot taken at the last datagram start, with the
    /// LUT of `ram`: what the datagram carries when the LUT does not change while it is sent
    /// (the chain itself reads the LUT bit by bit, C80).
    pub fn snapshot_signals(&self, ram: &[u8; 128]) -> [u32; 3] {
        let mut v = [0; 3];
        for (m, s) in v.iter_mut().enumerate() {
            let dir = (self.snap_dir >> m) & 1 != 0;
            let step = (self.snap_step >> m) & 1 != 0;
            *s = microstep::signals(ram, self.snap_w[m], self.snap_i_scale[m], dir, step, self.snap_pol);
        }
        v
    }

    /// cw as read back and in CDGW: waiting or being sent.
    #[inline]
    pub fn cw(&self, g: &Global) -> bool {
        g.cw || self.cover_busy
    }

    /// CDGW status bit (C88): cw OR the datagram-word handshake.
    #[inline]
    pub fn cdgw(&self, g: &Global) -> bool {
        g.cw || g.dgw || self.cover_busy || self.dgw_busy
    }

    /// Pin levels (nSCS_S, nSCS2, nSCS3, SCK_S, SDO_S) with the polarities of the global
    /// parameter register (C81).
    #[inline]
    pub fn pins(&self, g: &Global) -> (bool, bool, bool, bool, bool) {
        let sck = self.sck ^ (g.g(f::POL_SCK_S) != 0);
        if g.g(f::CS_COM_IND) != 0 {
            // Individual selects, always low active, one per motor (C81).
            let m = self.motor;
            (!(self.cs && m == 0), !(self.cs && m == 1), !(self.cs && m >= 2), sck, self.sdo)
        } else {
            let ncs = !self.cs ^ (g.g(f::POL_NSCS_S) != 0);
            (ncs, true, true, sck, self.sdo)
        }
    }
}
