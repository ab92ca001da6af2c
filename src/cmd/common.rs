//! Options shared by the subcommands (ARCHITECTURE.md, command line).

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

fn parse_chip(s: &str) -> Result<Chip, String> {
    s.parse()
}

fn parse_fclk(s: &str) -> Result<u64, String> {
    let t = s.trim();
    let (num, mult) = if let Some(n) = t.strip_suffix("MHz").or_else(|| t.strip_suffix("M")) {
        (n, 1e6)
    } else if let Some(n) = t.strip_suffix("kHz").or_else(|| t.strip_suffix("k")) {
        (n, 1e3)
    } else {
        (t.strip_suffix("Hz").unwrap_or(t), 1.0)
    };
    let v: f64 = num.trim().parse().map_err(|_| format!("expected a frequency in Hz (e.g. 16000000 or 16MHz), found '{s}'"))?;
    let hz = v * mult;
    if !(1.0..=1e9).contains(&hz) {
        return Err(format!("frequency {s} out of range (1 Hz .. 1 GHz)"));
    }
    Ok(hz.round() as u64)
}

/// Reads a file argument, or standard input for `-` / none. Returns (name for messages, text).
pub fn read_input(path: Option<&std::path::Path>) -> Result<(String, String), crate::UserError> {
    use std::io::Read;
    match path {
        Some(p) if p.as_os_str() != "-" => {
            let text = std::fs::read_to_string(p)
                .map_err(|e| crate::UserError(format!("{}: cannot read: {e}", p.display())))?;
            Ok((p.display().to_string(), text))
        }
        _ => {
            let mut s = String::new();
            std::io::stdin()
                .read_to_string(&mut s)
                .map_err(|e| crate::UserError(format!("<stdin>: cannot read: {e}")))?;
            Ok(("<stdin>".to_string(), s))
        }
    }
}
