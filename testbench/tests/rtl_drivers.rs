//! The Verilated RTL alone: driver-chain datagrams, cover, SCK_S timing, chip selects, refmux
//! sampling and the Step/Dir pin levels, with the exact values of the datasheets and the
//! contract (TMC428 Table 11-2, §9.3, §9.7, Table 6-2; C80–C93).
#![cfg(not(tmc429_no_rtl))] // needs Verilator (testbench/build.rs)

use tmc429_model::ram::{SINE_LUT, TABLE_11_2};
use tmc429_model::{Chip, Inputs, Outputs};
use tmc429_testbench::stimulus::{Driver, Frame, Txn};
use tmc429_testbench::{Rtl, Variant};

const GCONF: u8 = 0x3F;
const COVER_POS_LEN: u8 = 0x32;
const COVER_DATAGRAM: u8 = 0x33;
const IF_CONF: u8 = 0x34;

/// The RTL with the pins it was last driven with; every tick's outputs are recorded.
struct Bench {
    rtl: Rtl,
    pins: Inputs,
    trace: Vec<Outputs>,
}

impl Bench {
    fn new(chip: Chip) -> Bench {
        Bench { rtl: Rtl::new(Variant::Chip(chip)), pins: Inputs::default(), trace: Vec::new() }
    }

    fn tick(&mut self) -> Outputs {
        let o = self.rtl.tick(&self.pins);
        self.trace.push(o);
        o
    }

    /// One 32-bit SPI write through the pins (executes 2 CLK after nSCS_C rises, C12).
    fn write(&mut self, a7: u8, data: u32) {
        self.frame(Frame::write(a7, data));
    }

    fn read(&mut self, a7: u8) -> u32 {
        self.frame(Frame::read(a7)) & 0xFF_FFFF
    }

    fn frame(&mut self, f: Frame) -> u32 {
        let mut d = Driver::default();
        d.inputs = self.pins;
        d.start(Txn::Frame(f));
        let mut reply = 0u32;
        let mut out = self.rtl.outputs();
        for _ in 0..f.cycles() {
            let (inp, ev) = d.step();
            if let tmc429_testbench::stimulus::Event::Sample(_) = ev {
                let bit = if out.sdoz_c_oe { out.sdoz_c } else { out.nint_sdo_c };
                reply = reply << 1 | bit as u32;
            }
            self.pins = inp;
            out = self.tick();
        }
        reply
    }

    fn wait(&mut self, n: u64) {
        for _ in 0..n {
            self.tick();
        }
    }

    /// Driver-chain configuration cells from cell 0, written as RAM words.
    fn config(&mut self, cells: &[u8]) {
        for (w, p) in cells.chunks(2).enumerate() {
            let odd = p.get(1).copied().unwrap_or(0) as u32;
            self.write(0x40 | w as u8, odd << 8 | p[0] as u32);
        }
    }

    /// The TMC428 sine LUT (Table 12-2) into cells 64..127.
    fn lut(&mut self) {
        self.config_at(32, &SINE_LUT);
    }

    fn config_at(&mut self, word: u8, cells: &[u8]) {
        for (w, p) in cells.chunks(2).enumerate() {
            self.write(0x40 | (word + w as u8), (p[1] as u32) << 8 | p[0] as u32);
        }
    }
}

/// Datagrams on the pins since `from`: bits sampled from SDO_S at the rising edges of SCK_S
/// (SPI mode 3, C81) while the chip select (nSCS_S low) is active; one entry per select.
fn datagrams(t: &[Outputs]) -> Vec<(u32, u64)> {
    let mut out = Vec::new();
    let mut cur: Option<(u32, u64)> = None;
    for w in t.windows(2) {
        let (a, b) = (&w[0], &w[1]);
        if a.nscs_s && !b.nscs_s {
            cur = Some((0, 0));
        }
        if let Some((n, bits)) = cur.as_mut() {
            if !a.sck_s && b.sck_s {
                *n += 1;
                *bits = *bits << 1 | a.sdo_s as u64;
            }
        }
        if !a.nscs_s && b.nscs_s {
            out.extend(cur.take());
        }
    }
    out
}

/// Runs (level, length) of a pin.
fn runs(t: &[Outputs], pin: impl Fn(&Outputs) -> bool) -> Vec<(bool, usize)> {
    let mut r: Vec<(bool, usize)> = Vec::new();
    for o in t {
        let v = pin(o);
        match r.last_mut() {
            Some((l, n)) if *l == v => *n += 1,
            _ => r.push((v, 1)),
        }
    }
    r
}

/// A TMC429 with Table 11-2 and the sine LUT, LSMD 2, clk2_div 7.
fn table_11_2_chip() -> Bench {
    let mut b = Bench::new(Chip::Tmc429);
    b.config(&TABLE_11_2);
    b.lut();
    b.write(GCONF, 7 << 8 | 2);
    b
}

/// One datagram requested by a cover write with cover_len 0 (sent unchanged, TMC428 §9.3).
fn one_datagram(b: &mut Bench) -> (u32, u64) {
    b.write(COVER_POS_LEN, 0);
    b.trace.clear();
    b.write(COVER_DATAGRAM, 0);
    b.wait(1500);
    let d = datagrams(&b.trace);
    assert_eq!(d.len(), 1, "one datagram per request");
    d[0]
}

/// TMC428 Table 11-2 configuration, Table 12-2 LUT, LSMD 2, microstep index w.
#[test]
fn table_11_2_datagrams_on_the_pins() {
    let cases: [(u8, u64); 6] =
        [(0, 0x05F05F07F), (16, 0x35D35D37D), (64, 0x7C07C0FC0), (100, 0x55805F07F), (128, 0x01E05F07F), (200, 0x78705F07F)];
    for (w, want) in cases {
        let mut b = table_11_2_chip();
        let ws = if w == 16 || w == 64 { [w; 3] } else { [w, 0, 0] };
        for (m, &x) in ws.iter().enumerate() {
            b.write((m as u8) << 4 | 15, x as u32);
        }
        assert_eq!(one_datagram(&mut b), (36, want), "w = {ws:?}");
    }
    // i_scale %100 on every factor (Table 8-1: 50 %); power-on selection is is_aleat.
    let mut b = table_11_2_chip();
    for m in 0..3u8 {
        b.write(m << 4 | 15, 16);
        b.write(m << 4 | 8, 4 << 20 | 4 << 16 | 4 << 12);
    }
    assert_eq!(one_datagram(&mut b), (36, 0x1CF1CF1EF));
}

/// TMC429 §11.4.2: the TMC429's power-on RAM (One at the mixed-decay positions), w = 0.
#[test]
fn tmc429_power_on_datagram() {
    let mut b = Bench::new(Chip::Tmc429);
    b.write(GCONF, 15 << 8 | 2);
    b.write(COVER_POS_LEN, 0);
    b.trace.clear();
    b.write(COVER_DATAGRAM, 0);
    b.wait(3000);
    assert_eq!(datagrams(&b.trace), vec![(36, 0x87F87F87F)]);
}

/// C85, TMC428 §9.3: cover datagram positions and lengths.
#[test]
fn cover_datagram_bits() {
    for (pos, len, data, want) in [(0u32, 12u32, 0xABCu32, 0xABC05F07Fu64), (4, 31, 0xFFFFFF, 0x0FFFFFF7F), (30, 12, 0xA80, 0x05F05F06A)] {
        let mut b = table_11_2_chip();
        b.write(COVER_POS_LEN, pos << 8 | len);
        b.trace.clear();
        b.write(COVER_DATAGRAM, data);
        // cw reads 1 until the covered datagram has gone out (C85, C88)
        assert_eq!(b.read(COVER_POS_LEN) >> 23, 1);
        b.wait(1500);
        assert_eq!(b.read(COVER_POS_LEN), ((pos + 1) & 63) << 8 | len);
        assert_eq!(datagrams(&b.trace), vec![(36, want)], "pos {pos} len {len}");
    }
}

/// C81, TMC428 §9.7: SCK_S low half clk2_div + 1, period max(16, 2·(clk2_div + 1)); NxM gap one
/// period (clk2_div ≤ 7) or 1.5 periods; C82 / Table 6-2: a 1-bit datagram keeps the select
/// active 32 CLK at clk2_div 7 (48 CLK with the t_SUSCSdrv that follows).
#[test]
fn sck_s_timing() {
    for c in [0u32, 3, 7, 8, 20] {
        let mut b = table_11_2_chip();
        b.write(GCONF, c << 8 | 2);
        b.write(COVER_POS_LEN, 0);
        b.trace.clear();
        b.write(COVER_DATAGRAM, 0);
        b.wait(3000);
        let lo = c as usize + 1;
        let period = (2 * lo).max(16);
        let sck = runs(&b.trace, |o| o.sck_s);
        let lows: Vec<usize> = sck.iter().filter(|r| !r.0).map(|r| r.1).collect();
        assert_eq!(lows.len(), 36, "clk2_div {c}");
        assert!(lows.iter().all(|&l| l == lo), "clk2_div {c}: low half {lows:?}");
        // high halves between the bits of one driver, and the NxM gap after bit 12
        let highs: Vec<usize> = sck.iter().filter(|r| r.0).map(|r| r.1).collect();
        assert_eq!(highs[2], period - lo, "clk2_div {c}: high half");
        let gap = if c <= 7 { period } else { 3 * lo };
        assert_eq!(highs[12], period - lo + gap, "clk2_div {c}: NxM gap");
    }
    let mut b = Bench::new(Chip::Tmc428);
    b.config(&[0x31]); // cell 0: One with NxM
    b.write(GCONF, 7 << 8);
    b.trace.clear();
    b.write(COVER_DATAGRAM, 0);
    b.wait(300);
    // [429] Table 11.2 at clk2_div 7: t_HDSCSdrv 8 CLK before the first falling SCK_S edge, the
    // bit (8 + 8), a hold of 8 (C82): the chip select is active 32 CLK; the SCK_S low half
    // starts 8 CLK after it falls.
    let sel: Vec<(bool, usize)> = runs(&b.trace, |o| o.nscs_s).into_iter().filter(|r| !r.0).collect();
    assert_eq!(sel, vec![(false, 32)]);
    let cs_fall = b.trace.iter().position(|o| !o.nscs_s).unwrap();
    let sck_fall = b.trace.iter().position(|o| !o.sck_s).unwrap();
    assert_eq!(sck_fall - cs_fall, 8, "t_HDSCSdrv");
    assert_eq!(datagrams(&b.trace), vec![(1, 1)]);
}

/// [429] §8.2.4 note: the driver outputs are logic high after power-on until configured for
/// Step/Dir; Fig. 11.1: SDO_S high before the first bit and again when nSCS_S rises (C2, C81).
#[test]
fn driver_pins_high_after_power_on_and_between_datagrams() {
    for chip in [Chip::Tmc428, Chip::Tmc429] {
        let mut b = Bench::new(chip);
        let o = b.tick();
        assert!(o.sdo_s && o.sck_s && o.nscs_s && o.nscs2 && o.nscs3, "{chip:?}: power-on levels {o:?}");
        b.config(&TABLE_11_2);
        b.lut();
        b.write(GCONF, 7 << 8 | 1 << 4); // polarity_ph_ab: the last bit, PH_B, is 0 at w = 0
        b.write(COVER_POS_LEN, 0);
        b.trace.clear();
        b.write(COVER_DATAGRAM, 0);
        b.wait(400);
        assert_eq!(datagrams(&b.trace).len(), 1, "{chip:?}");
        for w in b.trace.windows(2) {
            assert!(!w[0].nscs_s || w[0].sdo_s, "{chip:?}: SDO_S high while nSCS_S is inactive");
            if !w[0].nscs_s && w[1].nscs_s {
                assert!(!w[0].sdo_s && w[1].sdo_s, "{chip:?}: SDO_S returns high with nSCS_S");
            }
        }
    }
}

/// C81, TMC428 §9.7: csCommonIndividual — nSCS_S, nSCS2, nSCS3 select the drivers of motors
/// 1, 2, 3 for their 12 bits each; polarity_nscs_s / polarity_sck_s invert the common select
/// and the clock.
#[test]
fn chip_selects_and_polarities() {
    let mut b = table_11_2_chip();
    b.write(GCONF, 1 << 7 | 7 << 8 | 2);
    b.trace.clear();
    b.write(COVER_DATAGRAM, 0);
    b.wait(1500);
    let rising = |sel: &dyn Fn(&Outputs) -> bool| b.trace.windows(2).filter(|w| !w[0].sck_s && w[1].sck_s && sel(&w[0])).count();
    assert_eq!(rising(&|o| !o.nscs_s && o.nscs2 && o.nscs3), 12);
    assert_eq!(rising(&|o| o.nscs_s && !o.nscs2 && o.nscs3), 12);
    assert_eq!(rising(&|o| o.nscs_s && o.nscs2 && !o.nscs3), 12);
    // polarities: the select high-active, SCK_S idles low
    let mut b = table_11_2_chip();
    b.write(GCONF, 0x0C | 7 << 8 | 2);
    let o = b.rtl.outputs();
    assert!(!o.nscs_s && !o.sck_s, "idle: select low, SCK_S low");
    b.trace.clear();
    b.write(COVER_DATAGRAM, 0);
    b.wait(1500);
    let sel: Vec<usize> = runs(&b.trace, |o| o.nscs_s).into_iter().filter(|r| r.0).map(|r| r.1).collect();
    assert_eq!(sel.len(), 1);
    let falls = b.trace.windows(2).filter(|w| w[0].sck_s && !w[1].sck_s && w[0].nscs_s).count();
    assert_eq!(falls, 36, "36 bits clocked on the inverted SCK_S");
}

/// C87, TMC428 §9.7 / Table 9-3: refmux = 1 samples REF1..3 through the 74HC157 on nSCS_S:
/// left switches while nSCS_S is high, right ones while it is low; 0 before the first datagram.
#[test]
fn refmux_sampling() {
    let mut b = table_11_2_chip();
    b.write(GCONF, 1 << 20 | 7 << 8 | 2);
    b.pins.ref1 = true;
    b.pins.ref3 = true;
    b.wait(10);
    assert_eq!(b.read(0x3E), 0, "nothing sampled before a datagram");
    b.write(COVER_DATAGRAM, 0);
    // the select fell with REF1, REF3 high: left switches L1, L3; now present the right ones
    b.pins.ref1 = false;
    b.pins.ref2 = true;
    b.wait(1500);
    // r1 bit 0, l1 1, r2 2, l2 3, r3 4, l3 5
    assert_eq!(b.read(0x3E), 0b11_0100 | 0b00_0010);
    assert_eq!(b.frame(Frame::read(0x3E)) >> 24 & 0x2A, 0b10_0010, "RS1, RS3 in the status");
}

/// C87, C88: SDI_S shifts into the 48-bit readback at each rising SCK_S; a datagram-word write
/// initializes both words to 0 ([429] §8.2.1) and sets CDGW until the next datagram ends.
#[test]
fn readback_and_cdgw() {
    let mut b = table_11_2_chip();
    b.write(0x30, 0);
    assert_ne!(b.frame(Frame::read(0x30)) >> 24 & 0x40, 0, "CDGW armed");
    b.pins.sdi_s = true;
    b.write(COVER_DATAGRAM, 0);
    b.wait(1500);
    assert_eq!(b.frame(Frame::read(0x30)) >> 24 & 0x40, 0, "CDGW clear after the datagram");
    // 36 ones shifted in (plus the synchronizer delay, C4)
    assert_eq!(b.read(0x30), 0xFF_FFFF);
    assert_eq!(b.read(0x31), 0x00_0FFF);
    b.write(0x30, 0x123456);
    assert_eq!((b.read(0x30), b.read(0x31)), (0, 0), "initialized by the write");
}

/// C91–C93: Step/Dir pin levels without steps — TMC429 S1..S3 / D1..D3 with inv_stp, inv_dir;
/// TMC4210 STEP and DIR high until en_sd = 1.
#[test]
fn step_dir_pins_at_rest() {
    let mut b = Bench::new(Chip::Tmc429);
    b.write(IF_CONF, 1 << 5 | 1 << 3);
    let o = b.rtl.outputs();
    assert_eq!((o.sdo_s, o.nscs_s, o.nscs2), (true, true, true), "STEP inverted: high");
    assert_eq!((o.sck_s, o.sdi_s_o, o.nscs3, o.sdi_s_oe), (false, false, false, true));
    b.write(IF_CONF, 1 << 5 | 1 << 4);
    let o = b.rtl.outputs();
    assert_eq!((o.sdo_s, o.sck_s, o.sdi_s_o, o.nscs3), (false, true, true, true), "DIR inverted");
    let mut b = Bench::new(Chip::Tmc4210);
    let o = b.rtl.outputs();
    assert_eq!((o.sdo_s, o.sck_s, o.nscs_s, o.sdi_s_oe), (true, true, true, false), "C92");
    b.write(IF_CONF, 1 << 5);
    let o = b.rtl.outputs();
    assert_eq!((o.sdo_s, o.sck_s), (false, false));
}
