//! Program commands type by type ([TMCL] §5.7.16–§5.7.22, §5.7.28, §5.7.31): CALC and CALCX
//! with every operation, COMP with every JC condition, WAIT with every condition and its
//! timeout, CLE; and the bank-0 parameters that act at power-on (64, 77, 85) and 79.

mod common;
use common::*;

use std::path::Path;
use tmcl::asm;
use tmcl::chip::ModelChip;
use tmcl::module::AppState;
use tmcl::personality::ModuleType;
use tmcl::proto::op;
use tmcl::Module;

fn run(m: &mut Module<ModelChip>, src: &str, ms: u64) {
    let code = asm::assemble(Path::new("p.tmc"), src, &asm::FileSystem).unwrap_or_else(|e| panic!("{e}")).code;
    m.load_program(&code).unwrap();
    ok(m, op::APP_RUN, 0, 0, 0);
    m.run_ms(ms);
}

#[test]
fn calc_and_calcx_every_operation() {
    // (operation, accumulator before, operand / X, result)
    let cases = [
        ("ADD", 7, 5, 12),
        ("SUB", 7, 5, 2),
        ("MUL", -7, 5, -35),
        ("DIV", -7, 2, -3),
        ("MOD", 7, 5, 2),
        ("AND", 0b1100, 0b1010, 0b1000),
        ("OR", 0b1100, 0b1010, 0b1110),
        ("XOR", 0b1100, 0b1010, 0b0110),
        ("NOT", 5, 0, !5),
        ("LOAD", 5, 9, 9),
    ];
    for (name, a, b, r) in cases {
        let mut m = module();
        run(&mut m, &format!("CALC LOAD, {a}\nCALC {name}, {b}\nAGP 0, 2\nSTOP\n"), 5);
        assert_eq!(m.user_var(0), r, "CALC {name}");
        if name == "NOT" || name == "LOAD" {
            continue;
        }
        run(&mut m, &format!("CALC LOAD, {b}\nCALCX LOAD\nCALC LOAD, {a}\nCALCX {name}\nAGP 0, 2\nSTOP\n"), 5);
        assert_eq!(m.user_var(0), r, "CALCX {name}");
    }
    // CALCX NOT inverts X, SWAP exchanges; a division by 0 changes nothing.
    let mut m = module();
    run(&mut m, "CALC LOAD, 5\nCALCX LOAD\nCALCX NOT\nCALC LOAD, 1\nCALCX SWAP\nCALC DIV, 0\nSTOP\n", 5);
    assert_eq!((m.vm.accu, m.vm.x), (!5, 1), "NOT of X, SWAP, CALC DIV by 0 refused");
    run(&mut m, "CALC LOAD, 0\nCALCX LOAD\nCALC LOAD, 7\nCALCX DIV\nCALCX MOD\nSTOP\n", 5);
    assert_eq!(m.vm.accu, 7, "CALCX DIV and MOD by X = 0 refused");
    assert_eq!(direct(&mut m, op::CALC, 3, 0, 0).0, 4);
    assert_eq!(direct(&mut m, op::CALC, 10, 0, 0).0, 3);
    assert_eq!(direct(&mut m, op::CALCX, 11, 0, 0).0, 3);
}

#[test]
fn comp_and_every_jc_condition() {
    // (accumulator, compared with, taken conditions)
    for (a, c) in [(5, 5), (4, 5), (6, 5)] {
        for (cond, taken) in [
            ("ZE", a == c),
            ("NZ", a != c),
            ("EQ", a == c),
            ("NE", a != c),
            ("GT", a > c),
            ("GE", a >= c),
            ("LT", a < c),
            ("LE", a <= c),
            ("ETO", false),
        ] {
            let mut m = module();
            run(&mut m, &format!("CALC LOAD, {a}\nCOMP {c}\nJC {cond}, T\nSTOP\nT: SGP 0, 2, 1\nSTOP\n"), 5);
            assert_eq!(m.user_var(0), taken as i32, "{a} COMP {c} JC {cond}");
        }
    }
}

/// WAIT TICKS, POS, REFSW, LIMSW, RFS: each waits for its condition; with a timeout it sets
/// ETO, which JC ETO sees and CLE ETO / CLE ALL clear.
#[test]
fn every_wait_condition() {
    let mut m = module();
    run(&mut m, "WAIT TICKS, 0, 20\nSGP 0, 2, 1\nSTOP\n", 150);
    assert_eq!(m.user_var(0), 0, "200 ms");
    m.run_ms(100);
    assert_eq!(m.user_var(0), 1);
    // POS on axis 2.
    let mut m = module();
    run(&mut m, "MVP ABS, 2, 800\nWAIT POS, 2, 0\nGAP 1, 2\nAGP 0, 2\nSTOP\n", 1);
    run_until(&mut m, 5000, |m| m.vm.state == AppState::Stop);
    assert_eq!(m.user_var(0), 800);
    // REFSW (home switch) and LIMSW (either end switch) of axis 1.
    for (cond, set) in [("REFSW", 0usize), ("LIMSW", 1), ("LIMSW", 2)] {
        let mut m = module();
        run(&mut m, &format!("WAIT {cond}, 1, 0\nSGP 0, 2, 1\nSTOP\n"), 50);
        assert_eq!(m.user_var(0), 0, "{cond} waits");
        match set {
            0 => m.world.home_forced[1] = true,
            1 => m.world.left_forced[1] = true,
            _ => m.world.right_forced[1] = true,
        }
        m.run_ms(5);
        assert_eq!(m.user_var(0), 1, "{cond} done");
    }
    // RFS on axis 0 (left switch at −500).
    let mut m = module();
    m.world.left[0] = Some(tmcl::io::World::left_end(-500));
    run(&mut m, "RFS START, 0\nWAIT RFS, 0, 0\nSGP 0, 2, 1\nSTOP\n", 50);
    assert_eq!(m.user_var(0), 0);
    run_until(&mut m, 10_000, |m| m.user_var(0) == 1);
    // Timeouts: ETO set, seen by JC ETO, cleared by CLE ETO and CLE ALL.
    for (cond, motor) in [("POS", 0), ("REFSW", 0), ("LIMSW", 0), ("RFS", 0)] {
        let mut m = module();
        let start = if cond == "POS" {
            "MVP ABS, 0, 100000\n"
        } else if cond == "RFS" {
            "RFS START, 0\n"
        } else {
            ""
        };
        run(
            &mut m,
            &format!("{start}WAIT {cond}, {motor}, 3\nJC ETO, T\nSTOP\nT: SGP 0, 2, 1\nCLE ETO\nJC ETO, B\nSGP 1, 2, 1\nSTOP\nB: STOP\n"),
            80,
        );
        assert_eq!((m.user_var(0), m.user_var(1)), (1, 1), "WAIT {cond} timeout");
    }
    let mut m = module();
    run(&mut m, "WAIT LIMSW, 0, 1\nCLE ALL\nJC ETO, B\nSGP 1, 2, 1\nB: STOP\n", 50);
    assert_eq!(m.user_var(1), 1, "CLE ALL clears ETO");
    assert!(!m.vm.eto);
    // Conditions and motors that do not exist are refused at download.
    assert!(m.check_instruction(&tmcl::Instruction::new(op::WAIT, 5, 0, 0)).is_err());
    assert!(m.check_instruction(&tmcl::Instruction::new(op::WAIT, 1, 3, 0)).is_err());
    assert!(module_of(ModuleType::Tmcm1311).check_instruction(&tmcl::Instruction::new(op::WAIT, 1, 1, 0)).is_err());
    for t in 0..=4 {
        assert_eq!(direct(&mut m, op::CLE, t, 0, 0).0, 100, "CLE {t}");
    }
    assert_eq!(direct(&mut m, op::CLE, 5, 0, 0).0, 3);
}

/// Global parameters 64 (magic), 77 (auto start), 85 (do not restore user variables) act at
/// the next power-on; 79 (end switch polarity) inverts the end switches at once.
#[test]
fn power_on_parameters_and_end_switch_polarity() {
    let dir = std::env::temp_dir().join(format!("tmcl-gp-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("gp.eep");
    let _ = std::fs::remove_file(&path);
    let power_on = || {
        let chip = ModelChip::new(tmc429_model::Chip::Tmc429, 16_000_000);
        Module::with_eeprom(chip, ModuleType::Tmcm3110, path.clone()).ok().unwrap()
    };
    {
        let mut m = power_on();
        ok(&mut m, op::SGP, 3, 2, 33);
        ok(&mut m, op::STGP, 3, 2, 0);
        ok(&mut m, op::SGP, 77, 0, 1);
        ok(&mut m, op::DOWNLOAD_START, 0, 0, 0);
        direct(&mut m, op::SGP, 4, 2, 44);
        direct(&mut m, op::STOP, 0, 0, 0);
        ok(&mut m, op::DOWNLOAD_END, 0, 0, 0);
        ok(&mut m, op::SAP, 4, 0, 1500);
        ok(&mut m, op::STAP, 4, 0, 0);
    }
    {
        let mut m = power_on();
        assert_eq!(m.vm.state, AppState::Run, "77 = 1: the program starts");
        m.run_ms(2);
        assert_eq!((m.user_var(4), m.user_var(3)), (44, 33));
        ok(&mut m, op::SGP, 85, 0, 1);
        ok(&mut m, op::SGP, 77, 0, 0);
    }
    {
        let mut m = power_on();
        assert_eq!(m.vm.state, AppState::Stop);
        assert_eq!(m.user_var(3), 0, "85 = 1: user variables not restored");
        assert_eq!(gap(&mut m, 4, 0), 1500);
        ok(&mut m, op::SGP, 64, 0, 0x12);
    }
    {
        let mut m = power_on();
        assert_eq!((gap(&mut m, 4, 0), ok(&mut m, op::GGP, 64, 0, 0)), (1000, 0xE4), "64 ≠ $E4: factory defaults");
    }
    let _ = std::fs::remove_dir_all(&dir);
    // 79: with reversed polarity an open switch reads pressed (TMC429 inv_ref).
    let mut m = module();
    assert_eq!(gap(&mut m, 11, 0), 0);
    ok(&mut m, op::SGP, 79, 0, 1);
    m.run_ms(2);
    assert_eq!((gap(&mut m, 11, 0), gap(&mut m, 10, 0)), (1, 1));
}
