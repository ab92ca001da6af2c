//! Every command of the TMCL firmware manual the module implements, type by type, on both
//! module types ([TMCL] §5.7): coordinates, parameters of every table entry, I/O, the control
//! commands 128..139, and the bugs found against the manual (RUN after the end, 138/139 in
//! download mode, SGP 66/76 = 0, SAP 138 / 128 after ROR and MST).

mod common;
use common::*;

use std::path::Path;
use tmcl::asm;
use tmcl::chip::ModelChip;
use tmcl::personality::{Access, ModuleType};
use tmcl::proto::{op, Instruction};
use tmcl::{Module, Response};

fn program(m: &mut Module<ModelChip>, src: &str) {
    let code = asm::assemble(Path::new("p.tmc"), src, &asm::FileSystem).unwrap().code;
    m.load_program(&code).unwrap();
}

/// SCO, GCO, CCO, ACO, MVP COORD; coordinate 0; n, 255 to and from the EEPROM image.
#[test]
fn coordinates() {
    for kind in ModuleType::ALL {
        let mut m = module_of(kind);
        let last = kind.axes() as u8 - 1;
        ok(&mut m, op::SCO, 1, last, 1000);
        assert_eq!(ok(&mut m, op::GCO, 1, last, 0), 1000);
        ok(&mut m, op::SCO, 0, 0, -700);
        assert_eq!(ok(&mut m, op::GCO, 0, 0, 0), -700);
        assert_eq!(direct(&mut m, op::SCO, 21, 0, 5).0, 3, "coordinates 0..20");
        assert_eq!(direct(&mut m, op::GCO, 1, last + 1, 0).0, 4, "no such motor");
        // MVP COORD moves to a coordinate.
        ok(&mut m, op::MVP, 2, last, 1);
        run_until(&mut m, 5000, |m| gap(m, 8, last) == 1 && gap(m, 3, last) == 0);
        assert_eq!(gap(&mut m, 1, last), 1000);
        assert_eq!(direct(&mut m, op::MVP, 2, last, 21).0, 4);
        // CCO captures the actual position; ACO takes the accumulator (from a program).
        ok(&mut m, op::CCO, 5, last, 0);
        assert_eq!(ok(&mut m, op::GCO, 5, last, 0), 1000);
        program(&mut m, &format!("CALC LOAD, 4242\nACO 6, {last}\nSTOP\n"));
        ok(&mut m, op::APP_RUN, 0, 0, 0);
        m.run_ms(5);
        assert_eq!(ok(&mut m, op::GCO, 6, last, 0), 4242);
        // SCO n, 255 copies to the EEPROM image (1..20; 0 = all but coordinate 0).
        ok(&mut m, op::SCO, 5, 255, 0);
        assert_eq!(m.eeprom_image().coords[last as usize][5], 1000);
        assert_eq!(m.eeprom_image().coords[last as usize][6], 0, "only coordinate 5");
        ok(&mut m, op::SCO, 0, 255, 0);
        assert_eq!(m.eeprom_image().coords[last as usize][6], 4242);
        assert_eq!(m.eeprom_image().coords[0][0], 0, "coordinate 0 stays in RAM");
        // GCO n, 255 copies back.
        ok(&mut m, op::SCO, 6, last, 1);
        ok(&mut m, op::GCO, 6, 255, 0);
        assert_eq!(ok(&mut m, op::GCO, 6, last, 0), 4242);
        ok(&mut m, op::SCO, 6, last, 2);
        ok(&mut m, op::SCO, 1, last, 3);
        ok(&mut m, op::GCO, 0, 255, 0);
        assert_eq!((ok(&mut m, op::GCO, 6, last, 0), ok(&mut m, op::GCO, 1, last, 0)), (4242, 1000));
        // Global parameter 84 = 1: every coordinate write goes to the EEPROM too.
        ok(&mut m, op::SGP, 84, 0, 1);
        ok(&mut m, op::SCO, 9, last, 99);
        assert_eq!(m.eeprom_image().coords[last as usize][9], 99);
    }
}

/// Every axis parameter of the module's table: GAP answers 100 where readable, SAP takes the
/// factory default where writable (and answers 3 where not), STAP/RSAP take exactly the
/// stored ones; numbers outside the table answer 3.
#[test]
fn every_axis_parameter() {
    for kind in ModuleType::ALL {
        let mut m = module_of(kind);
        for p in kind.axis_params() {
            let (s, _) = direct(&mut m, op::GAP, p.no, 0, 0);
            assert_eq!(s, if p.access.readable() { 100 } else { 3 }, "{kind:?} GAP {}", p.no);
            if !p.live {
                assert_eq!(direct(&mut m, op::SAP, p.no, 0, p.default), (100, p.default), "{kind:?} SAP {}", p.no);
                assert_eq!(ok(&mut m, op::GAP, p.no, 0, 0), p.default, "{kind:?} GAP {} default", p.no);
            } else if !p.access.writable() {
                assert_eq!(direct(&mut m, op::SAP, p.no, 0, 0).0, 3, "{kind:?} SAP {} is read-only", p.no);
            }
            let stored = !p.live && p.access == Access::RWE;
            assert_eq!(direct(&mut m, op::STAP, p.no, 0, 0).0, if stored { 100 } else { 3 }, "{kind:?} STAP {}", p.no);
            assert_eq!(direct(&mut m, op::RSAP, p.no, 0, 0).0, if stored { 100 } else { 3 }, "{kind:?} RSAP {}", p.no);
            if p.max < i32::MAX as i64 && p.no != 193 {
                assert_eq!(direct(&mut m, op::SAP, p.no, 0, p.max as i32 + 1).0, if p.access.writable() { 4 } else { 3 });
            }
        }
        for n in 0..=255u8 {
            if kind.axis_param(n).is_none() {
                assert_eq!(direct(&mut m, op::GAP, n, 0, 0).0, 3, "{kind:?} GAP {n}");
                assert_eq!(direct(&mut m, op::SAP, n, 0, 0).0, 3, "{kind:?} SAP {n}");
            }
        }
    }
}

/// STAP stores the value in use, SAP changes it, RSAP brings the stored one back.
#[test]
fn stap_and_rsap() {
    for kind in ModuleType::ALL {
        let mut m = module_of(kind);
        ok(&mut m, op::SAP, 6, 0, 200);
        ok(&mut m, op::STAP, 6, 0, 0);
        ok(&mut m, op::SAP, 6, 0, 10);
        assert_eq!(ok(&mut m, op::RSAP, 6, 0, 0), 200);
        assert_eq!(gap(&mut m, 6, 0), 200);
    }
}

/// Every bank-0 parameter: GGP answers, SGP takes the factory default of a setting; bank 2
/// (0..255, 0..55 stored), bank 3, bank 1 (not available: 4); RSGP of both.
#[test]
fn every_global_parameter() {
    for kind in ModuleType::ALL {
        let mut m = module_of(kind);
        for p in kind.global_params() {
            assert_eq!(direct(&mut m, op::GGP, p.no, 0, 0).0, 100, "{kind:?} GGP {}", p.no);
            if !p.live && p.no != 73 {
                assert_eq!(direct(&mut m, op::SGP, p.no, 0, p.default), (100, p.default), "{kind:?} SGP {}", p.no);
                assert_eq!(direct(&mut m, op::STGP, p.no, 0, 0), (100, p.default), "{kind:?} STGP {}", p.no);
            }
        }
        for p in [128u8, 129, 130, 133] {
            assert_eq!(direct(&mut m, op::SGP, p, 0, 0).0, 3, "{kind:?} {p} is read-only");
        }
        assert_eq!(direct(&mut m, op::GGP, 0, 1, 0).0, 4, "bank 1");
        ok(&mut m, op::SGP, 255, 2, -5);
        assert_eq!(ok(&mut m, op::GGP, 255, 2, 0), -5);
        assert_eq!(direct(&mut m, op::STGP, 56, 2, 0).0, 3, "user variables 56..255 are not stored");
        // RSGP: a user variable and a bank-0 setting come back from the EEPROM image.
        ok(&mut m, op::SGP, 55, 2, 77);
        ok(&mut m, op::STGP, 55, 2, 0);
        ok(&mut m, op::SGP, 55, 2, 1);
        assert_eq!(ok(&mut m, op::RSGP, 55, 2, 0), 77);
        assert_eq!(ok(&mut m, op::GGP, 55, 2, 0), 77);
        assert_eq!(ok(&mut m, op::RSGP, 76, 0, 0), 2);
        assert_eq!(direct(&mut m, op::RSGP, 0, 3, 0).0, 3, "bank 3 is not stored");
        // Bank 3: timer periods, switch and input transitions of this module type.
        ok(&mut m, op::SGP, 2, 3, 250);
        assert_eq!(ok(&mut m, op::GGP, 2, 3, 0), 250);
        assert_eq!(direct(&mut m, op::SGP, 46, 3, 4).0, 4);
        let last_switch = 27 + 2 * kind.axes() as u8 - 1;
        ok(&mut m, op::SGP, last_switch, 3, 2);
        assert_eq!(direct(&mut m, op::SGP, last_switch + 1, 3, 2).0, 3);
        // Serial address and host address 0..255 ([TMCL] §10.1): 0 is an address.
        assert_eq!(direct(&mut m, op::SGP, 76, 0, 0), (100, 0));
        assert_eq!(direct(&mut m, op::SGP, 66, 0, 0), (100, 0));
        assert_eq!(m.addresses(), (0, 0));
        let f = frame([0, op::GGP, 66, 0, 0, 0, 0, 0]);
        assert_eq!(m.handle_bytes(&f).to_bytes(), frame([0, 0, 100, op::GGP, 0, 0, 0, 0]).to_vec());
    }
}

/// SIO and GIO on every port and bank; SIO 255, 2, −1 copies the accumulator's low 8 bits.
#[test]
fn sio_and_gio() {
    for kind in ModuleType::ALL {
        let mut m = module_of(kind);
        m.io.analog = [1234, 4095];
        m.io.driven = [Some(true); 8];
        m.io.driven[5] = Some(false);
        for port in 0..8u8 {
            ok(&mut m, op::SIO, port, 2, 1);
            assert_eq!(ok(&mut m, op::GIO, port, 2, 0), 1);
            assert_eq!(ok(&mut m, op::GIO, port, 0, 0), (port != 5) as i32, "{kind:?} IN{port}");
        }
        assert_eq!(ok(&mut m, op::GIO, 255, 2, 0), 0xff);
        assert_eq!(ok(&mut m, op::GIO, 255, 0, 0), 0xdf);
        m.io.driven[3] = None;
        assert_eq!((ok(&mut m, op::GIO, 0, 1, 0), ok(&mut m, op::GIO, 4, 1, 0), ok(&mut m, op::GIO, 8, 1, 0)), (1234, 4095, 240));
        ok(&mut m, op::SIO, 255, 2, 0x0f);
        assert_eq!(ok(&mut m, op::GIO, 255, 2, 0), 0x0f);
        program(&mut m, "CALC LOAD, $1A5\nSIO 255, 2, -1\nSTOP\n");
        ok(&mut m, op::APP_RUN, 0, 0, 0);
        m.run_ms(5);
        assert_eq!(ok(&mut m, op::GIO, 255, 2, 0), 0xa5);
        // Ports and banks that do not exist.
        assert_eq!(direct(&mut m, op::SIO, 8, 2, 1).0, 3);
        assert_eq!(direct(&mut m, op::SIO, 0, 2, 2).0, 4);
        assert_eq!(direct(&mut m, op::GIO, 9, 1, 0).0, 3, "temperature: not modelled");
        assert_eq!(direct(&mut m, op::GIO, 0, 3, 0).0, 4);
        // Pull-ups (bank 0) are the TMCM-3110's.
        let pullups = kind == ModuleType::Tmcm3110;
        assert_eq!(direct(&mut m, op::SIO, 3, 0, 0).0, if pullups { 100 } else { 4 });
        assert_eq!(ok(&mut m, op::GIO, 3, 0, 0), 0, "open IN3: pull-up off (TMCM-3110), none (TMCM-1311)");
    }
}

/// Control commands 128..135 and the user functions.
#[test]
fn control_commands() {
    for kind in ModuleType::ALL {
        let mut m = module_of(kind);
        program(&mut m, "SGP 1, 2, 11\nWAIT TICKS, 0, 10\nSGP 2, 2, 22\nSTOP\n");
        assert_eq!(ok(&mut m, op::APP_STATUS, 0, 0, 0), 0);
        // 130 step: one instruction at a time.
        ok(&mut m, op::APP_STEP, 0, 0, 0);
        assert_eq!((m.user_var(1), ok(&mut m, op::GGP, 130, 0, 0), ok(&mut m, op::APP_STATUS, 0, 0, 0)), (11, 1, 2));
        // 131 reset: back to address 0, state 3.
        ok(&mut m, op::APP_RESET, 0, 0, 0);
        assert_eq!((ok(&mut m, op::GGP, 130, 0, 0), ok(&mut m, op::GGP, 128, 0, 0)), (0, 3));
        // 129 run, 128 stop (pauses), 129 resumes.
        ok(&mut m, op::APP_RUN, 0, 0, 0);
        m.run_ms(20);
        assert_eq!(ok(&mut m, op::APP_STATUS, 0, 0, 0), 1);
        ok(&mut m, op::APP_STOP, 0, 0, 0);
        let pc = ok(&mut m, op::GGP, 130, 0, 0);
        assert_eq!(pc, 1, "stopped in the WAIT");
        ok(&mut m, op::APP_RUN, 0, 0, 0);
        m.run_ms(200);
        assert_eq!((m.user_var(2), ok(&mut m, op::APP_STATUS, 0, 0, 0)), (22, 0));
        // RUN after the program ran to its end starts it again from address 0.
        ok(&mut m, op::SGP, 1, 2, 0);
        ok(&mut m, op::APP_RUN, 0, 0, 0);
        m.run_ms(5);
        assert_eq!(m.user_var(1), 11, "RUN (129 type 0) after STOP runs the program again");
        // 129 type 1 starts at an address.
        ok(&mut m, op::SGP, 1, 2, 0);
        ok(&mut m, op::APP_RUN, 1, 0, 2);
        m.run_ms(5);
        assert_eq!(m.user_var(1), 0);
        assert_eq!(direct(&mut m, op::APP_RUN, 1, 0, 2048).0, 4);
        // 134 read memory; global parameter 81 bit 0 protects against it, switching the
        // protection off erases the program.
        assert_eq!(ok(&mut m, op::READ_MEMORY, 1, 0, 0), 11);
        ok(&mut m, op::SGP, 81, 0, 1);
        assert_eq!(direct(&mut m, op::READ_MEMORY, 1, 0, 0).0, 6);
        ok(&mut m, op::SGP, 81, 0, 0);
        assert_eq!(m.program().len(), 0);
        // Bit 1 protects against overwriting (download).
        ok(&mut m, op::SGP, 81, 0, 2);
        assert_eq!(direct(&mut m, op::DOWNLOAD_START, 0, 0, 0).0, 6);
        ok(&mut m, op::SGP, 81, 0, 0);
        for uf in op::UF0..=op::UF7 {
            assert_eq!(direct(&mut m, uf, 0, 0, 0).0, 6);
        }
    }
}

/// Download mode: every instruction is checked, a refused one is not stored and answers its
/// status (the address stays); 138 and 139 answer 6 there; the module stays in binary mode.
#[test]
fn download_mode() {
    let mut m = module();
    ok(&mut m, op::DOWNLOAD_START, 0, 0, 0);
    assert_eq!(m.download_address(), Some(0));
    assert_eq!(direct(&mut m, op::ROR, 0, 0, 100), (101, 100));
    assert_eq!(direct(&mut m, op::ROL, 0, 0, 50_000).0, 4, "outside the TMCM-3110's −2047..2047");
    assert_eq!(direct(&mut m, op::SAP, 202, 0, 200).0, 3, "no such parameter");
    assert_eq!(direct(&mut m, op::MST, 0, 3, 0).0, 4, "no motor 3");
    assert_eq!(direct(&mut m, op::TARGET_REACHED_EVENT, 0, 0, 0).0, 6);
    assert_eq!(direct(&mut m, op::ASCII_MODE, 0, 0, 0).0, 6);
    assert_eq!(direct(&mut m, op::STOP, 0, 0, 0), (101, 0));
    ok(&mut m, op::DOWNLOAD_END, 0, 0, 0);
    assert_eq!(m.program(), &[Instruction::new(op::ROR, 0, 0, 100), Instruction::new(op::STOP, 0, 0, 0)]);
    let mut l = tmcl::link::Link::new(false);
    let f = frame([1, op::DOWNLOAD_START, 0, 0, 0, 0, 0, 0]);
    l.feed(&mut m, &f, 0);
    l.feed(&mut m, &frame([1, op::ASCII_MODE, 0, 0, 0, 0, 0, 0]), 0);
    assert_eq!(l.mode, tmcl::link::Mode::Binary, "139 in download mode does not switch");
    l.feed(&mut m, &frame([1, op::DOWNLOAD_END, 0, 0, 0, 0, 0, 0]), 0);
    l.feed(&mut m, &frame([1, op::ASCII_MODE, 0, 0, 0, 0, 0, 0]), 0);
    assert_eq!(l.mode, tmcl::link::Mode::Ascii);
}

/// SAP 138 (TMCM-3110) / 128 (TMCM-1311) after ROR and MST switches to positioning where the
/// axis is, at the configured speed: no move back to an older target.
#[test]
fn ramp_mode_after_ror_and_mst() {
    for (kind, ap) in [(ModuleType::Tmcm3110, 138u8), (ModuleType::Tmcm1311, 128)] {
        let mut m = module_of(kind);
        ok(&mut m, op::MVP, 0, 0, 500);
        run_until(&mut m, 5000, |m| gap(m, 8, 0) == 1 && gap(m, 3, 0) == 0);
        ok(&mut m, op::ROR, 0, 0, if kind == ModuleType::Tmcm1311 { 30_000 } else { 1000 });
        m.run_ms(300);
        ok(&mut m, op::MST, 0, 0, 0);
        run_until(&mut m, 5000, |m| gap(m, 3, 0) == 0);
        let x = gap(&mut m, 1, 0);
        assert!(x > 1000);
        ok(&mut m, op::SAP, ap, 0, 0);
        m.run_ms(300);
        assert_eq!((gap(&mut m, 1, 0), gap(&mut m, 0, 0), gap(&mut m, 3, 0)), (x, x, 0), "{kind:?}: stays at {x}");
        assert_eq!(gap(&mut m, ap, 0), 0);
        // Into velocity mode: target speed 0, no motion.
        ok(&mut m, op::SAP, ap, 0, if kind == ModuleType::Tmcm1311 { 1 } else { 2 });
        m.run_ms(100);
        assert_eq!((gap(&mut m, 1, 0), gap(&mut m, 2, 0)), (x, 0));
    }
}

/// Command 136 in both forms and the motor mask of command 138 for each module type.
#[test]
fn firmware_version_and_event_of_each_module_type() {
    for (kind, text) in [(ModuleType::Tmcm3110, *b"3110V100"), (ModuleType::Tmcm1311, *b"1311V100")] {
        let mut m = module_of(kind);
        match m.handle_instruction(&Instruction::new(op::FIRMWARE_VERSION, 0, 0, 0)) {
            Response::Version { host, text: t } => assert_eq!((host, t), (2, text)),
            other => panic!("{other:?}"),
        }
        assert_eq!(ok(&mut m, op::FIRMWARE_VERSION, 1, 0, 0), ((kind.number() as i32) << 16) | 0x0100);
        assert_eq!(ok(&mut m, op::TARGET_REACHED_EVENT, 0, 0, 7), if kind == ModuleType::Tmcm1311 { 1 } else { 7 });
    }
}
