//! Atomic file output: write to a temporary sibling, then rename.

use crate::{Error, Result};
use std::fs::OpenOptions;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

/// Distinguishes temporary files of concurrent renders in one process.
static COUNTER: AtomicU64 = AtomicU64::new(0);

/// A temporary file next to the target, removed on drop unless persisted.
///
/// Its name keeps the target's extension (the PNG encoder picks the format
/// from it) and starts with a dot so that it is hidden while it exists.
pub(crate) struct TempFile {
    tmp: PathBuf,
    target: PathBuf,
    persisted: bool,
}

impl TempFile {
    /// Creates the (empty) temporary file, failing if the directory is not
    /// writable.
    pub(crate) fn create(target: &Path) -> Result<Self> {
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
    pub(crate) fn path(&self) -> &Path {
        &self.tmp
    }

    /// Renames the temporary file over the target.
    pub(crate) fn persist(mut self) -> Result<()> {
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
