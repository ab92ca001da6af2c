//! The repository stands alone: its documentation, comments and test names cite the datasheets
//! ([428] §x, [429] §y, [4210] §z) and docs/model-contract.md (C-numbers, X-numbers, errata),
//! never a document or a tracker that is not in the repository. This test reads every source and
//! documentation file (Rust, Verilog, Python, C, scripts, Markdown, scenario and script examples)
//! and fails on a citation of an outside summary or of a tracker number, naming file and line.

use std::path::{Path, PathBuf};

/// Text files a reader of the repository sees.
const EXTS: [&str; 14] = ["rs", "md", "v", "vh", "sv", "py", "pyi", "c", "h", "cc", "toml", "tmc", "spi", "gtkw"];
/// Generated data and build output (the directories .gitignore names): not the repository's text.
/// Hidden directories (`.git`, the Python virtual environment `.venv`) are skipped too.
const SKIP_DIRS: [&str; 7] = ["target", "golden", "node_modules", "demo-out", "out", "build", "tmc429-cocotb"];

fn files(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(rd) = std::fs::read_dir(dir) else { return };
    for e in rd.flatten() {
        let p = e.path();
        let name = e.file_name().to_string_lossy().into_owned();
        if p.is_dir() {
            if !name.starts_with('.') && !SKIP_DIRS.contains(&name.as_str()) {
                files(&p, out);
            }
        } else {
            let ext = p.extension().map(|x| x.to_string_lossy().into_owned());
            let script = p.parent().is_some_and(|d| d.ends_with("scripts")) && ext.is_none();
            if script || ext.is_some_and(|x| EXTS.contains(&x.as_str())) {
                out.push(p);
            }
        }
    }
}

/// The forbidden citations, lower case (assembled so that this file does not cite them itself).
fn forbidden() -> Vec<String> {
    let d = ["di", "gest"].concat();
    vec![
        format!("spec-{d}"),
        format!("{d} §"),
        format!("[{d}]"),
        format!("{d}_5_"),
        ["shared/", "reference"].concat(),
        ["architecture", ".md"].concat(),
    ]
}

/// "issue" followed by a number (a tracker reference).
fn cites_tracker(line: &str) -> bool {
    let l = line.to_lowercase();
    let word = ["iss", "ue"].concat();
    l.match_indices(&word).any(|(i, _)| {
        let rest = l[i + word.len()..].trim_start_matches([' ', '#']);
        rest.starts_with(|c: char| c.is_ascii_digit())
    })
}

#[test]
fn no_citation_outside_the_repository() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut all = Vec::new();
    files(root, &mut all);
    assert!(all.len() > 100, "only {} files found under {}", all.len(), root.display());
    let pats = forbidden();
    let mut bad = Vec::new();
    for f in &all {
        let Ok(text) = std::fs::read_to_string(f) else { continue };
        for (n, line) in text.lines().enumerate() {
            let l = line.to_lowercase();
            if pats.iter().any(|p| l.contains(p.as_str())) || cites_tracker(line) {
                bad.push(format!("{}:{}: {}", f.strip_prefix(root).unwrap_or(f).display(), n + 1, line.trim()));
            }
        }
    }
    assert!(bad.is_empty(), "citations of documents outside the repository:\n{}", bad.join("\n"));
}

#[test]
fn the_patterns_catch_what_they_are_for() {
    let d = ["di", "gest"].concat();
    let pats = forbidden();
    for cited in [format!("(spec-{d} §5.2)"), format!("({d} §6 #22)"), format!("([{d}] §7)")] {
        assert!(pats.iter().any(|p| cited.to_lowercase().contains(p.as_str())), "{cited}");
    }
    assert!(cites_tracker(&format!("({} 9: C at most 2× slower)", ["iss", "ue"].concat())));
    assert!(cites_tracker(&format!("see {} #12", ["Iss", "ue"].concat())));
    assert!(!cites_tracker("an issue of timing"));
    // A file-content digest (a different meaning) is not a citation.
    assert!(!pats.iter().any(|p| format!("no {d} of the whole file").contains(p.as_str())));
}
