//! File output that never loses what the user had: write to a temporary file
//! in the same directory, then rename over the target.

use std::io::Write;
use std::path::{Path, PathBuf};

use crate::error::{Error, Result};

/// Write `bytes` to `path` atomically: a failed write leaves any existing
/// file untouched and no partial file behind.
///
/// # Errors
/// [`Error::Io`] naming `path` when the directory does not exist or is not
/// writable, or the rename fails.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<()> {
    write_atomic_with(path, |file| {
        file.write_all(bytes)
            .map_err(|source| io_error(path, source))
    })
}

/// Like [`write_atomic`], with the content produced by `fill` on the temporary
/// path (for writers, such as plot backends, that open the file themselves).
///
/// # Errors
/// As [`write_atomic`], or whatever `fill` returns.
pub fn write_atomic_path(path: &Path, fill: impl FnOnce(&Path) -> Result<()>) -> Result<()> {
    let tmp = temp_path(path);
    let r = fill(&tmp)
        .and_then(|()| std::fs::rename(&tmp, path).map_err(|source| io_error(path, source)));
    if r.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    r
}

fn write_atomic_with(
    path: &Path,
    fill: impl FnOnce(&mut std::fs::File) -> Result<()>,
) -> Result<()> {
    write_atomic_path(path, |tmp| {
        let mut f = std::fs::File::create(tmp).map_err(|source| io_error(path, source))?;
        fill(&mut f)?;
        f.sync_all().map_err(|source| io_error(path, source))
    })
}

/// `dir/.name.tmp-PID` next to `path`.
fn temp_path(path: &Path) -> PathBuf {
    let name = path
        .file_name()
        .map_or_else(|| "out".into(), |n| n.to_string_lossy().into_owned());
    path.with_file_name(format!(".{name}.tmp-{}", std::process::id()))
}

/// Check, before any computation, that `path` can be written: its directory
/// exists and accepts a new file.
///
/// # Errors
/// [`Error::Io`] naming `path`.
pub fn check_writable(path: &Path) -> Result<()> {
    let tmp = temp_path(path);
    std::fs::File::create(&tmp).map_err(|source| io_error(path, source))?;
    let _ = std::fs::remove_file(&tmp);
    Ok(())
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn failed_write_keeps_existing_file() {
        let dir = std::env::temp_dir().join(format!("persson-io-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let p = dir.join("keep.txt");
        std::fs::write(&p, "original").unwrap();
        let r = write_atomic_path(&p, |_| Err(Error::invalid("x", 1.0, "test failure")));
        assert!(r.is_err());
        assert_eq!(std::fs::read_to_string(&p).unwrap(), "original");
        assert_eq!(
            std::fs::read_dir(&dir).unwrap().count(),
            1,
            "temporary file left behind"
        );
        write_atomic(&p, b"new").unwrap();
        assert_eq!(std::fs::read_to_string(&p).unwrap(), "new");
        assert!(write_atomic(&dir.join("no/such/dir/x"), b"1").is_err());
    }
}
