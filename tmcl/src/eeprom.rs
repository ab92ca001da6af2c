//! The module's EEPROM as a file: stored axis and global parameters, user variables,
//! coordinates and the TMCL program.
//!
//! Layout (all integers little-endian):
//! ```text
//! 0   8 bytes  "TMCLEEP2"
//! 8   u32      payload length N
//! 12  N bytes  payload
//! 12+N u32     CRC-32 (IEEE 802.3) of bytes 0 .. 12+N
//! payload: u8 module type (ModuleType::code: 0 TMCM-3110, 1 TMCM-1311)
//!        | 3 x A x i32 axis parameters | G x i32 bank-0 parameters (the module type's
//!          parameters with access E, in table order: config::Settings::stored_params)
//!        | 56 x i32 user variables | 3 x 21 x i32 coordinates
//!        | u32 program length L (<= 2048) | L x 7 bytes instructions (7-byte form)
//! ```
//! A file that fails any check is rejected as a whole: nothing of it is applied.

use crate::config::*;
use crate::personality::ModuleType;
use crate::proto::Instruction;
use std::fmt;
use std::path::Path;

const MAGIC: &[u8; 8] = b"TMCLEEP2";

/// Everything the EEPROM holds.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Image {
    pub axes: [AxisConfig; AXES],
    pub global: GlobalConfig,
    pub user_vars: [i32; STORED_USER_VARS],
    pub coords: [[i32; COORDS]; AXES],
    pub program: Vec<Instruction>,
}

impl Default for Image {
    fn default() -> Self {
        Image::factory(ModuleType::Tmcm3110)
    }
}

impl Image {
    /// Factory defaults of a module type.
    pub fn factory(kind: ModuleType) -> Self {
        Image {
            axes: [AxisConfig::axis(kind); AXES],
            global: GlobalConfig::global(kind),
            user_vars: [0; STORED_USER_VARS],
            coords: [[0; COORDS]; AXES],
            program: Vec::new(),
        }
    }
}

/// Why an EEPROM file was rejected.
#[derive(Debug)]
pub enum EepromError {
    Io(std::io::Error),
    Corrupt(String),
}

impl fmt::Display for EepromError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            EepromError::Io(e) => write!(f, "{e}"),
            EepromError::Corrupt(s) => write!(f, "corrupt EEPROM image: {s}"),
        }
    }
}

impl std::error::Error for EepromError {}

/// CRC-32 (IEEE 802.3, reflected, polynomial $EDB88320).
pub fn crc32(data: &[u8]) -> u32 {
    let mut crc = 0xffff_ffffu32;
    for &b in data {
        crc ^= b as u32;
        for _ in 0..8 {
            crc = if crc & 1 != 0 { (crc >> 1) ^ 0xedb8_8320 } else { crc >> 1 };
        }
    }
    !crc
}

/// The payload of an image file: after the signature and the length field, before the CRC-32,
/// each checked.
fn payload(b: &[u8]) -> Result<&[u8], EepromError> {
    let bad = |s: &str| Err(EepromError::Corrupt(s.to_string()));
    if b.len() < 16 {
        return bad(&format!("file has {} bytes, at least 16 expected", b.len()));
    }
    if &b[..8] != MAGIC {
        return bad("missing the \"TMCLEEP2\" signature at offset 0");
    }
    let n = u32::from_le_bytes([b[8], b[9], b[10], b[11]]) as usize;
    if b.len() != 12 + n + 4 {
        return bad(&format!("payload length field says {n} bytes, file size implies {}", b.len().saturating_sub(16)));
    }
    let stored = u32::from_le_bytes([b[12 + n], b[13 + n], b[14 + n], b[15 + n]]);
    let computed = crc32(&b[..12 + n]);
    if stored != computed {
        return bad(&format!("CRC-32 mismatch: stored ${stored:08x}, computed ${computed:08x}"));
    }
    Ok(&b[12..12 + n])
}

impl Image {
    pub fn encode(&self) -> Vec<u8> {
        let mut p = vec![self.global.kind().code()];
        let put = |p: &mut Vec<u8>, v: i32| p.extend_from_slice(&v.to_le_bytes());
        for a in &self.axes {
            for q in a.stored_params() {
                put(&mut p, a.get(q).unwrap_or(0));
            }
        }
        for q in self.global.stored_params() {
            put(&mut p, self.global.get(q).unwrap_or(0));
        }
        for v in self.user_vars {
            put(&mut p, v);
        }
        for a in &self.coords {
            for v in a {
                put(&mut p, *v);
            }
        }
        p.extend_from_slice(&(self.program.len() as u32).to_le_bytes());
        for i in &self.program {
            p.extend_from_slice(&i.to_bytes7());
        }
        let mut out = MAGIC.to_vec();
        out.extend_from_slice(&(p.len() as u32).to_le_bytes());
        out.extend_from_slice(&p);
        let c = crc32(&out);
        out.extend_from_slice(&c.to_le_bytes());
        out
    }

    pub fn decode(b: &[u8]) -> Result<Image, EepromError> {
        let bad = |s: &str| Err(EepromError::Corrupt(s.to_string()));
        let p = payload(b)?;
        let mut pos = 1usize;
        let code = p.first().copied().unwrap_or(0xff);
        let Some(kind) = ModuleType::from_code(code) else {
            return bad(&format!("unknown module type code {code} at offset 12"));
        };
        let mut img = Image::factory(kind);
        let (na, ng) = (img.axes[0].stored_params().count(), img.global.stored_params().count());
        let fixed = 1 + 4 * (AXES * na + ng + STORED_USER_VARS + AXES * COORDS) + 4;
        if p.len() < fixed {
            return bad(&format!("payload has {} bytes, at least {fixed} expected", p.len()));
        }
        let get = |pos: &mut usize| {
            let v = i32::from_le_bytes([p[*pos], p[*pos + 1], p[*pos + 2], p[*pos + 3]]);
            *pos += 4;
            v
        };
        img.read_stored(&mut || get(&mut pos)).map_err(EepromError::Corrupt)?;
        let len = get(&mut pos) as u32 as usize;
        if len > PROGRAM_SIZE {
            return bad(&format!("program length {len} exceeds the {PROGRAM_SIZE} instructions of program memory"));
        }
        if p.len() != fixed + 7 * len {
            return bad(&format!("program of {len} instructions needs {} payload bytes, found {}", fixed + 7 * len, p.len()));
        }
        for _ in 0..len {
            let mut s = [0u8; 7];
            s.copy_from_slice(&p[pos..pos + 7]);
            pos += 7;
            img.program.push(Instruction::from_bytes7(&s));
        }
        Ok(img)
    }

    /// The stored parameters, user variables and coordinates in the image's order, each word
    /// from `get`; an axis or the global parameters out of range is an error.
    fn read_stored(&mut self, get: &mut dyn FnMut() -> i32) -> Result<(), String> {
        for a in 0..AXES {
            for q in self.axes[a].stored_params() {
                let v = get();
                self.axes[a].set_raw(q, v);
            }
            if let Err(e) = self.axes[a].validate() {
                return Err(format!("axis {a}: {e}"));
            }
        }
        for q in self.global.stored_params() {
            let v = get();
            self.global.set_raw(q, v);
        }
        if let Err(e) = self.global.validate() {
            return Err(e);
        }
        for i in 0..STORED_USER_VARS {
            self.user_vars[i] = get();
        }
        for a in 0..AXES {
            for c in 0..COORDS {
                self.coords[a][c] = get();
            }
        }
        Ok(())
    }

    /// Loads a file: `Ok(None)` if it does not exist (factory defaults apply).
    pub fn load(path: &Path) -> Result<Option<Image>, EepromError> {
        match std::fs::read(path) {
            Ok(b) => Image::decode(&b).map(Some),
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => Ok(None),
            Err(e) => Err(EepromError::Io(e)),
        }
    }

    /// Writes the image atomically: the bytes go to `PATH.tmp`, are flushed to the disk, and the
    /// temporary file is renamed over `PATH`. A store that fails (a full disk, a read-only
    /// directory) removes the temporary file and leaves `PATH` as it was: the file holds either
    /// the old image or the new one, whole.
    pub fn save(&self, path: &Path) -> Result<(), EepromError> {
        use std::io::Write;
        let mut tmp = path.as_os_str().to_owned();
        tmp.push(".tmp");
        let tmp = std::path::PathBuf::from(tmp);
        let written = std::fs::File::create(&tmp).and_then(|mut f| {
            f.write_all(&self.encode())?;
            f.sync_all()
        });
        match written.and_then(|_| std::fs::rename(&tmp, path)) {
            Ok(()) => Ok(()),
            Err(e) => {
                let _ = std::fs::remove_file(&tmp);
                Err(EepromError::Io(e))
            }
        }
    }
}
