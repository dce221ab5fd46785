//! File output that never loses what the user had: write to a temporary file
//! in the same directory, then rename over the target. Inputs are opened
//! read-only.

use std::fs::OpenOptions;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

use crate::error::{Error, Result};

/// Distinguishes temporary files of concurrent renders in one process.
static COUNTER: AtomicU64 = AtomicU64::new(0);

/// A temporary file next to a target, removed on drop unless persisted.
///
/// Its name keeps the target's extension (the PNG encoder picks the format
/// from it) and starts with a dot so that it is hidden while it exists.
pub struct TempFile {
    tmp: PathBuf,
    target: PathBuf,
    persisted: bool,
}

impl TempFile {
    /// Creates the (empty) temporary file, failing if the directory is not
    /// writable.
    pub fn create(target: &Path) -> Result<Self> {
        let dir = match target.parent() {
            Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
            _ => PathBuf::from("."),
        };
        let name = target
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_else(|| "plot".into());
        let ext = target
            .extension()
            .map(|e| e.to_string_lossy().into_owned())
            .unwrap_or_default();
        let n = COUNTER.fetch_add(1, Ordering::Relaxed);
        let tmp = dir.join(format!(".{name}.{}-{n}.tmp.{ext}", std::process::id()));
        OpenOptions::new()
            .write(true)
            .create_new(true)
            .open(&tmp)
            .map_err(|source| Error::Io {
                path: target.to_path_buf(),
                source,
            })?;
        Ok(TempFile {
            tmp,
            target: target.to_path_buf(),
            persisted: false,
        })
    }

    /// The temporary file's path.
    pub fn path(&self) -> &Path {
        &self.tmp
    }

    /// Renames the temporary file over the target.
    pub fn persist(mut self) -> Result<()> {
        std::fs::rename(&self.tmp, &self.target).map_err(|source| Error::Io {
            path: self.target.clone(),
            source,
        })?;
        self.persisted = true;
        Ok(())
    }
}

impl Drop for TempFile {
    fn drop(&mut self) {
        if !self.persisted {
            // Best effort: the file may already be gone.
            let _ = std::fs::remove_file(&self.tmp);
        }
    }
}

/// Write `bytes` to `path` atomically: a failed write leaves any existing
/// file untouched and no partial file behind.
///
/// # Errors
/// [`Error::Io`] naming `path` when the directory does not exist or is not
/// writable, or the rename fails.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<()> {
    let tmp = TempFile::create(path)?;
    std::fs::write(tmp.path(), bytes).map_err(|source| io_error(path, source))?;
    tmp.persist()
}

/// Check, before any computation, that `path` can be written: its directory
/// exists and accepts a new file.
///
/// # Errors
/// [`Error::Io`] naming `path`.
pub fn check_writable(path: &Path) -> Result<()> {
    TempFile::create(path).map(drop)
}

/// Read a whole input file (opened read-only).
///
/// # Errors
/// [`Error::Io`] naming `path`.
pub fn read(path: &Path) -> Result<Vec<u8>> {
    std::fs::read(path).map_err(|source| io_error(path, source))
}

fn io_error(path: &Path, source: std::io::Error) -> Error {
    Error::Io {
        path: path.to_path_buf(),
        source,
    }
}

/// The shortest text that reads back to the same `f64`: plain digits in
/// [1e-4, 1e16), scientific otherwise (`1e-12`, not `0.000000000001`).
pub fn csv_number(v: f64) -> String {
    if !v.is_finite() {
        return if v.is_nan() {
            "NaN".into()
        } else if v > 0.0 {
            "inf".into()
        } else {
            "-inf".into()
        };
    }
    let a = v.abs();
    if a != 0.0 && !(1e-4..1e16).contains(&a) {
        format!("{v:e}")
    } else {
        format!("{v}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn failed_write_keeps_existing_file() {
        let dir = std::env::temp_dir().join(format!("persson-io-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let p = dir.join("keep.txt");
        std::fs::write(&p, "original").unwrap();
        drop(TempFile::create(&p).unwrap()); // a render that failed before persisting
        assert_eq!(std::fs::read_to_string(&p).unwrap(), "original");
        assert_eq!(
            std::fs::read_dir(&dir).unwrap().count(),
            1,
            "temporary file left behind"
        );
        write_atomic(&p, b"new").unwrap();
        assert_eq!(std::fs::read_to_string(&p).unwrap(), "new");
        assert!(write_atomic(&dir.join("no/such/dir/x"), b"1").is_err());
        assert!(check_writable(&dir.join("no/such/dir/x")).is_err());
    }
}
