//! Helpers shared by the driver-side tests: a pin-level recorder of chain datagrams and steps.
#![allow(dead_code)]

use std::cell::RefCell;
use std::rc::Rc;

use tmc429_model::events::{Event, EventDecoder};
use tmc429_model::host::Host;
use tmc429_model::regmap::{global_a7, motor_a7, ram_a7};
use tmc429_model::{Chip, Outputs};

pub type Log = Rc<RefCell<Vec<(Event, Outputs)>>>;

/// A host whose every edge goes through the pin-level [`EventDecoder`].
pub fn host_with_events(chip: Chip) -> (Host, Rc<RefCell<Vec<Event>>>) {
    let mut h = Host::new(chip);
    let log = Rc::new(RefCell::new(Vec::new()));
    let l2 = log.clone();
    let mut dec = EventDecoder::new();
    h.set_observer(Box::new(move |c, _i, o| {
        let cyc = c.cycle();
        dec.observe(c, o, cyc, &mut |e| l2.borrow_mut().push(e));
    }));
    (h, log)
}

pub fn chains(log: &Rc<RefCell<Vec<Event>>>) -> Vec<(u64, u32, u64)> {
    log.borrow()
        .iter()
        .filter_map(|e| match *e {
            Event::Chain { cycle, nbits, bits } => Some((cycle, nbits, bits)),
            _ => None,
        })
        .collect()
}

pub fn steps(log: &Rc<RefCell<Vec<Event>>>) -> Vec<(u64, u8, bool)> {
    log.borrow()
        .iter()
        .filter_map(|e| match *e {
            Event::Step { cycle, motor, negative } => Some((cycle, motor, negative)),
            _ => None,
        })
        .collect()
}

/// TMC428 Table 11-3 configuration datagrams (Table 11-2 RAM contents).
pub const TABLE_11_3: [u32; 18] = [
    0x80000510, 0x82000304, 0x84000602, 0x86000D10, 0x88000B0C, 0x8A002E0A, 0x8C000510, 0x8E000304,
    0x90000602, 0x92000D10, 0x94000B0C, 0x96002E0A, 0x98000507, 0x9A000304, 0x9C000602, 0x9E000D0F,
    0xA0000B0C, 0xA2002E0A,
];

/// TMC428 Table 12-2 LUT datagrams.
pub const TABLE_12_2: [u32; 32] = [
    0xC0000200, 0xC2000503, 0xC4000806, 0xC6000B09, 0xC8000E0C, 0xCA001110, 0xCC001413, 0xCE001716,
    0xD0001A18, 0xD2001D1B, 0xD400201E, 0xD6002221, 0xD8002524, 0xDA002726, 0xDC002A29, 0xDE002C2B,
    0xE0002E2D, 0xE200302F, 0xE4003231, 0xE6003433, 0xE8003635, 0xEA003837, 0xEC003938, 0xEE003B3A,
    0xF0003C3B, 0xF2003D3C, 0xF4003E3D, 0xF6003E3E, 0xF8003F3F, 0xFA003F3F, 0xFC003F3F, 0xFE003F3F,
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
