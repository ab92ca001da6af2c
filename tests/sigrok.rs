//! The sigrok protocol decoders of `sigrok/` under Debian's sigrok-cli (scripts/setup installs
//! it): on captures exported from the golden model (`tmc429 capture export`, as a sigrok session
//! file and as the pin-only VCD), they print what the project's own decoding prints — the
//! register names and fields of `tmc429 spi --decode` for the datasheet's example frames, and
//! the demo's every SPI frame and driver-chain datagram from its test vectors — and the steps,
//! positions and nINT edges of a Step/Dir run. The decoder's register table is the rendering of
//! the register map.

use std::path::{Path, PathBuf};
use std::process::Command;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn scratch(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("tmc429-sigrok-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn tmc429(args: &[&str]) -> String {
    let o = Command::new(env!("CARGO_BIN_EXE_tmc429")).args(args).current_dir(root()).output().unwrap();
    assert!(o.status.code().is_some_and(|c| c <= 1), "tmc429 {args:?}: {}", String::from_utf8_lossy(&o.stderr));
    String::from_utf8(o.stdout).unwrap()
}

/// sigrok-cli with the project's decoders; the annotations of `decoder` (its `-A` value), one
/// per line without the `decoder-1: ` prefix.
fn sigrok(input: &Path, pd: &str, ann: &str) -> Vec<String> {
    let o = Command::new("sigrok-cli")
        .env("SIGROKDECODE_DIR", root().join("sigrok"))
        .args(["-i", input.to_str().unwrap(), "-P", pd, "-A", ann])
        .output()
        .unwrap_or_else(|e| panic!("sigrok-cli does not run ({e}): install it with scripts/setup"));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success() && err.trim().is_empty(), "sigrok-cli -P {pd}: {err}");
    let id = ann.split('=').next().unwrap();
    let prefix = format!("{id}-1: ");
    String::from_utf8(o.stdout).unwrap().lines().filter_map(|l| l.strip_prefix(&prefix)).map(str::to_string).collect()
}

const SPI: &str = "spi:clk=SCK_C:miso=SDOZ_C:mosi=SDI_C:cs=nSCS_C:cpol=1:cpha=1,tmc429";

#[test]
fn the_register_table_is_the_register_map() {
    let file = std::fs::read_to_string(root().join("sigrok/tmc429/regmap.py")).unwrap();
    assert!(
        tmc429(&["regmap", "--format", "sigrok"]) == file,
        "sigrok/tmc429/regmap.py is stale: run `tmc429 regmap --format sigrok > sigrok/tmc429/regmap.py`"
    );
}

#[test]
fn the_datasheet_frames_decode_as_tmc429_spi_does() {
    let dir = scratch("datasheet");
    let sr = dir.join("datasheet.sr");
    tmc429(&["capture", "export", "examples/spi/datasheet.spi", "-o", sr.to_str().unwrap(), "--rate", "24MHz"]);
    let want: Vec<String> =
        tmc429(&["spi", "--decode", "examples/spi/datasheet.spi"]).lines().map(|l| l.split_once("  # ").unwrap().1.to_string()).collect();
    let got = sigrok(&sr, SPI, "tmc429=datagrams");
    assert_eq!(got, want);
    // the TMC429 datasheet's example: type_version $429101 (TMC429 §8.2.4.4)
    assert!(got.contains(&"R type_version type_version=4362497 ($429101) | status $15: xEQt3 xEQt2 xEQt1".to_string()));
    let fields = sigrok(&sr, SPI, "tmc429=fields");
    assert_eq!(&fields[..3], ["dx_ref_tolerance=291 ($123)", "dx_ref_tolerance=291 ($123)", "cell127=35"]);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The rows of a CSV of the vectors (header dropped), split at commas.
fn csv(path: &Path) -> Vec<Vec<String>> {
    std::fs::read_to_string(path).unwrap().lines().skip(1).map(|l| l.split(',').map(str::to_string).collect()).collect()
}

#[test]
fn the_demo_decodes_as_its_vectors_record_it() {
    let dir = scratch("demo");
    let out = dir.join("demo-out");
    tmc429(&["demo", "--engine", "model", "--out", out.to_str().unwrap()]);
    let vcd = dir.join("demo-pins.vcd");
    tmc429(&["capture", "export", "examples/scenarios/demo.toml", "-o", vcd.to_str().unwrap(), "--rate", "100MHz"]);
    // every µC frame: R|W register fields | status, as the SPI CSV has it
    let want: Vec<String> = csv(&out.join("spi-demo-tmc429.csv"))
        .iter()
        .map(|r| format!("{} {} {} | {}", if r[5] == "read" { "R" } else { "W" }, r[6], r[7], r[8]))
        .collect();
    let got = sigrok(&vcd, SPI, "tmc429=datagrams");
    assert_eq!(got, want);
    assert!(got.contains(&"W x_target[0] x_target=1200 | status $15: xEQt3 xEQt2 xEQt1".to_string()), "{got:?}");
    assert!(got.contains(&"R x_latched[2] x_latched=-300 | status $20: RS3".to_string()), "{got:?}");
    // every driver-chain datagram: length and bits, as the chain CSV has it
    let want: Vec<String> = csv(&out.join("chain-demo-tmc429.csv")).iter().map(|r| format!("{} bits ${}", r[2], r[3])).collect();
    let chain = "tmc429_chain:cs=nSCS_S:clk=SCK_S:sdo=SDO_S:sdi=SDI_S:drivers=tmc23x-24x";
    let got = sigrok(&vcd, chain, "tmc429_chain=datagrams");
    assert_eq!(got.len(), want.len());
    assert!(got == want, "the chain decoder's datagrams differ from chain-demo-tmc429.csv");
    // the Table 11-2 groups of the first datagram: coil A of motor 0 from its DAC value
    let groups = sigrok(&vcd, chain, "tmc429_chain=groups");
    let first = &csv(&out.join("chain-demo-tmc429.csv"))[0];
    let ca = first[6].parse::<u32>().unwrap() >> 2;
    assert!(groups[0].starts_with(&format!("motor 0: MDA=0 CA={ca} PHA={} ", first[7])), "{}", groups[0]);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn step_dir_and_nint_decode_as_the_run_counts_them() {
    let dir = scratch("stepdir");
    let sr = dir.join("stepdir.sr");
    tmc429(&["capture", "export", "examples/scenarios/bench-stepdir.toml", "-o", sr.to_str().unwrap(), "--rate", "24MHz"]);
    let run = tmc429(&["run", "examples/scenarios/bench-stepdir.toml"]);
    let pd = "tmc429_stepdir:step1=SDO_S:dir1=SCK_S:step2=nSCS_S:dir2=SDI_S:step3=nSCS2:dir3=nSCS3";
    for m in 0..3 {
        let steps = sigrok(&sr, pd, &format!("tmc429_stepdir=motor{m}"));
        // the summary: "motor M:      S steps, x_actual X, …, P STEP pulses"
        let line = run.lines().find(|l| l.starts_with(&format!("motor {m}:"))).unwrap();
        let x: i64 = line.split("x_actual ").nth(1).unwrap().split(',').next().unwrap().parse().unwrap();
        let pulses: usize = line.split(", ").find(|p| p.ends_with("STEP pulses")).unwrap().split(' ').next().unwrap().parse().unwrap();
        assert_eq!(steps.len(), pulses, "motor {m}: {line}");
        let last: i64 = steps.last().unwrap().split(' ').nth(1).unwrap().parse().unwrap();
        assert_eq!(last, x, "motor {m}: {line}");
    }
    // motor 1 raises INT at its target; the write at 14 ms clears it
    let int = sigrok(&sr, "tmc429_int:nint=nINT_SDO_C:cs=nSCS_C", "tmc429_int=edges");
    assert_eq!(int, ["nINT falls (INT active)", "nINT rises (INT inactive)"]);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn the_chain_readback_and_the_cover_datagram_decode() {
    let dir = scratch("chain");
    let sr = dir.join("chain.sr");
    tmc429(&["capture", "export", "examples/scenarios/bench-chain.toml", "-o", sr.to_str().unwrap(), "--rate", "100MHz"]);
    let pd = "tmc429_chain:cs=nSCS_S:clk=SCK_S:sdo=SDO_S:sdi=SDI_S:drivers=tmc23x-24x:cover_pos=12:cover_len=12";
    // SDI_S is high from 3 ms to 13 ms (the scenario): all-ones readback, TMC246 status bits set
    let rb = sigrok(&sr, pd, "tmc429_chain=readback");
    assert!(rb.contains(&"readback 36 bits $FFFFFFFFF".to_string()) && rb[0] == "readback 36 bits $000000000", "{rb:?}");
    let groups = sigrok(&sr, pd, "tmc429_chain=readback-groups");
    assert!(groups.contains(&"motor 1: LD=7 OT OTPW UV OCHS OLB OLA OCB OCA".to_string()), "{groups:?}");
    // the cover datagram $A5C at positions 12..23 (TMC429 §8.2.2): in the datagram after 5 ms
    let cov = sigrok(&sr, pd, "tmc429_chain=datagrams");
    assert!(cov.contains(&"cover 12 bits $A5C".to_string()), "{cov:?}");
    std::fs::remove_dir_all(&dir).unwrap();
}
