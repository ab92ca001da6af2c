//! Input text as error messages show it: every parser of the project (datagram scripts,
//! scenario files, TMCL sources, command-line values) quotes the offending input through
//! [`shown`], so that control bytes (NUL, ESC, …) never reach the terminal raw and a 100 kB line
//! or a 300-digit number is not echoed whole; and reads files through [`utf8`], which names the
//! line and byte offset of the first byte that is not UTF-8.

/// Characters of input an error message quotes at most; a longer value is cut and ends in `…`.
pub const SHOWN_MAX: usize = 40;

/// `s` as an error message shows it: control characters escaped ([`escaped`]), at most
/// [`SHOWN_MAX`] characters of it, and `…` when it was cut.
pub fn shown(s: &str) -> String {
    match s.char_indices().nth(SHOWN_MAX) {
        Some((cut, _)) => escaped(&s[..cut]) + "…",
        None => escaped(s),
    }
}

/// `s` with its control characters escaped (`\0`, `\t`, `\r`, `\n`, `\x1b`, `\u{85}`) and the
/// invisible format characters that reorder or hide text on a terminal (`\u{202e}`): what an
/// error message may print of any input.
pub fn escaped(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '\0' => out.push_str("\\0"),
            '\t' => out.push_str("\\t"),
            '\r' => out.push_str("\\r"),
            '\n' => out.push_str("\\n"),
            c if (c as u32) < 0x80 && c.is_control() => out.push_str(&format!("\\x{:02x}", c as u32)),
            c if c.is_control() || is_invisible_format(c) => out.push_str(&format!("\\u{{{:x}}}", c as u32)),
            c => out.push(c),
        }
    }
    out
}

/// Unicode format characters that reorder or hide text on a terminal (bidirectional overrides
/// and isolates, zero-width characters, the byte-order mark).
fn is_invisible_format(c: char) -> bool {
    matches!(c, '\u{200b}'..='\u{200f}' | '\u{202a}'..='\u{202e}' | '\u{2060}'..='\u{2064}' | '\u{2066}'..='\u{2069}' | '\u{feff}')
}

/// Bytes as text: the whole input if it is UTF-8, else an error that names the line (1-based)
/// and the byte offset (0-based, from the start of the input) of the first byte that is not,
/// with the byte shown in hex: `3: byte offset 57: \xff is not UTF-8 (the file must be UTF-8
/// text)`. The caller puts the file name in front.
pub fn utf8(bytes: Vec<u8>) -> Result<String, String> {
    String::from_utf8(bytes).map_err(|e| {
        let err = e.utf8_error();
        let bytes = e.as_bytes();
        let at = err.valid_up_to();
        let line = bytes[..at].iter().filter(|&&b| b == b'\n').count() + 1;
        let bad = match err.error_len() {
            Some(n) => &bytes[at..at + n],
            None => &bytes[at..],
        };
        let hex: String = bad.iter().map(|b| format!("\\x{b:02x}")).collect();
        let what = if err.error_len().is_none() { "an incomplete UTF-8 sequence at the end" } else { "not UTF-8" };
        format!("{line}: byte offset {at}: {hex} is {what} (the file must be UTF-8 text)")
    })
}

/// Reads a file as UTF-8 text; errors name the file: `FILE: cannot read: …`, or
/// `FILE:LINE: byte offset N: … is not UTF-8 …` ([`utf8`]).
pub fn read_file(path: &std::path::Path) -> Result<String, String> {
    let bytes = std::fs::read(path).map_err(|e| format!("{}: cannot read: {e}", path.display()))?;
    utf8(bytes).map_err(|e| format!("{}:{e}", path.display()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn control_bytes_are_escaped() {
        assert_eq!(shown("a\0b\x1b[2Jc\td"), "a\\0b\\x1b[2Jc\\td");
        assert_eq!(shown("\u{85}\u{202e}µ"), "\\u{85}\\u{202e}µ");
    }

    #[test]
    fn long_values_are_cut() {
        let s = "9".repeat(300);
        let t = shown(&s);
        assert_eq!(t.chars().count(), SHOWN_MAX + 1);
        assert!(t.ends_with("9…"));
        assert_eq!(shown(&"x".repeat(SHOWN_MAX)), "x".repeat(SHOWN_MAX));
    }

    #[test]
    fn bad_utf8_names_line_and_offset() {
        assert_eq!(utf8(b"ok\nfine\n\xffbad".to_vec()).unwrap_err(), "3: byte offset 8: \\xff is not UTF-8 (the file must be UTF-8 text)");
        assert_eq!(
            utf8(b"a\xe2\x82".to_vec()).unwrap_err(),
            "1: byte offset 1: \\xe2\\x82 is an incomplete UTF-8 sequence at the end (the file must be UTF-8 text)"
        );
        assert_eq!(utf8(b"\0\x1b".to_vec()).unwrap(), "\0\x1b");
    }
}
