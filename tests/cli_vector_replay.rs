//! `tmc429 vectors` replayed on the RTL under Icarus Verilog: clean, with a planted bug (the
//! first mismatch at the right cycle and column), and corrupt vector files.

mod vectors_common;
use vectors_common::*;

/// Bits `lo .. lo + w` of a vector line's word (hex digits, bit 0 the last digit's lowest).
fn word_field(l: &str, lo: usize, w: usize) -> u64 {
    let bit = |b: usize| (l.as_bytes()[l.len() - 1 - b / 4] as char).to_digit(16).unwrap() as u64 >> (b % 4) & 1;
    (lo..lo + w).rev().fold(0u64, |a, b| a << 1 | bit(b))
}

/// A copy of the vector lines with line `k` changed: each `(digit, mask)` XORs the mask into the
/// hex digit at that position from the left (an expected bit and the same bit of the check
/// digit, so that the file stays valid), written as `planted.hex` in `dir`.
fn plant(dir: &std::path::Path, lines: &[&str], k: usize, digits: &[(usize, u32)]) -> std::path::PathBuf {
    let mut bad: Vec<String> = lines.iter().map(|l| l.to_string()).collect();
    let mut c: Vec<char> = bad[k].chars().collect();
    for &(i, x) in digits {
        c[i] = char::from_digit(c[i].to_digit(16).unwrap() ^ x, 16).unwrap().to_ascii_uppercase();
    }
    bad[k] = c.into_iter().collect();
    let planted = dir.join("planted.hex");
    std::fs::write(&planted, bad.join("\n") + "\n").unwrap();
    planted
}

/// The chip-hold vectors replay clean; with PLANT_BUG_STATUS (CDGW ignores the datagram-word
/// flag) the first mismatch is the status byte's bit 30 on the data pins, in the 8-bit status
/// frame after the datagram_low_word write: frame start + setup (3) + bit 0 (2·3) = SCK_C falls
/// for bit 1, acted on 2 edges later (C4, C11).
#[test]
fn planted_bug_fails_at_the_right_cycle_and_column() {
    let dir = tmpdir("bug");
    export(&dir, &["--unit", "chip", "--scenario", "chip-hold"]);
    export(&dir, &["--unit", "spi", "--scenario", "chip-hold", "--format", "csv"]);
    let stem = dir.join("chip-chip-hold-tmc429");
    let cycles: u64 = meta(&stem, "cycles").parse().unwrap();

    let clean = build_chip_tb(&dir, None);
    let out = replay(&clean, &stem, None);
    assert_eq!(out.last().unwrap(), &format!("{cycles} passed, 0 failed"), "{out:?}");

    // the status frame after the datagram_low_word write
    let rows = csv(&dir.join("spi-chip-hold-tmc429.csv"));
    let w = rows.iter().position(|r| r[6] == "datagram_low_word" && r[5] == "write").unwrap();
    let st = &rows[w + 1];
    assert_eq!((st[5].as_str(), st[4].as_str()), ("short", "55"), "CDGW set in the model: {st:?}");
    let start: u64 = st[0].parse().unwrap();
    let expected = start + 3 + 2 * 3 + 2;

    let bug = build_chip_tb(&dir, Some("PLANT_BUG_STATUS"));
    let out = replay(&bug, &stem, None);
    let first: Vec<&String> = out.iter().filter(|l| l.starts_with("MISMATCH")).take(2).collect();
    assert_eq!(
        first,
        [
            &format!("MISMATCH cycle {expected} column nint_sdo_c: expected 1 got 0"),
            &format!("MISMATCH cycle {expected} column sdoz_c: expected 1 got 0"),
        ]
    );
    let last = out.last().unwrap();
    assert!(last.ends_with(" failed") && !last.ends_with(" 0 failed"), "{last}");
    std::fs::remove_dir_all(&dir).ok();
}

/// A truncated line, a line of the wrong width, a changed digit and a missing line are reported
/// as corrupt, never replayed as a pass.
#[test]
fn corrupt_vector_files_are_reported() {
    let dir = tmpdir("corrupt");
    export(&dir, &["--unit", "chip", "--scenario", "datasheet"]);
    let stem = dir.join("chip-datasheet-tmc429");
    let cycles: u64 = meta(&stem, "cycles").parse().unwrap();
    let good = std::fs::read_to_string(stem.with_extension("hex")).unwrap();
    let lines: Vec<&str> = good.lines().collect();
    assert_eq!(lines.len() as u64, cycles);
    assert!(lines.iter().all(|l| l.len() == 8 && l.starts_with('A')));
    let vvp = build_chip_tb(&dir, None);
    let write = |name: &str, f: &dyn Fn(&mut Vec<String>)| {
        let mut v: Vec<String> = lines.iter().map(|s| s.to_string()).collect();
        f(&mut v);
        let p = dir.join(name);
        std::fs::write(&p, v.join("\n") + "\n").unwrap();
        p
    };
    let cases: [(&str, &dyn Fn(&mut Vec<String>), String); 4] = [
        (
            "trunc.hex",
            &|v| {
                v[99].pop();
            },
            "line 100: 7 characters, expected 8 hex digits".into(),
        ),
        ("wide.hex", &|v| v[9].push('0'), "line 10: 9 characters, expected 8 hex digits".into()),
        (
            "digit.hex",
            &|v| {
                let d = if &v[499][3..4] == "0" { "1" } else { "0" };
                v[499].replace_range(3..4, d)
            },
            "line 500: check digit wrong".into(),
        ),
        (
            "short.hex",
            &|v| {
                v.pop();
            },
            format!("has {} lines", cycles - 1),
        ),
    ];
    for (name, f, msg) in cases {
        let p = write(name, f);
        let out = replay(&vvp, &stem, Some(&p));
        assert!(out.iter().any(|l| l.starts_with("CORRUPT") && l.contains(&msg)), "{name}: {out:?}");
        assert_eq!(out.last().unwrap(), &format!("0 passed, {cycles} failed"), "{name}");
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// Pin-level lut vectors (tmc429_microstep): Table 12-4 / 12-2 / 8-1 values at the unit's ports,
/// a clean replay, and a flipped expected bit in a copy that the replay reports at its line and
/// column (not as a corrupt file: the check digit is flipped with it).
#[test]
fn lut_pins_replay_and_report_a_planted_fault() {
    let dir = tmpdir("lutpins");
    export(&dir, &["--unit", "lut", "--scenario", "tables", "--format", "pins"]);
    let stem = dir.join("lut-tables-tmc429");
    assert_eq!(meta(&stem, "cycles"), (2 * 2 * 2 * 8 * (4 + 8 + 16 + 32 + 64 + 128 + 256 + 256)).to_string());
    assert_eq!(meta(&stem, "width"), "56");
    let hex = std::fs::read_to_string(stem.with_extension("hex")).unwrap();
    let lines: Vec<&str> = hex.lines().collect();
    // word: A | w 8 | coil_b 1 | lut 6 | i_scale 3 | code 5 | dac_q 6 | neg, step, pol 5 | lut_idx 6 | dac 6 | bit_out 1 | _check 5
    let field = |l: &str, lo: u32, w: u32| (u64::from_str_radix(l, 16).unwrap() >> lo) & ((1 << w) - 1);
    let ports = |l: &str| (field(l, 44, 8), field(l, 43, 1), field(l, 37, 6), field(l, 12, 6), field(l, 6, 6));
    // sine, usrs 0, +, i_scale 0, row 1 (w = 64, Table 12-4): coil A reads sin index 63 = 63, coil B cos index 0 = 0
    assert_eq!(ports(lines[2]), (64, 0, 63, 63, 63));
    assert_eq!(ports(lines[3]), (64, 1, 0, 0, 0));
    // i_scale %100 (Table 8-1): rows 4·4 + 1 → (63 · 4) >> 3 = 31
    assert_eq!(ports(lines[2 * (4 * 4 + 1)]), (64, 0, 63, 63, 31));

    let vvp = build_unit_tb(&dir, "tb_lut", &["tmc429_microstep.v"]);
    let out = replay(&vvp, &stem, None);
    assert_eq!(out.last().unwrap(), &format!("{} passed, 0 failed", lines.len()), "{out:?}");

    // flip bit_out (bit 1 of digit 12) of line 1000 and the same bit of the check digit
    let expected = (field(lines[1000], 5, 1), field(lines[1000], 5, 1) ^ 1);
    let planted = plant(&dir, &lines, 1000, &[(12, 2), (13, 2)]);
    let out = replay(&vvp, &stem, Some(&planted));
    assert_eq!(
        out[..2],
        [
            format!("MISMATCH cycle 1000 column bit_out: expected {} got {}", expected.1, expected.0),
            format!("{} passed, 1 failed", lines.len() - 1)
        ],
        "{out:?}"
    );
    std::fs::remove_dir_all(&dir).ok();
}

/// The reference search's pin-level ramp vectors (tmc429_ramp) in `dir`: their stem, their
/// text and the number of lines of each motor. Word bits: _sentinel 255..252 | inputs 251..136 (rst 251,
/// sample_tick 249, cond_tick 248, we 164, widx 163..160, wdata 159..136) | outputs 135..7
/// (x_actual 135..112, v 111..92, xeqt 21, stop 20) | _check 6..0 (3 zero pad bits and the check
/// digit).
fn ramp_pins(dir: &std::path::Path) -> (std::path::PathBuf, String, usize) {
    export(dir, &["--unit", "ramp", "--scenario", "reference-search", "--format", "pins"]);
    let stem = dir.join("ramp-reference-search-tmc429");
    assert_eq!(meta(&stem, "width"), "256");
    let hex = std::fs::read_to_string(stem.with_extension("hex")).unwrap();
    let cycles: usize = meta(&stem, "cycles").parse().unwrap();
    assert_eq!((hex.lines().count(), cycles % 3), (cycles, 0));
    (stem, hex, cycles / 3)
}

/// The first line of a motor's ramp vectors after its switch stop: the stop condition held
/// in the edge before the motor's condition slot and in the slot (C52, C61).
fn after_switch_stop(m: &[&str]) -> usize {
    1 + m
        .windows(2)
        .position(|w| word_field(w[0], 20, 1) == 1 && word_field(w[1], 20, 1) == 1 && word_field(w[1], 248, 1) == 1)
        .expect("a switch stop")
}

/// Pin-level ramp vectors (tmc429_ramp) of the reference search: the motors one after the
/// other, each from its reset line; motor 0's switch stop (C61), its zeroing by a µC write
/// (C3) and its RAMP_MODE move ending on x_target = 40 with V = 0 (C52); motor 1 holds.
#[test]
fn ramp_pins_of_the_reference_search() {
    let dir = tmpdir("ramppins-values");
    let (_, hex, per) = ramp_pins(&dir);
    let lines: Vec<&str> = hex.lines().collect();
    let field = word_field;
    for m in 0..3 {
        assert_eq!(field(lines[m * per], 251, 1), 1, "motor {m} begins with its reset line");
        assert_eq!(field(lines[m * per + 1], 251, 1), 0);
    }
    let m0 = &lines[..per];
    // sample_tick is the edge before the condition slot (C52): its line is followed by the
    // slot's; motor 0's slot is phase 14 (C41), so line k (the k-th edge after reset, whose old
    // state has the pre-divider at k - 1) takes the conditions when k mod 32 = 14
    assert!(m0[1..].windows(2).all(|w| field(w[0], 249, 1) == field(w[1], 248, 1)));
    assert!((1..per).all(|k| (field(m0[k], 249, 1) == 1) == (k % 32 == 14)));
    // V is 0 after the switch stop
    let s = after_switch_stop(m0);
    assert_eq!(field(m0[s + 1], 92, 20), 0);
    // the µC write x_actual := 0 (IDX 1) is executed in its edge
    let z = m0.iter().position(|l| field(l, 164, 1) == 1 && field(l, 160, 4) == 1).expect("x_actual write");
    assert!(z > s);
    assert_eq!((field(m0[z], 136, 24), field(m0[z], 112, 24)), (0, 0));
    // the move ends on x_target = 40 with V = 0
    let last = m0[per - 1];
    assert_eq!((field(last, 112, 24), field(last, 92, 20), field(last, 21, 1)), (40, 0, 1));
    // motor 1 holds at 0 all along
    assert!(lines[per..2 * per].iter().all(|l| field(l, 112, 24) == 0 && field(l, 92, 20) == 0));
    std::fs::remove_dir_all(&dir).ok();
}

/// The reference search's ramp vectors replay clean on tmc429_ramp with tmc429_accel serving
/// it; a flipped expected `stop` bit in a copy is reported at its line and column.
#[test]
fn ramp_pins_replay_and_report_a_planted_fault() {
    let dir = tmpdir("ramppins");
    let (stem, hex, per) = ramp_pins(&dir);
    let lines: Vec<&str> = hex.lines().collect();
    let vvp = build_unit_tb(&dir, "tb_ramp", &["tmc429_ramp.v", "tmc429_accel.v", "tmc429_pram.v", "tmc429_wram.v"]);
    let out = replay(&vvp, &stem, None);
    assert_eq!(out.last().unwrap(), &format!("{} passed, 0 failed", lines.len()), "{out:?}");

    // flip `stop` (word bit 20: bit 0 of digit 58) of the line after motor 0's switch stop in
    // motor 1's lines, and the same bit of the check digit (63)
    let k = per + after_switch_stop(&lines[..per]) + 1;
    let was = word_field(lines[k], 20, 1);
    let planted = plant(&dir, &lines, k, &[(58, 1), (63, 1)]);
    let out = replay(&vvp, &stem, Some(&planted));
    assert_eq!(
        out[..2],
        [format!("MISMATCH cycle {k} column stop: expected {} got {was}", was ^ 1), format!("{} passed, 1 failed", lines.len() - 1)],
        "{out:?}"
    );
    std::fs::remove_dir_all(&dir).ok();
}

/// Pin-level vectors of the driver-chain master (tmc429_chain) of the chain-unit set replay
/// clean on the RTL; the en_sd abort (C89) gives the taken cover and datagram-word flags back;
/// a flipped expected SDO_S bit in a copy of the file is reported at its line and column.
#[test]
fn chain_pins_replay_and_report_a_planted_fault() {
    let dir = tmpdir("chainpins");
    export(&dir, &["--unit", "chain", "--scenario", "chain-unit", "--format", "pins"]);
    let stem = dir.join("chain-chain-unit-tmc429");
    assert_eq!((meta(&stem, "width").as_str(), meta(&stem, "in_width").as_str(), meta(&stem, "out_width").as_str()), ("204", "105", "88"));
    let hex = std::fs::read_to_string(stem.with_extension("hex")).unwrap();
    let lines: Vec<&str> = hex.lines().collect();
    let cycles: usize = meta(&stem, "cycles").parse().unwrap();
    assert_eq!(lines.len(), cycles);
    // word bits: A 203..200 | inputs 199..95 (rst 199, spi_mode 197, cw 139, dgw 138)
    // | outputs 94..7 (cover_busy 83, dgw_busy 82, cs 33, sdo 31, state 23..21) | _check 6..0
    // (3 zero pad bits and the check digit)
    let field = word_field;
    assert_eq!((field(lines[0], 199, 1), field(lines[1], 199, 1)), (1, 0));
    // the abort: a busy chain sees spi_mode 0, goes to IDLE with CS inactive; the next line
    // presents cw and dgw waiting again (the register file took them back, C89)
    let a = (1..cycles).find(|&k| field(lines[k], 197, 1) == 0).expect("an en_sd abort");
    assert_ne!(field(lines[a - 1], 21, 3), 0, "busy before the abort");
    assert_eq!((field(lines[a - 1], 83, 1), field(lines[a - 1], 82, 1)), (1, 1));
    assert_eq!((field(lines[a], 21, 3), field(lines[a], 33, 1), field(lines[a], 83, 1), field(lines[a], 82, 1)), (0, 0, 0, 0));
    assert_eq!((field(lines[a + 1], 139, 1), field(lines[a + 1], 138, 1)), (1, 1));

    let vvp = build_unit_tb(&dir, "tb_chain", &["tmc429_chain.v", "tmc429_microstep.v"]);
    let out = replay(&vvp, &stem, None);
    assert_eq!(out.last().unwrap(), &format!("{cycles} passed, 0 failed"), "{out:?}");

    // flip `sdo` (word bit 31: bit 3 of the 8th digit from the right) of the first line with
    // SDO_S high while the chip select is active (a datagram bit; SDO_S idles high, C81), and
    // the same bit of the check digit (the last)
    let k = lines.iter().position(|l| field(l, 31, 1) == 1 && field(l, 33, 1) == 1).expect("an SDO_S high bit");
    let n = lines[k].len();
    let planted = plant(&dir, &lines, k, &[(n - 1 - 7, 8), (n - 1, 8)]);
    let out = replay(&vvp, &stem, Some(&planted));
    assert_eq!(
        out[..2],
        [format!("MISMATCH cycle {k} column sdo: expected 0 got 1"), format!("{} passed, 1 failed", cycles - 1)],
        "{out:?}"
    );
    std::fs::remove_dir_all(&dir).ok();
}
