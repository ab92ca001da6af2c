//! Output files that appear whole or not at all, alone or as a set (the vectors of a unit, a
//! VCD with its GTKWave save file, a plot, a TMCL binary).
//!
//! A writer writes to a temporary name beside the target ([`tmp_path`]: same directory, so the
//! final rename stays on one file system). [`commit_all`] (or [`commit_staged`] for files a
//! library wrote by name) flushes every file to the disk and then renames them as one
//! transaction: a target that already exists is first moved aside, and if any step fails, every
//! file already renamed is removed and every file moved aside is put back, so the directory
//! holds either all the new files or the old ones. A [`Staged`] or [`AtomicFile`] dropped without
//! a commit (an error on the way, a full disk) removes its temporary file.
//!
//! A new output format plugs in by creating its files with [`AtomicFile::create`] and handing
//! them to [`commit_all`] with the others of its set.

use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

/// `dir/.stem.tmp-PID.ext` beside `p`: hidden, unique to the process, with the target's extension
/// (some writers choose the format by it).
pub fn tmp_path(p: &Path) -> PathBuf {
    beside(p, "tmp")
}

fn beside(p: &Path, tag: &str) -> PathBuf {
    let stem = p.file_stem().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
    let ext = p.extension().map(|e| format!(".{}", e.to_string_lossy())).unwrap_or_default();
    p.with_file_name(format!(".{stem}.{tag}-{}{ext}", std::process::id()))
}

fn cannot_write(p: &Path, e: impl std::fmt::Display) -> String {
    format!("{}: cannot write: {e}", p.display())
}

/// A target and its temporary file; the temporary file is removed when this is dropped without
/// a commit.
pub struct Staged {
    path: PathBuf,
    tmp: PathBuf,
}

impl Staged {
    pub fn new(path: &Path) -> Staged {
        Staged { path: path.to_path_buf(), tmp: tmp_path(path) }
    }

    /// The name the file gets when committed.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// Where the writer writes until the commit.
    pub fn tmp(&self) -> &Path {
        &self.tmp
    }

    /// Commits this file alone ([`commit_staged`]).
    pub fn commit(self) -> Result<PathBuf, String> {
        commit_staged(vec![self]).map(|mut v| v.remove(0))
    }
}

impl Drop for Staged {
    fn drop(&mut self) {
        // After a commit the temporary name no longer exists.
        let _ = std::fs::remove_file(&self.tmp);
    }
}

/// A buffered file under its temporary name.
pub struct AtomicFile {
    staged: Staged,
    file: Option<BufWriter<File>>,
}

impl AtomicFile {
    pub fn create(path: &Path) -> Result<AtomicFile, String> {
        let staged = Staged::new(path);
        let f = File::create(staged.tmp()).map_err(|e| cannot_write(path, e))?;
        Ok(AtomicFile { staged, file: Some(BufWriter::with_capacity(1 << 16, f)) })
    }

    pub fn path(&self) -> &Path {
        self.staged.path()
    }

    pub fn file(&mut self) -> &mut BufWriter<File> {
        self.file.as_mut().expect("file open until commit")
    }

    pub fn error(&self, e: std::io::Error) -> String {
        cannot_write(self.path(), e)
    }

    pub fn write_all(&mut self, b: &[u8]) -> Result<(), String> {
        let r = self.file().write_all(b);
        r.map_err(|e| self.error(e))
    }

    /// Writes out and empties `buf`, a writer's own encoding buffer, once it holds at least
    /// `at_least` bytes (0: now).
    #[inline]
    pub fn drain(&mut self, buf: &mut Vec<u8>, at_least: usize) -> Result<(), String> {
        if buf.len() < at_least {
            return Ok(());
        }
        let r = self.write_all(buf);
        buf.clear();
        r
    }

    fn close(&mut self) -> Result<(), String> {
        let f = self.file.take().expect("file open until commit");
        let r = f.into_inner().map_err(|e| e.into_error());
        r.map(drop).map_err(|e| self.error(e))
    }
}

/// Writes `bytes` as the whole content of `path` (temporary file, flushed, renamed).
pub fn write_whole(path: &Path, bytes: &[u8]) -> Result<(), String> {
    let mut f = AtomicFile::create(path)?;
    f.write_all(bytes)?;
    commit_all(vec![f]).map(drop)
}

/// Flushes every file, then renames them all to their final names as one transaction
/// ([`commit_staged`]). Returns the final paths.
pub fn commit_all(files: Vec<AtomicFile>) -> Result<Vec<PathBuf>, String> {
    let mut files = files;
    for f in files.iter_mut() {
        f.close()?;
    }
    commit_staged(files.into_iter().map(|f| f.staged).collect())
}

/// Renames every staged file to its target, all or none: each temporary file is synced to the
/// disk first (a full disk shows here at the latest); a target that exists and is not a file (a
/// directory in the way) fails the commit before anything is renamed; an existing file is moved
/// aside and put back if a later rename fails. On error nothing of the set is left: the
/// temporary files are removed and the targets are as they were.
pub fn commit_staged(staged: Vec<Staged>) -> Result<Vec<PathBuf>, String> {
    for s in &staged {
        File::open(&s.tmp).and_then(|f| f.sync_all()).map_err(|e| cannot_write(&s.path, e))?;
        if let Ok(m) = std::fs::symlink_metadata(&s.path) {
            if m.is_dir() {
                return Err(cannot_write(&s.path, "a directory of that name is in the way"));
            }
        }
    }
    let mut done: Vec<(&Staged, Option<PathBuf>)> = Vec::new();
    for s in &staged {
        if let Err(e) = replace(s, &mut done) {
            roll_back(done);
            return Err(cannot_write(&s.path, e));
        }
    }
    for (_, old) in done {
        if let Some(old) = old {
            let _ = std::fs::remove_file(old);
        }
    }
    Ok(staged.iter().map(|s| s.path.clone()).collect())
}

/// Moves the existing target aside (if any) and renames the temporary file over it; records
/// what it did in `done`, or undoes its own part on failure.
fn replace<'a>(s: &'a Staged, done: &mut Vec<(&'a Staged, Option<PathBuf>)>) -> std::io::Result<()> {
    let old = match std::fs::symlink_metadata(&s.path) {
        Ok(_) => {
            let old = beside(&s.path, "old");
            std::fs::rename(&s.path, &old)?;
            Some(old)
        }
        Err(_) => None,
    };
    if let Err(e) = std::fs::rename(&s.tmp, &s.path) {
        if let Some(old) = old {
            let _ = std::fs::rename(old, &s.path);
        }
        return Err(e);
    }
    done.push((s, old));
    Ok(())
}

/// Undoes [`replace`] in reverse order: the new files go, the old ones come back.
fn roll_back(done: Vec<(&Staged, Option<PathBuf>)>) {
    for (s, old) in done.into_iter().rev() {
        let _ = std::fs::remove_file(&s.path);
        if let Some(old) = old {
            let _ = std::fs::rename(old, &s.path);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn dir(tag: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("tmc429-files-{tag}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap();
        d
    }

    fn names(d: &Path) -> Vec<String> {
        let mut v: Vec<String> = std::fs::read_dir(d).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
        v.sort();
        v
    }

    fn file(d: &Path, name: &str, text: &str) -> AtomicFile {
        let mut f = AtomicFile::create(&d.join(name)).unwrap();
        f.write_all(text.as_bytes()).unwrap();
        f
    }

    #[test]
    fn a_set_appears_together_and_replaces_old_files() {
        let d = dir("set");
        std::fs::write(d.join("b.csv"), "old").unwrap();
        let set = vec![file(&d, "a.hex", "new a"), file(&d, "b.csv", "new b")];
        assert_eq!(
            names(&d),
            [
                ".a.tmp-".to_string() + &std::process::id().to_string() + ".hex",
                format!(".b.tmp-{}.csv", std::process::id()),
                "b.csv".into()
            ]
        );
        commit_all(set).unwrap();
        assert_eq!(names(&d), ["a.hex", "b.csv"]);
        assert_eq!(std::fs::read_to_string(d.join("b.csv")).unwrap(), "new b");
        std::fs::remove_dir_all(&d).unwrap();
    }

    /// A name blocked by a directory: nothing of the set appears, the old files stay.
    #[test]
    fn a_blocked_name_leaves_nothing_of_the_set() {
        let d = dir("blocked");
        std::fs::write(d.join("a.hex"), "old a").unwrap();
        std::fs::create_dir(d.join("c.meta")).unwrap();
        let set = vec![file(&d, "a.hex", "new a"), file(&d, "b.cols", "new b"), file(&d, "c.meta", "new c")];
        let e = commit_all(set).unwrap_err();
        assert_eq!(e, format!("{}: cannot write: a directory of that name is in the way", d.join("c.meta").display()));
        assert_eq!(names(&d), ["a.hex", "c.meta"]);
        assert_eq!(std::fs::read_to_string(d.join("a.hex")).unwrap(), "old a");
        std::fs::remove_dir_all(&d).unwrap();
    }

    /// A rename that fails half-way (the target directory vanished after the check) is rolled
    /// back: the files renamed before it are removed again, the old ones restored.
    #[test]
    fn a_failed_rename_is_rolled_back() {
        let d = dir("rollback");
        std::fs::write(d.join("a.hex"), "old a").unwrap();
        std::fs::create_dir(d.join("sub")).unwrap();
        let a = Staged::new(&d.join("a.hex"));
        std::fs::write(a.tmp(), "new a").unwrap();
        let b = Staged::new(&d.join("sub/b.csv"));
        std::fs::write(b.tmp(), "new b").unwrap();
        let b_tmp = b.tmp().to_path_buf();
        let mut done = Vec::new();
        replace(&a, &mut done).unwrap();
        std::fs::remove_file(&b_tmp).unwrap(); // the rename of b fails: its source is gone
        assert!(replace(&b, &mut done).is_err());
        roll_back(done);
        drop((a, b));
        assert_eq!(names(&d), ["a.hex", "sub"]);
        assert_eq!(std::fs::read_to_string(d.join("a.hex")).unwrap(), "old a");
        assert!(names(&d.join("sub")).is_empty());
        std::fs::remove_dir_all(&d).unwrap();
    }

    #[test]
    fn dropped_files_leave_nothing() {
        let d = dir("drop");
        drop(file(&d, "a.hex", "x"));
        let s = Staged::new(&d.join("p.png"));
        std::fs::write(s.tmp(), "x").unwrap();
        drop(s);
        assert!(names(&d).is_empty());
        std::fs::remove_dir_all(&d).unwrap();
    }
}
