//! Transaction-level stimulus: SPI frames, pin changes, idle time, power down; proptest
//! strategies to generate them (reusable from tests and from the command line through a
//! seeded [`Stimulus`]), and the [`Driver`] that turns them into pin levels per CLK cycle.

use proptest::prelude::*;
use proptest::strategy::ValueTree;
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};

use tmc429_model::Chip;

mod driver;
mod driver_side;

pub use driver::{Driver, Event, Phase};
pub use driver_side::driver_sequence;

/// Minimum SCK_C half period, nSCS_C setup and hold, in CLK cycles ([428] Table 6-1).
pub const MIN_HALF: u32 = 3;

/// One µC SPI frame at pin level.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Frame {
    /// The 32-bit datagram: `A7 << 25 | RW << 24 | DATA` ([428] §6.2). A frame of fewer
    /// than 32 bits sends its first `nbits` bits, MSB first.
    pub datagram: u32,
    /// Bits sent after the first 32 when `nbits` > 32 (MSB of the used bits first).
    pub extra: u32,
    /// Number of SCK_C periods (1..=64); only 32 executes (C12).
    pub nbits: u8,
    /// SCK_C low and high time, CLK cycles (≥ 3).
    pub half: u32,
    /// nSCS_C low to the first SCK_C falling edge, CLK cycles (≥ 3).
    pub setup: u32,
    /// Last SCK_C rising edge to nSCS_C high, CLK cycles (≥ 3).
    pub hold: u32,
    /// nSCS_C high time after the frame, CLK cycles (≥ 3).
    pub gap: u32,
}

impl Frame {
    /// A 32-bit frame at the slowest SCK of the vendor advice (8 CLK per SCK period).
    pub fn new(datagram: u32) -> Frame {
        Frame { datagram, extra: 0, nbits: 32, half: 4, setup: 4, hold: 4, gap: 4 }
    }
    pub fn write(a7: u8, data: u32) -> Frame {
        Frame::new(((a7 as u32 & 0x7F) << 25) | (data & 0xFF_FFFF))
    }
    pub fn read(a7: u8) -> Frame {
        Frame::new(((a7 as u32 & 0x7F) << 25) | 1 << 24)
    }
    pub fn a7(&self) -> u8 {
        (self.datagram >> 25) as u8
    }
    pub fn is_read(&self) -> bool {
        self.datagram >> 24 & 1 == 1
    }
    pub fn data(&self) -> u32 {
        self.datagram & 0xFF_FFFF
    }
    /// The frame executes (exactly 32 bits, C12).
    pub fn executes(&self) -> bool {
        self.nbits == 32
    }
    /// Bit `i` (0 = first sent).
    pub fn bit(&self, i: u32) -> bool {
        if i < 32 {
            self.datagram >> (31 - i) & 1 == 1
        } else {
            let k = self.nbits as u32 - 1 - i;
            self.extra >> (k.min(31)) & 1 == 1
        }
    }
    /// CLK cycles the frame takes on the pins, gap included.
    pub fn cycles(&self) -> u64 {
        self.setup as u64 + 2 * self.half as u64 * self.nbits as u64 + self.hold as u64 + self.gap as u64
    }
}

/// Levels of the non-SPI inputs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PinLevels {
    pub ref_: [bool; 3],
    pub refr: [bool; 3],
    pub sdi_s: bool,
}

/// One stimulus transaction.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Txn {
    Frame(Frame),
    /// New levels of REF1..3, REFR1..3 and SDI_S, held for `hold` cycles.
    Pins {
        levels: PinLevels,
        hold: u32,
    },
    /// Nothing changes for this many cycles.
    Idle(u32),
}

/// What the generated traffic may touch.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Profile {
    /// Every address with any data.
    Full,
    /// The register file without motion and driver chain (this RTL): the motors are put in
    /// HOLD_MODE first and stay there (rm written as %11), v_actual is written 0 only, no
    /// cover_datagram write (it starts a driver-chain datagram), continuous_update and
    /// refmux stay 0. Everything else is free: every register and RAM word with random and
    /// boundary data, short, long and back-to-back frames, pin changes, power down.
    Registers,
    /// The register profile's motors (HOLD_MODE, v_actual 0: no motion core needed) with the
    /// whole driver side running: cover datagrams, continuous_update and refmux are free, the
    /// global parameter register is drawn with small clk2_div values most of the time, and
    /// directed sequences ([`driver_sequence`]) write driver-chain configurations (TMC428
    /// Table 11-2 and random valid NxM/LSMD chains), microstep indices, current scales,
    /// polarities, csCommonIndividual, cover datagrams and the Step/Dir bits of
    /// if_configuration (en_sd, step_half, inv_stp, inv_dir).
    Drivers,
    /// Everything moves (verif/src/motion_stim.rs): moves in all four ramp modes with valid
    /// and boundary parameters, target and mode changes during motion, reference searches with
    /// switch events and latching, current scaling, driver-chain configurations, cover
    /// datagrams, continuous update, refmux, Step/Dir — mixed with the traffic of `Full`.
    Motion,
    /// `Motion` without the traffic whose effect reaches the compared signals only through the
    /// driver chain, for an RTL without the chain: accesses to datagram_low/high_word and
    /// cover_datagram become reads of cover_pos_len (their readback, CDGW and cw come from the
    /// chain), refmux stays 0 (the switches would be sampled by the chain). Datagrams are
    /// still requested (steps, continuous update) but no compared signal depends on them.
    MotionCore,
}

impl Profile {
    pub fn name(self) -> &'static str {
        match self {
            Profile::Full => "full",
            Profile::Registers => "registers",
            Profile::Drivers => "drivers",
            Profile::Motion => "motion",
            Profile::MotionCore => "motion-core",
        }
    }
    pub fn parse(s: &str) -> Option<Profile> {
        match s {
            "full" => Some(Profile::Full),
            "registers" => Some(Profile::Registers),
            "drivers" => Some(Profile::Drivers),
            "motion" => Some(Profile::Motion),
            "motion-core" => Some(Profile::MotionCore),
            _ => None,
        }
    }
}

/// Motors addressable on a chip (TMC4210: one axis, C21).
pub fn motors(chip: Chip) -> usize {
    if chip == Chip::Tmc4210 {
        1
    } else {
        3
    }
}

/// Adjusts a frame to a profile (see [`Profile::Registers`], [`Profile::Drivers`], [`Profile::MotionCore`]).
pub fn sanitize(profile: Profile, f: &mut Frame) {
    if profile == Profile::MotionCore {
        let a7 = f.a7();
        if matches!(a7, 0x30 | 0x31 | 0x33) {
            f.datagram = 0x32 << 25 | 1 << 24;
        } else if a7 == 0x3F && !f.is_read() {
            f.datagram &= !(1 << 20); // refmux
        }
        return;
    }
    if !matches!(profile, Profile::Registers | Profile::Drivers) || f.is_read() {
        return;
    }
    if profile == Profile::Drivers {
        sanitize_drivers(f);
        return;
    }
    let a7 = f.a7();
    let data = f.data();
    let new_data = if a7 < 0x30 {
        match a7 & 0xF {
            10 => data | 3,     // rm = HOLD_MODE
            5 => data & !0xFFF, // v_actual = 0
            _ => data,
        }
    } else if a7 == 0x33 {
        // cover_datagram: read instead
        f.datagram |= 1 << 24;
        data
    } else if a7 == 0x3F {
        data & !(1 << 16 | 1 << 20) // continuous_update, refmux
    } else {
        data
    };
    f.datagram = (f.datagram & 0xFF00_0000) | (new_data & 0xFF_FFFF);
}

/// [`Profile::Drivers`]: the motors stay in HOLD_MODE with v_actual 0; a random write of the
/// global parameter register keeps clk2_div below 16 in 7 of 8 frames (short datagrams).
pub fn sanitize_drivers(f: &mut Frame) {
    let a7 = f.a7();
    let data = f.data();
    let new_data = if a7 < 0x30 {
        match a7 & 0xF {
            10 => data | 3,
            5 => data & !0xFFF,
            _ => data,
        }
    } else if a7 == 0x3F && data & 0xE000 != 0 {
        data & !0xF000
    } else {
        data
    };
    f.datagram = (f.datagram & 0xFF00_0000) | (new_data & 0xFF_FFFF);
}

/// Transactions that bring a fresh chip into the state a profile assumes.
pub fn prologue(chip: Chip, profile: Profile) -> Vec<Txn> {
    match profile {
        Profile::Full | Profile::Motion | Profile::MotionCore => Vec::new(),
        Profile::Registers | Profile::Drivers => (0..motors(chip)).map(|m| Txn::Frame(Frame::write((m as u8) << 4 | 10, 3))).collect(),
    }
}

/// Data words at the edges of the fields.
pub const BOUNDARY_DATA: [u32; 16] = [
    0x000000, 0xFFFFFF, 0x800000, 0x7FFFFF, 0x000001, 0x0007FF, 0x000800, 0x000FFF, 0x00FFFF, 0x008000, 0x00FF00, 0x0000FF, 0x7FF7FF,
    0x555555, 0xAAAAAA, 0x000F00,
];

/// Strategy for a frame's datagram: any address (registers and RAM), read or write,
/// random, boundary or small data (small values make positions meet: x_actual = x_target,
/// x_actual = 0, pos_comp matches). The TMC4210 draws its one motor and the globals more
/// often (its other addresses are unused).
pub fn datagram_strategy(chip: Chip) -> impl Strategy<Value = u32> {
    let a7 = if chip == Chip::Tmc4210 {
        prop_oneof![
            4 => 0u32..0x10,     // motor 1
            3 => 0x30u32..0x40,  // globals
            1 => 0x10u32..0x30,  // unused motor 2, 3
            1 => 0x40u32..0x80,  // RAM (C30)
        ]
        .boxed()
    } else {
        prop_oneof![
            6 => 0u32..0x40,     // registers
            3 => 0x40u32..0x80,  // RAM
        ]
        .boxed()
    };
    let data = prop_oneof![
        6 => 0u32..0x100_0000,
        2 => proptest::sample::select(&BOUNDARY_DATA[..]),
        1 => 0u32..4,
    ];
    (a7, any::<bool>(), data).prop_map(|(a, rw, d)| a << 25 | (rw as u32) << 24 | d)
}

/// Strategy for a frame: mostly 32 bits; short (1..31, 8 = status read), long (33..64);
/// SCK_C half period from the fastest legal (3 CLK) to slow (64 CLK); back-to-back frames.
pub fn frame_strategy(chip: Chip) -> impl Strategy<Value = Frame> {
    let nbits = prop_oneof![
        40 => Just(32u8),
        2 => Just(8u8),
        2 => 1u8..32,
        1 => 33u8..=64,
    ];
    let half = prop_oneof![
        3 => Just(MIN_HALF),
        3 => 4u32..9,
        1 => 9u32..=64,
    ];
    let edge = prop_oneof![2 => Just(MIN_HALF), 1 => 4u32..12];
    let gap = prop_oneof![2 => Just(MIN_HALF), 2 => 4u32..40, 1 => 40u32..400];
    (datagram_strategy(chip), any::<u32>(), nbits, half, edge.clone(), edge, gap)
        .prop_map(|(datagram, extra, nbits, half, setup, hold, gap)| Frame { datagram, extra, nbits, half, setup, hold, gap })
}

/// Strategy for non-SPI pin changes: one pin toggled or all levels random.
pub fn pins_strategy() -> impl Strategy<Value = (u8, PinLevels, u32)> {
    (0u8..8, any::<[bool; 7]>(), prop_oneof![3 => 1u32..16, 1 => 16u32..600])
        .prop_map(|(which, b, hold)| (which, PinLevels { ref_: [b[0], b[1], b[2]], refr: [b[3], b[4], b[5]], sdi_s: b[6] }, hold))
}

/// Kinds of generated step.
#[derive(Clone, Copy, Debug)]
enum Kind {
    Frame,
    Pins,
    Idle,
    PowerDown,
    Meet,
    Drivers,
}

/// A reproducible stream of transactions for one chip, from a seed.
pub struct Stimulus {
    pub(crate) chip: Chip,
    pub(crate) profile: Profile,
    runner: TestRunner,
    pub(crate) pending: std::collections::VecDeque<Txn>,
    pub(crate) levels: PinLevels,
    /// Last x_target written per motor by a motion sequence (on-the-fly changes move it).
    pub(crate) targets: [u32; 3],
}

impl Stimulus {
    pub fn new(chip: Chip, profile: Profile, seed: u64) -> Stimulus {
        let mut key = [0u8; 32];
        key[..8].copy_from_slice(&seed.to_le_bytes());
        key[8..16].copy_from_slice(b"tmc429tb");
        let rng = TestRng::from_seed(RngAlgorithm::ChaCha, &key);
        let runner = TestRunner::new_with_rng(Config::default(), rng);
        Stimulus {
            chip,
            profile,
            runner,
            pending: prologue(chip, profile).into(),
            levels: PinLevels { ref_: [false; 3], refr: [true; 3], sdi_s: false },
            targets: [0; 3],
        }
    }

    pub fn chip(&self) -> Chip {
        self.chip
    }

    pub(crate) fn draw<S: Strategy>(&mut self, s: S) -> S::Value {
        s.new_tree(&mut self.runner).expect("strategies of this module never reject").current()
    }

    /// The next transaction.
    pub fn next_txn(&mut self) -> Txn {
        let mut t = if let Some(t) = self.pending.pop_front() {
            t
        } else if matches!(self.profile, Profile::Motion | Profile::MotionCore) {
            self.motion_txn()
        } else {
            self.register_txn()
        };
        if let Txn::Frame(f) = &mut t {
            sanitize(self.profile, f);
        }
        t
    }

    /// A transaction of the register profiles: a frame, a pin change, idle time, power down or
    /// a directed position meeting; with [`Profile::Drivers`] also a [`driver_sequence`].
    pub(crate) fn register_txn(&mut self) -> Txn {
        let drivers = if self.profile == Profile::Drivers { 12 } else { 0 };
        let kind = self.draw(prop_oneof![
            80 => Just(Kind::Frame),
            14 => Just(Kind::Pins),
            4 => Just(Kind::Idle),
            2 => Just(Kind::PowerDown),
            2 => Just(Kind::Meet),
            drivers => Just(Kind::Drivers),
        ]);
        match kind {
            Kind::Frame => {
                let mut f = self.draw(frame_strategy(self.chip));
                sanitize(self.profile, &mut f);
                Txn::Frame(f)
            }
            Kind::Pins => self.pins_txn(),
            Kind::Idle => Txn::Idle(self.draw(prop_oneof![3 => 1u32..64, 1 => 64u32..3000])),
            Kind::PowerDown => {
                // power_down (JDX 8), then a while asleep; the next frame wakes the chip
                let data = self.draw(0u32..0x100_0000);
                let sleep = self.draw(prop_oneof![1 => 1u32..20, 2 => 20u32..2000]);
                self.pending.push_back(Txn::Idle(sleep));
                Txn::Frame(Frame::write(0x38, data))
            }
            Kind::Drivers => {
                let chip = self.chip;
                let mut pick = |n: u32| self.draw(0..n.max(1));
                let mut seq = driver_sequence(chip, &mut pick);
                let first = seq.remove(0);
                self.pending.extend(seq);
                first
            }
            Kind::Meet => self.meet_txn(),
        }
    }

    /// A switch or SDI_S pin toggled (or all levels drawn anew), held for a while.
    fn pins_txn(&mut self) -> Txn {
        let (which, random, hold) = self.draw(pins_strategy());
        let mut l = self.levels;
        match which {
            0..=2 => l.ref_[which as usize] = !l.ref_[which as usize],
            3..=5 => l.refr[which as usize - 3] = !l.refr[which as usize - 3],
            6 => l.sdi_s = !l.sdi_s,
            _ => l = random,
        }
        self.levels = l;
        Txn::Pins { levels: l, hold }
    }

    /// A directed sequence: a motor's x_actual moves onto x_target and onto pos_comp (POS_END,
    /// REF_MISS at 0, position compare), then the flags are read.
    fn meet_txn(&mut self) -> Txn {
        let m = self.draw(0..motors(self.chip) as u8);
        let v = self.draw(prop_oneof![1 => Just(0u32), 3 => 0u32..0x100_0000]);
        let mask = self.draw(any::<u8>()) as u32;
        let w = |a7: u8, d: u32| Txn::Frame(Frame::write(a7, d));
        let mut seq = vec![w(m << 4 | 11, mask << 8 | 0xFF), w(m << 4, (v + 1) & 0xFF_FFFF), w(m << 4 | 1, v ^ 0x40)];
        if self.chip != Chip::Tmc428 {
            seq.push(w(0x36, 0x100)); // pos_comp_int: M = 1
            seq.push(w(0x35, v)); // pos_comp
        }
        seq.push(w(m << 4 | 1, v)); // x_actual = pos_comp
        seq.push(w(m << 4, v)); // x_target = x_actual
        seq.push(Txn::Frame(Frame::read(m << 4 | 11)));
        if self.chip != Chip::Tmc428 {
            seq.push(Txn::Frame(Frame::read(0x36)));
        }
        let first = seq.remove(0);
        self.pending.extend(seq);
        first
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Pin sequence of a frame: setup, then per bit `half` cycles low and `half` high.
    #[test]
    fn frame_timing() {
        let f = Frame { datagram: 0xA000_0000, extra: 0, nbits: 2, half: 3, setup: 3, hold: 3, gap: 3 };
        let mut d = Driver::default();
        d.start(Txn::Frame(f));
        let mut seq = Vec::new();
        let mut evs = Vec::new();
        for _ in 0..f.cycles() {
            let (i, e) = d.step();
            seq.push((i.nscs_c as u8, i.sck_c as u8, i.sdi_c as u8));
            evs.push(e);
        }
        assert!(d.ready() || d.phase() == Phase::Gap);
        let expect: Vec<(u8, u8, u8)> = [
            vec![(0, 1, 0); 3],
            vec![(0, 0, 1); 3],
            vec![(0, 1, 1); 3],
            vec![(0, 0, 0); 3],
            vec![(0, 1, 0); 3],
            vec![(0, 1, 0); 3],
            vec![(1, 1, 0); 3],
        ]
        .concat();
        assert_eq!(seq, expect);
        assert_eq!(evs[6], Event::Sample(0));
        assert_eq!(evs[12], Event::Sample(1));
        assert_eq!(evs[18], Event::FrameEnd(f));
    }

    #[test]
    fn sanitize_registers_profile() {
        let mut f = Frame::write(0x1A, 0x000100); // motor 2 ref_conf/rm
        sanitize(Profile::Registers, &mut f);
        assert_eq!(f.datagram, 0x1A << 25 | 0x000103);
        let mut f = Frame::write(0x05, 0xFFF); // v_actual
        sanitize(Profile::Registers, &mut f);
        assert_eq!(f.data(), 0);
        let mut f = Frame::write(0x33, 0x123); // cover_datagram
        sanitize(Profile::Registers, &mut f);
        assert!(f.is_read());
        let mut f = Frame::write(0x3F, 0xFFFFFF);
        sanitize(Profile::Registers, &mut f);
        assert_eq!(f.data(), 0xEEFFFF);
    }

    #[test]
    fn stimulus_is_reproducible() {
        let mut a = Stimulus::new(Chip::Tmc429, Profile::Registers, 7);
        let mut b = Stimulus::new(Chip::Tmc429, Profile::Registers, 7);
        let mut c = Stimulus::new(Chip::Tmc429, Profile::Registers, 8);
        let va: Vec<Txn> = (0..200).map(|_| a.next_txn()).collect();
        let vb: Vec<Txn> = (0..200).map(|_| b.next_txn()).collect();
        let vc: Vec<Txn> = (0..200).map(|_| c.next_txn()).collect();
        assert_eq!(va, vb);
        assert_ne!(va, vc);
        // prologue: HOLD_MODE for the three motors
        assert_eq!(va[0], Txn::Frame(Frame::write(0x0A, 3)));
        assert_eq!(va[2], Txn::Frame(Frame::write(0x2A, 3)));
    }

    proptest! {
        #[test]
        fn generated_frames_are_legal(f in frame_strategy(Chip::Tmc429)) {
            prop_assert!(f.half >= MIN_HALF && f.setup >= MIN_HALF && f.hold >= MIN_HALF && f.gap >= MIN_HALF);
            prop_assert!((1..=64).contains(&f.nbits));
        }
    }
}
