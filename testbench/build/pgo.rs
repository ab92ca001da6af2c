//! The profile of the Verilated models' profile-guided build (docs/performance.md,
//! "The profile-guided build of the Verilated RTL").
//!
//! clang compiles the untraced models of the three variants with `-fprofile-instr-generate`
//! and links them with cpp/pgo_train.cc; the training run replays the golden pin-level vectors
//! of each variant (vectors/golden, every set whose .meta says `unit chip`: registers,
//! chip-hold, reference search, the datasheet's example) on them, and `llvm-profdata` merges
//! the counts. The models are then compiled with `-fprofile-instr-use` of that profile: clang
//! lays out the one large function Verilator makes of each model's edge by how often each
//! branch was taken, which makes the edge about 10 % faster. The profile only guides the
//! compiler: the code computes the same, whatever the training ran.
//!
//! No profile (a cargo warning says why, and the models are compiled as before) when the
//! compiler is not clang, when no `llvm-profdata` of clang's version runs, or when a step of
//! the training fails; none and no warning with `TMC429_VL_PGO=0`.

use std::env;
use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;

/// The untraced model of each variant that the training run exercises, with the variant's
/// name in the vectors' .meta (`chip …`) and its number on pgo_train's command line.
const TRAINED: [(&str, &str, u32); 3] = [("Vtmc429_428", "tmc428", 0), ("Vtmc429_429", "tmc429", 1), ("Vtmc429_4210", "tmc4210", 2)];

/// What the profile is made with.
pub struct Training<'a> {
    /// clang++, the models' compiler
    pub cxx: &'a str,
    /// the models' build (flags, includes, defines) without its files
    pub build: cc::Build,
    /// Verilator's output directory
    pub mdir: &'a Path,
    /// vectors/golden
    pub golden: &'a Path,
    /// the generated .cpp files of a model prefix
    pub sources: &'a dyn Fn(&str) -> Vec<PathBuf>,
    /// Verilator's runtime sources
    pub runtime: &'a [PathBuf],
}

/// A profile and the sources it applies to.
pub struct Profile {
    /// the merged profile (`-fprofile-instr-use=`)
    pub path: PathBuf,
    /// the generated sources of the trained models: only these are compiled with the profile
    /// (Verilator's runtime, whose trace writer the training never calls, and the traced
    /// models without it)
    pub sources: Vec<PathBuf>,
}

/// The profile to compile the trained models with, or `None` (with a cargo warning unless
/// turned off).
pub fn profile(t: &Training) -> Option<Profile> {
    println!("cargo:rerun-if-env-changed=TMC429_VL_PGO");
    if env::var("TMC429_VL_PGO").is_ok_and(|v| v == "0") {
        return None;
    }
    let sources: Vec<PathBuf> = TRAINED.iter().flat_map(|(prefix, _, _)| (t.sources)(prefix)).collect();
    match make(t, &sources) {
        Ok(path) => Some(Profile { path, sources }),
        Err(why) => {
            println!(
                "cargo:warning=the Verilated RTL is compiled without a profile ({why}): about 10 % slower \
                 (scripts/setup installs llvm; TMC429_VL_PGO=0 turns the profile off)"
            );
            None
        }
    }
}

/// The merged profile of the training run on the models compiled from `sources`.
fn make(t: &Training, sources: &[PathBuf]) -> Result<PathBuf, String> {
    let profdata = llvm_profdata(t.cxx)?;
    let dir = t.mdir.with_file_name("pgo");
    let _ = fs::remove_dir_all(&dir);
    fs::create_dir_all(&dir).map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
    let mut args = Vec::new();
    for (_, chip, code) in TRAINED {
        let pins = dir.join(format!("train-{chip}.pins"));
        let (words, read) = crate::pgo_pins::training_pins(t.golden, chip)?;
        for f in std::iter::once(t.golden.to_path_buf()).chain(read) {
            println!("cargo:rerun-if-changed={}", f.display());
        }
        fs::write(&pins, words).map_err(|e| format!("cannot write {}: {e}", pins.display()))?;
        args.push(code.to_string());
        args.push(pins.display().to_string());
    }
    let exe = instrumented_trainer(t, sources, &dir)?;
    let raw = dir.join("train.profraw");
    run(Command::new(&exe).args(&args).env("LLVM_PROFILE_FILE", &raw), "the training run")?;
    let merged = dir.join("rtl.profdata");
    run(Command::new(&profdata).arg("merge").arg("-o").arg(&merged).arg(&raw), "llvm-profdata merge")?;
    Ok(merged)
}

/// The trained models (`sources`), Verilator's runtime and cpp/pgo_train.cc compiled with
/// `-fprofile-instr-generate` into `dir/obj`, linked as `dir/pgo_train`.
fn instrumented_trainer(t: &Training, sources: &[PathBuf], dir: &Path) -> Result<PathBuf, String> {
    println!("cargo:rerun-if-changed=cpp/pgo_train.cc");
    let mut b = t.build.clone();
    b.out_dir(dir.join("obj")).flag("-fprofile-instr-generate").include("cpp").file("cpp/pgo_train.cc").files(t.runtime).files(sources);
    let objects = b.try_compile_intermediates().map_err(|e| format!("the instrumented models do not compile: {e}"))?;
    let exe = dir.join("pgo_train");
    run(
        Command::new(t.cxx).arg("-fprofile-instr-generate").args(&objects).arg("-o").arg(&exe).args(["-lpthread", "-latomic"]),
        "linking the instrumented models",
    )?;
    Ok(exe)
}

/// Runs `cmd`; `what` names it in the error.
fn run(cmd: &mut Command, what: &str) -> Result<(), String> {
    let out = cmd.output().map_err(|e| format!("{what}: {e}"))?;
    if out.status.success() {
        Ok(())
    } else {
        let err = String::from_utf8_lossy(&out.stderr);
        Err(format!("{what} failed: {}", err.lines().next().unwrap_or("no message")))
    }
}

/// `llvm-profdata-N` or `llvm-profdata` of the major version N of clang `cxx`.
fn llvm_profdata(cxx: &str) -> Result<String, String> {
    let version = super::version(cxx).unwrap_or_default();
    let major = version
        .split("clang version ")
        .nth(1)
        .and_then(|v| v.split('.').next())
        .ok_or_else(|| format!("`{cxx} --version` names no clang version"))?
        .to_string();
    for name in [format!("llvm-profdata-{major}"), "llvm-profdata".to_string()] {
        // `llvm-profdata --version` alone is an error; a command's `--version` prints LLVM's
        let v = Command::new(&name).args(["merge", "--version"]).output();
        if v.is_ok_and(|o| o.status.success() && String::from_utf8_lossy(&o.stdout).contains(&format!("LLVM version {major}."))) {
            return Ok(name);
        }
    }
    Err(format!("no llvm-profdata of clang {major}"))
}
