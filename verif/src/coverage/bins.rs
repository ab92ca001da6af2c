//! The coverage bins' names: which bins a chip has under a stimulus profile.

use tmc429_model::regmap;
use tmc429_model::Chip;

use super::{reg_name, FLAG_NAMES};
use crate::stimulus::Profile;

/// The bin of a step at each usrs (named without formatting: it is hit in the per-cycle path).
pub(super) const USRS_STEP_BINS: [&str; 8] = [
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

/// Every bin of a chip under a stimulus profile.
pub(super) fn bin_names(chip: Chip, profile: Profile) -> Vec<String> {
    let mut names = register_bins(chip, profile);
    names.extend(frame_and_pin_bins(chip, profile));
    names.extend(variant_bins(chip, profile));
    names
}

/// A write and a read of each register the profile reaches, of each RAM word, and of an
/// unused address.
fn register_bins(chip: Chip, profile: Profile) -> Vec<String> {
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
    names
}

/// Frame shapes, power down, interrupt flags and switch levels.
fn frame_and_pin_bins(chip: Chip, profile: Profile) -> Vec<String> {
    let mut names: Vec<String> = Vec::new();
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
    names
}

/// The bins of one variant's own features, the driver side and the motion profile.
fn variant_bins(chip: Chip, profile: Profile) -> Vec<String> {
    let mut names: Vec<String> = Vec::new();
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
    names
}
