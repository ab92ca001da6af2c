//! The compared signals: every output pin and every probe, flattened into one list with
//! names, widths and a [`Compare`] mask.

use tmc429_model::{Outputs, Probes};

/// A compared signal: name (scope.signal as in the VCD), width in bits, signed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Signal {
    pub scope: &'static str,
    pub name: &'static str,
    pub width: u32,
    pub signed: bool,
}

const fn s(scope: &'static str, name: &'static str, width: u32, signed: bool) -> Signal {
    Signal { scope, name, width, signed }
}

macro_rules! motor_signals {
    ($scope:literal) => {
        [
            s($scope, "x_target", 24, false),
            s($scope, "x_actual", 24, false),
            s($scope, "v_internal", 20, true),
            s($scope, "v_target", 12, true),
            s($scope, "a_actual", 12, true),
            s($scope, "ustep", 8, false),
            s($scope, "step", 1, false),
            s($scope, "dir", 1, false),
            s($scope, "pulse_acc", 11, false),
        ]
    };
}

pub const N_PINS: usize = 11;
pub const N_MOTOR: usize = 9;
pub const N_CHAIN: usize = 7;
/// Number of compared signals.
pub const N_SIGNALS: usize = N_PINS + 3 * N_MOTOR + N_CHAIN + 3;

/// All compared signals, in the order of [`flatten`].
pub static SIGNALS: [Signal; N_SIGNALS] = {
    let pins = [
        s("top", "nint_sdo_c", 1, false),
        s("top", "sdoz_c", 1, false),
        s("top", "sdoz_c_oe", 1, false),
        s("top", "nscs_s", 1, false),
        s("top", "sck_s", 1, false),
        s("top", "sdo_s", 1, false),
        s("top", "sdi_s_o", 1, false),
        s("top", "sdi_s_oe", 1, false),
        s("top", "nscs2", 1, false),
        s("top", "nscs3", 1, false),
        s("top", "poscmp", 1, false),
    ];
    let m0 = motor_signals!("motor0");
    let m1 = motor_signals!("motor1");
    let m2 = motor_signals!("motor2");
    let chain = [
        s("chain", "state", 8, false),
        s("chain", "cell", 8, false),
        s("chain", "motor", 8, false),
        s("chain", "bit_count", 8, false),
        s("chain", "pending", 1, false),
        s("chain", "cover_waiting", 1, false),
        s("chain", "readback", 48, false),
    ];
    let global = [s("top", "prescaler", 32, false), s("top", "power_down", 1, false), s("top", "status", 8, false)];
    let mut out = [s("", "", 0, false); N_SIGNALS];
    let mut i = 0;
    let mut j = 0;
    while j < N_PINS {
        out[i] = pins[j];
        i += 1;
        j += 1;
    }
    j = 0;
    while j < N_MOTOR {
        out[i] = m0[j];
        out[i + N_MOTOR] = m1[j];
        out[i + 2 * N_MOTOR] = m2[j];
        i += 1;
        j += 1;
    }
    i += 2 * N_MOTOR;
    j = 0;
    while j < N_CHAIN {
        out[i] = chain[j];
        i += 1;
        j += 1;
    }
    j = 0;
    while j < 3 {
        out[i] = global[j];
        i += 1;
        j += 1;
    }
    out
};

/// Index of a signal by its full name `scope.name`.
pub fn index_of(full: &str) -> Option<usize> {
    SIGNALS.iter().position(|s| format!("{}.{}", s.scope, s.name) == full)
}

/// All pins and probes as raw bit patterns (signed values masked to their width).
pub fn flatten(o: &Outputs, p: &Probes) -> [u64; N_SIGNALS] {
    let mut v = [0u64; N_SIGNALS];
    let pins = [o.nint_sdo_c, o.sdoz_c, o.sdoz_c_oe, o.nscs_s, o.sck_s, o.sdo_s, o.sdi_s_o, o.sdi_s_oe, o.nscs2, o.nscs3, o.poscmp];
    for (i, b) in pins.iter().enumerate() {
        v[i] = *b as u64;
    }
    let mut i = N_PINS;
    for m in &p.motor {
        let f = [
            m.x_target as u64,
            m.x_actual as u64,
            m.v_internal as u32 as u64,
            m.v_target as u32 as u64,
            m.a_actual as u32 as u64,
            m.ustep as u64,
            m.step as u64,
            m.dir as u64,
            m.pulse_acc as u64,
        ];
        for x in f {
            v[i] = x;
            i += 1;
        }
    }
    let c = &p.chain;
    for x in [c.state as u64, c.cell as u64, c.motor as u64, c.bit_count as u64, c.pending as u64, c.cover_waiting as u64, c.readback] {
        v[i] = x;
        i += 1;
    }
    v[i] = p.prescaler as u64;
    v[i + 1] = p.power_down as u64;
    v[i + 2] = p.status as u64;
    for (k, s) in SIGNALS.iter().enumerate() {
        if s.width < 64 {
            v[k] &= (1u64 << s.width) - 1;
        }
    }
    v
}

/// Formats a raw value of a signal: hex, and decimal for signed signals.
pub fn format_value(sig: &Signal, raw: u64) -> String {
    let digits = sig.width.div_ceil(4) as usize;
    if sig.width == 1 {
        format!("{raw}")
    } else if sig.signed {
        let shift = 64 - sig.width;
        let val = ((raw << shift) as i64) >> shift;
        format!("0x{raw:0digits$x} ({val})")
    } else {
        format!("0x{raw:0digits$x}")
    }
}

/// Which signals are compared. Bit k stands for `SIGNALS[k]`.
///
/// Tri-state pins: `sdoz_c` is compared only while both sides enable it (`sdoz_c_oe`),
/// `sdi_s_o` only while both enable `sdi_s_oe`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Compare(pub u64);

impl Compare {
    /// Every pin and probe.
    pub fn all() -> Compare {
        Compare((1u64 << N_SIGNALS) - 1)
    }

    /// The output pins only (a design under test without the probe ports).
    pub fn pins() -> Compare {
        Compare((1u64 << N_PINS) - 1)
    }

    /// What the RTL of this issue implements: everything except the driver-chain pins
    /// (nSCS_S, SCK_S, SDO_S, SDI_S out, nSCS2, nSCS3) and the chain probes.
    pub fn without_chain() -> Compare {
        let mut c = Compare::all();
        for n in ["top.nscs_s", "top.sck_s", "top.sdo_s", "top.sdi_s_o", "top.sdi_s_oe", "top.nscs2", "top.nscs3"] {
            c = c.without(n);
        }
        for s in SIGNALS.iter().filter(|s| s.scope == "chain") {
            c = c.without(&format!("{}.{}", s.scope, s.name));
        }
        c
    }

    /// This mask without one signal (by full name); unknown names leave it unchanged.
    pub fn without(self, full: &str) -> Compare {
        match index_of(full) {
            Some(i) => Compare(self.0 & !(1u64 << i)),
            None => self,
        }
    }

    pub fn includes(self, i: usize) -> bool {
        self.0 >> i & 1 == 1
    }

    /// Names of the compared signals.
    pub fn names(self) -> Vec<String> {
        SIGNALS.iter().enumerate().filter(|(i, _)| self.includes(*i)).map(|(_, s)| format!("{}.{}", s.scope, s.name)).collect()
    }
}

/// One differing signal.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Diff {
    pub signal: Signal,
    pub model: u64,
    pub rtl: u64,
}

const I_SDOZ_C: usize = 1;
const I_SDOZ_C_OE: usize = 2;
const I_SDI_S_O: usize = 6;
const I_SDI_S_OE: usize = 7;

/// The signals of `mask` that differ (empty if none).
pub fn diff(mask: Compare, a: &[u64; N_SIGNALS], b: &[u64; N_SIGNALS]) -> Vec<Diff> {
    let mut out = Vec::new();
    for i in 0..N_SIGNALS {
        if !mask.includes(i) || a[i] == b[i] {
            continue;
        }
        if i == I_SDOZ_C && !(a[I_SDOZ_C_OE] == 1 && b[I_SDOZ_C_OE] == 1) {
            continue;
        }
        if i == I_SDI_S_O && !(a[I_SDI_S_OE] == 1 && b[I_SDI_S_OE] == 1) {
            continue;
        }
        out.push(Diff { signal: SIGNALS[i], model: a[i], rtl: b[i] });
    }
    out
}

/// Fast check: do two states agree under `mask`? (The slow path is [`diff`].)
#[inline]
pub fn agree(mask: Compare, oa: &Outputs, pa: &Probes, ob: &Outputs, pb: &Probes) -> bool {
    if oa == ob && pa == pb {
        return true;
    }
    diff(mask, &flatten(oa, pa), &flatten(ob, pb)).is_empty()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn signal_table() {
        assert_eq!(N_SIGNALS, 48);
        assert_eq!(index_of("top.nint_sdo_c"), Some(0));
        assert_eq!(index_of("top.sdoz_c"), Some(I_SDOZ_C));
        assert_eq!(index_of("top.sdi_s_oe"), Some(I_SDI_S_OE));
        assert_eq!(index_of("motor0.x_target"), Some(11));
        assert_eq!(index_of("motor2.pulse_acc"), Some(11 + 27 - 1));
        assert_eq!(index_of("chain.readback"), Some(44));
        assert_eq!(index_of("top.status"), Some(47));
        let c = Compare::without_chain();
        assert_eq!(c.names().len(), 48 - 7 - 7);
        assert!(!c.includes(index_of("top.sck_s").unwrap()));
        assert!(c.includes(index_of("top.poscmp").unwrap()));
    }

    #[test]
    fn tristate_compared_only_when_enabled() {
        let o = Outputs::IDLE;
        let p = Probes::default();
        let mut o2 = o;
        o2.sdoz_c = true;
        assert!(agree(Compare::all(), &o, &p, &o2, &p));
        let mut o3 = o;
        o3.sdoz_c_oe = true;
        o3.sdoz_c = true;
        let mut o4 = o3;
        o4.sdoz_c = false;
        let d = diff(Compare::all(), &flatten(&o3, &p), &flatten(&o4, &p));
        assert_eq!(d.len(), 1);
        assert_eq!(d[0].signal.name, "sdoz_c");
        assert_eq!((d[0].model, d[0].rtl), (1, 0));
    }

    #[test]
    fn signed_values_are_masked_and_formatted() {
        let mut p = Probes::default();
        p.motor[1].v_internal = -256;
        let v = flatten(&Outputs::IDLE, &p);
        let i = index_of("motor1.v_internal").unwrap();
        assert_eq!(v[i], 0xFFF00);
        assert_eq!(format_value(&SIGNALS[i], v[i]), "0xfff00 (-256)");
    }
}
