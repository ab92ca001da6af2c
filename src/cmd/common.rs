//! Pieces shared by the subcommands: the chip options (`--chip`, `--fclk`, `--package`), reading an
//! input file, the progress line.

use clap::Args;
use tmc429_model::Chip;

#[derive(Args, Clone, Debug)]
pub struct ChipArgs {
    /// Chip variant: tmc428, tmc429 or tmc4210.
    #[arg(long, default_value = "tmc429", value_parser = parse_chip)]
    pub chip: Chip,
    /// CLK frequency in Hz (default: 16 MHz for the TMC428, 32 MHz otherwise).
    #[arg(long, value_parser = parse_fclk)]
    pub fclk: Option<u64>,
}

impl ChipArgs {
    /// The CLK frequency: `--fclk`, or the variant's default.
    #[allow(dead_code)] // used by the subcommands that report time
    pub fn fclk(&self) -> u64 {
        self.fclk.unwrap_or_else(|| self.chip.default_fclk())
    }
}

pub fn parse_chip(s: &str) -> Result<Chip, String> {
    s.parse()
}

pub fn parse_package(s: &str) -> Result<tmc429_model::Package, String> {
    s.parse()
}

/// The chip in `package` (docs/model-contract.md C90), or in its full package.
pub fn chip_in(chip: Chip, package: Option<tmc429_model::Package>) -> Result<tmc429_model::Tmc429, crate::UserError> {
    match package {
        Some(p) => tmc429_model::Tmc429::with_package(chip, p).map_err(|e| crate::UserError(format!("--package: {e}"))),
        None => Ok(tmc429_model::Tmc429::new(chip)),
    }
}

pub fn parse_fclk(s: &str) -> Result<u64, String> {
    let t = s.trim();
    let (num, mult) = if let Some(n) = t.strip_suffix("MHz").or_else(|| t.strip_suffix("M")) {
        (n, 1e6)
    } else if let Some(n) = t.strip_suffix("kHz").or_else(|| t.strip_suffix("k")) {
        (n, 1e3)
    } else {
        (t.strip_suffix("Hz").unwrap_or(t), 1.0)
    };
    let v: f64 = num
        .trim()
        .parse()
        .map_err(|_| format!("expected a frequency in Hz (e.g. 16000000 or 16MHz), found '{}'", tmc429_model::text::shown(s)))?;
    let hz = v * mult;
    if !(1.0..=1e9).contains(&hz) {
        return Err(format!("frequency {s} out of range (1 Hz .. 1 GHz)"));
    }
    Ok(hz.round() as u64)
}

/// Reads a file argument, or standard input for `-` / none. Returns (name for messages, text).
/// Input that is not UTF-8 is an error naming the line and byte offset of the first bad byte.
pub fn read_input(path: Option<&std::path::Path>) -> Result<(String, String), crate::UserError> {
    use std::io::Read;
    use tmc429_model::text;
    match path {
        Some(p) if p.as_os_str() != "-" => {
            let text = text::read_file(p).map_err(crate::UserError)?;
            Ok((p.display().to_string(), text))
        }
        _ => {
            let mut b = Vec::new();
            std::io::stdin().read_to_end(&mut b).map_err(|e| crate::UserError(format!("<stdin>: cannot read: {e}")))?;
            let text = text::utf8(b).map_err(|e| crate::UserError(format!("<stdin>:{e}")))?;
            Ok(("<stdin>".to_string(), text))
        }
    }
}

/// Progress of a long run on stderr: shown only when stderr is a terminal and the run has
/// taken more than a second; the line is cleared at the end.
pub struct Progress {
    label: String,
    start: std::time::Instant,
    last: Option<std::time::Instant>,
    tty: bool,
}

impl Progress {
    pub fn new(label: &str) -> Progress {
        use std::io::IsTerminal;
        Progress { label: label.to_string(), start: std::time::Instant::now(), last: None, tty: std::io::stderr().is_terminal() }
    }

    /// `done` of `total` CLK cycles.
    pub fn update(&mut self, done: u64, total: u64) {
        if !self.tty {
            return;
        }
        let now = std::time::Instant::now();
        let t = now.duration_since(self.start).as_secs_f64();
        if t < 1.0 || self.last.is_some_and(|l| now.duration_since(l).as_millis() < 200) {
            return;
        }
        self.last = Some(now);
        let pct = if total == 0 { 100.0 } else { 100.0 * done as f64 / total as f64 };
        eprint!("\r{}: {pct:5.1} % ({done} of {total} cycles, {t:.1} s)\x1b[K", self.label);
    }

    pub fn finish(&mut self) {
        if self.tty && self.last.is_some() {
            eprint!("\r\x1b[K");
        }
    }
}

/// Checks that an output file can be created (before a long run), without leaving it behind.
pub fn check_output(opt: &str, p: &std::path::Path) -> Result<(), crate::UserError> {
    let dir = match p.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => std::path::PathBuf::from("."),
    };
    if !dir.is_dir() {
        return Err(crate::UserError(format!("{opt} {}: directory {} does not exist", p.display(), dir.display())));
    }
    let probe = tmc429_testbench::vectors::files::tmp_path(p);
    std::fs::File::create(&probe).map_err(|e| crate::UserError(format!("{opt} {}: cannot write: {e}", p.display())))?;
    let _ = std::fs::remove_file(&probe);
    Ok(())
}
