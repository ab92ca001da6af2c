//! The seed-coverage table and the parameter tables of docs/tmcl.md are the ones the module's
//! parameter tables make (`tmcl::seed`), and every row agrees with what the module answers:
//! "not available" parameters answer 3, commands 6; the others answer 100 where readable.

mod common;
use common::*;

use tmcl::personality::ModuleType;
use tmcl::proto::op;
use tmcl::seed::{self, Coverage};

fn doc() -> String {
    std::fs::read_to_string(std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs/tmcl.md")).unwrap()
}

/// The text between `<!-- generated: NAME -->` and the next `<!-- end generated -->`.
fn block(doc: &str, name: &str) -> String {
    let start = format!("<!-- generated: {name} -->\n");
    let i = doc.find(&start).unwrap_or_else(|| panic!("docs/tmcl.md has no block {name}")) + start.len();
    let n = doc[i..].find("<!-- end generated -->").unwrap();
    doc[i..i + n].to_string()
}

fn generated() -> [(String, String); 3] {
    [
        ("tmcl::seed::coverage_markdown".into(), seed::coverage_markdown()),
        ("tmcl::seed::parameters_markdown(Tmcm3110)".into(), seed::parameters_markdown(ModuleType::Tmcm3110)),
        ("tmcl::seed::parameters_markdown(Tmcm1311)".into(), seed::parameters_markdown(ModuleType::Tmcm1311)),
    ]
}

/// With TMCL_UPDATE_DOCS=1 the blocks are written into docs/tmcl.md first.
#[test]
fn tables_in_the_docs_are_the_generated_ones() {
    let mut d = doc();
    if std::env::var_os("TMCL_UPDATE_DOCS").is_some() {
        for (name, text) in generated() {
            let old = block(&d, &name);
            let at = d.find(&format!("<!-- generated: {name} -->\n")).unwrap();
            d = format!("{}{}", &d[..at], d[at..].replacen(&old, &text, 1));
        }
        std::fs::write(std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs/tmcl.md"), &d).unwrap();
    }
    for (name, text) in generated() {
        assert_eq!(block(&d, &name), text, "{name}: TMCL_UPDATE_DOCS=1 cargo test -p tmcl --test coverage writes it");
    }
}

/// Units the manual gives ([TMCL] §6, §10.1): axis parameter 204 in ms, 214 in 10 ms.
#[test]
fn units_as_the_manual() {
    for kind in ModuleType::ALL {
        assert!(kind.axis_param(204).unwrap().name.ends_with("[ms]"), "{kind:?}");
        assert_eq!((kind.axis_param(204).unwrap().min, kind.axis_param(204).unwrap().max), (0, 65535));
        assert!(kind.axis_param(214).unwrap().name.ends_with("[10 ms]"), "{kind:?}");
        assert!(kind.global_param(68).unwrap().name.ends_with("[ms]"), "{kind:?}");
    }
}

#[test]
fn every_row_agrees_with_the_module() {
    for kind in ModuleType::ALL {
        let mut m = module_of(kind);
        for &(no, name) in seed::AXIS_PARAMS {
            let (s, _) = direct(&mut m, op::GAP, no, 0, 0);
            match seed::axis_coverage(kind, no) {
                Coverage::NotAvailable(_) => {
                    assert_eq!(s, 3, "{kind:?} GAP {no} ({name})");
                    assert_eq!(direct(&mut m, op::SAP, no, 0, 0).0, 3, "{kind:?} SAP {no} ({name})");
                }
                _ => {
                    let readable = kind.axis_param(no).unwrap().access.readable();
                    assert_eq!(s, if readable { 100 } else { 3 }, "{kind:?} GAP {no} ({name})");
                }
            }
        }
        for &(no, name) in seed::GLOBAL_PARAMS {
            let s = direct(&mut m, op::GGP, no, 0, 0).0;
            let want = if matches!(seed::global_coverage(kind, no), Coverage::NotAvailable(_)) { 3 } else { 100 };
            assert_eq!(s, want, "{kind:?} GGP {no} ({name})");
        }
        for &(no, name, _, c3110, c1311) in seed::COMMANDS {
            let c = if kind == ModuleType::Tmcm3110 { c3110 } else { c1311 };
            let Some(no) = no else { continue };
            if let Coverage::NotAvailable(_) = c {
                for o in no..=if no == op::UF0 { op::UF7 } else { no } {
                    assert_eq!(direct(&mut m, o, 0, 0, 0).0, 6, "{kind:?} command {o} ({name})");
                }
            }
        }
    }
}

/// Every command of the table is one the assembler knows or a control command (so the table
/// names commands of this module), and the manual's lists hold no number twice.
#[test]
fn the_lists_are_consistent() {
    for &(no, name, ..) in seed::COMMANDS {
        if let Some(n) = no {
            assert!(tmcl::asm::is_program_opcode(n) || n >= 128, "{n} {name}");
        }
    }
    for list in [seed::AXIS_PARAMS, seed::GLOBAL_PARAMS] {
        let mut nos: Vec<u8> = list.iter().map(|(n, _)| *n).collect();
        nos.dedup();
        assert_eq!(nos.len(), list.len());
        assert!(nos.windows(2).all(|w| w[0] < w[1]), "in the manual's order");
    }
}
