//! The motion profile of the stimulus ([`Profile::Motion`]): directed-random sequences that
//! make the motors move — moves in all four ramp modes with valid and boundary parameters,
//! on-the-fly target changes, mode changes during motion, reference searches with switch
//! events and latching, current-scale settings, driver-chain configurations (Table 11-2 and
//! random valid chains), cover datagrams, continuous update, refmux and Step/Dir — mixed with
//! the register traffic of [`Profile::Full`].

use proptest::prelude::*;

use tmc429_model::motor_regs::{RAMP_MODE, SOFT_MODE, VELOCITY_MODE};
use tmc429_model::pmulpdiv;
use tmc429_model::ram::TABLE_11_2;
use tmc429_model::regmap::{f, idx, jdx};
use tmc429_model::Chip;

use crate::stimulus::{motors, Frame, Profile, Stimulus, Txn};

/// a7 of a motor register (motor 0..2, [428] Table 8-1).
fn ma7(m: u8, i: u8) -> u8 {
    m << 4 | i
}

/// a7 of a global register ([428] Table 9-1).
fn ga7(j: u8) -> u8 {
    0x30 | j
}

fn w(a7: u8, data: u32) -> Txn {
    Txn::Frame(Frame::write(a7, data & 0xFF_FFFF))
}

fn r(a7: u8) -> Txn {
    Txn::Frame(Frame::read(a7))
}

/// Kinds of motion-profile step.
#[derive(Clone, Copy, Debug)]
enum Kind {
    Random,
    Move,
    Retarget,
    ModeChange,
    RefSearch,
    CurrentScale,
    Chain,
    Cover,
    StepDir,
    Idle,
    Other,
}

/// One RAM configuration cell: a primary signal code ([428] Table 11-1) without NxM.
fn code_strategy() -> impl Strategy<Value = u8> {
    prop_oneof![4 => 0u8..0x14, 1 => 0x14u8..0x20]
}

impl Stimulus {
    /// The next transaction of the motion profile (pending sequences first, by the caller).
    pub(crate) fn motion_txn(&mut self) -> Txn {
        debug_assert!(matches!(self.profile, Profile::Motion | Profile::MotionCore));
        let kind = self.draw_kind();
        let seq = match kind {
            Kind::Random => {
                let f = self.draw(crate::stimulus::frame_strategy(self.chip));
                vec![Txn::Frame(f)]
            }
            Kind::Move => self.move_seq(),
            Kind::Retarget => self.retarget_seq(),
            Kind::ModeChange => self.mode_change_seq(),
            Kind::RefSearch => self.ref_search_seq(),
            Kind::CurrentScale => self.current_scale_seq(),
            Kind::Chain => self.chain_seq(),
            Kind::Cover => self.cover_seq(),
            Kind::StepDir => self.step_dir_seq(),
            Kind::Idle => {
                vec![Txn::Idle(self.draw(prop_oneof![2 => 64u32..4000, 2 => 4000u32..40_000, 1 => 40_000u32..200_000]))]
            }
            Kind::Other => vec![self.register_txn()],
        };
        self.push_seq(seq)
    }

    /// The kind of the next sequence, drawn by weight (the driver chain's and Step/Dir's only
    /// where the chip has them).
    fn draw_kind(&mut self) -> Kind {
        let chain = self.chip != Chip::Tmc4210;
        let step_dir = self.chip != Chip::Tmc428;
        let weights = [
            (30, Kind::Random),
            (14, Kind::Move),
            (6, Kind::Retarget),
            (3, Kind::ModeChange),
            (3, Kind::RefSearch),
            (2, Kind::CurrentScale),
            (if chain { 3 } else { 0 }, Kind::Chain),
            (if chain { 3 } else { 0 }, Kind::Cover),
            (if step_dir { 2 } else { 0 }, Kind::StepDir),
            (10, Kind::Idle),
            (26, Kind::Other),
        ];
        let total: u32 = weights.iter().map(|(w, _)| w).sum();
        let mut x = self.draw(0..total);
        let mut kind = Kind::Other;
        for (wt, k) in weights {
            if x < wt {
                kind = k;
                break;
            }
            x -= wt;
        }
        kind
    }

    /// A new x_target near the last one (or farther) for a motor.
    fn retarget_seq(&mut self) -> Vec<Txn> {
        let m = self.motor();
        let d = self.draw(prop_oneof![3 => -2000i32..2000, 1 => -200_000i32..200_000]);
        let t = self.targets[m as usize].wrapping_add(d as u32) & 0xFF_FFFF;
        self.targets[m as usize] = t;
        vec![w(ma7(m, idx::X_TARGET), t)]
    }

    /// A ramp mode and ref_conf for a motor; VELOCITY_MODE with a v_target.
    fn mode_change_seq(&mut self) -> Vec<Txn> {
        let m = self.motor();
        let rm = self.draw(0u32..4);
        let conf = self.draw(0u32..16);
        let mut s = vec![w(ma7(m, idx::REF_CONF_RM), conf << 8 | rm)];
        if rm == VELOCITY_MODE as u32 {
            let v = self.draw(prop_oneof![3 => -300i32..300, 1 => -2048i32..2048]);
            s.push(w(ma7(m, idx::V_TARGET), v as u32 & 0xFFF));
        }
        s
    }

    /// The current scales and a_threshold of a motor.
    fn current_scale_seq(&mut self) -> Vec<Txn> {
        let m = self.motor();
        let (a, b, c) = (self.draw(0u32..8), self.draw(0u32..8), self.draw(0u32..8));
        let th = self.draw(prop_oneof![3 => 0u32..64, 1 => 0u32..2048]);
        vec![w(ma7(m, idx::CURRENT_SCALING), f::IS_AGTAT.put(a) | f::IS_ALEAT.put(b) | f::IS_V0.put(c) | f::A_THRESHOLD.put(th))]
    }

    /// A cover datagram: position, length, data, and the position read back.
    fn cover_seq(&mut self) -> Vec<Txn> {
        let pos = self.draw(prop_oneof![3 => 0u32..48, 1 => 0u32..64]);
        let len = self.draw(prop_oneof![3 => 1u32..25, 1 => 0u32..32]);
        let data = self.draw(0u32..0x100_0000);
        vec![
            w(ga7(jdx::COVER_POS_LEN), f::COVER_POS.put(pos) | f::COVER_LEN.put(len)),
            w(ga7(jdx::COVER_DATAGRAM), data),
            r(ga7(jdx::COVER_POS_LEN)),
        ]
    }

    /// Step/Dir on or off, with its bits of if_configuration and the step divider.
    fn step_dir_seq(&mut self) -> Vec<Txn> {
        let en = self.draw(prop_oneof![3 => Just(true), 1 => Just(false)]);
        let bits = self.draw(0u32..0x20) & !0x2; // keep sdo_int as the profile found it
        let sel = self.draw(0u32..4);
        let stpdiv = self.draw(prop_oneof![3 => 0u32..3, 1 => 0u32..16]);
        let gconf = f::CLK2_DIV.put(stpdiv) | f::LSMD.put(2);
        vec![
            w(ga7(jdx::GLOBAL_PARAMETERS), gconf),
            w(ga7(jdx::IF_CONFIGURATION), bits & 0x1D | f::EN_SD.put(en as u32) | f::POS_COMP_SEL.put(sel)),
        ]
    }

    fn push_seq(&mut self, mut seq: Vec<Txn>) -> Txn {
        let first = seq.remove(0);
        self.pending.extend(seq);
        first
    }

    fn motor(&mut self) -> u8 {
        let n = motors(self.chip) as u8;
        self.draw(0..n)
    }

    /// A complete move: clock dividers and microstep resolution, velocity limits, an a_max
    /// within the limits of [428] §8.7.1 and its p_mul/p_div ([428] §8.11), then a start
    /// position, a target and the mode; then time to move.
    fn move_seq(&mut self) -> Vec<Txn> {
        let m = self.motor();
        let pulse_div = self.draw(prop_oneof![6 => 0u32..3, 2 => 3u32..6, 1 => 6u32..14]);
        let ramp_div = (pulse_div + self.draw(prop_oneof![3 => 0u32..4, 1 => 4u32..8])).min(13);
        let usrs = self.draw(0u32..8);
        let v_max = self.draw(prop_oneof![3 => 1u32..400, 2 => 400u32..2048, 1 => Just(2047u32), 1 => Just(1u32)]);
        let v_min = self.draw(prop_oneof![3 => 0u32..4, 1 => 0u32..=v_max, 1 => Just(v_max)]);
        let e = ramp_div as i32 - pulse_div as i32;
        let lo = (1i64 << e.max(1)) / 2; // 2^(e-1), at least 1 for e = 0 (C-code: (int) 0.5 = 0)
        let hi = ((1i64 << (12 + e)) - 1).min(2047);
        let a_max = self.draw(prop_oneof![
            3 => lo.max(1)..=hi.max(1),
            1 => Just(lo.max(1)),
            1 => Just(hi.max(1)),
        ]) as i32;
        let red = self.draw(prop_oneof![Just(0.0f32), Just(0.01f32), Just(0.05f32)]);
        let pp = pmulpdiv::calc(a_max, ramp_div as i32, pulse_div as i32, red);
        let preg = match pp.register_value() {
            Some(v) => v,
            None => 0x80 << 8, // p_mul 128, p_div 0: the hardware accepts any value
        };
        let mode = self.draw(prop_oneof![4 => Just(RAMP_MODE), 2 => Just(SOFT_MODE), 2 => Just(VELOCITY_MODE)]);
        let start = self.draw(prop_oneof![2 => Just(0u32), 2 => 0u32..0x100_0000, 1 => 0xFF_FF00u32..0x100_0000]);
        let dist = self.draw(prop_oneof![
            3 => -3000i32..3000,
            2 => -40_000i32..40_000,
            1 => prop_oneof![Just(1i32), Just(-1), Just(2), Just(-2)],
            1 => -600_000i32..600_000,
        ]);
        let target = start.wrapping_add(dist as u32) & 0xFF_FFFF;
        self.targets[m as usize] = target;
        let conf = self.draw(prop_oneof![3 => Just(0u32), 1 => 0u32..16]);
        let mut s = vec![
            w(ma7(m, idx::REF_CONF_RM), conf << 8 | 3), // HOLD while configuring
            w(ma7(m, idx::V_ACTUAL), 0),
            w(ma7(m, idx::CLK_CONFIG), f::PULSE_DIV.put(pulse_div) | f::RAMP_DIV.put(ramp_div) | f::USRS.put(usrs)),
            w(ma7(m, idx::V_MIN), v_min),
            w(ma7(m, idx::V_MAX), v_max),
            w(ma7(m, idx::A_MAX), a_max as u32),
            w(ma7(m, idx::PMUL_PDIV), preg),
            w(ma7(m, idx::INTERRUPT), 0xFF00 | 0xFF),
            w(ma7(m, idx::X_ACTUAL), start),
            w(ma7(m, idx::X_TARGET), target),
        ];
        if mode == VELOCITY_MODE {
            let v = self.draw(prop_oneof![3 => -(v_max as i32)..=(v_max as i32), 1 => Just(-2048i32), 1 => Just(2047i32)]);
            s.push(w(ma7(m, idx::V_TARGET), v as u32 & 0xFFF));
        }
        s.push(w(ma7(m, idx::REF_CONF_RM), conf << 8 | mode as u32));
        let wait = self.draw(prop_oneof![2 => 200u32..5000, 2 => 5000u32..50_000, 1 => 50_000u32..300_000]);
        s.push(Txn::Idle(wait));
        s.push(r(ma7(m, idx::X_ACTUAL)));
        s.push(r(ma7(m, idx::V_ACTUAL)));
        s.push(r(ma7(m, idx::INTERRUPT)));
        s
    }

    /// A reference search ([428] §8.12, §8.15): move toward a switch in VELOCITY mode with the
    /// stop enabled (hard or soft) and the latch armed, the switch becomes active, then leaves.
    fn ref_search_seq(&mut self) -> Vec<Txn> {
        let m = self.motor();
        let soft = self.draw(any::<bool>()) as u32;
        let rnl = self.draw(any::<bool>()) as u32;
        let tol = self.draw(prop_oneof![2 => Just(0u32), 1 => 0u32..64]);
        let neg = self.draw(any::<bool>());
        let v = self.draw(20i32..400);
        let a_max = self.draw(1u32..200);
        let before = self.draw(500u32..20_000);
        let after = self.draw(500u32..20_000);
        let pin = self.draw(0usize..3);
        let mut s = vec![
            w(ma7(m, idx::REF_CONF_RM), 3),
            w(ma7(m, idx::CLK_CONFIG), f::PULSE_DIV.put(0) | f::RAMP_DIV.put(self.draw(0u32..3))),
            w(ma7(m, idx::V_MAX), 2047),
            w(ma7(m, idx::A_MAX), a_max),
            w(ma7(m, idx::DX_REF_TOLERANCE), tol),
            w(ma7(m, idx::INTERRUPT), 0xFF00 | 0xFF),
            w(ma7(m, idx::V_TARGET), (if neg { -v } else { v }) as u32 & 0xFFF),
            w(ma7(m, idx::X_LATCHED), 0), // arms the latch
            w(ma7(m, idx::REF_CONF_RM), (rnl << 3 | soft << 2) << 8 | VELOCITY_MODE as u32),
            Txn::Idle(before),
        ];
        // the switch becomes active, stays, then releases (both latch edges)
        let mut l = self.levels;
        l.ref_[pin] = !l.ref_[pin];
        s.push(Txn::Pins { levels: l, hold: after });
        let mut l2 = l;
        l2.ref_[pin] = !l2.ref_[pin];
        if self.chip == Chip::Tmc429 {
            l2.refr[pin] = !l2.refr[pin];
        }
        self.levels = l2;
        s.push(w(ma7(m, idx::X_LATCHED), 0));
        s.push(Txn::Pins { levels: l2, hold: after });
        s.push(r(ma7(m, idx::X_LATCHED)));
        s.push(r(ma7(m, idx::INTERRUPT)));
        s
    }

    /// A driver-chain configuration: the RAM (Table 11-2 or a random valid chain of 1..3
    /// drivers with NxM at the end of each) and the global parameter register with random
    /// polarities, clk2_div, continuous update, refmux and individual chip selects.
    fn chain_seq(&mut self) -> Vec<Txn> {
        let table = self.draw(prop_oneof![2 => Just(true), 1 => Just(false)]);
        let mut cells = [0u8; 64];
        let lsmd;
        if table {
            cells[..36].copy_from_slice(&TABLE_11_2);
            lsmd = 2;
        } else {
            lsmd = self.draw(0u32..3);
            let mut pos = 0usize;
            for _ in 0..=lsmd {
                let n = self.draw(prop_oneof![3 => 4usize..13, 1 => 1usize..21]);
                for k in 0..n {
                    if pos < 64 {
                        cells[pos] = self.draw(code_strategy()) | if k + 1 == n { 0x20 } else { 0 };
                        pos += 1;
                    }
                }
            }
        }
        let mut s: Vec<Txn> =
            (0..32u8).map(|a| w(0x40 | a, (cells[2 * a as usize + 1] as u32) << 8 | cells[2 * a as usize] as u32)).collect();
        let clk2 = self.draw(prop_oneof![3 => 0u32..16, 1 => 0u32..256]);
        let pol = self.draw(0u32..64) & 0x3C; // polarity bits 2..5
        let dac = self.draw(any::<bool>()) as u32;
        let csi = self.draw(prop_oneof![3 => Just(0u32), 1 => Just(1u32)]);
        let cont = self.draw(any::<bool>()) as u32;
        let refmux = self.draw(prop_oneof![3 => Just(0u32), 1 => Just(1u32)]);
        let mot1r = self.draw(prop_oneof![3 => Just(0u32), 1 => Just(1u32)]);
        let gconf = f::LSMD.put(lsmd)
            | pol
            | f::POL_DAC_AB.put(dac)
            | f::CS_COM_IND.put(csi)
            | f::CLK2_DIV.put(clk2)
            | f::CONT_UPDATE.put(cont)
            | f::REFMUX.put(refmux)
            | f::MOT1R.put(mot1r);
        if self.chip == Chip::Tmc429 {
            s.push(w(ga7(jdx::IF_CONFIGURATION), 0)); // SPI mode
        }
        s.push(w(ga7(jdx::GLOBAL_PARAMETERS), gconf));
        s
    }
}
