//! Grid file I/O: the one `.npy` reader and writer, the one text reader
//! (matrices and columns of numbers, in UTF-8, UTF-16 or Latin-1), and
//! atomic writes. The BEM's surfaces ([`crate::bem`]), the measured
//! surfaces ([`crate::topography`]) and the tabulated spectra all read
//! through here, so one file reads the same everywhere.
//!
//! | what | reader | writer |
//! |---|---|---|
//! | numpy `.npy`, float32/float64, either byte order, C or Fortran order, rank 2 | [`npy::parse`] | [`npy::write`] (atomic) |
//! | text: rows of numbers, header lines, `#` comments | [`text::rows`], [`text::matrix`] | – |
//! | any bytes | [`read`] (read-only; [`mount`]ed files first) | [`write_atomic`] |
//!
//! # Conventions
//! A [`Matrix`] is row-major, `values[row·cols + col]`, with `rows × cols`
//! the shape numpy prints: the first index is the row. For a height map a
//! row runs along x (numpy's image convention), so a map of `ny` rows and
//! `nx` columns is the array of shape `(ny, nx)`. Every error is an
//! [`Error::Parse`] naming the file (and the line where it helps).
//!
//! # Atomic writes
//! [`write_atomic`] writes to a temporary file in the target's directory,
//! then renames it over the target: a failed write leaves any existing file
//! untouched and no partial file behind.

mod memory;
pub mod npy;
pub mod text;

pub use memory::{mount, unmount_all};

use std::fs::OpenOptions;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

use crate::error::{Error, Result};

/// A 2-D array of numbers, row-major: `values[row·cols + col]` (module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct Matrix {
    /// Number of rows (numpy's first axis; y for a height map).
    pub rows: usize,
    /// Number of columns (numpy's second axis; x for a height map).
    pub cols: usize,
    /// The values, `rows·cols` of them, row by row.
    pub values: Vec<f64>,
}

impl Matrix {
    /// The transpose: `cols × rows`, element `(i, j)` of the result is
    /// element `(j, i)` of `self`.
    pub(crate) fn transposed(&self) -> Matrix {
        let mut t = vec![0.0; self.values.len()];
        for i in 0..self.rows {
            for j in 0..self.cols {
                t[j * self.rows + i] = self.values[i * self.cols + j];
            }
        }
        Matrix {
            rows: self.cols,
            cols: self.rows,
            values: t,
        }
    }
}

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

    /// The file it will be renamed over.
    pub fn target(&self) -> &Path {
        &self.target
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

/// Write `bytes` to `path` atomically (module docs): a failed write leaves
/// any existing file untouched and no partial file behind.
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
    if let Some(bytes) = memory::get(path) {
        return Ok(bytes.to_vec());
    }
    std::fs::read(path).map_err(|source| io_error(path, source))
}

/// The first `n` bytes of an input file (fewer if it is shorter), without
/// reading the rest: a format's magic.
///
/// # Errors
/// [`Error::Io`] naming `path`.
pub fn read_head(path: &Path, n: usize) -> Result<Vec<u8>> {
    use std::io::Read;
    if let Some(bytes) = memory::get(path) {
        return Ok(bytes[..n.min(bytes.len())].to_vec());
    }
    let mut head = Vec::with_capacity(n);
    std::fs::File::open(path)
        .and_then(|f| f.take(n as u64).read_to_end(&mut head))
        .map_err(|source| io_error(path, source))?;
    Ok(head)
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
