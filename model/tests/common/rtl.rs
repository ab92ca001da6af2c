//! The RTL sources of `rtl/`, for the tests that hold the RTL to the model's single sources
//! (the generated headers, no hand-written numbers).

use std::path::{Path, PathBuf};

pub fn rtl_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../rtl")
}

/// The text (after leading blanks) starts with a number: a hand-written value in a decode.
pub fn starts_with_number(s: &str) -> bool {
    s.trim_start().starts_with(|c: char| c.is_ascii_digit())
}

/// The code of an RTL source line: its text before a `//` comment.
pub fn code_of(line: &str) -> &str {
    line.split("//").next().unwrap_or("")
}

/// The generated header `name` in `rtl/` as the file holds it.
pub fn header(name: &str) -> String {
    let path = rtl_dir().join(name);
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// Every line of every `rtl/*.v` that `find` reports (line number from 1, the line), as
/// `path:line: text`.
pub fn lines_found(find: fn(&str) -> Vec<(usize, String)>) -> Vec<String> {
    let mut sources: Vec<PathBuf> =
        std::fs::read_dir(rtl_dir()).unwrap().map(|e| e.unwrap().path()).filter(|p| p.extension().is_some_and(|x| x == "v")).collect();
    sources.sort();
    assert!(sources.len() > 10, "rtl/ holds the sources");
    let mut found = Vec::new();
    for p in &sources {
        let text = std::fs::read_to_string(p).unwrap();
        for (n, line) in find(&text) {
            found.push(format!("{}:{n}: {line}", p.display()));
        }
    }
    found
}
