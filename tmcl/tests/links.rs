//! ASCII interface ([TMCL] §4.4), binary framing with timeouts, reference search, EEPROM
//! persistence, and the server under garbage and flooding.

mod common;
use common::*;

use std::io::{Read, Write};
use std::time::Duration;
use tmcl::chip::ModelChip;
use tmcl::io::World;
use tmcl::link::{Link, Mode};
use tmcl::personality::ModuleType;
use tmcl::proto::{op, Instruction};
use tmcl::server::{Options, Server};
use tmcl::{Module, Response};

fn direct(m: &mut Module<ModelChip>, o: u8, t: u8, mo: u8, v: i32) -> (u8, i32) {
    match m.handle_instruction(&Instruction::new(o, t, mo, v)) {
        Response::Normal(r) => (r.status, r.value),
        other => panic!("{other:?}"),
    }
}

#[test]
fn ascii_mode_and_echo_modes() {
    let mut m = module();
    let mut l = Link::new(false);
    // Enter ASCII mode with binary command 139.
    let r = l.feed(&mut m, &frame([1, 139, 0, 0, 0, 0, 0, 0]), 0);
    assert_eq!(r, frame([2, 1, 100, 139, 0, 0, 0, 0]).to_vec());
    assert_eq!(l.mode, Mode::Ascii);
    // Echo mode 00: every character echoed, then the reply "BA 100 <value>".
    let r = l.feed(&mut m, b"A MVP ABS, 0, 5000\r", 1);
    assert_eq!(String::from_utf8(r).unwrap(), "A MVP ABS, 0, 5000\rBA 100 5000\r");
    m.run_ms(1500);
    let r = l.feed(&mut m, b"AGAP 0, 0\r", 2);
    assert_eq!(String::from_utf8(r).unwrap(), "AGAP 0, 0\rBA 100 5000\r");
    // Manual §4.4.2 example: actual position -5000 reads "BA 100 -5000".
    direct(&mut m, op::SAP, 1, 1, -5000);
    let r = l.feed(&mut m, b"AGAP 1, 1\r", 3);
    assert!(String::from_utf8(r).unwrap().ends_with("BA 100 -5000\r"));
    // Backspace erases a character.
    let r = l.feed(&mut m, b"AGAP 4, 00\x08\r", 4);
    assert_eq!(String::from_utf8(r).unwrap(), "AGAP 4, 00\x08\rBA 100 1000\r");
    // Another module's address character: ignored, no echo.
    assert_eq!(l.feed(&mut m, b"BGAP 1, 0\r", 5), Vec::<u8>::new());
    // Commands not allowed in ASCII mode, unknown commands: status 2; bad operands: 4.
    assert!(String::from_utf8(l.feed(&mut m, b"AJA 3\r", 6)).unwrap().ends_with("BA 2 0\r"));
    assert!(String::from_utf8(l.feed(&mut m, b"AFOO\r", 6)).unwrap().ends_with("BA 2 0\r"));
    assert!(String::from_utf8(l.feed(&mut m, b"AGAP x\r", 6)).unwrap().ends_with("BA 4 0\r"));
    // Echo mode bit 4: the whole line after <CR>.
    let r = l.feed(&mut m, b"ASGP 67, 0, 16\r", 7);
    assert!(String::from_utf8(r).unwrap().ends_with("BA 100 16\r"));
    let r = l.feed(&mut m, b"AROR 0, 100\r", 8);
    assert_eq!(String::from_utf8(r).unwrap(), "AROR 0, 100\rBA 100 100\r");
    // Echo mode bit 5: no echo, only the reply.
    l.feed(&mut m, b"ASGP 67, 0, 32\r", 9);
    let r = l.feed(&mut m, b"AMST 0\r", 10);
    assert_eq!(String::from_utf8(r).unwrap(), "BA 100 0\r");
    // RUN and STOP (ASCII only), then BIN back to binary mode.
    assert_eq!(String::from_utf8(l.feed(&mut m, b"ARUN\r", 11)).unwrap(), "BA 100 0\r");
    assert_eq!(String::from_utf8(l.feed(&mut m, b"ASTOP\r", 11)).unwrap(), "BA 100 0\r");
    assert_eq!(String::from_utf8(l.feed(&mut m, b"ABIN\r", 12)).unwrap(), "BA 100 0\r");
    assert_eq!(l.mode, Mode::Binary);
    let r = l.feed(&mut m, &frame([1, 6, 4, 0, 0, 0, 0, 0]), 13);
    assert_eq!(r, frame([2, 1, 100, 6, 0, 0, 0x03, 0xe8]).to_vec());
    // Start-up mode from bit 0 of global parameter 67.
    direct(&mut m, op::SGP, 67, 0, 1);
    assert_eq!(Link::for_module(&m).mode, Mode::Ascii);
}

#[test]
fn partial_frames_time_out_and_wrong_addresses_are_silent() {
    let mut m = module();
    let mut l = Link::new(false);
    let f = frame([1, 6, 1, 0, 0, 0, 0, 0]);
    // Half a frame, a pause longer than the timeout, then a whole frame: one reply.
    assert!(l.feed(&mut m, &f[..4], 0).is_empty());
    assert!(l.poll(&mut m, 100).is_empty());
    let r = l.feed(&mut m, &f, 100);
    assert_eq!(r, frame([2, 1, 100, 6, 0, 0, 0, 0]).to_vec());
    // Split across two reads without a pause: still one frame.
    assert!(l.feed(&mut m, &f[..5], 200).is_empty());
    assert_eq!(l.feed(&mut m, &f[5..], 210).len(), 9);
    // Another module's address: no reply.
    assert!(l.feed(&mut m, &frame([5, 6, 1, 0, 0, 0, 0, 0]), 300).is_empty());
}

#[test]
fn target_reached_event_138() {
    let mut m = module();
    let mut l = Link::new(false);
    l.feed(&mut m, &frame([1, 4, 0, 1, 0, 0, 0x07, 0xd0]), 0); // MVP ABS, 1, 2000
    let r = l.feed(&mut m, &frame([1, 138, 0, 0, 0, 0, 0, 2]), 0);
    assert_eq!(r, frame([2, 1, 100, 138, 0, 0, 0, 2]).to_vec());
    assert!(l.poll(&mut m, 1).is_empty());
    m.run_ms(1000);
    assert_eq!(l.poll(&mut m, 2), frame([2, 1, 128, 138, 0, 0, 0, 2]).to_vec());
    assert!(l.poll(&mut m, 3).is_empty());
}

#[test]
fn reference_search_left_switch_and_home() {
    let mut m = module();
    // Left end switch of axis 0 active at positions <= -3000.
    m.world.left[0] = Some(World::left_end(-3000));
    direct(&mut m, op::SAP, 193, 0, 1);
    direct(&mut m, op::SAP, 194, 0, 300);
    direct(&mut m, op::SAP, 195, 0, 20);
    assert_eq!(direct(&mut m, op::RFS, 0, 0, 0).0, 100);
    assert_ne!(direct(&mut m, op::RFS, 2, 0, 0).1, 0);
    let mut ms = 0;
    while direct(&mut m, op::RFS, 2, 0, 0).1 != 0 && ms < 10000 {
        m.run_ms(10);
        ms += 10;
    }
    assert_eq!(direct(&mut m, op::RFS, 2, 0, 0), (100, 0));
    // The switching point (mechanical -3000) is now position 0, within the polling latency.
    let x = direct(&mut m, op::GAP, 1, 0, 0).1;
    let mech = m.chip.mechanical_position_of(0);
    assert!((mech + 3000 - x).abs() <= 3, "position {x}, mechanical {mech}");
    assert_eq!(direct(&mut m, op::GAP, 11, 0, 0).1, (mech <= -3000) as i32);
    // Mode 7: home switch in positive direction.
    m.world.home[1] = Some((1000, 1200));
    direct(&mut m, op::SAP, 193, 1, 7);
    direct(&mut m, op::RFS, 0, 1, 0);
    let mut ms = 0;
    while direct(&mut m, op::RFS, 2, 1, 0).1 != 0 && ms < 10000 {
        m.run_ms(10);
        ms += 10;
    }
    let x = direct(&mut m, op::GAP, 1, 1, 0).1;
    let mech = m.chip.mechanical_position_of(1);
    assert!((mech - 1000 - x).abs() <= 10, "position {x}, mechanical {mech}");
}

#[test]
fn end_switch_stops_motor_via_chip() {
    let mut m = module();
    m.world.right[2] = Some(World::right_end(800));
    direct(&mut m, op::ROR, 0, 2, 200);
    m.run_ms(500);
    assert_eq!(direct(&mut m, op::GAP, 10, 2, 0).1, 1);
    assert_eq!(direct(&mut m, op::GAP, 3, 2, 0).1, 0);
    let x = direct(&mut m, op::GAP, 1, 2, 0).1;
    assert!((800..=820).contains(&x), "stopped at {x}");
    // Right limit switch disabled (parameter 12): it runs on.
    direct(&mut m, op::SAP, 12, 2, 1);
    m.run_ms(200);
    assert!(direct(&mut m, op::GAP, 1, 2, 0).1 > 900);
}

/// A TMCM-3110 module whose EEPROM image is the file `module.eep` in a fresh directory of the
/// test `tag`: the file's path and the module's constructor.
fn eeprom_module(tag: &str) -> (std::path::PathBuf, impl Fn() -> Result<Module<ModelChip>, (ModelChip, tmcl::eeprom::EepromError)>) {
    let dir = std::env::temp_dir().join(format!("tmcl-eeprom-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("module.eep");
    let p = path.clone();
    (path, move || Module::with_eeprom(ModelChip::new(tmc429_model::Chip::Tmc429, 16_000_000), ModuleType::Tmcm3110, p.clone()))
}

#[test]
fn eeprom_persistence() {
    let (path, new) = eeprom_module("keep");
    {
        let mut m = new().ok().expect("missing file = factory defaults");
        assert_eq!(direct(&mut m, op::GAP, 4, 0, 0), (100, 1000));
        direct(&mut m, op::SAP, 4, 0, 1500);
        direct(&mut m, op::STAP, 4, 0, 0);
        direct(&mut m, op::SAP, 5, 1, 700); // not stored
        direct(&mut m, op::SGP, 7, 2, 99);
        direct(&mut m, op::STGP, 7, 2, 0);
        direct(&mut m, op::SGP, 77, 0, 0); // bank 0: stored by SGP
        direct(&mut m, op::DOWNLOAD_START, 0, 0, 0);
        direct(&mut m, op::SGP, 8, 2, 5);
        direct(&mut m, op::STOP, 0, 0, 0);
        direct(&mut m, op::DOWNLOAD_END, 0, 0, 0);
        // RSAP restores the stored value.
        direct(&mut m, op::SAP, 4, 0, 10);
        assert_eq!(direct(&mut m, op::RSAP, 4, 0, 0), (100, 1500));
    }
    let mut m = new().ok().unwrap();
    assert_eq!(direct(&mut m, op::GAP, 4, 0, 0), (100, 1500));
    assert_eq!(direct(&mut m, op::GAP, 5, 1, 0), (100, 1000));
    assert_eq!(direct(&mut m, op::GGP, 7, 2, 0), (100, 99));
    assert_eq!(m.program(), &[Instruction::new(op::SGP, 8, 2, 5), Instruction::new(op::STOP, 0, 0, 0)]);
    // Read memory (command 134): type 0 opcode/type/motor, type 1 value.
    assert_eq!(direct(&mut m, op::READ_MEMORY, 0, 0, 0), (100, (9 << 24) | (8 << 16) | (2 << 8)));
    assert_eq!(direct(&mut m, op::READ_MEMORY, 1, 0, 0), (100, 5));
    // Restore factory defaults (137, value 1234): no reply.
    assert!(matches!(m.handle_instruction(&Instruction::new(op::FACTORY_DEFAULTS, 0, 0, 1234)), Response::None));
    assert_eq!(direct(&mut m, op::GAP, 4, 0, 0), (100, 1000));
    assert_eq!(std::fs::read(&path).unwrap(), tmcl::eeprom::Image::default().encode());
    let _ = std::fs::remove_dir_all(path.parent().unwrap());
}

#[test]
fn eeprom_corruption() {
    let (path, new) = eeprom_module("corrupt");
    let good = tmcl::eeprom::Image::default().encode();
    // Corrupt: one flipped byte, a truncated file: rejected as a whole.
    let mut bad = good.clone();
    bad[20] ^= 1;
    std::fs::write(&path, &bad).unwrap();
    let e = new().err().expect("corrupt file rejected").1.to_string();
    assert!(e.starts_with("corrupt EEPROM image: CRC-32 mismatch"), "{e}");
    std::fs::write(&path, &good[..good.len() - 5]).unwrap();
    let e = new().err().expect("truncated file rejected").1.to_string();
    assert!(e.contains("payload length field"), "{e}");
    // A stored program must pass the download check; an image of the other module type is
    // not loaded either.
    let img = tmcl::eeprom::Image { program: vec![Instruction::new(op::ROR, 0, 0, 5000)], ..Default::default() };
    img.save(&path).unwrap();
    let e = new().err().expect("program refused").1.to_string();
    assert_eq!(e, "corrupt EEPROM image: program instruction 0: velocity 5000 is outside −2047..2047 (TMC429 units; --module tmcm-1311 takes pps) (status 4)");
    tmcl::eeprom::Image::factory(ModuleType::Tmcm1311).save(&path).unwrap();
    let e = new().err().expect("other module type").1.to_string();
    assert_eq!(e, "corrupt EEPROM image: the image is of a TMCM-1311, this module is a TMCM-3110");
    let chip = ModelChip::new(tmc429_model::Chip::Tmc429, 16_000_000);
    assert!(Module::with_eeprom(chip, ModuleType::Tmcm1311, path.clone()).is_ok());
    let _ = std::fs::remove_dir_all(path.parent().unwrap());
}

/// A server of a fresh module on a free TCP port of 127.0.0.1 (no pty), real time, 50 ms frame timeout.
fn tcp_server() -> (Server, std::net::SocketAddr) {
    let srv =
        Server::start(module(), &Options { tcp: Some("127.0.0.1:0".into()), pty: false, time_scale: 1.0, frame_timeout_ms: 50 }).unwrap();
    let addr = srv.tcp_addr.unwrap();
    (srv, addr)
}

fn connect(addr: std::net::SocketAddr) -> std::net::TcpStream {
    let s = std::net::TcpStream::connect(addr).unwrap();
    s.set_read_timeout(Some(Duration::from_secs(5))).unwrap();
    s
}

fn ask(s: &mut std::net::TcpStream, f: [u8; 9]) -> [u8; 9] {
    s.write_all(&f).unwrap();
    let mut r = [0u8; 9];
    s.read_exact(&mut r).unwrap();
    r
}

#[test]
fn server_survives_garbage_and_floods() {
    let (srv, addr) = tcp_server();
    let mut good = connect(addr);
    assert_eq!(ask(&mut good, frame([1, 5, 4, 0, 0, 0, 0x04, 0xb0])), frame([2, 1, 100, 5, 0, 0, 0x04, 0xb0]));
    assert_eq!(ask(&mut good, frame([1, 9, 42, 2, 0, 0, 0, 7])), frame([2, 1, 100, 9, 0, 0, 0, 7]));
    // Wrong checksum: status 1.
    let mut bad = frame([1, 6, 4, 0, 0, 0, 0, 0]);
    bad[8] = bad[8].wrapping_add(1);
    let mut g2 = connect(addr);
    assert_eq!(ask(&mut g2, bad), frame([2, 1, 1, 0, 0, 0, 0, 0]));
    // A half frame then silence: dropped after the timeout, the next frame is answered.
    g2.write_all(&[1, 6, 4]).unwrap();
    std::thread::sleep(Duration::from_millis(150));
    assert_eq!(ask(&mut g2, frame([1, 6, 4, 0, 0, 0, 0, 0])), frame([2, 1, 100, 6, 0, 0, 0x04, 0xb0]));
    // Flooders: random garbage and valid frames without reading replies, then vanish.
    let mut floods = Vec::new();
    for k in 0..3u32 {
        floods.push(std::thread::spawn(move || {
            let mut s = std::net::TcpStream::connect(addr).unwrap();
            let mut x = 0x1234_5678u32.wrapping_add(k);
            let mut buf = vec![0u8; 65536];
            for _ in 0..20 {
                for b in buf.iter_mut() {
                    x ^= x << 13;
                    x ^= x >> 17;
                    x ^= x << 5;
                    *b = x as u8;
                }
                if s.write_all(&buf).is_err() {
                    break;
                }
            }
        }));
    }
    // Meanwhile the well-behaved client is served and its state is intact.
    for _ in 0..20 {
        assert_eq!(ask(&mut good, frame([1, 10, 42, 2, 0, 0, 0, 0])), frame([2, 1, 100, 10, 0, 0, 0, 7]));
    }
    for f in floods {
        f.join().unwrap();
    }
    let mut g3 = connect(addr);
    assert_eq!(ask(&mut g3, frame([1, 6, 4, 0, 0, 0, 0, 0])), frame([2, 1, 100, 6, 0, 0, 0x04, 0xb0]));
    assert_eq!(ask(&mut g3, frame([1, 10, 42, 2, 0, 0, 0, 0])), frame([2, 1, 100, 10, 0, 0, 0, 7]));
    srv.shutdown();
}

/// Sends the ASCII command `line` (CR appended) on `s` and checks what comes back: the line's
/// echo (echo mode 00), then `reply` and CR.
fn ascii(s: &mut std::net::TcpStream, line: &str, reply: &str) {
    s.write_all(format!("{line}\r").as_bytes()).unwrap();
    let want = format!("{line}\r{reply}\r");
    let mut got = Vec::new();
    let mut b = [0u8; 64];
    while got.len() < want.len() {
        let n = s.read(&mut b).expect("reply within the read timeout");
        assert!(n > 0, "connection closed after {:?}", String::from_utf8_lossy(&got));
        got.extend_from_slice(&b[..n]);
    }
    assert_eq!(String::from_utf8_lossy(&got), want);
}

/// The ASCII interface ([TMCL] §4.4) over the TCP link: command 139 switches that connection to
/// ASCII mode, command lines are echoed character by character (echo mode 00, global parameter
/// 67 = 0) and answered `BA <status> <value>` CR; another connection stays binary; BIN returns.
#[test]
fn ascii_mode_over_tcp() {
    let (srv, addr) = tcp_server();
    let mut a = connect(addr);
    assert_eq!(ask(&mut a, frame([1, 139, 0, 0, 0, 0, 0, 0])), frame([2, 1, 100, 139, 0, 0, 0, 0]));
    ascii(&mut a, "AGAP 4, 0", "BA 100 1000");
    ascii(&mut a, "ASAP 4, 1, 1234", "BA 100 1234");
    // A second connection is binary and sees the same module.
    let mut b = connect(addr);
    assert_eq!(ask(&mut b, frame([1, 6, 4, 1, 0, 0, 0, 0])), frame([2, 1, 100, 6, 0, 0, 0x04, 0xd2]));
    // Unknown command: status 2; BIN: back to binary frames.
    ascii(&mut a, "AFOO", "BA 2 0");
    ascii(&mut a, "ABIN", "BA 100 0");
    assert_eq!(ask(&mut a, frame([1, 6, 4, 0, 0, 0, 0, 0])), frame([2, 1, 100, 6, 0, 0, 0x03, 0xe8]));
    srv.shutdown();
}
