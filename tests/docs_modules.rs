//! docs/rtl.md "Modules" is the one block list of the RTL and the model: one row for every
//! `rtl/tmc429_*.v` module, and every file of `model/src/` either named in a row's Model column or
//! in the paragraph after the table that lists the model's files that are not units of the chip.

use std::collections::BTreeSet;
use std::path::Path;

const ROOT: &str = env!("CARGO_MANIFEST_DIR");

/// The "Modules" section of docs/rtl.md: its table rows and the text after the table.
fn section() -> (Vec<Vec<String>>, String) {
    let doc = std::fs::read_to_string(Path::new(ROOT).join("docs/rtl.md")).unwrap();
    let start = doc.find("\n## Modules\n").expect("docs/rtl.md has a \"## Modules\" section");
    let body = &doc[start + 1..];
    let end = body[3..].find("\n## ").map_or(body.len(), |e| e + 3);
    let body = &body[..end];
    let rows = body
        .lines()
        .filter(|l| l.starts_with("| `"))
        .map(|l| l.trim_matches('|').split(" | ").map(|c| c.trim().to_string()).collect())
        .collect();
    let rest = body.lines().filter(|l| !l.starts_with('|')).collect::<Vec<_>>().join("\n");
    (rows, rest)
}

/// The file names (no directory) between backticks in `text` that end in `ext`.
fn ticked(text: &str, ext: &str) -> BTreeSet<String> {
    text.split('`').skip(1).step_by(2).filter(|t| t.ends_with(ext) && !t.contains('/')).map(str::to_string).collect()
}

fn files(dir: &str, prefix: &str, ext: &str) -> BTreeSet<String> {
    std::fs::read_dir(Path::new(ROOT).join(dir))
        .unwrap()
        .flatten()
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| n.starts_with(prefix) && n.ends_with(ext))
        .collect()
}

#[test]
fn every_rtl_module_has_one_row() {
    let (rows, _) = section();
    let listed: Vec<String> = rows.iter().map(|r| format!("{}.v", r[0].trim_matches('`'))).collect();
    let unique: BTreeSet<String> = listed.iter().cloned().collect();
    assert_eq!(unique.len(), listed.len(), "a module has two rows: {listed:?}");
    assert_eq!(unique, files("rtl", "tmc429_", ".v"), "docs/rtl.md \"Modules\" rows against rtl/tmc429_*.v");
}

#[test]
fn every_model_file_is_a_unit_or_named_as_not_one() {
    let (rows, rest) = section();
    let mut named = BTreeSet::new();
    for r in &rows {
        assert_eq!(r.len(), 4, "a row of four columns (module, job, contract, model): {r:?}");
        named.extend(ticked(&r[3], ".rs"));
    }
    let not_units = ticked(&rest, ".rs");
    let model = files("model/src", "", ".rs");
    for f in named.iter().chain(&not_units) {
        assert!(model.contains(f), "docs/rtl.md names model/src/{f}, which does not exist");
    }
    for f in &model {
        assert!(
            named.contains(f) || not_units.contains(f),
            "model/src/{f} is neither in a row of docs/rtl.md \"Modules\" nor in the list after it"
        );
    }
    assert!(named.len() >= 14, "the Model column names {} files", named.len());
}
