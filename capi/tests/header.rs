//! Checks `include/tmc429.h` against the Rust side (every file of `src/`): every `extern "C"` function
//! with the same parameter names and C types, every `#[repr(C)]` struct field by field, every
//! `TMC429_*` constant by value, and nothing more or less in either file.

use std::collections::BTreeMap;

const HEADER: &str = include_str!("../include/tmc429.h");

/// The Rust sources of the library, every module of `src/`.
fn rust_sources() -> String {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files: Vec<_> =
        std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().path()).filter(|p| p.extension() == Some("rs".as_ref())).collect();
    files.sort();
    files.iter().map(|p| std::fs::read_to_string(p).unwrap()).collect::<Vec<_>>().join("\n")
}

/// The header's include guard: not `TMC429_H`, which vendor drivers' `TMC429.h` use.
const GUARD: &str = "TMC429_CAPI_H_INCLUDED";

#[test]
fn include_guard_is_unique() {
    assert!(HEADER.contains(&format!("#ifndef {GUARD}\n#define {GUARD}\n")));
    assert!(!HEADER.contains("TMC429_H\n"));
}

/// The C spelling of a Rust type used in the ABI.
fn c_type(rust: &str) -> String {
    let t = rust.trim();
    if let Some(rest) = t.strip_prefix("*const ") {
        return format!("const {} *", c_type(rest));
    }
    if let Some(rest) = t.strip_prefix("*mut ") {
        return format!("{} *", c_type(rest));
    }
    match t {
        "u8" => "uint8_t",
        "u16" => "uint16_t",
        "u32" => "uint32_t",
        "u64" => "uint64_t",
        "i32" => "int32_t",
        "usize" => "size_t",
        "c_int" => "int",
        "c_uint" => "unsigned int",
        "c_char" => "char",
        other if other.starts_with("tmc429_") => other,
        other => panic!("type {other} has no C mapping in this test"),
    }
    .to_string()
}

/// Whitespace-normalized C type: `const uint8_t *`.
fn norm(c: &str) -> String {
    let c = c.replace('*', " * ");
    let mut s = c.split_whitespace().collect::<Vec<_>>().join(" ");
    // The handle typedef is uint64_t (checked below).
    s = s.replace("tmc429_handle_t", "uint64_t");
    s
}

type Sig = (String, Vec<(String, String)>); // return type, [(name, type)]

fn rust_functions() -> BTreeMap<String, Sig> {
    let mut m = BTreeMap::new();
    let rust = rust_sources().replace("pub unsafe extern \"C\" fn ", "pub extern \"C\" fn ");
    for part in rust.split("pub extern \"C\" fn ").skip(1) {
        let head = &part[..part.find('{').unwrap()];
        let name = head[..head.find('(').unwrap()].trim().to_string();
        let args = &head[head.find('(').unwrap() + 1..head.rfind(')').unwrap()];
        let ret = head[head.rfind(')').unwrap() + 1..].trim().trim_start_matches("->").trim();
        let params = args
            .split(',')
            .map(str::trim)
            .filter(|a| !a.is_empty())
            .map(|a| {
                let (n, t) = a.split_once(':').unwrap();
                (n.trim().to_string(), norm(&c_type(t)))
            })
            .collect();
        m.insert(name, (norm(&c_type(ret)), params));
    }
    m
}

/// Splits `const uint8_t *tx` into (`tx`, `const uint8_t *`).
fn split_decl(d: &str) -> (String, String) {
    let d = d.trim();
    let cut = d.rfind([' ', '*']).unwrap();
    (d[cut + 1..].to_string(), norm(&d[..=cut]))
}

fn header_functions() -> BTreeMap<String, Sig> {
    // Drop comments and preprocessor lines, then read `type name(params);` declarations.
    let mut text = String::new();
    let mut rest = HEADER;
    while let Some(i) = rest.find("/*") {
        text.push_str(&rest[..i]);
        rest = &rest[i + rest[i..].find("*/").unwrap() + 2..];
    }
    text.push_str(rest);
    let text: String = text.lines().filter(|l| !l.trim_start().starts_with('#')).collect::<Vec<_>>().join("\n");
    let mut m = BTreeMap::new();
    for stmt in text.split(';') {
        let s = stmt.trim();
        if s.contains('{') || s.contains('}') || !s.contains('(') || s.starts_with("typedef") {
            continue;
        }
        let open = s.find('(').unwrap();
        let (name, ret) = split_decl(&s[..open]);
        let args = &s[open + 1..s.rfind(')').unwrap()];
        let params = if args.trim() == "void" { vec![] } else { args.split(',').map(split_decl).collect() };
        m.insert(name, (ret, params));
    }
    m
}

#[test]
fn every_function_matches() {
    let r = rust_functions();
    let h = header_functions();
    assert!(r.len() >= 20, "found only {} Rust functions", r.len());
    let rn: Vec<_> = r.keys().collect();
    let hn: Vec<_> = h.keys().collect();
    assert_eq!(rn, hn, "function sets differ");
    for (name, (ret, params)) in &r {
        let (hret, hparams) = &h[name];
        // The header spells tmc429_abi_version's and every function's return type; Rust `()`
        // never occurs.
        assert_eq!(ret, hret, "{name}: return type");
        assert_eq!(params, hparams, "{name}: parameters");
    }
}

#[test]
fn handle_typedef_is_u64() {
    assert!(HEADER.contains("typedef uint64_t tmc429_handle_t;"));
}

fn rust_structs() -> BTreeMap<String, Vec<(String, String)>> {
    let mut m = BTreeMap::new();
    for part in rust_sources().split("#[repr(C)]").skip(1) {
        let i = part.find("pub struct ").unwrap() + "pub struct ".len();
        let name = part[i..i + part[i..].find(' ').unwrap()].to_string();
        let body = &part[part.find('{').unwrap() + 1..part.find('}').unwrap()];
        let fields = body
            .lines()
            .map(str::trim)
            .filter(|l| l.starts_with("pub "))
            .map(|l| {
                let (n, t) = l.trim_start_matches("pub ").trim_end_matches(',').split_once(':').unwrap();
                (n.trim().to_string(), norm(&c_type(t)))
            })
            .collect();
        m.insert(name, fields);
    }
    m
}

fn header_structs() -> BTreeMap<String, Vec<(String, String)>> {
    let mut m = BTreeMap::new();
    for part in HEADER.split("typedef struct ").skip(1) {
        let body = &part[part.find('{').unwrap() + 1..part.find('}').unwrap()];
        let after = &part[part.find('}').unwrap() + 1..];
        let name = after[..after.find(';').unwrap()].trim().to_string();
        let fields = body
            .lines()
            .map(|l| l.split("/*").next().unwrap().trim())
            .filter(|l| !l.is_empty())
            .map(|l| split_decl(l.trim_end_matches(';')))
            .collect();
        m.insert(name, fields);
    }
    m
}

#[test]
fn every_struct_matches() {
    let r = rust_structs();
    assert_eq!(r.len(), 3);
    assert_eq!(r, header_structs());
    assert_eq!(std::mem::size_of::<tmc429::tmc429_event_t>(), 32);
    assert_eq!(std::mem::size_of::<tmc429::tmc429_outputs_t>(), 12);
    assert_eq!(std::mem::size_of::<tmc429::tmc429_motor_probe_t>(), 32);
}

fn parse_int(s: &str) -> i64 {
    let s = s.trim().trim_start_matches('(').trim_end_matches(')').replace('_', "");
    match s.strip_prefix("0x") {
        Some(hex) => i64::from_str_radix(hex, 16).unwrap_or_else(|_| panic!("not an integer: {s}")),
        None => s.parse().unwrap_or_else(|_| panic!("not an integer: {s}")),
    }
}

#[test]
fn every_constant_matches() {
    let mut r = BTreeMap::new();
    for l in rust_sources().lines().filter(|l| l.starts_with("pub const TMC429_")) {
        let (lhs, v) = l.trim_end_matches(';').split_once('=').unwrap();
        let name = lhs["pub const ".len()..lhs.find(':').unwrap()].to_string();
        r.insert(name, parse_int(v));
    }
    let mut h = BTreeMap::new();
    for l in HEADER.lines().filter(|l| l.starts_with("#define TMC429_") && !l.starts_with(&format!("#define {GUARD}"))) {
        let l = l.split("/*").next().unwrap();
        let mut it = l.split_whitespace().skip(1);
        let name = it.next().unwrap().to_string();
        let v: String = it.collect();
        h.insert(name, parse_int(&v));
    }
    assert!(r.len() >= 20);
    assert_eq!(r, h);
}
