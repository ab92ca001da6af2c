//! Functional coverage of the co-simulation: named bins, counted while the regression runs
//! (docs/cosim.md lists them).

use std::collections::BTreeMap;
use std::fmt::Write as _;

use tmc429_model::regmap::{self, Addr};
use tmc429_model::{chain, current, motor_regs, stepdir, Chip, Outputs, Probes, Tmc429};

use crate::stimulus::{Frame, PinLevels, Profile, MIN_HALF};

/// Interrupt flag names, bit 0 first ([428] Table 8-7).
pub const FLAG_NAMES: [&str; 8] =
    ["POS_END", "REF_WRONG", "REF_MISS", "STOP", "STOP_LEFT_LOW", "STOP_RIGHT_LOW", "STOP_LEFT_HIGH", "STOP_RIGHT_HIGH"];

/// Name of a register address for reports: `x_target[1]` (motor 1..3 as in the datasheet),
/// `ram_microstep_table[word 40]`, `unused $37`.
pub fn reg_name(chip: Chip, a7: u8) -> String {
    let a7 = a7 & 0x7F;
    match regmap::lookup(chip, a7) {
        Some((r, Some(m))) => format!("{}[{}]", r.name, m + 1),
        Some((r, None)) => match Addr::from_a7(a7) {
            Addr::Ram(a) => format!("{}[word {}]", r.name, a),
            _ => r.name.to_string(),
        },
        None => format!("unused ${a7:02X}"),
    }
}

/// Counted bins; only registered bins count.
#[derive(Clone, Debug, Default)]
pub struct Coverage {
    bins: BTreeMap<String, u64>,
    last_flags: [u8; 3],
    last_cover_pos: u8,
    last_power_down: bool,
    last_poscmp: Option<bool>,
    last_pins: Option<PinLevels>,
    last_chain_state: u8,
    last_mux: u8,
    /// The datagram under way carries the cover datagram.
    cover_seen: bool,
    /// Motion-profile observations of the previous cycle (see [`Coverage::model`]).
    motion: Option<MotionSeen>,
}

/// What [`Coverage::model`] remembers from the previous cycle.
#[derive(Clone, Copy, Debug, Default)]
struct MotionSeen {
    rm: [u8; 3],
    x_target: [u32; 3],
    /// V ≠ 0 seen since the last stop in RAMP or SOFT mode.
    moved: [bool; 3],
    stop: [bool; 3],
    lp: [bool; 3],
    chain_state: u8,
    mux: u8,
    sd_dir: [bool; 3],
    cupd: [u16; 3],
}

/// The bin of a step at each usrs (named without formatting: it is hit in the per-cycle path).
const USRS_STEP_BINS: [&str; 8] = [
    "step with usrs 0",
    "step with usrs 1",
    "step with usrs 2",
    "step with usrs 3",
    "step with usrs 4",
    "step with usrs 5",
    "step with usrs 6",
    "step with usrs 7",
];

/// Ramp mode names ([428] Table 8-3).
pub const MODE_NAMES: [&str; 4] = ["RAMP_MODE", "SOFT_MODE", "VELOCITY_MODE", "HOLD_MODE"];

/// The bins of the motion profile (the motion core and the driver side).
pub fn motion_bins(chip: Chip) -> Vec<String> {
    let mut v: Vec<String> = Vec::new();
    for m in ["RAMP_MODE", "SOFT_MODE"] {
        v.push(format!("{m}: move ends at x_target"));
    }
    v.push("VELOCITY_MODE: v_actual reaches v_target".into());
    v.push("HOLD_MODE: moving at a written v_actual".into());
    v.push("|v_actual| = 2047".into());
    v.push("mode change during motion".into());
    v.push("x_target change during motion".into());
    v.push("switch stop, hard".into());
    v.push("switch stop, soft".into());
    v.push("latch on a rising switch edge".into());
    v.push("latch on a falling switch edge".into());
    v.extend(USRS_STEP_BINS.iter().map(|b| b.to_string()));
    v.push("step negative".into());
    v.push("step positive".into());
    if chip != Chip::Tmc4210 {
        for n in ["is_aleat", "is_agtat", "is_v0"] {
            v.push(format!("current scale {n} selected"));
        }
        for n in [
            "datagram sent",
            "datagram with an NxM gap",
            "cover datagram sent",
            "continuous update request",
            "datagram with individual chip selects",
            "refmux: switches sampled",
        ] {
            v.push(n.into());
        }
    }
    if chip != Chip::Tmc428 {
        for n in ["Step/Dir: step pulse", "Step/Dir: step_half toggle", "Step/Dir: direction change"] {
            v.push(n.into());
        }
    }
    v
}

/// Driver-side bins of [`Profile::Drivers`] (SPI chips: TMC428, TMC429).
pub const CHAIN_BINS: [&str; 16] = [
    "chain datagram sent",
    "chain NxM gap",
    "chain datagram of 3 drivers",
    "chain cover datagram sent",
    "chain back-to-back datagrams",
    "chain continuous-update datagram",
    "chain endless datagram (127 bits, no NxM)",
    "chain readback nonzero",
    "chain csCommonIndividual: nSCS2 selects",
    "chain csCommonIndividual: nSCS3 selects",
    "chain polarity_nscs_s: select high",
    "chain polarity_sck_s: SCK_S low while idle",
    "chain DAC scaled (i_scale != 0)",
    "chain polarity_dac_ab in a datagram",
    "refmux: switch sampled on nSCS_S",
    "current scale is_v0 selected",
];

impl Coverage {
    /// The bins of this blocks for a chip under a stimulus profile.
    pub fn new(chip: Chip, profile: Profile) -> Coverage {
        let mut names: Vec<String> = Vec::new();
        let mut unused = false;
        for a7 in 0u8..0x40 {
            match regmap::lookup(chip, a7) {
                Some((r, _)) => {
                    let n = reg_name(chip, a7);
                    let chain_word = matches!(r.name, "cover_datagram" | "datagram_low_word" | "datagram_high_word");
                    let core_chain_word = profile == Profile::MotionCore && chain_word;
                    let writable_in_profile = !(profile == Profile::Registers && r.name == "cover_datagram" || core_chain_word);
                    if writable_in_profile {
                        names.push(format!("write {n}"));
                    }
                    if !core_chain_word {
                        names.push(format!("read {n}"));
                    }
                }
                None => unused = true,
            }
        }
        if unused {
            names.push("write unused address".into());
            names.push("read unused address".into());
        }
        if regmap::lookup(chip, 0x40).is_some() {
            for w in 0..64 {
                names.push(format!("ram write word {w}"));
                names.push(format!("ram read word {w}"));
            }
        }
        for n in [
            "frame short (1..31 bits, not executed)",
            "frame 8 bits (status byte only)",
            "frame long (33..64 bits, not executed)",
            "frame back-to-back (nSCS_C high 3 CLK)",
            "frame SCK_C half period 3 CLK (fastest)",
            "frame SCK_C half period >= 32 CLK (slow)",
            "power down",
            "wake-up by nSCS_C",
            "x_latched write arms lp",
            "pmul bit 15 reads 1",
            "INT in status byte",
            "interrupt flags cleared by writing 1",
            "interrupt flags forced 0 by the mask",
            "REF pin change",
            "SDI_S pin change",
        ] {
            names.push(n.into());
        }
        for (k, f) in FLAG_NAMES.iter().enumerate() {
            // STOP needs a moving motor: only in the motion and full profiles
            if k == 3 && matches!(profile, Profile::Registers | Profile::Drivers) {
                continue;
            }
            names.push(format!("interrupt flag {f} set"));
        }
        let switch_bits: &[&str] = match chip {
            Chip::Tmc428 => &["r1", "l1", "l2", "l3"],
            Chip::Tmc429 => &["r1", "l1", "r2", "l2", "r3", "l3"],
            Chip::Tmc4210 => &["r1 (REF_R)", "l1 (REF_L)", "l2 (GP_IN)"],
        };
        for s in switch_bits {
            names.push(format!("ref_switches {s} active"));
        }
        if chip != Chip::Tmc4210 && profile != Profile::MotionCore {
            names.push("CDGW armed by a datagram_low/high write".into());
            names.push("cover_pos 63 reads back 0".into());
        }
        if chip != Chip::Tmc428 {
            for n in ["type_version reads $429101", "pos_comp match sets I", "inv_ref inverts the switches"] {
                names.push(n.into());
            }
        }
        if chip == Chip::Tmc429 {
            // the TMC4210 has the registers, not the pins (C90)
            for n in ["POSCMP pin rises", "POSCMP pin falls", "sdo_int: frame with data on SDOZ_C only"] {
                names.push(n.into());
            }
            names.push("REFR pin change".into());
            names.push("en_refr: REFR switches read".into());
        }
        if profile == Profile::Drivers {
            if chip != Chip::Tmc4210 {
                names.extend(CHAIN_BINS.iter().map(|s| s.to_string()));
            }
            if chip == Chip::Tmc429 {
                names.push("en_sd aborts a datagram".into());
                names.push("Step/Dir pins (SDI_S driven)".into());
            }
            if chip == Chip::Tmc4210 {
                names.push("Step/Dir mode: STEP/DIR pins configured".into());
            }
        }
        let motion = matches!(profile, Profile::Motion | Profile::MotionCore);
        if motion {
            let chain_only = ["cover datagram sent", "refmux: switches sampled"];
            names.extend(motion_bins(chip).into_iter().filter(|n| profile == Profile::Motion || !chain_only.contains(&n.as_str())));
        }
        Coverage {
            bins: names.into_iter().map(|n| (n, 0)).collect(),
            last_power_down: false,
            motion: motion.then(MotionSeen::default),
            ..Coverage::default()
        }
    }

    #[inline]
    pub fn hit(&mut self, bin: &str) {
        if let Some(c) = self.bins.get_mut(bin) {
            *c += 1;
        }
    }

    pub fn bins(&self) -> &BTreeMap<String, u64> {
        &self.bins
    }

    /// Bins never hit.
    pub fn missed(&self) -> Vec<&str> {
        self.bins.iter().filter(|(_, c)| **c == 0).map(|(n, _)| n.as_str()).collect()
    }

    /// A frame ended; `reply` is what the model sent back (bit 31 first, `nbits` bits).
    pub fn frame(&mut self, chip: Chip, f: &Frame, reply: u64, model: &Tmc429) {
        if f.nbits < 32 {
            self.hit("frame short (1..31 bits, not executed)");
        }
        if f.nbits == 8 {
            self.hit("frame 8 bits (status byte only)");
        }
        if f.nbits > 32 {
            self.hit("frame long (33..64 bits, not executed)");
        }
        if f.gap == MIN_HALF {
            self.hit("frame back-to-back (nSCS_C high 3 CLK)");
        }
        if f.half == MIN_HALF {
            self.hit("frame SCK_C half period 3 CLK (fastest)");
        }
        if f.half >= 32 {
            self.hit("frame SCK_C half period >= 32 CLK (slow)");
        }
        if f.nbits >= 8 {
            let status = (reply >> (f.nbits as u32 - 8)) as u8;
            if status & 0x80 != 0 {
                self.hit("INT in status byte");
            }
            if status & 0x40 != 0 {
                self.hit("CDGW armed by a datagram_low/high write");
            }
        }
        let g = model.global();
        if f.nbits == 32 && chip == Chip::Tmc429 && g.ifconf & 2 != 0 {
            self.hit("sdo_int: frame with data on SDOZ_C only");
        }
        if !f.executes() {
            return;
        }
        let a7 = f.a7();
        let present = regmap::lookup(chip, a7).is_some();
        let data = (reply & 0xFF_FFFF) as u32;
        if a7 >= 0x40 {
            if present {
                let w = a7 & 0x3F;
                let n = if f.is_read() { format!("ram read word {w}") } else { format!("ram write word {w}") };
                self.hit(&n);
            }
            return;
        }
        if !present {
            self.hit(if f.is_read() { "read unused address" } else { "write unused address" });
            return;
        }
        let name = reg_name(chip, a7);
        self.hit(&format!("{} {}", if f.is_read() { "read" } else { "write" }, name));
        let motor = (a7 >> 4) as usize;
        let idx = a7 & 0xF;
        if f.is_read() {
            match (a7 < 0x30, idx) {
                (true, 9) if data & 0x8000 != 0 => self.hit("pmul bit 15 reads 1"),
                (true, 10) if data & 0x1_0000 != 0 => self.hit("x_latched write arms lp"),
                (true, 11) => {
                    self.last_flags[motor] = data as u8;
                    for (k, fl) in FLAG_NAMES.iter().enumerate() {
                        if data >> k & 1 == 1 {
                            self.hit(&format!("interrupt flag {fl} set"));
                        }
                    }
                }
                (false, 2) if self.last_cover_pos == 63 && (data >> 8) & 63 == 0 => self.hit("cover_pos 63 reads back 0"),
                (false, 6) if data & 1 == 1 => self.hit("pos_comp match sets I"),
                (false, 9) if data == 0x429101 => self.hit("type_version reads $429101"),
                (false, 14) => {
                    let names: &[(u32, &str)] = match chip {
                        Chip::Tmc4210 => &[(0, "r1 (REF_R)"), (1, "l1 (REF_L)"), (3, "l2 (GP_IN)")],
                        _ => &[(0, "r1"), (1, "l1"), (2, "r2"), (3, "l2"), (4, "r3"), (5, "l3")],
                    };
                    for (b, n) in names {
                        if data >> b & 1 == 1 {
                            self.hit(&format!("ref_switches {n} active"));
                        }
                    }
                    if chip != Chip::Tmc428 && g.ifconf & 1 != 0 {
                        self.hit("inv_ref inverts the switches");
                    }
                    if chip == Chip::Tmc429 && g.ifconf & 0x100 != 0 && g.gconf & (1 << 21 | 1 << 20) == 0 {
                        self.hit("en_refr: REFR switches read");
                    }
                }
                _ => {}
            }
        } else {
            let wdata = f.data();
            match (a7 < 0x30, idx) {
                (true, 11) => {
                    let flags = self.last_flags[motor];
                    if flags & wdata as u8 != 0 {
                        self.hit("interrupt flags cleared by writing 1");
                    }
                    if flags & !((wdata >> 8) as u8) != 0 {
                        self.hit("interrupt flags forced 0 by the mask");
                    }
                }
                (false, 2) => self.last_cover_pos = ((wdata >> 8) & 63) as u8,
                _ => {}
            }
        }
    }

    /// Called every cycle with the model's state after the tick.
    #[inline]
    pub fn cycle(&mut self, o: &Outputs, p: &Probes) {
        let pd = p.power_down != 0;
        if pd != self.last_power_down {
            self.hit(if pd { "power down" } else { "wake-up by nSCS_C" });
            self.last_power_down = pd;
        }
        if self.last_poscmp != Some(o.poscmp) {
            if let Some(prev) = self.last_poscmp {
                self.hit(if prev { "POSCMP pin falls" } else { "POSCMP pin rises" });
            }
            self.last_poscmp = Some(o.poscmp);
        }
    }

    /// Called every cycle of [`Profile::Drivers`] with the model after the tick.
    #[inline]
    pub fn drivers(&mut self, chip: Chip, o: &Outputs, p: &Probes, model: &Tmc429) {
        let st = p.chain.state;
        let last = self.last_chain_state;
        let g = model.global();
        if chip != Chip::Tmc4210 {
            let c = model.chain();
            if st != last {
                match (last, st) {
                    (5, 6) => {
                        self.hit("chain datagram sent");
                        if c.motor == 2 {
                            self.hit("chain datagram of 3 drivers");
                        }
                    }
                    (6, 1) => self.hit("chain back-to-back datagrams"),
                    (_, 4) => self.hit("chain NxM gap"),
                    (2, 3) if c.bits == 127 => self.hit("chain endless datagram (127 bits, no NxM)"),
                    (l, 0) if l != 6 && chip == Chip::Tmc429 => self.hit("en_sd aborts a datagram"),
                    _ => {}
                }
                if st == 1 {
                    if !c.cover_busy && !g.cw {
                        self.hit("chain continuous-update datagram");
                    }
                    if c.snap_i_scale.iter().any(|&k| k != 0) {
                        self.hit("chain DAC scaled (i_scale != 0)");
                    }
                    if c.snap_pol.dac_ab {
                        self.hit("chain polarity_dac_ab in a datagram");
                    }
                }
                if (last, st) == (5, 6) && self.cover_seen {
                    self.hit("chain cover datagram sent");
                }
                self.last_chain_state = st;
            }
            self.cover_seen = c.cover_busy;
            if p.chain.readback != 0 {
                self.hit("chain readback nonzero");
            }
            if !o.nscs2 {
                self.hit("chain csCommonIndividual: nSCS2 selects");
            }
            if !o.nscs3 {
                self.hit("chain csCommonIndividual: nSCS3 selects");
            }
            if c.cs && o.nscs_s && g.gconf & 0x84 == 0x04 {
                self.hit("chain polarity_nscs_s: select high");
            }
            if st == 0 && !o.sck_s && !o.sdi_s_oe {
                self.hit("chain polarity_sck_s: SCK_S low while idle");
            }
            if g.mux_switches != self.last_mux {
                self.hit("refmux: switch sampled on nSCS_S");
                self.last_mux = g.mux_switches;
            }
            if (0..3).any(|m| model.current_scale(m).sel == tmc429_model::current::SEL_V0) {
                self.hit("current scale is_v0 selected");
            }
        }
        if o.sdi_s_oe {
            self.hit("Step/Dir pins (SDI_S driven)");
        }
        if chip == Chip::Tmc4210 && g.ifconf & 0x20 != 0 {
            self.hit("Step/Dir mode: STEP/DIR pins configured");
        }
    }

    /// Motion-profile bins, from the model's state after each tick (a few loads per cycle; the
    /// per-motor mode checks run once per 32-cycle frame, after the pulse phase).
    #[inline]
    pub fn model(&mut self, t: &Tmc429, p: &Probes) {
        let Some(mut seen) = self.motion else { return };
        let chip = t.chip();
        let n = t.motor_count();
        let g = t.global();
        for i in 0..n {
            let m = t.motor(i);
            let pm = &p.motor[i];
            if pm.step != 0 {
                self.hit(USRS_STEP_BINS[(m.usrs & 7) as usize]);
                self.hit(if pm.dir != 0 { "step negative" } else { "step positive" });
            }
            let stop = m.cond_prev & motor_regs::INT_STOP != 0;
            if stop && !seen.stop[i] {
                self.hit(if m.ref_conf & motor_regs::SOFT_STOP != 0 { "switch stop, soft" } else { "switch stop, hard" });
            }
            seen.stop[i] = stop;
            if seen.lp[i] && !m.lp {
                self.hit(if m.ref_prev { "latch on a rising switch edge" } else { "latch on a falling switch edge" });
            }
            seen.lp[i] = m.lp;
        }
        if chip != Chip::Tmc4210 {
            let c = t.chain();
            if c.state != seen.chain_state {
                match c.state {
                    chain::SETUP => {
                        self.hit("datagram sent");
                        if c.cover_busy {
                            self.hit("cover datagram sent");
                        }
                        if g.gconf & regmap::f::CS_COM_IND.put(1) != 0 {
                            self.hit("datagram with individual chip selects");
                        }
                    }
                    chain::GAP => self.hit("datagram with an NxM gap"),
                    _ => {}
                }
                seen.chain_state = c.state;
            }
            for i in 0..3 {
                let k = c.cupd[i];
                if k == 0 && seen.cupd[i] == chain::CUPD_RAMP_TICKS - 1 {
                    self.hit("continuous update request");
                }
                seen.cupd[i] = k;
            }
            if g.mux_switches != seen.mux {
                self.hit("refmux: switches sampled");
                seen.mux = g.mux_switches;
            }
        }
        if chip != Chip::Tmc428 && g.ifconf & regmap::f::EN_SD.put(1) != 0 {
            let sd = t.step_dir();
            for i in 0..n {
                if sd.dir[i] != seen.sd_dir[i] {
                    self.hit("Step/Dir: direction change");
                    seen.sd_dir[i] = sd.dir[i];
                }
                if sd.state[i] == stepdir::PULSE && sd.cnt[i] > 0 {
                    self.hit(if g.ifconf & regmap::f::STEP_HALF.put(1) != 0 {
                        "Step/Dir: step_half toggle"
                    } else {
                        "Step/Dir: step pulse"
                    });
                }
            }
        }
        if p.prescaler & 31 == 0 {
            for i in 0..n {
                let m = t.motor(i);
                let v_act = m.v_actual();
                if v_act.unsigned_abs() == 2047 {
                    self.hit("|v_actual| = 2047");
                }
                if m.v != 0 && m.rm != seen.rm[i] {
                    self.hit("mode change during motion");
                }
                if m.v != 0 && m.rm <= motor_regs::SOFT_MODE && m.x_target != seen.x_target[i] {
                    self.hit("x_target change during motion");
                }
                match m.rm {
                    motor_regs::RAMP_MODE | motor_regs::SOFT_MODE => {
                        if m.v != 0 {
                            seen.moved[i] = true;
                        } else if seen.moved[i] && m.x_actual == m.x_target {
                            self.hit(&format!("{}: move ends at x_target", MODE_NAMES[m.rm as usize]));
                            seen.moved[i] = false;
                        }
                    }
                    motor_regs::VELOCITY_MODE => {
                        seen.moved[i] = false;
                        if m.v != 0 && v_act == m.vt {
                            self.hit("VELOCITY_MODE: v_actual reaches v_target");
                        }
                    }
                    _ => {
                        seen.moved[i] = false;
                        if m.v != 0 {
                            self.hit("HOLD_MODE: moving at a written v_actual");
                        }
                    }
                }
                seen.rm[i] = m.rm;
                seen.x_target[i] = m.x_target;
                if chip != Chip::Tmc4210 {
                    let name = match t.current_scale(i).sel {
                        current::SEL_AGTAT => "current scale is_agtat selected",
                        current::SEL_V0 => "current scale is_v0 selected",
                        _ => "current scale is_aleat selected",
                    };
                    self.hit(name);
                }
            }
        }
        self.motion = Some(seen);
    }

    /// A pin-change transaction.
    pub fn pins(&mut self, l: &PinLevels) {
        if let Some(p) = self.last_pins {
            if p.ref_ != l.ref_ {
                self.hit("REF pin change");
            }
            if p.refr != l.refr {
                self.hit("REFR pin change");
            }
            if p.sdi_s != l.sdi_s {
                self.hit("SDI_S pin change");
            }
        }
        self.last_pins = Some(*l);
    }

    /// Starting pin levels (the driver's idle levels).
    pub fn set_initial_pins(&mut self, l: PinLevels) {
        self.last_pins = Some(l);
    }

    /// The coverage table: every bin with its count, then the bins never hit.
    pub fn table(&self) -> String {
        let mut s = String::new();
        let width = self.bins.keys().map(|k| k.len()).max().unwrap_or(0);
        let _ = writeln!(s, "coverage: {} bins, {} hit", self.bins.len(), self.bins.len() - self.missed().len());
        for (n, c) in &self.bins {
            let _ = writeln!(s, "  {n:<width$}  {c}");
        }
        let missed = self.missed();
        if missed.is_empty() {
            let _ = writeln!(s, "bins never hit: none");
        } else {
            let _ = writeln!(s, "bins never hit ({}):", missed.len());
            for n in missed {
                let _ = writeln!(s, "  {n}");
            }
        }
        s
    }
}
