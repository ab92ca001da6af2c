//! Output files that appear only when complete: written to a temporary name beside the target
//! and renamed by [`commit_all`]; dropped without a commit, the temporary file is removed.

use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

pub struct AtomicFile {
    path: PathBuf,
    tmp: PathBuf,
    file: Option<BufWriter<File>>,
}

impl AtomicFile {
    pub fn create(path: &Path) -> Result<AtomicFile, String> {
        let name = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
        let tmp = path.with_file_name(format!(".{name}.tmp{}", std::process::id()));
        let f = File::create(&tmp).map_err(|e| format!("{}: cannot write: {e}", path.display()))?;
        Ok(AtomicFile { path: path.to_path_buf(), tmp, file: Some(BufWriter::with_capacity(1 << 16, f)) })
    }

    pub fn path(&self) -> &Path {
        &self.path
    }

    pub fn file(&mut self) -> &mut BufWriter<File> {
        self.file.as_mut().expect("file open until commit")
    }

    pub fn error(&self, e: std::io::Error) -> String {
        format!("{}: cannot write: {e}", self.path.display())
    }

    pub fn write_all(&mut self, b: &[u8]) -> Result<(), String> {
        let r = self.file().write_all(b);
        r.map_err(|e| self.error(e))
    }

    fn flush(&mut self) -> Result<(), String> {
        let mut f = self.file.take().expect("file open until commit");
        let r = f.flush();
        r.map_err(|e| self.error(e))
    }
}

impl Drop for AtomicFile {
    fn drop(&mut self) {
        if self.tmp.exists() {
            let _ = std::fs::remove_file(&self.tmp);
        }
    }
}

/// Flushes every file, then renames them all to their final names. Returns the final paths.
pub fn commit_all(files: Vec<AtomicFile>) -> Result<Vec<PathBuf>, String> {
    let mut files = files;
    for f in files.iter_mut() {
        f.flush()?;
    }
    let mut out = Vec::new();
    for f in files.iter() {
        std::fs::rename(&f.tmp, &f.path).map_err(|e| format!("{}: cannot write: {e}", f.path.display()))?;
        out.push(f.path.clone());
    }
    Ok(out)
}
