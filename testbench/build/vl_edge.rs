//! How the bridge applies a CLK edge to an untraced model (cpp/vl_pins.h), decided from the C++
//! Verilator generated for it (docs/performance.md, "The rising edge without the eval loop").
//!
//! A model's `eval()` runs Verilator's scheduling loop: it forms the triggers (the posedge of
//! clk from clk and its previous value), runs the always blocks of each trigger, and loops
//! until no trigger fires. Every always block of rtl/ is clocked by the rising edge of clk
//! alone and no signal follows an input pin combinationally between edges (Verilator's
//! input-combinational region is empty), so Verilator 5.006 makes of the whole design one
//! function run on that trigger (`…___nba_sequent__TOP__0`), and an eval at the rising edge
//! runs exactly that function once. The bridge then calls it directly, without the loop
//! around it; the falling edge only records the clock's level. Both are taken only where the
//! generated code has exactly that form, checked here for every untraced model; for any other
//! form (another Verilator, a signal that follows an input between edges, a second clock) the
//! bridge calls `eval()` as for the traced models.

use std::fs;
use std::path::Path;

/// The edge forms every untraced model of `prefixes` allows.
pub struct EdgeForm {
    /// the model keeps clk's previous level in `__Vtrigrprev__TOP__clk` (the falling edge
    /// sets it without an eval): `TMC429_VL_TRIGRPREV`
    pub trigger_flag: bool,
    /// the rising edge is one call of `…___nba_sequent__TOP__0`: `TMC429_VL_DIRECT_EDGE`
    pub direct_posedge: bool,
}

impl EdgeForm {
    /// The forms of the untraced models `prefixes`, generated into `mdir`.
    pub fn of(mdir: &Path, prefixes: &[&str]) -> EdgeForm {
        let trigger_flag = prefixes.iter().all(|p| has_trigger_flag(mdir, p));
        let direct_posedge = trigger_flag && prefixes.iter().all(|p| one_posedge_function(mdir, p));
        if !direct_posedge {
            println!(
                "cargo:warning=the Verilated RTL's rising edge runs through Verilator's eval loop (its generated code \
                 is not the one-function form of Verilator 5.006, build/vl_edge.rs): about 5 % slower"
            );
        }
        EdgeForm { trigger_flag, direct_posedge }
    }

    /// The C++ defines of the forms.
    pub fn defines(&self) -> [(&'static str, &'static str); 2] {
        let b = |v: bool| if v { "1" } else { "0" };
        [("TMC429_VL_TRIGRPREV", b(self.trigger_flag)), ("TMC429_VL_DIRECT_EDGE", b(self.direct_posedge))]
    }
}

/// Whether the model `prefix` keeps the previous value of `clk` for its edge detection in the
/// member `__Vtrigrprev__TOP__clk` of its root class (Verilator 5.006; other versions name it
/// otherwise, and the bridge then evaluates the falling edge like any other).
fn has_trigger_flag(mdir: &Path, prefix: &str) -> bool {
    fs::read_to_string(mdir.join(format!("{prefix}___024root.h"))).is_ok_and(|h| h.contains("CData/*0:0*/ __Vtrigrprev__TOP__clk;"))
}

/// Whether the eval of model `prefix` is the one posedge-of-clk trigger running the one
/// function `…___nba_sequent__TOP__0`: one trigger in each region, formed from clk alone, no
/// work in the active region, the one function in the NBA region, and no input-combinational
/// region.
fn one_posedge_function(mdir: &Path, prefix: &str) -> bool {
    let root = format!("{prefix}___024root");
    let Ok(header) = fs::read_to_string(mdir.join(format!("{root}.h"))) else { return false };
    let one_trigger = ["VlTriggerVec<1> __VactTriggered;", "VlTriggerVec<1> __VnbaTriggered;"].iter().all(|d| header.contains(d));
    let src = dep_sets(mdir, &root);
    let stmts = |f: &str| body(&src, &format!("void {root}___{f}({root}* vlSelf) {{")).map(|b| statements(&b));
    let act_trigger = "vlSelf->__VactTriggered.at(0U)=((IData)(vlSelf->clk)&(~(IData)(vlSelf->__Vtrigrprev__TOP__clk)));\
                       vlSelf->__Vtrigrprev__TOP__clk=vlSelf->clk;";
    let nba = format!("if(vlSelf->__VnbaTriggered.at(0U)){{{root}___nba_sequent__TOP__0(vlSelf);}}");
    one_trigger
        && !src.contains("nba_sequent__TOP__1")
        && stmts("eval_triggers__act").as_deref() == Some(act_trigger)
        && stmts("eval_act").as_deref() == Some("")
        && stmts("eval_nba").as_deref() == Some(nba.as_str())
        && stmts("eval").is_some_and(|e| !e.contains("ico"))
}

/// The generated sources of the root class `root` that hold its eval functions (not the
/// `__Slow` ones of construction and settling), one after the other.
fn dep_sets(mdir: &Path, root: &str) -> String {
    let Ok(dir) = fs::read_dir(mdir) else { return String::new() };
    let mut names: Vec<String> = dir
        .filter_map(|e| e.ok().map(|e| e.file_name().to_string_lossy().into_owned()))
        .filter(|n| n.starts_with(&format!("{root}__DepSet_")) && n.ends_with(".cpp") && !n.contains("__Slow"))
        .collect();
    names.sort();
    names.iter().filter_map(|n| fs::read_to_string(mdir.join(n)).ok()).collect::<Vec<_>>().join("\n")
}

/// The lines of the function that starts with the line `head`, up to its closing `}` at the
/// start of a line; `None` if there is no such function.
fn body(src: &str, head: &str) -> Option<String> {
    let start = src.lines().position(|l| l == head)?;
    let lines: Vec<&str> = src.lines().skip(start + 1).take_while(|l| *l != "}").collect();
    Some(lines.join("\n"))
}

/// A function body's statements without whitespace: no comments, no preprocessor blocks (the
/// generated code's `#ifdef VL_DEBUG`), no `VL_DEBUG_IF`, unused-variable guard or symbol
/// table local.
fn statements(body: &str) -> String {
    let mut out = String::new();
    let mut in_if = 0;
    for l in body.lines().map(str::trim) {
        if l.starts_with("#if") {
            in_if += 1;
        } else if l.starts_with("#endif") {
            in_if -= 1;
        } else if in_if == 0
            && !l.starts_with("//")
            && !l.starts_with("VL_DEBUG_IF")
            && !l.starts_with("if (false && vlSelf)")
            && !l.contains("* const __restrict vlSymsp")
        {
            out.extend(l.chars().filter(|c| !c.is_whitespace()));
        }
    }
    out
}
