//! The RTL's frame schedule comes from the model's lanes (docs/model-contract.md C41):
//! `rtl/tmc429_schedule.vh` is the rendering of `model/src/schedule.rs` (`tmc429 regmap --format
//! verilog-schedule`), and no RTL source decodes a phase of the frame with a number of its own.

mod common;

use common::rtl::{self, starts_with_number};
use tmc429_model::schedule_verilog;

#[test]
fn the_rtl_header_is_the_frame_schedule() {
    let file = rtl::header("tmc429_schedule.vh");
    assert!(file == schedule_verilog::header(), "rtl/tmc429_schedule.vh is stale: run `{}`", schedule_verilog::REGENERATE);
}

/// Signals that carry the frame's phase (prescaler[4:0], or the phase after an edge).
const PHASE_SIGNALS: &[&str] = &["ph", "phase", "phase_nx", "prescaler[4:0]"];

/// The lines of `text` that compare a phase signal with a number, or label a `case` on one with
/// numbers: (line number from 1, the line).
fn literal_phases(text: &str) -> Vec<(usize, String)> {
    let mut found = Vec::new();
    let mut in_phase_case = false;
    for (n, line) in text.lines().enumerate() {
        let code = rtl::code_of(line);
        let t = code.trim_start();
        if t.starts_with("case") {
            in_phase_case = PHASE_SIGNALS.iter().any(|s| t.contains(&format!("({s})")));
        } else if t.starts_with("endcase") {
            in_phase_case = false;
        }
        let compare = PHASE_SIGNALS.iter().any(|s| {
            code.match_indices(s).any(|(i, _)| {
                let before = code[..i].chars().next_back();
                let ident = |c: char| c.is_ascii_alphanumeric() || c == '_';
                let r = code[i + s.len()..].trim_start();
                !before.is_some_and(ident)
                    && !r.starts_with(ident)
                    && (r.starts_with("==") || r.starts_with("!=") || r.starts_with(">=") || r.starts_with("<="))
                    && starts_with_number(&r[2..])
            })
        });
        let label = in_phase_case && !t.starts_with("case") && t.split(':').next().is_some_and(starts_with_number);
        if compare || label {
            found.push((n + 1, line.trim().to_string()));
        }
    }
    found
}

#[test]
fn the_rtl_decodes_phases_through_the_header_names() {
    let bad = rtl::lines_found(literal_phases);
    assert!(bad.is_empty(), "frame phase with a number instead of a name of rtl/tmc429_schedule.vh:\n{}", bad.join("\n"));
}

/// The forms of the schedule decode the RTL had before the header, each caught; a name of the
/// header and other signals are not.
#[test]
fn hand_written_phases_are_found() {
    let old = "\
    wire ph_ramp_nx  = ~pd_nx & (run ? (ph == 5'd15) : (ph == 5'd16));
    case (phase_nx)
    5'd0:  begin n_a_snap = 1'b1; n_a_m = 2'd0; end
    5'd1, 5'd8, 5'd15: n_a_c = 1'b1;
    default: ;
    endcase
    if (phase == 5'd14) commit = 1'b1;
";
    let lines: Vec<usize> = literal_phases(old).into_iter().map(|(n, _)| n).collect();
    assert_eq!(lines, vec![1, 3, 4, 7]);
    let new = "\
    wire ph_ramp_nx  = run ? (ph == PH_RAMP - 5'd1) : (ph == PH_RAMP);
    if (phase_nx == `TMC429_PH_COMMIT(mm))
    if (graph == 5'd3) x = 1'b1;
    case (jdx)
    4'd0: y = 1'b1;
    endcase
";
    assert!(literal_phases(new).is_empty());
}
