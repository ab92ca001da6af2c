//! Builds the Verilated RTL models and the cxx bridge (docs/cosim.md).
//!
//! For each variant, Debian's `verilator --cc` translates rtl/tmc429_*.v into C++ (one model
//! per CHIP value, plus a model with a planted bug for the harness self-test), twice: once
//! without tracing, the model every run uses, and once with `--trace` (prefix `…_tr`), the model
//! of the runs that write Verilator's VCD. Without `--trace` Verilator keeps the intermediate
//! signals in locals instead of the traced model state, which makes the cycle about 10 % faster
//! (docs/performance.md). The generated C++ and Verilator's runtime are compiled with clang++ at
//! -O2 when there is one (`clang++`, `clang++-N`): for the one large straight-line function
//! Verilator makes of this design, its code runs about 25 % faster than GCC's best (-O1; GCC's
//! -O2 is slower still), which is what brings the lock-step pair to its 3 M cycles/s. Without
//! clang the models are compiled with the default C++ compiler at -O1 and a cargo warning says
//! so. `TMC429_VL_CXX` names the compiler instead (at -O2 if it is a clang, else at -O1). The
//! bridge (cpp/rtl_bridge.cc) is compiled with cxx-build at -O2; all of it also in debug builds.
//!
//! With clang the untraced models are compiled with a profile (build/pgo.rs): instrumented
//! models replay the golden pin-level vectors first, and clang lays out each model's edge by
//! the branches they took, about 10 % faster again. `TMC429_VL_PGO=0` turns it off.
//!
//! The bridge applies the untraced models' CLK edges without Verilator's eval loop where the
//! generated code allows it (build/vl_edge.rs): about 5 % faster again.
//!
//! Without the default feature `rtl` (the Python package builds the crate so, python/) nothing
//! of the RTL is built, as without Verilator but without a warning.
//!
//! Without Verilator (`verilator` not on PATH, or `VERILATOR` naming a program that does not
//! run) the crate builds without the RTL: a cargo warning says so and the cfg `tmc429_no_rtl`
//! leaves out the cxx bridge; `Rtl::try_new` then returns the error `rtl::MISSING` and the
//! commands that need the RTL exit 2 with it (src/rtl.rs). The golden model, the vectors and
//! `--engine model` work as before.

use std::env;
use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;

#[path = "build/pgo.rs"]
mod pgo;
#[path = "build/pgo_pins.rs"]
mod pgo_pins;
#[path = "build/vl_edge.rs"]
mod vl_edge;

use vl_edge::EdgeForm;

/// (prefix, CHIP parameter, extra Verilog defines); each is built as `prefix` (no trace) and
/// `prefix_tr` (`--trace`).
const VARIANTS: &[(&str, u32, &[&str])] =
    &[("Vtmc429_428", 0, &[]), ("Vtmc429_429", 1, &[]), ("Vtmc429_4210", 2, &[]), ("Vtmc429_429_bug_status", 1, &["PLANT_BUG_STATUS"])];

const VERILATOR_INCLUDE: &str = "/usr/share/verilator/include";

fn main() {
    println!("cargo:rustc-check-cfg=cfg(tmc429_no_rtl)");
    println!("cargo:rerun-if-env-changed=VERILATOR");
    if env::var_os("CARGO_FEATURE_RTL").is_none() {
        // Built without the feature `rtl` (the Python package, python/): no RTL on purpose.
        println!("cargo:rustc-cfg=tmc429_no_rtl");
        return;
    }
    let verilator = env::var("VERILATOR").unwrap_or_else(|_| "verilator".into());
    if !runs(&verilator) {
        no_rtl(&verilator);
        return;
    }
    let manifest = PathBuf::from(env::var("CARGO_MANIFEST_DIR").unwrap());
    let rtl_dir = manifest.join("../rtl");
    let out = PathBuf::from(env::var("OUT_DIR").unwrap());
    let mdir = out.join("vl");
    // stale files of an older RTL (other module hashes) would be compiled in as well
    let _ = fs::remove_dir_all(&mdir);
    fs::create_dir_all(&mdir).expect("create Verilator output directory");

    let sources = rtl_sources(&rtl_dir);
    let (generated, edges) = verilate(&verilator, &rtl_dir, &mdir, &sources);
    let compiler = model_compiler();
    let profile = match &compiler.cxx {
        Some(cxx) if compiler.clang => pgo::profile(&pgo::Training {
            cxx,
            build: model_build(&compiler, &mdir, &edges),
            mdir: &mdir,
            golden: &manifest.join("../vectors/golden"),
            sources: &|prefix| generated_sources(&mdir, prefix),
            runtime: &runtime_sources(),
        }),
        _ => None,
    };
    let objects = compile_models(&compiler, &generated, &mdir, &edges, profile.as_ref());
    compile_bridge(&objects, &mdir, &edges);
    println!("cargo:rustc-link-lib=pthread");
    if compiler.clang {
        // clang calls libatomic where GCC inlines (Verilator's runtime: `__atomic_is_lock_free`)
        println!("cargo:rustc-link-lib=atomic");
    }
}

/// The defines Verilator's models and runtime are compiled with.
const VL_DEFINES: [(&str, &str); 6] =
    [("VM_COVERAGE", "0"), ("VM_SC", "0"), ("VM_TRACE", "1"), ("VM_TRACE_VCD", "1"), ("VM_TRACE_FST", "0"), ("VM_TIMING", "0")];

/// The RTL's module files (`rtl/tmc429_*.v`, sorted), with the files a change of which rebuilds.
fn rtl_sources(rtl_dir: &Path) -> Vec<PathBuf> {
    let mut sources: Vec<PathBuf> = fs::read_dir(rtl_dir)
        .unwrap_or_else(|e| panic!("cannot read {}: {e}", rtl_dir.display()))
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "v") && p.file_name().is_some_and(|n| n.to_string_lossy().starts_with("tmc429_")))
        .collect();
    sources.sort();
    println!("cargo:rerun-if-changed={}", rtl_dir.display());
    for s in &sources {
        println!("cargo:rerun-if-changed={}", s.display());
    }
    // the register map and the frame schedule the sources include (`include "tmc429_regmap.vh"`,
    // `include "tmc429_schedule.vh"`, found through -I)
    println!("cargo:rerun-if-changed={}", rtl_dir.join("tmc429_regmap.vh").display());
    println!("cargo:rerun-if-changed={}", rtl_dir.join("tmc429_schedule.vh").display());
    println!("cargo:rerun-if-changed=cpp/rtl_bridge.h");
    println!("cargo:rerun-if-changed=cpp/rtl_bridge.cc");
    println!("cargo:rerun-if-changed=cpp/vl_pins.h");
    println!("cargo:rerun-if-changed=src/rtl.rs");
    sources
}

/// Verilates every variant, untraced and traced, into `mdir`: the generated C++ files, and
/// how the bridge may apply the CLK edges to the untraced models (build/vl_edge.rs).
fn verilate(verilator: &str, rtl_dir: &Path, mdir: &Path, sources: &[PathBuf]) -> (Vec<PathBuf>, EdgeForm) {
    let mut generated = Vec::new();
    for (base, chip, defines) in VARIANTS {
        for traced in [false, true] {
            let prefix = if traced { format!("{base}_tr") } else { base.to_string() };
            let mut cmd = Command::new(verilator);
            cmd.arg("--cc");
            if traced {
                cmd.arg("--trace");
            }
            cmd.args(["-O3", "-Wno-fatal", "--x-assign", "fast", "--x-initial", "fast", "--top-module", "tmc429_top"])
                .arg(format!("-GCHIP={chip}"))
                .arg("--prefix")
                .arg(&prefix)
                .arg("-Mdir")
                .arg(mdir)
                .arg(format!("-I{}", rtl_dir.display()));
            for d in *defines {
                cmd.arg(format!("-D{d}"));
            }
            cmd.args(sources);
            let status = cmd.status().unwrap_or_else(|e| panic!("cannot run `{verilator}` ({e}); install Verilator 5 (scripts/setup)"));
            assert!(status.success(), "verilator failed for {prefix}");
            generated.extend(generated_sources(mdir, &prefix));
        }
    }
    let untraced: Vec<&str> = VARIANTS.iter().map(|(base, _, _)| *base).collect();
    (generated, EdgeForm::of(mdir, &untraced))
}

/// The models and Verilator's runtime with clang++ at -O2 (the trained models with their
/// `profile`, if there is one), else at -O1 (see the top of this file), as objects of the
/// bridge's library.
fn compile_models(
    compiler: &ModelCompiler,
    generated: &[PathBuf],
    mdir: &Path,
    edges: &EdgeForm,
    profile: Option<&pgo::Profile>,
) -> Vec<PathBuf> {
    if compiler.cxx.is_none() {
        println!(
            "cargo:warning=clang++ not found: the Verilated RTL is compiled with the default C++ compiler at -O1, \
             about 20 % slower than with clang++ -O2 (scripts/setup installs clang; TMC429_VL_CXX names a compiler)"
        );
        // installing clang brings it in with the next build
        rerun_on_path();
    }
    let trained = |g: &PathBuf| profile.is_some_and(|p| p.sources.contains(g));
    let mut objects = Vec::new();
    if let Some(p) = profile {
        let mut models = model_build(compiler, mdir, edges);
        models.files(generated.iter().filter(|g| trained(g))).flag(format!("-fprofile-instr-use={}", p.path.display()));
        objects.extend(models.compile_intermediates());
    }
    let mut rest = model_build(compiler, mdir, edges);
    rest.files(generated.iter().filter(|g| !trained(g))).files(runtime_sources());
    objects.extend(rest.compile_intermediates());
    objects
}

/// Verilator's runtime sources that the models are linked with.
fn runtime_sources() -> Vec<PathBuf> {
    let inc = Path::new(VERILATOR_INCLUDE);
    ["verilated.cpp", "verilated_threads.cpp", "verilated_vcd_c.cpp"].iter().map(|f| inc.join(f)).collect()
}

/// The models' compiler with its flags, includes and defines, without files.
fn model_build(compiler: &ModelCompiler, mdir: &Path, edges: &EdgeForm) -> cc::Build {
    let inc = Path::new(VERILATOR_INCLUDE);
    let mut models = cc::Build::new();
    if let Some(cxx) = &compiler.cxx {
        models.compiler(cxx);
    }
    models
        .cpp(true)
        .include(mdir)
        .include(inc)
        .include(inc.join("vltstd"))
        .std("c++17")
        .opt_level(if compiler.clang { 2 } else { 1 })
        .debug(false)
        .warnings(false)
        .flag_if_supported("-faligned-new")
        .flag_if_supported("-fno-math-errno");
    for (k, v) in VL_DEFINES {
        models.define(k, v);
    }
    for (k, v) in edges.defines() {
        models.define(k, v);
    }
    models
}

/// The cxx bridge (src/rtl.rs, cpp/rtl_bridge.cc) with the models' objects, as the library
/// `tmc429_vrtl`.
fn compile_bridge(objects: &[PathBuf], mdir: &Path, edges: &EdgeForm) {
    let inc = Path::new(VERILATOR_INCLUDE);
    let mut build = cxx_build::bridge("src/rtl.rs");
    build
        .file("cpp/rtl_bridge.cc")
        .objects(objects)
        .include(mdir)
        .include(inc)
        .include(inc.join("vltstd"))
        .std("c++17")
        .opt_level(2)
        .debug(false)
        .warnings(false)
        .flag_if_supported("-faligned-new")
        .flag_if_supported("-fno-math-errno");
    for (k, v) in VL_DEFINES {
        build.define(k, v);
    }
    for (k, v) in edges.defines() {
        build.define(k, v);
    }
    build.compile("tmc429_vrtl");
}

/// The C++ compiler of the Verilated models.
struct ModelCompiler {
    /// the program; `None`: the cc crate's default (`CXX`, else c++)
    cxx: Option<String>,
    /// whether it is clang (compiled at -O2 and linked with libatomic; any other at -O1)
    clang: bool,
}

/// `TMC429_VL_CXX` if set, else the first of `clang++`, `clang++-20` … `clang++-14` that runs,
/// else the default.
fn model_compiler() -> ModelCompiler {
    println!("cargo:rerun-if-env-changed=TMC429_VL_CXX");
    if let Ok(cxx) = env::var("TMC429_VL_CXX") {
        let version = version(&cxx).unwrap_or_else(|| panic!("TMC429_VL_CXX names `{cxx}`, which does not run (`{cxx} --version`)"));
        let clang = version.contains("clang");
        return ModelCompiler { cxx: Some(cxx), clang };
    }
    let names = std::iter::once("clang++".to_string()).chain((14..=20).rev().map(|v| format!("clang++-{v}")));
    for name in names {
        if runs(&name) {
            return ModelCompiler { cxx: Some(name), clang: true };
        }
    }
    ModelCompiler { cxx: None, clang: false }
}

/// Whether `program --version` runs.
fn runs(program: &str) -> bool {
    version(program).is_some()
}

/// What `program --version` prints, if it runs.
fn version(program: &str) -> Option<String> {
    let o = Command::new(program).arg("--version").stderr(std::process::Stdio::null()).output().ok()?;
    o.status.success().then(|| String::from_utf8_lossy(&o.stdout).into_owned())
}

/// A build without the RTL: the warning, the cfg, and a rerun when a program appears on PATH
/// (so that installing Verilator brings the RTL in with the next build).
fn no_rtl(verilator: &str) {
    println!(
        "cargo:warning=Verilator not found (`{verilator} --version` does not run): building without the RTL; \
         `--engine model` works, the co-simulation and `--engine rtl|cosim` need Verilator 5: \
         install it with scripts/setup (Debian: apt-get install verilator)"
    );
    println!("cargo:rustc-cfg=tmc429_no_rtl");
    rerun_on_path();
}

/// A rerun of the build script when a program appears on PATH.
fn rerun_on_path() {
    if let Some(path) = env::var_os("PATH") {
        for dir in env::split_paths(&path).filter(|d| d.is_dir()) {
            println!("cargo:rerun-if-changed={}", dir.display());
        }
    }
    println!("cargo:rerun-if-env-changed=PATH");
}

/// The .cpp files Verilator generated for one prefix.
fn generated_sources(mdir: &Path, prefix: &str) -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = fs::read_dir(mdir)
        .expect("read Verilator output")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| {
            let name = p.file_name().unwrap().to_string_lossy().into_owned();
            name.ends_with(".cpp")
                && (name == format!("{prefix}.cpp")
                    || name.starts_with(&format!("{prefix}__"))
                    || name.starts_with(&format!("{prefix}___")))
        })
        .collect();
    v.sort();
    v
}
