//! GTKWave save files (`.gtkw`) for the VCD of a run: they open the VCD on the signals a reader
//! of a motion scenario looks at first — the µC's SPI frames, INT and the status byte, each
//! motor's position and velocity as analog traces with its step and direction, the reference
//! switches, and the driver-chain pins.

use tmc429_testbench::signals::SIGNALS;

/// One line of the view: a comment (group title) or a signal with GTKWave's display flags.
enum Row {
    Comment(String),
    Signal { name: String, flags: u32, analog_rows: u32 },
}

// GTKWave trace flags (gtkwave analyzer.h): hex, dec, bin, right-justify, signed, analog.
const HEX: u32 = 0x2;
const DEC: u32 = 0x4;
const BIN: u32 = 0x8;
const RJUSTIFY: u32 = 0x20;
const SIGNED: u32 = 0x400;
const ANALOG_INTERPOLATED: u32 = 0x10000;
const ANALOG_STEP: u32 = 0x8000;

fn width_of(full: &str) -> u32 {
    let (scope, name) = full.rsplit_once('.').unwrap_or(("", full));
    let scope = scope.strip_prefix("rtl.").unwrap_or(scope);
    SIGNALS.iter().find(|s| s.scope == scope && s.name == name).map(|s| s.width).unwrap_or(1)
}

/// A VCD name as GTKWave lists it: vectors carry their bit range.
pub fn gtkw_name(full: &str) -> String {
    let w = width_of(full);
    if w > 1 {
        format!("{full}[{}:0]", w - 1)
    } else {
        full.to_string()
    }
}

fn rows(motors: usize, cosim: bool) -> Vec<Row> {
    let sig = |n: &str, flags: u32| Row::Signal { name: n.to_string(), flags, analog_rows: 0 };
    let analog = |n: String, step: bool| Row::Signal {
        name: n,
        flags: (if step { ANALOG_STEP } else { ANALOG_INTERPOLATED }) | SIGNED | DEC | RJUSTIFY,
        analog_rows: 6,
    };
    let mut v = Vec::new();
    if cosim {
        v.push(Row::Comment("co-simulation".into()));
        v.push(sig("cosim.mismatch", BIN | RJUSTIFY));
    }
    v.push(Row::Comment("µC SPI".into()));
    for n in ["top.nscs_c", "top.sck_c", "top.sdi_c", "top.nint_sdo_c"] {
        v.push(sig(n, BIN | RJUSTIFY));
    }
    v.push(sig("spi.transaction", BIN | RJUSTIFY));
    v.push(sig("top.status", HEX | RJUSTIFY));
    for m in 0..motors {
        v.push(Row::Comment(format!("motor {m}")));
        v.push(analog(format!("motor{m}.x_actual"), false));
        v.push(analog(format!("motor{m}.v_internal"), true));
        v.push(sig(&format!("motor{m}.x_target"), SIGNED | DEC | RJUSTIFY));
        v.push(sig(&format!("motor{m}.a_actual"), SIGNED | DEC | RJUSTIFY));
        v.push(sig(&format!("motor{m}.step"), BIN | RJUSTIFY));
        v.push(sig(&format!("motor{m}.dir"), BIN | RJUSTIFY));
        v.push(sig(&format!("motor{m}.ustep"), DEC | RJUSTIFY));
        if cosim {
            v.push(sig(&format!("rtl.motor{m}.x_actual"), SIGNED | DEC | RJUSTIFY));
        }
    }
    v.push(Row::Comment("switches".into()));
    for n in ["top.ref1", "top.ref2", "top.ref3"] {
        v.push(sig(n, BIN | RJUSTIFY));
    }
    v.push(Row::Comment("driver chain".into()));
    for n in ["top.nscs_s", "top.sck_s", "top.sdo_s"] {
        v.push(sig(n, BIN | RJUSTIFY));
    }
    v.push(sig("chain.state", HEX | RJUSTIFY));
    v
}

/// The VCD variables (`scope.name`, no bit range) a save file names.
pub fn signals(motors: usize, cosim: bool) -> Vec<String> {
    rows(motors, cosim)
        .into_iter()
        .filter_map(|r| match r {
            Row::Signal { name, .. } => Some(name),
            Row::Comment(_) => None,
        })
        .collect()
}

/// The save file for `vcd_file` (a path as GTKWave should open it, relative to the save file)
/// over `end_ps` picoseconds.
pub fn save_file(vcd_file: &str, title: &str, motors: usize, cosim: bool, end_ps: u64) -> String {
    let mut s = String::new();
    s.push_str(&format!("[*] {title}\n[*] usage: gtkwave {}\n", vcd_file.replace(".vcd", ".gtkw")));
    s.push_str(&format!("[dumpfile] \"{vcd_file}\"\n"));
    s.push_str("[timestart] 0\n[size] 1600 1000\n[pos] -1 -1\n");
    // zoom so the whole run fits about 1500 pixels: GTKWave's zoom is log2 of time per pixel, negated
    let zoom = -((end_ps as f64 / 1500.0).max(1.0)).log2().ceil();
    s.push_str(&format!("*{zoom:.6} 0 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1\n"));
    s.push_str("[sst_width] 240\n[signals_width] 280\n[sst_expanded] 1\n[sst_vpaned_height] 200\n");
    let mut flags_now = u32::MAX;
    for r in rows(motors, cosim) {
        match r {
            Row::Comment(c) => {
                s.push_str("@200\n");
                s.push_str(&format!("-{c}\n"));
                flags_now = 0x200;
            }
            Row::Signal { name, flags, analog_rows } => {
                if flags != flags_now {
                    s.push_str(&format!("@{flags:x}\n"));
                    flags_now = flags;
                }
                s.push_str(&gtkw_name(&name));
                s.push('\n');
                if analog_rows > 0 {
                    // extra height of an analog trace: blank rows flagged 0x20000
                    s.push_str("@20000\n");
                    for _ in 0..analog_rows {
                        s.push_str("-\n");
                    }
                    flags_now = 0x20000;
                }
            }
        }
    }
    s.push_str("[pattern_trace] 1\n[pattern_trace] 0\n");
    s
}
