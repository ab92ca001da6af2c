//! The manual's example programs (§5.6.5, §5.7.20, §11.2, §11.3, §11.4, §11.6): they assemble,
//! survive a disassembly round trip, and run on the module; program interrupts from switches,
//! inputs and target reached; the serial heartbeat (global parameter 68).

mod common;
use common::*;

use std::path::Path;
use tmcl::asm;
use tmcl::chip::ModelChip;
use tmcl::module::AppState;
use tmcl::proto::{op, Instruction};
use tmcl::{Module, Origin, Response};

fn assemble(src: &str) -> Vec<Instruction> {
    let p = asm::assemble(Path::new("example.tmc"), src, &asm::FileSystem).unwrap_or_else(|e| panic!("{e}"));
    // Round trip: disassembly assembles to the same binary.
    let text = asm::disassemble(&p.code);
    let q = asm::assemble(Path::new("round.tmc"), &text, &asm::FileSystem).unwrap_or_else(|e| panic!("{e}\n{text}"));
    assert_eq!(p.code, q.code, "round trip of\n{text}");
    p.code
}

fn gap(m: &mut Module<ModelChip>, p: u8, mo: u8) -> i32 {
    let (s, v) = m.execute(&Instruction::new(op::GAP, p, mo, 0), Origin::Direct);
    assert_eq!(s, 100);
    v
}

fn start(m: &mut Module<ModelChip>, code: &[Instruction]) {
    m.load_program(code).unwrap();
    m.vm.state = AppState::Run;
}

const TIMER_IRQ: &str = r#"
VECT 0, Timer0Irq //define the interrupt vector
SGP 0, 3, 1000 //configure the interrupt: set its period to 1000ms
EI 0 //enable this interrupt
EI 255 //globally switch on interrupt processing

//Main program: toggles output 3, using a WAIT command for the delay
Loop:
  SIO 3, 2, 1
  WAIT TICKS, 0, 50
  SIO 3, 2, 0
  WAIT TICKS, 0, 50
  JA Loop

//Here is the interrupt handling routine
Timer0Irq:
  GIO 0, 2 //check if OUT0 is high
  JC NZ, Out0Off //jump if not
  SIO 0, 2, 1 //switch OUT0 high
  RETI //end of interrupt
Out0Off:
  SIO 0, 2, 0 //switch OUT0 low
  RETI //end of interrupt
"#;

#[test]
fn timer_interrupt_example_5_6_5() {
    let code = assemble(TIMER_IRQ);
    assert_eq!(code.len(), 15);
    assert_eq!(code[0], Instruction::new(op::VECT, 0, 0, 9));
    assert_eq!(code[8], Instruction::new(op::JA, 0, 0, 4));
    // The variant with Interrupts.inc assembles to the same first four instructions.
    let inc =
        "#include Interrupts.inc\n  VECT TI_TIMER0, Timer0Irq\n  SGP TI_TIMER0, 3, 1000\n  EI TI_TIMER0\n  EI TI_GLOBAL\nTimer0Irq: RETI\n";
    let c2 = assemble(inc);
    assert_eq!(&c2[1..4], &code[1..4]);
    assert_eq!(c2[0], Instruction::new(op::VECT, 0, 0, 4));

    let mut m = module();
    start(&mut m, &code);
    let out = |m: &Module<ModelChip>, n: u8| (m.io.outputs >> n) & 1;
    m.run_ms(250);
    assert_eq!((out(&m, 3), out(&m, 0)), (1, 0));
    m.run_ms(500); // 750 ms
    assert_eq!((out(&m, 3), out(&m, 0)), (0, 0));
    m.run_ms(400); // 1150 ms: timer interrupt once
    assert_eq!(out(&m, 0), 1);
    m.run_ms(1000); // 2150 ms: twice
    assert_eq!(out(&m, 0), 0);
    m.run_ms(1000); // 3150 ms
    assert_eq!(out(&m, 0), 1);
    assert_eq!(m.vm.state, AppState::Run);
}

const MAIN_LOOP_11_2: &str = r#"
//Initialization
    SAP 4, 0, 500 //define max. positioning speed
    SAP 5, 0, 100 //define max. acceleration
MainLoop:
    //do something, in this example just running between two positions
    MVP ABS, 0, 5000
    WAIT POS, 0, 0
    MVP ABS, 0, 0
    WAIT POS, 0, 0
    JA MainLoop //end of the main loop => run infinitely
"#;

const CONSTANTS_11_3: &str = r#"
//Define some constants
#include TMCLParam.tmc
MaxSpeed = 500
MaxAcc = 100
Position0 = 0
Position1 = 5000
//Initialization
    SAP APMaxPositioningSpeed, Motor0, MaxSpeed
    SAP APMaxAcceleration, Motor0, MaxAcc
MainLoop:
    MVP ABS, Motor0, Position1
    WAIT POS, Motor0, 0
    MVP ABS, Motor0, Position0
    WAIT POS, Motor0, 0
    JA MainLoop
"#;

fn run_between_positions(code: &[Instruction]) {
    let mut m = module();
    start(&mut m, code);
    let (mut max, mut back) = (0, false);
    for _ in 0..400 {
        m.run_ms(10);
        let x = gap(&mut m, 1, 0);
        assert!((0..=5000).contains(&x), "position {x} outside 0..5000");
        max = max.max(x);
        if max == 5000 && x == 0 {
            back = true;
        }
    }
    assert_eq!(max, 5000);
    assert!(back, "returned to 0");
    assert_eq!(gap(&mut m, 4, 0), 500);
    assert_eq!(gap(&mut m, 5, 0), 100);
    assert_eq!(m.vm.state, AppState::Run);
}

#[test]
fn main_loop_example_11_2() {
    let code = assemble(MAIN_LOOP_11_2);
    assert_eq!(code.len(), 7);
    run_between_positions(&code);
}

#[test]
fn symbolic_constants_example_11_3() {
    let code = assemble(CONSTANTS_11_3);
    // Same program as §11.2, written with constants.
    assert_eq!(code, assemble(MAIN_LOOP_11_2));
    run_between_positions(&code);
}

#[test]
fn variables_example_11_4() {
    // The listing with its "..." elisions left out.
    let src = r#"
MyVariable = 42
    //Use a symbolic name for the user variable
    //(This makes the program better readable and understandable.)
SGP MyVariable, 2, 1234    //Initialize the variable with the value 1234
GGP MyVariable, 2        //Copy the contents of the variable to the accumulator register
CALC MUL, 2              //Multiply accumulator register with two
AAP MyVariable, 2        //Store contents of the accumulator register to the variable
"#;
    let code = assemble(src);
    assert_eq!(code[0], Instruction::new(op::SGP, 42, 2, 1234));
    // As printed, the last line stores with AAP (accumulator to axis parameter 42 of motor 2)
    // where AGP is meant: the module refuses it at download, naming the reason.
    let mut m = module();
    let e = m.load_program(&code).unwrap_err();
    assert_eq!(e, "instruction 3 (AAP 42, 2, 0): axis parameter 42: not an axis parameter of the TMCM-3110 (status 3)");
    // With AGP (accumulator to global parameter) the variable takes the result.
    let mut c2 = code.clone();
    c2[3] = Instruction::new(op::AGP, 42, 2, 0);
    start(&mut m, &c2);
    m.run_ms(5);
    assert_eq!(m.vm.state, AppState::Stop);
    assert_eq!(m.vm.accu, 2468);
    assert_eq!(m.user_var(42), 2468);
}

const MIXING_11_6: &str = r#"
//Jump commands to the TMCL routines
Func1:      JA Func1Start
Func2:      JA Func2Start
Func3:      JA Func3Start
Func1Start: MVP ABS, 0, 1000
             WAIT POS, 0, 0
             MVP ABS, 0, 0
             WAIT POS, 0, 0
             STOP
Func2Start: ROL 0, 500
             WAIT TICKS, 0, 100
             MST 0
             STOP
Func3Start: ROR 0, 1000
             WAIT TICKS, 0, 700
             MST 0
             STOP
"#;

fn direct(m: &mut Module<ModelChip>, o: u8, t: u8, mo: u8, v: i32) -> (u8, i32) {
    match m.handle_instruction(&Instruction::new(o, t, mo, v)) {
        Response::Normal(r) => (r.status, r.value),
        other => panic!("{other:?}"),
    }
}

#[test]
fn mixing_direct_and_standalone_11_6() {
    let code = assemble(MIXING_11_6);
    assert_eq!(&code[..3], &[Instruction::new(op::JA, 0, 0, 3), Instruction::new(op::JA, 0, 0, 8), Instruction::new(op::JA, 0, 0, 12)]);
    let mut m = module();
    m.load_program(&code).unwrap();
    // Run command with address 1 calls the second function (ROL 0, 500 for one second).
    assert_eq!(direct(&mut m, op::APP_RUN, 1, 0, 1), (100, 1));
    m.run_ms(500);
    assert_eq!(direct(&mut m, op::APP_STATUS, 0, 0, 0), (100, 1));
    // Direct-mode queries while the program runs; the accumulator is untouched.
    m.vm.accu = 77;
    assert_eq!(direct(&mut m, op::GAP, 2, 0, 0), (100, -500));
    assert!(direct(&mut m, op::GAP, 1, 0, 0).1 < 0);
    assert_eq!(m.vm.accu, 77);
    m.run_ms(1000);
    assert_eq!(direct(&mut m, op::GGP, 128, 0, 0), (100, 0)); // stopped
    assert_eq!(direct(&mut m, op::GAP, 2, 0, 0), (100, 0)); // MST
                                                            // Address 0: the first function moves to 1000 and back to 0, then stops.
    assert_eq!(direct(&mut m, op::APP_RUN, 1, 0, 0).0, 100);
    let mut seen = 0;
    for _ in 0..3000 {
        m.run_ms(1);
        seen = seen.max(direct(&mut m, op::GAP, 1, 0, 0).1);
        if m.vm.state == AppState::Stop {
            break;
        }
    }
    // Came from a negative position after ROL: it went up to 1000 and back to 0.
    assert_eq!(seen, 1000);
    assert_eq!(m.vm.state, AppState::Stop);
    assert_eq!(direct(&mut m, op::GAP, 1, 0, 0), (100, 0));
    assert_eq!(direct(&mut m, op::GGP, 130, 0, 0).1, 7); // program counter at the STOP
}

#[test]
fn subroutine_example_5_7_20() {
    let src = "Loop: MVP ABS, 0, 10000\n CSUB SubW //Save program counter and jump to label SubW\n MVP ABS, 0, 0\n JA Loop\n\nSubW: WAIT POS, 0, 0\n WAIT TICKS, 0, 50\n RSUB //Continue with the command following the CSUB command\n";
    let code = assemble(src);
    assert_eq!(code[1], Instruction::new(op::CSUB, 0, 0, 4));
    let mut m = module();
    start(&mut m, &code);
    m.run_ms(200);
    assert_eq!(m.vm.stack, vec![2]);
    m.run_ms(2000);
    let x = gap(&mut m, 1, 0);
    assert!((0..=10000).contains(&x));
}

#[test]
fn calc_comp_jc_and_nesting() {
    // Eight levels of subroutines; a ninth call is ignored ([TMCL] §5.7.20).
    let mut src = String::from("CALC LOAD, 5\nCALCX LOAD\nCALC MUL, 3\nCALCX SUB\nCOMP 10\nJC EQ, Ok1\nSTOP\nOk1: CALCX SWAP\n");
    src.push_str("CSUB S1\nSTOP\n");
    for i in 1..=9 {
        src.push_str(&format!("S{i}: AGP {i}, 2\n"));
        if i < 9 {
            src.push_str(&format!("CSUB S{}\n", i + 1));
        }
        src.push_str("RSUB\n");
    }
    let code = assemble(&src);
    let mut m = module();
    start(&mut m, &code);
    m.run_ms(5);
    assert_eq!(m.vm.state, AppState::Stop);
    // accu = 5*3 - 5 = 10 → EQ taken → SWAP: accu 5, X 10.
    assert_eq!((m.vm.accu, m.vm.x), (5, 10));
    for i in 1..=8 {
        assert_eq!(m.user_var(i), 5, "S{i} ran");
    }
    assert_eq!(m.user_var(9), 0, "the ninth nested call is ignored");
}

#[test]
fn wait_timeout_sets_eto() {
    let code =
        assemble("MVP ABS, 0, 100000\nWAIT POS, 0, 5\nJC ETO, T\nSTOP\nT: SGP 0, 2, 1\nCLE ETO\nJC ETO, Bad\nSTOP\nBad: SGP 1, 2, 1\n");
    let mut m = module();
    start(&mut m, &code);
    m.run_ms(100);
    assert_eq!(m.user_var(0), 1);
    assert_eq!(m.user_var(1), 0);
    assert!(!m.vm.eto);
}

#[test]
fn assembler_errors_name_file_and_line() {
    let e = asm::assemble(Path::new("bad.tmc"), "SAP 4, 0, 100\n  FOO 1\n", &asm::FileSystem).unwrap_err();
    assert_eq!(e.to_string(), "bad.tmc:2: unknown command 'FOO'");
    let e = asm::assemble(Path::new("bad.tmc"), "MVP XYZ, 0, 1\n", &asm::FileSystem).unwrap_err();
    assert_eq!(e.to_string(), "bad.tmc:1: unknown symbol 'XYZ'; expected one of ABS, REL, COORD");
    let e = asm::assemble(Path::new("bad.tmc"), "\nJA Nowhere\n", &asm::FileSystem).unwrap_err();
    assert_eq!(e.to_string(), "bad.tmc:2: unknown symbol 'Nowhere'");
    let e = asm::assemble(Path::new("bad.tmc"), "SAP 4, 0\n", &asm::FileSystem).unwrap_err();
    assert_eq!(e.to_string(), "bad.tmc:1: SAP expects 3 operand(s), found 2");
}

/// Global parameter 68, serial heartbeat ([TMCL] §10.1: "If this time limit is up and no further
/// command is noticed the motor will be stopped"): commands every 50 ms keep a 100 ms heartbeat
/// alive; without them every motor is stopped (target speed 0, ramped down to 0); a new command
/// re-arms it.
#[test]
fn serial_heartbeat_stops_the_motors() {
    let mut m = module();
    let cmd = |m: &mut Module<ModelChip>, o: u8, t: u8, mo: u8, v: i32| match m.handle_instruction(&Instruction::new(o, t, mo, v)) {
        Response::Normal(r) => assert_eq!(r.status, 100, "op {o}"),
        other => panic!("op {o}: {other:?}"),
    };
    cmd(&mut m, op::SGP, 68, 0, 100);
    cmd(&mut m, op::ROR, 0, 0, 300);
    cmd(&mut m, op::ROR, 0, 2, 200);
    for _ in 0..20 {
        m.run_ms(50);
        cmd(&mut m, op::GAP, 3, 0, 0);
    }
    // 1 s with commands every 50 ms: both axes at their speed (parameters 2 target, 3 actual)
    assert_eq!((gap(&mut m, 2, 0), gap(&mut m, 3, 0)), (300, 300));
    assert_eq!((gap(&mut m, 2, 2), gap(&mut m, 3, 2)), (200, 200));
    m.run_ms(90);
    assert_eq!(gap(&mut m, 2, 0), 300, "90 ms without a command: still running");
    m.run_ms(1000);
    for axis in [0, 2] {
        assert_eq!((gap(&mut m, 2, axis), gap(&mut m, 3, axis)), (0, 0), "axis {axis} stopped");
    }
    // a command re-arms the heartbeat; the motor runs again
    cmd(&mut m, op::ROR, 0, 0, 300);
    m.run_ms(50);
    assert_eq!(gap(&mut m, 2, 0), 300);
    // SGP 68, 0 switches it off: no stop after a second of silence
    cmd(&mut m, op::SGP, 68, 0, 0);
    m.run_ms(1000);
    assert_eq!((gap(&mut m, 2, 0), gap(&mut m, 3, 0)), (300, 300));
}

const SWITCH_INPUT_TARGET_IRQ: &str = r#"
#include Interrupts.inc
    VECT TI_STOPL1, StopL1
    VECT TI_PIN2, Pin2
    VECT TI_TARGET0, Target0
    SGP TI_STOPL1, 3, 1     //left stop switch of axis 1: on pressing (rising)
    SGP TI_PIN2, 3, 2       //IN2: on the falling edge
    EI TI_STOPL1
    EI TI_PIN2
    EI TI_TARGET0
    EI TI_GLOBAL
    MVP ABS, 0, 2000
Loop:
    JA Loop

StopL1:                     //user variable 10 counts the switch interrupts
    GGP 10, 2
    CALC ADD, 1
    AGP 10, 2
    RETI
Pin2:                       //user variable 11 counts the input interrupts
    GGP 11, 2
    CALC ADD, 1
    AGP 11, 2
    RETI
Target0:                    //user variable 12 = the position at "target reached"
    GAP 1, 0
    AGP 12, 2
    RETI
"#;

/// Program interrupts from a stop switch (27..32), an input (39..46) and "target reached" (3..5)
/// ([TMCL] §5.7 EI/VECT, bank 3 of SGP): each handler runs once per configured edge and not on
/// the other edge; the target interrupt runs when axis 0 arrives at 2000.
#[test]
fn switch_input_and_target_interrupts_of_a_program() {
    let code = assemble(SWITCH_INPUT_TARGET_IRQ);
    let mut m = module();
    start(&mut m, &code);
    let var = |m: &mut Module<ModelChip>, n: u8| {
        let (s, v) = m.execute(&Instruction::new(op::GGP, n, 2, 0), Origin::Direct);
        assert_eq!(s, 100);
        v
    };
    m.run_ms(20);
    assert_eq!((var(&mut m, 10), var(&mut m, 11)), (0, 0));
    // press and release the left switch of axis 1 twice: two interrupts (rising only)
    for _ in 0..2 {
        m.world.left_forced[1] = true;
        m.run_ms(10);
        m.world.left_forced[1] = false;
        m.run_ms(10);
    }
    assert_eq!(var(&mut m, 10), 2);
    // IN2 low then open (pull-up high) three times: three interrupts (falling only)
    for _ in 0..3 {
        m.io.driven[2] = Some(false);
        m.run_ms(10);
        m.io.driven[2] = None;
        m.run_ms(10);
    }
    assert_eq!(var(&mut m, 11), 3);
    assert_eq!(var(&mut m, 10), 2, "no switch interrupt from the inputs");
    for _ in 0..500 {
        if var(&mut m, 12) != 0 {
            break;
        }
        m.run_ms(10);
    }
    assert_eq!(var(&mut m, 12), 2000);
    assert_eq!(gap(&mut m, 1, 0), 2000);
    assert_eq!(m.vm.state, AppState::Run);
}
