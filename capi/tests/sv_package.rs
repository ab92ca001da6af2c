//! `sv/tmc429_pkg.sv` mirrors the header: every `localparam TMC429_*` has the header's value, and
//! every DPI-C import names a function of the header with the same parameter names and the SV
//! types that map to its C types (IEEE 1800 Annex H: int = int32, int unsigned = uint32,
//! longint unsigned = uint64, string = const char *, an output is a pointer).

use std::collections::BTreeMap;

const SV: &str = include_str!("../sv/tmc429_pkg.sv");
const HEADER: &str = include_str!("../include/tmc429.h");

fn c_of_sv(ty: &str, dir: &str) -> String {
    let base = match ty {
        "int" => "int",
        "int unsigned" => "uint32_t",
        "longint unsigned" => "uint64_t",
        "string" => return "const char *".into(),
        other => panic!("SV type {other} has no mapping in this test"),
    };
    if dir == "output" {
        format!("{base} *")
    } else {
        base.into()
    }
}

fn norm(c: &str) -> String {
    c.replace('*', " * ").split_whitespace().collect::<Vec<_>>().join(" ").replace("tmc429_handle_t", "uint64_t")
}

/// `name(type a, type b)` of the header, as (name, [(param, C type)], return type).
fn header_fn(name: &str) -> (Vec<(String, String)>, String) {
    let i = HEADER
        .find(&format!(" {name}("))
        .or_else(|| HEADER.find(&format!("*{name}(")))
        .unwrap_or_else(|| panic!("{name} not in the header"));
    let line_start = HEADER[..i].rfind('\n').unwrap() + 1;
    let decl = &HEADER[line_start..i + HEADER[i..].find(';').unwrap()];
    let open = decl.find('(').unwrap();
    let ret = norm(&decl[..open].replace(name, ""));
    let args = &decl[open + 1..decl.rfind(')').unwrap()];
    let params = if args.trim() == "void" {
        vec![]
    } else {
        args.split(',')
            .map(|a| {
                let a = a.trim();
                let cut = a.rfind([' ', '*']).unwrap();
                (a[cut + 1..].to_string(), norm(&a[..=cut]))
            })
            .collect()
    };
    (params, ret)
}

#[test]
fn constants_match_the_header() {
    let mut h = BTreeMap::new();
    for l in HEADER.lines().filter(|l| l.starts_with("#define TMC429_") && !l.starts_with("#define TMC429_CAPI_H_INCLUDED")) {
        let mut it = l.split("/*").next().unwrap().split_whitespace().skip(1);
        let name = it.next().unwrap().to_string();
        let v: String = it.collect();
        let v = v.trim_start_matches('(').trim_end_matches(')').to_string();
        h.insert(name, v.strip_prefix("0x").map_or_else(|| v.parse::<i64>().unwrap(), |x| i64::from_str_radix(x, 16).unwrap()));
    }
    let mut n = 0;
    for l in SV.lines().map(str::trim).filter(|l| l.starts_with("localparam int TMC429_")) {
        let (lhs, v) = l.trim_end_matches(';').split_once('=').unwrap();
        let name = lhs.trim().trim_start_matches("localparam int ").to_string();
        let v = v.trim();
        let value = v.strip_prefix("'h").map_or_else(|| v.parse::<i64>().unwrap(), |x| i64::from_str_radix(x, 16).unwrap());
        assert_eq!(h.get(&name), Some(&value), "{name}");
        n += 1;
    }
    assert!(n >= 14, "found {n} constants");
}

#[test]
fn imports_match_the_header() {
    let flat = SV.split_whitespace().collect::<Vec<_>>().join(" ");
    let mut n = 0;
    for part in flat.split("import \"DPI-C\" function ").skip(1) {
        let decl = &part[..part.find(");").unwrap() + 1];
        let open = decl.find('(').unwrap();
        let head = &decl[..open];
        let name = head.rsplit(' ').next().unwrap();
        let ret_sv = head[..head.len() - name.len()].trim();
        let (params, ret) = header_fn(name);
        assert_eq!(norm(&c_of_sv(ret_sv, "input")), if ret == "unsigned int" { "uint32_t".into() } else { ret.clone() }, "{name}: return");
        let args = &decl[open + 1..decl.len() - 1];
        let sv: Vec<(String, String)> = if args.trim().is_empty() {
            vec![]
        } else {
            args.split(',')
                .map(|a| {
                    let w: Vec<&str> = a.split_whitespace().collect();
                    let (dir, rest) = (w[0], &w[1..]);
                    let pname = rest.last().unwrap().split('[').next().unwrap();
                    let is_array = rest.last().unwrap().contains('[');
                    let ty = rest[..rest.len() - 1].join(" ");
                    // a fixed-size unpacked array is passed as a pointer to its first element
                    let c = if is_array { format!("{} *", c_of_sv(&ty, "input")) } else { c_of_sv(&ty, dir) };
                    (pname.to_string(), norm(&c))
                })
                .collect()
        };
        assert_eq!(sv, params, "{name}: parameters");
        n += 1;
    }
    assert!(n >= 15, "found {n} imports");
}
