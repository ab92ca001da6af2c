//! The chip's pins in a capture and the pin map (`--pin NAME=CHANNEL`): which capture channel
//! was probed on which pin. Pin names are the datasheets' (TMC429 §1.5, TMC4210 §1.5); a
//! channel named like a pin (case-insensitive), or like one of its other names, is mapped to it
//! without `--pin`.

use tmc429_model::script;
use tmc429_model::{Inputs, Outputs};

use super::{Capture, CaptureError};

/// A pin of the chip that a capture can hold.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Pin {
    NscsC,
    SckC,
    SdiC,
    NintSdoC,
    SdozC,
    SdiS,
    NscsS,
    SckS,
    SdoS,
    Nscs2,
    Nscs3,
    Ref1,
    Ref2,
    Ref3,
    Refr1,
    Refr2,
    Refr3,
    Poscmp,
}

/// Every pin, in the order of exported captures.
pub const ALL: [Pin; 18] = [
    Pin::NscsC,
    Pin::SckC,
    Pin::SdiC,
    Pin::NintSdoC,
    Pin::SdozC,
    Pin::NscsS,
    Pin::SckS,
    Pin::SdoS,
    Pin::SdiS,
    Pin::Nscs2,
    Pin::Nscs3,
    Pin::Ref1,
    Pin::Ref2,
    Pin::Ref3,
    Pin::Refr1,
    Pin::Refr2,
    Pin::Refr3,
    Pin::Poscmp,
];

/// The pins a comparison cannot do without: the µC's bus (and one of the data outputs).
pub const REQUIRED: [Pin; 3] = [Pin::NscsC, Pin::SckC, Pin::SdiC];

impl Pin {
    /// The datasheet name (TMC429 §1.5).
    pub fn name(self) -> &'static str {
        match self {
            Pin::NscsC => "nSCS_C",
            Pin::SckC => "SCK_C",
            Pin::SdiC => "SDI_C",
            Pin::NintSdoC => "nINT_SDO_C",
            Pin::SdozC => "SDOZ_C",
            Pin::SdiS => "SDI_S",
            Pin::NscsS => "nSCS_S",
            Pin::SckS => "SCK_S",
            Pin::SdoS => "SDO_S",
            Pin::Nscs2 => "nSCS2",
            Pin::Nscs3 => "nSCS3",
            Pin::Ref1 => "REF1",
            Pin::Ref2 => "REF2",
            Pin::Ref3 => "REF3",
            Pin::Refr1 => "REFR1",
            Pin::Refr2 => "REFR2",
            Pin::Refr3 => "REFR3",
            Pin::Poscmp => "POSCMP",
        }
    }

    /// Other names of the pin: its Step/Dir function (TMC429 §10: STEP1 = SDO_S, DIR1 = SCK_S,
    /// STEP2 = nSCS_S, DIR2 = SDI_S, STEP3 = nSCS2, DIR3 = nSCS3), the TMC4210's names
    /// (TMC4210 §1.5: STEP, DIR, REF_L, GP_IN, REF_R) and the usual short ones.
    pub fn aliases(self) -> &'static [&'static str] {
        match self {
            Pin::NscsC => &["nCS", "CS"],
            Pin::SckC => &["SCK", "SCLK"],
            Pin::SdiC => &["MOSI", "SDI"],
            Pin::NintSdoC => &["SDO_C", "nINT"],
            Pin::SdozC => &["MISO"],
            Pin::SdoS => &["STEP1", "STEP"],
            Pin::SckS => &["DIR1", "DIR"],
            Pin::NscsS => &["STEP2"],
            Pin::SdiS => &["DIR2"],
            Pin::Nscs2 => &["STEP3"],
            Pin::Nscs3 => &["DIR3"],
            Pin::Ref1 => &["REF_L"],
            Pin::Ref2 => &["GP_IN"],
            Pin::Ref3 => &["REF_R"],
            _ => &[],
        }
    }

    /// The pin named `s` (its name or another name, case-insensitive).
    pub fn parse(s: &str) -> Option<Pin> {
        let s = s.trim();
        ALL.iter().copied().find(|p| p.name().eq_ignore_ascii_case(s) || p.aliases().iter().any(|a| a.eq_ignore_ascii_case(s)))
    }

    /// Inputs the chip samples (replayed into the model). SDI_S is an input in SPI mode (the
    /// driver chain's data) and the DIR2 output in Step/Dir mode.
    pub fn is_input(self) -> bool {
        matches!(
            self,
            Pin::NscsC | Pin::SckC | Pin::SdiC | Pin::SdiS | Pin::Ref1 | Pin::Ref2 | Pin::Ref3 | Pin::Refr1 | Pin::Refr2 | Pin::Refr3
        )
    }

    /// Sets this input pin in `i` (no effect for outputs).
    pub fn set_input(self, i: &mut Inputs, level: bool) {
        match self {
            Pin::NscsC => i.nscs_c = level,
            Pin::SckC => i.sck_c = level,
            Pin::SdiC => i.sdi_c = level,
            // the switches and SDI_S, as `tmc429 spi`'s `pin` command sets them
            p => {
                if let Some(sp) = script::Pin::parse(p.name()) {
                    sp.set(i, level)
                }
            }
        }
    }

    /// The level of this pin on the board for the chip's inputs and outputs: SDI_S is the chip's
    /// driver while it drives it (Step/Dir mode), else the input; SDOZ_C reads its data while
    /// enabled and 1 (pulled up) while not driven.
    pub fn level(self, i: &Inputs, o: &Outputs) -> bool {
        match self {
            Pin::NscsC => i.nscs_c,
            Pin::SckC => i.sck_c,
            Pin::SdiC => i.sdi_c,
            Pin::NintSdoC => o.nint_sdo_c,
            Pin::SdozC => !o.sdoz_c_oe || o.sdoz_c,
            Pin::SdiS => {
                if o.sdi_s_oe {
                    o.sdi_s_o
                } else {
                    i.sdi_s
                }
            }
            Pin::NscsS => o.nscs_s,
            Pin::SckS => o.sck_s,
            Pin::SdoS => o.sdo_s,
            Pin::Nscs2 => o.nscs2,
            Pin::Nscs3 => o.nscs3,
            Pin::Ref1 => i.ref1,
            Pin::Ref2 => i.ref2,
            Pin::Ref3 => i.ref3,
            Pin::Refr1 => i.refr1,
            Pin::Refr2 => i.refr2,
            Pin::Refr3 => i.refr3,
            Pin::Poscmp => o.poscmp,
        }
    }
}

/// Parses `--pin` values: `NAME=CHANNEL`, several separated by commas.
pub fn parse_assignments(args: &[String]) -> Result<Vec<(Pin, String)>, String> {
    let mut out = Vec::new();
    for a in args.iter().flat_map(|a| a.split(',')) {
        let a = a.trim();
        if a.is_empty() {
            continue;
        }
        let (p, ch) = a.split_once('=').ok_or_else(|| format!("--pin '{a}': expected PIN=CHANNEL, e.g. nSCS_C=D0"))?;
        let pin = Pin::parse(p).ok_or_else(|| {
            format!("--pin '{a}': unknown pin '{p}': expected one of {}", ALL.iter().map(|p| p.name()).collect::<Vec<_>>().join(", "))
        })?;
        if ch.trim().is_empty() {
            return Err(format!("--pin '{a}': no channel after '='"));
        }
        out.push((pin, ch.trim().to_string()));
    }
    Ok(out)
}

/// Which channel of a capture holds which pin.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PinMap {
    chan: Vec<(Pin, usize)>,
}

impl PinMap {
    /// Maps the pins: the `--pin` assignments first, then channels named like a pin.
    pub fn resolve(cap: &Capture, assign: &[(Pin, String)], file: &str) -> Result<PinMap, CaptureError> {
        let mut chan: Vec<(Pin, usize)> = Vec::new();
        for (pin, name) in assign {
            let k = cap.channel(name).ok_or_else(|| {
                CaptureError(format!(
                    "{file}: --pin {}={name}: the capture has no channel '{name}' (channels: {})",
                    pin.name(),
                    channel_list(cap)
                ))
            })?;
            chan.retain(|(p, _)| p != pin);
            chan.push((*pin, k));
        }
        for (k, c) in cap.channels.iter().enumerate() {
            if chan.iter().any(|&(_, kk)| kk == k) {
                continue;
            }
            if let Some(p) = Pin::parse(&c.name) {
                if !chan.iter().any(|&(pp, _)| pp == p) {
                    chan.push((p, k));
                }
            }
        }
        let map = PinMap { chan };
        let mut missing: Vec<&str> = REQUIRED.iter().filter(|p| map.get(**p).is_none()).map(|p| p.name()).collect();
        if map.get(Pin::NintSdoC).is_none() && map.get(Pin::SdozC).is_none() {
            missing.push("nINT_SDO_C or SDOZ_C");
        }
        if !missing.is_empty() {
            return Err(CaptureError(format!(
                "{file}: no channel for {}: a comparison needs the µC's bus (channels: {}; map a channel with --pin {}=CHANNEL)",
                missing.join(", "),
                channel_list(cap),
                missing[0].split(' ').next().unwrap_or("PIN")
            )));
        }
        Ok(map)
    }

    /// The channel index of a pin.
    pub fn get(&self, p: Pin) -> Option<usize> {
        self.chan.iter().find(|&&(pp, _)| pp == p).map(|&(_, k)| k)
    }

    /// The pins mapped, with their channel index.
    pub fn pins(&self) -> impl Iterator<Item = (Pin, usize)> + '_ {
        self.chan.iter().copied()
    }
}

fn channel_list(cap: &Capture) -> String {
    if cap.channels.is_empty() {
        return "none".into();
    }
    cap.channels.iter().map(|c| c.name.as_str()).collect::<Vec<_>>().join(", ")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_and_aliases() {
        for p in ALL {
            assert_eq!(Pin::parse(p.name()), Some(p));
            assert_eq!(Pin::parse(&p.name().to_ascii_lowercase()), Some(p));
        }
        assert_eq!(Pin::parse("step2"), Some(Pin::NscsS));
        assert_eq!(Pin::parse("D0"), None);
        let a = parse_assignments(&["nSCS_C=D0,SCK_C=D1".into(), "SDI_C=D2".into()]).unwrap();
        assert_eq!(a, vec![(Pin::NscsC, "D0".into()), (Pin::SckC, "D1".into()), (Pin::SdiC, "D2".into())]);
        assert!(parse_assignments(&["FOO=D1".into()]).unwrap_err().contains("unknown pin 'FOO'"));
    }
}
