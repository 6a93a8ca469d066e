//! Where a report may go. wrapcalc writes into a directory only when it does not exist yet, is
//! empty, or is a report wrapcalc wrote itself, recognised by the marker file [`MARKER`] it puts
//! into every report directory. A regular file, or a directory holding anything else, is
//! refused and left exactly as it was.
//!
//! Two processes writing the same directory take turns: the check and the replacement happen
//! while holding an advisory lock on a file beside the directory (`.<name>.wrapcalc-lock`), so
//! the last writer's report is there whole, never a mix of both.

use super::{ReportError, io};
use std::fs::{self, File, OpenOptions};
use std::path::{Path, PathBuf};

/// The marker file in every report directory wrapcalc writes.
pub const MARKER: &str = ".wrapcalc-report";

/// What writes a report directory (named in its marker).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ReportKind {
    /// `wrapcalc run`: the directory is replaced whole.
    Run,
    /// `wrapcalc sweep` and `merge`: their files are added to the directory (shards share it).
    Sweep,
    /// `wrapcalc bench`: the directory is replaced whole.
    Bench,
}

impl ReportKind {
    fn name(self) -> &'static str {
        match self {
            ReportKind::Run => "run",
            ReportKind::Sweep => "sweep",
            ReportKind::Bench => "bench",
        }
    }
}

/// The marker's text: what the directory is and what wrapcalc does with it.
pub fn marker_text(kind: ReportKind) -> String {
    let what = match kind {
        ReportKind::Sweep => "adds its sweep files to this directory, replacing those of the same name,",
        ReportKind::Run | ReportKind::Bench => "replaces this whole directory",
    };
    format!(
        "wrapcalc report ({})\n\
         Written by wrapcalc, which {what} when it writes\n\
         here again: keep no files of your own here. Without this file wrapcalc refuses to write here.\n",
        kind.name()
    )
}

/// What a report target holds now (everything else is refused).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Existing {
    /// Nothing at the path.
    Missing,
    /// An empty directory.
    Empty,
    /// A directory with wrapcalc's marker.
    Report,
}

/// The directory a report for `dir` goes to: a symbolic link is followed, so the link stays
/// and the report replaces what it points to.
pub fn resolve(dir: &Path) -> PathBuf {
    match fs::symlink_metadata(dir) {
        Ok(m) if m.file_type().is_symlink() => fs::canonicalize(dir).unwrap_or_else(|_| dir.to_path_buf()),
        _ => dir.to_path_buf(),
    }
}

/// Whether wrapcalc may write a report to `dir`; refuses (touching nothing) a path that is not
/// a directory, and a directory with content but no marker.
pub fn check(dir: &Path) -> Result<Existing, ReportError> {
    let meta = match fs::metadata(dir) {
        Ok(m) => m,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(Existing::Missing),
        Err(e) => return Err(io(dir)(e)),
    };
    let refuse = |reason: String| ReportError::Refused { path: dir.display().to_string(), reason };
    if meta.is_file() {
        return Err(refuse("it is a regular file, not a report directory".into()));
    }
    if !meta.is_dir() {
        return Err(refuse("it is not a directory".into()));
    }
    let mut names = Vec::new();
    for entry in fs::read_dir(dir).map_err(io(dir))? {
        let entry = entry.map_err(io(dir))?;
        if entry.file_name() == MARKER && entry.file_type().is_ok_and(|t| t.is_file()) {
            return Ok(Existing::Report);
        }
        let slash = if entry.file_type().is_ok_and(|t| t.is_dir()) { "/" } else { "" };
        names.push(format!("{}{slash}", entry.file_name().to_string_lossy()));
    }
    if names.is_empty() {
        return Ok(Existing::Empty);
    }
    names.sort();
    let count = names.len();
    let mut shown: Vec<String> = names.into_iter().take(3).collect();
    if count > shown.len() {
        shown.push("…".into());
    }
    Err(refuse(format!(
        "the directory holds {count} entr{} ({}) and is not a wrapcalc report (it has no {MARKER} file), \
         so writing the report there could replace {}",
        if count == 1 { "y" } else { "ies" },
        shown.join(", "),
        if count == 1 { "it" } else { "them" }
    )))
}

/// Writes the marker of a `kind` report into `dir`.
pub fn mark(dir: &Path, kind: ReportKind) -> Result<(), ReportError> {
    let path = dir.join(MARKER);
    fs::write(&path, marker_text(kind)).map_err(io(&path))
}

/// The directory a report at `dir` is staged in and locked from: its parent (`.` for a bare
/// name).
pub fn parent_of(dir: &Path) -> PathBuf {
    match dir.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    }
}

/// An exclusive lock on writing the report at `dir`, held until dropped.
#[derive(Debug)]
pub struct Lock {
    _file: File,
}

/// Waits for and takes the lock of the report at `dir`: an advisory lock on
/// `.<name>.wrapcalc-lock` beside it (created if needed, never deleted, so that every writer
/// locks the same file). The operating system releases it when the process ends, however it ends.
pub fn lock(dir: &Path) -> Result<Lock, ReportError> {
    let parent = parent_of(dir);
    fs::create_dir_all(&parent).map_err(io(&parent))?;
    let name = match dir.file_name() {
        Some(n) => n.to_string_lossy().into_owned(),
        None => fs::canonicalize(dir)
            .ok()
            .and_then(|p| p.file_name().map(|n| n.to_string_lossy().into_owned()))
            .unwrap_or_else(|| "report".into()),
    };
    let path = parent.join(format!(".{name}.wrapcalc-lock"));
    let file = OpenOptions::new().create(true).truncate(false).write(true).open(&path).map_err(io(&path))?;
    file.lock().map_err(io(&path))?;
    Ok(Lock { _file: file })
}
