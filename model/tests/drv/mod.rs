//! Helpers shared by the driver-side tests: a pin-level recorder of chain datagrams and steps.
#![allow(dead_code)]

use std::sync::{Arc, Mutex};

use tmc429_model::events::{Event, EventDecoder};
use tmc429_model::host::Host;
use tmc429_model::regmap::{global_a7, motor_a7, ram_a7};
use tmc429_model::{Chip, Outputs};

pub type Log = Arc<Mutex<Vec<(Event, Outputs)>>>;

/// A host whose every edge goes through the pin-level [`EventDecoder`].
pub fn host_with_events(chip: Chip) -> (Host, Arc<Mutex<Vec<Event>>>) {
    let mut h = Host::new(chip);
    let log = Arc::new(Mutex::new(Vec::new()));
    let l2 = log.clone();
    let mut dec = EventDecoder::new();
    h.set_observer(Box::new(move |c, _i, o| {
        let cyc = c.cycle();
        dec.observe(c, o, cyc, &mut |e| l2.lock().unwrap().push(e));
    }));
    (h, log)
}

pub fn chains(log: &Arc<Mutex<Vec<Event>>>) -> Vec<(u64, u32, u64)> {
    log.lock()
        .unwrap()
        .iter()
        .filter_map(|e| match *e {
            Event::Chain { cycle, nbits, bits } => Some((cycle, nbits, bits)),
            _ => None,
        })
        .collect()
}

pub fn steps(log: &Arc<Mutex<Vec<Event>>>) -> Vec<(u64, u8, bool)> {
    log.lock()
        .unwrap()
        .iter()
        .filter_map(|e| match *e {
            Event::Step { cycle, motor, negative } => Some((cycle, motor, negative)),
            _ => None,
        })
        .collect()
}

/// TMC428 Table 11-3 configuration datagrams (Table 11-2 RAM contents).
pub const TABLE_11_3: [u32; 18] = [
    0x80000510, 0x82000304, 0x84000602, 0x86000D10, 0x88000B0C, 0x8A002E0A, 0x8C000510, 0x8E000304, 0x90000602, 0x92000D10, 0x94000B0C,
    0x96002E0A, 0x98000507, 0x9A000304, 0x9C000602, 0x9E000D0F, 0xA0000B0C, 0xA2002E0A,
];

/// TMC428 Table 12-2 LUT datagrams.
pub const TABLE_12_2: [u32; 32] = [
    0xC0000200, 0xC2000503, 0xC4000806, 0xC6000B09, 0xC8000E0C, 0xCA001110, 0xCC001413, 0xCE001716, 0xD0001A18, 0xD2001D1B, 0xD400201E,
    0xD6002221, 0xD8002524, 0xDA002726, 0xDC002A29, 0xDE002C2B, 0xE0002E2D, 0xE200302F, 0xE4003231, 0xE6003433, 0xE8003635, 0xEA003837,
    0xEC003938, 0xEE003B3A, 0xF0003C3B, 0xF2003D3C, 0xF4003E3D, 0xF6003E3E, 0xF8003F3F, 0xFA003F3F, 0xFC003F3F, 0xFE003F3F,
];

pub const GCONF: u8 = global_a7(15);
pub const COVER_POS_LEN: u8 = global_a7(2);
pub const COVER_DATAGRAM: u8 = global_a7(3);
pub const IF_CONF: u8 = global_a7(4);

/// Global parameter word: LSMD, clk2_div, plus extra bits.
pub fn gconf(lsmd: u32, clk2_div: u32, extra: u32) -> u32 {
    lsmd | clk2_div << 8 | extra
}

/// Loads Table 11-2 and Table 12-2 through µC datagrams, LSMD = 2, clk2_div = 7.
pub fn load_tables(h: &mut Host) {
    for d in TABLE_11_3.iter().chain(TABLE_12_2.iter()) {
        h.datagram(*d);
    }
    h.write(GCONF, gconf(2, 7, 0));
}

pub fn set_ustep(h: &mut Host, m: u8, w: u8) {
    h.write(motor_a7(m, 15), w as u32);
}

/// Requests one datagram with an empty cover (cover_len 0 sends an unchanged datagram).
pub fn request(h: &mut Host) {
    h.write(COVER_DATAGRAM, 0);
}

/// Waits until the chain is idle again (at most `max` cycles).
pub fn settle(h: &mut Host, max: u64) {
    for _ in 0..max {
        if h.chip().chain().state == tmc429_model::chain::IDLE && !h.chip().chain().req && !h.chip().global().cw {
            return;
        }
        h.wait(1);
    }
}

pub fn ram_word(a: u8) -> u8 {
    ram_a7(a)
}

/// A host that records the outputs after every edge: `trace[i]` = (cycle, outputs).
pub fn host_with_trace(chip: Chip) -> (Host, Arc<Mutex<Vec<(u64, Outputs)>>>) {
    let mut h = Host::new(chip);
    let log = Arc::new(Mutex::new(Vec::new()));
    let l2 = log.clone();
    h.set_observer(Box::new(move |c, _i, o| l2.lock().unwrap().push((c.cycle(), *o))));
    (h, log)
}

/// Intervals (start cycle, length) during which `level(outputs)` is true.
pub fn pulses(trace: &[(u64, Outputs)], level: impl Fn(&Outputs) -> bool) -> Vec<(u64, u64)> {
    let mut v = Vec::new();
    let mut start = None;
    for &(c, o) in trace {
        match (level(&o), start) {
            (true, None) => start = Some(c),
            (false, Some(s)) => {
                v.push((s, c - s));
                start = None;
            }
            _ => {}
        }
    }
    v
}

/// Runs `cycles` edges emulating a 74HC157 on nSCS_S: REFn = left[n] while nSCS_S is high,
/// right[n] while low; and a driver chain returning `ret` (MSB first, `nret` bits) on SDI_S,
/// one bit per falling SCK_S edge while a chip select is active (SPI mode 3).
pub fn run_board(h: &mut Host, cycles: u64, left: [bool; 3], right: [bool; 3], ret: u64, nret: u32) {
    let mut k = 0u32;
    let mut prev = h.outputs();
    for _ in 0..cycles {
        let o = h.outputs();
        let cs = !o.nscs_s || !o.nscs2 || !o.nscs3;
        let prev_cs = !prev.nscs_s || !prev.nscs2 || !prev.nscs3;
        if cs && !prev_cs {
            k = 0;
        }
        if cs && prev.sck_s && !o.sck_s {
            k += 1;
        }
        // SPI mode 3: bit i goes out at the (i+1)-th falling edge, sampled at the next rising one.
        let bit = if k >= 1 && k <= nret { (ret >> (nret - k)) & 1 != 0 } else { false };
        let sel = if o.nscs_s { left } else { right };
        let p = h.pins_mut();
        p.ref1 = sel[0];
        p.ref2 = sel[1];
        p.ref3 = sel[2];
        p.sdi_s = bit;
        prev = o;
        h.wait(1);
    }
}
