//! The firmware manual's examples, byte for byte, and every status code ([TMCL] §4, §5.7).

mod common;
use common::*;

use std::path::Path;
use tmcl::asm;
use tmcl::chip::ModelChip;
use tmcl::proto::{checksum, op, Command, Instruction, Reply, Status};
use tmcl::{Module, Response};

fn send(m: &mut Module<ModelChip>, b8: [u8; 8]) -> Vec<u8> {
    m.handle_bytes(&frame(b8)).to_bytes()
}

fn one(src: &str) -> Instruction {
    let p = asm::assemble(Path::new("t.tmc"), src, &asm::FileSystem).expect("assembles");
    assert_eq!(p.code.len(), 1);
    p.code[0]
}

/// Mnemonic → the 8 bytes the manual prints (target address 1), and the checksum.
#[test]
fn manual_command_bytes() {
    let cases: &[(&str, [u8; 8])] = &[
        ("ROR 0, 10000", [0x01, 0x01, 0x00, 0x00, 0x00, 0x00, 0x27, 0x10]),
        ("ROL 0, 10000", [0x01, 0x02, 0x00, 0x00, 0x00, 0x00, 0x27, 0x10]),
        ("MST 0", [0x01, 0x03, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00]),
        // §5.7.4 prints the mnemonic with 9000 but the bytes and text say 90000.
        ("MVP ABS, 0, 90000", [0x01, 0x04, 0x00, 0x00, 0x00, 0x01, 0x5f, 0x90]),
        ("MVP REL, 0, -1000", [0x01, 0x04, 0x01, 0x00, 0xff, 0xff, 0xfc, 0x18]),
        ("MVP COORD, 0, 8", [0x01, 0x04, 0x02, 0x00, 0x00, 0x00, 0x00, 0x08]),
        ("SAP 6, 0, 200", [0x01, 0x05, 0x06, 0x00, 0x00, 0x00, 0x00, 0xc8]),
        // §5.7.6 prints "GAP 6, 0" with motor byte 1.
        ("GAP 6, 1", [0x01, 0x06, 0x06, 0x01, 0x00, 0x00, 0x00, 0x00]),
        ("STAP 4, 0", [0x01, 0x07, 0x04, 0x00, 0x00, 0x00, 0x00, 0x00]),
        ("RSAP 6, 0", [0x01, 0x08, 0x06, 0x00, 0x00, 0x00, 0x00, 0x00]),
        ("SGP 66, 0, 3", [0x01, 0x09, 0x42, 0x00, 0x00, 0x00, 0x00, 0x03]),
        ("GGP 66, 0", [0x01, 0x0a, 0x42, 0x00, 0x00, 0x00, 0x00, 0x00]),
        ("STGP 42, 2", [0x01, 0x0b, 0x2a, 0x02, 0x00, 0x00, 0x00, 0x00]),
        ("RSGP 42, 2", [0x01, 0x0c, 0x2a, 0x02, 0x00, 0x00, 0x00, 0x00]),
        ("RFS START, 0", [0x01, 0x0d, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00]),
        ("SIO 7, 2, 1", [0x01, 0x0e, 0x07, 0x02, 0x00, 0x00, 0x00, 0x01]),
        ("GIO 0, 1", [0x01, 0x0f, 0x00, 0x01, 0x00, 0x00, 0x00, 0x00]),
        ("CALC MUL, -5000", [0x01, 0x13, 0x02, 0x00, 0xFF, 0xFF, 0xEC, 0x78]),
        ("COMP 1000", [0x01, 0x14, 0x00, 0x00, 0x00, 0x00, 0x03, 0xe8]),
        ("JC GE, 10", [0x01, 0x15, 0x05, 0x00, 0x00, 0x00, 0x00, 0x0a]),
        ("JA 20", [0x01, 0x16, 0x00, 0x00, 0x00, 0x00, 0x00, 0x14]),
        ("CSUB 100", [0x01, 0x17, 0x00, 0x00, 0x00, 0x00, 0x00, 0x64]),
        ("RSUB", [0x01, 0x18, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00]),
        ("WAIT POS, 0, 0", [0x01, 0x1b, 0x01, 0x00, 0x00, 0x00, 0x00, 0x00]),
        ("STOP", [0x01, 0x1c, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00]),
        ("SCO 1, 0, 1000", [0x01, 0x1e, 0x01, 0x00, 0x00, 0x00, 0x03, 0xe8]),
        ("GCO 1, 0", [0x01, 0x1f, 0x01, 0x00, 0x00, 0x00, 0x00, 0x00]),
        ("CCO 3, 0", [0x01, 0x20, 0x03, 0x00, 0x00, 0x00, 0x00, 0x00]),
        ("CALCX MUL", [0x01, 0x21, 0x02, 0x00, 0x00, 0x00, 0x00, 0x00]),
        ("AAP 0, 0", [0x01, 0x22, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00]),
        ("AGP 3, 2", [0x01, 0x23, 0x03, 0x02, 0x00, 0x00, 0x00, 0x00]),
        ("CLE ETO", [0x01, 0x24, 0x01, 0x00, 0x00, 0x00, 0x00, 0x00]),
        ("VECT 3, 500", [0x01, 0x25, 0x03, 0x00, 0x00, 0x00, 0x01, 0xF4]),
        ("ACO 1, 0", [0x01, 0x27, 0x01, 0x00, 0x00, 0x00, 0x00, 0x00]),
        ("EI, 255", [0x01, 0x19, 0xFF, 0x00, 0x00, 0x00, 0x00, 0x00]),
        ("EI 3", [0x01, 0x19, 0x03, 0x00, 0x00, 0x00, 0x00, 0x00]),
        ("DI, 255", [0x01, 0x1A, 0xFF, 0x00, 0x00, 0x00, 0x00, 0x00]),
        ("DI 3", [0x01, 0x1A, 0x03, 0x00, 0x00, 0x00, 0x00, 0x00]),
    ];
    for (src, bytes) in cases {
        let ins = one(src);
        let c = Command { address: 1, ins };
        let b = c.to_bytes();
        assert_eq!(&b[..8], &bytes[..], "{src}");
        assert_eq!(b[8], bytes.iter().fold(0u8, |s, x| s.wrapping_add(*x)), "{src} checksum");
        assert_eq!(Command::from_bytes(&b), Ok(c), "{src} decodes");
    }
    // §5.7.35 prints RETI with value $0100 (value is don't care): it decodes as RETI.
    let reti = Command::from_bytes(&frame([0x01, 0x26, 0x00, 0x00, 0x00, 0x00, 0x01, 0x00])).unwrap();
    assert_eq!(reti.ins.op, op::RETI);
    assert_eq!(one("RETI").op, 38);
}

#[test]
fn checksum_as_in_manual() {
    // §4.1.1: 8-bit sum of the first eight bytes.
    assert_eq!(checksum(&[0x01, 0x04, 0x00, 0x00, 0x00, 0x01, 0x5f, 0x90]), 0xf5);
    assert_eq!(checksum(&[0xff, 0x02]), 0x01);
    let f = frame([0x01, 0x06, 0x06, 0x01, 0x00, 0x00, 0x00, 0x00]);
    assert_eq!(f[8], 0x0e);
}

#[test]
fn manual_replies_byte_for_byte() {
    let mut m = module();
    // §5.7.10: GGP 66, 0 → $02 $01 $64 $0a $00 $00 $00 $01.
    let r = send(&mut m, [0x01, 0x0a, 0x42, 0x00, 0, 0, 0, 0]);
    assert_eq!(r, frame([0x02, 0x01, 0x64, 0x0a, 0x00, 0x00, 0x00, 0x01]).to_vec());
    // §5.7.15: GIO 0, 1 with AIN0 at 302 → $02 $01 $64 $0f $00 $00 $01 $2e.
    m.io.analog[0] = 302;
    let r = send(&mut m, [0x01, 0x0f, 0x00, 0x01, 0, 0, 0, 0]);
    assert_eq!(r, frame([0x02, 0x01, 0x64, 0x0f, 0x00, 0x00, 0x01, 0x2e]).to_vec());
    // §5.7.16: CALC MUL, -5000 → $02 $01 $64 $13 $ff $ff $ec $78.
    let r = send(&mut m, [0x01, 0x13, 0x02, 0x00, 0xFF, 0xFF, 0xEC, 0x78]);
    assert_eq!(r, frame([0x02, 0x01, 0x64, 0x13, 0xff, 0xff, 0xec, 0x78]).to_vec());
    // §5.7.25 prints command byte $0a for GCO (a copy of the GGP example); the reply carries $1f.
    let r = send(&mut m, [0x01, 0x1f, 0x01, 0x00, 0, 0, 0, 0]);
    assert_eq!(r, frame([0x02, 0x01, 0x64, 0x1f, 0x00, 0x00, 0x00, 0x00]).to_vec());
    // §5.7.6 reply format (value $0280 as printed).
    let rep = Reply { host: 2, module: 1, status: 100, op: 6, value: 0x280 };
    assert_eq!(rep.to_bytes(), frame([0x02, 0x01, 0x64, 0x06, 0x00, 0x00, 0x02, 0x80]));
    assert_eq!(rep.to_bytes7(), [0x01, 0x64, 0x06, 0x00, 0x00, 0x02, 0x80]);
    // §5.7.9: SGP 66, 0, 3 sets the address; the reply already carries it (it is sent after
    // execution) and the module then answers only to address 3.
    let r = send(&mut m, [0x01, 0x09, 0x42, 0x00, 0, 0, 0, 3]);
    assert_eq!(r, frame([0x02, 0x03, 0x64, 0x09, 0, 0, 0, 3]).to_vec());
    assert_eq!(send(&mut m, [0x01, 0x0a, 0x42, 0x00, 0, 0, 0, 0]), Vec::<u8>::new());
    let r = send(&mut m, [0x03, 0x0a, 0x42, 0x00, 0, 0, 0, 0]);
    assert_eq!(r, frame([0x02, 0x03, 0x64, 0x0a, 0, 0, 0, 3]).to_vec());
}

#[test]
fn firmware_version_both_forms() {
    let mut m = module();
    // §5.7.39 type 0: host address + 8 characters, no checksum.
    let r = send(&mut m, [0x01, 136, 0, 0, 0, 0, 0, 0]);
    assert_eq!(r, b"\x023110V100".to_vec());
    // Type 1: module type in the upper 16 bits, version major, minor.
    let r = send(&mut m, [0x01, 136, 1, 0, 0, 0, 0, 0]);
    assert_eq!(r, frame([0x02, 0x01, 0x64, 136, 0x0c, 0x26, 0x01, 0x00]).to_vec());
}

#[test]
fn every_status_code() {
    let mut m = module();
    let st = |m: &mut Module<ModelChip>, o, t, mo, v| match m.handle_instruction(&Instruction::new(o, t, mo, v)) {
        Response::Normal(r) => r.status,
        other => panic!("{other:?}"),
    };
    // 100
    assert_eq!(st(&mut m, op::SAP, 4, 0, 500), Status::Ok.code());
    // 1: wrong checksum → status 1, command 0, value 0.
    let mut f = frame([0x01, 0x06, 0x01, 0x00, 0, 0, 0, 0]);
    f[8] ^= 0x55;
    assert_eq!(m.handle_bytes(&f).to_bytes(), frame([0x02, 0x01, 0x01, 0x00, 0, 0, 0, 0]).to_vec());
    // 2: invalid command.
    assert_eq!(st(&mut m, 99, 0, 0, 0), Status::InvalidCommand.code());
    assert_eq!(st(&mut m, 0, 0, 0, 0), Status::InvalidCommand.code());
    // 3: wrong type (parameter of a driver chip this module does not model; MVP type 3).
    assert_eq!(st(&mut m, op::GAP, 174, 0, 0), Status::WrongType.code());
    assert_eq!(st(&mut m, op::MVP, 3, 0, 0), Status::WrongType.code());
    assert_eq!(st(&mut m, op::GGP, 69, 0, 0), Status::WrongType.code());
    // 4: invalid value (motor 3 of a 3-axis module; v_max above 2047; bank 7).
    assert_eq!(st(&mut m, op::GAP, 1, 3, 0), Status::InvalidValue.code());
    assert_eq!(st(&mut m, op::SAP, 4, 0, 2048), Status::InvalidValue.code());
    assert_eq!(st(&mut m, op::GGP, 0, 7, 0), Status::InvalidValue.code());
    assert_eq!(st(&mut m, op::MVP, 0, 0, 1 << 23), Status::InvalidValue.code());
    // 5: configuration EEPROM locked (global parameter 73 = 1234 locks, 4321 unlocks).
    assert_eq!(st(&mut m, op::SGP, 73, 0, 1234), Status::Ok.code());
    assert_eq!(st(&mut m, op::GGP, 73, 0, 0), Status::Ok.code());
    assert_eq!(st(&mut m, op::STAP, 4, 0, 0), Status::EepromLocked.code());
    assert_eq!(st(&mut m, op::STGP, 42, 2, 0), Status::EepromLocked.code());
    assert_eq!(st(&mut m, op::SGP, 77, 0, 1), Status::EepromLocked.code());
    assert_eq!(st(&mut m, op::SGP, 73, 0, 4321), Status::Ok.code());
    assert_eq!(st(&mut m, op::STAP, 4, 0, 0), Status::Ok.code());
    // 6: command not available (user functions; program flow in direct mode).
    assert_eq!(st(&mut m, 64, 0, 0, 0), Status::NotAvailable.code());
    assert_eq!(st(&mut m, op::JA, 0, 0, 0), Status::NotAvailable.code());
    // 101: command loaded into program memory (download mode).
    assert_eq!(st(&mut m, op::DOWNLOAD_START, 0, 0, 0), Status::Ok.code());
    assert_eq!(st(&mut m, op::MVP, 0, 0, 1000), Status::Loaded.code());
    assert_eq!(st(&mut m, op::STOP, 0, 0, 0), Status::Loaded.code());
    assert_eq!(st(&mut m, op::DOWNLOAD_END, 0, 0, 0), Status::Ok.code());
    assert_eq!(m.program().len(), 2);
    for (c, s) in [
        (100, "Successfully executed, no error"),
        (101, "Command loaded into TMCL program EEPROM"),
        (1, "Wrong checksum"),
        (2, "Invalid command"),
        (3, "Wrong type"),
        (4, "Invalid value"),
        (5, "Configuration EEPROM locked"),
        (6, "Command not available"),
    ] {
        assert_eq!(Status::from_code(c).unwrap().meaning(), s);
    }
}
