//! Gzip-compressed files: any format the readers know, compressed (an
//! exported `matrix.txt.gz`). Inflated in memory; the inner file's format
//! by its name without `.gz`, or by its content.

use std::io::Read;
use std::path::{Path, PathBuf};

use crate::error::{Error, Result};

/// The gzip magic (RFC 1952, ID1 ID2).
pub(super) const MAGIC: &[u8] = b"\x1f\x8b";

/// Most bytes a file may inflate to: a decompression bomb is refused
/// before it fills the memory (a 32768² map of f64 text is about 15 GB,
/// far beyond what the readers and the BEM take anyway).
const MAX_INFLATED: u64 = 1 << 31;

/// The inflated bytes of the gzip file `bytes` (`path` in errors).
///
/// # Errors
/// [`Error::Parse`] naming the file for a corrupt or truncated stream, or
/// one that inflates beyond 2 GiB.
pub(super) fn inflate(path: &Path, bytes: &[u8]) -> Result<Vec<u8>> {
    let mut out = Vec::new();
    flate2::read::MultiGzDecoder::new(bytes)
        .take(MAX_INFLATED + 1)
        .read_to_end(&mut out)
        .map_err(|e| Error::parse(path, 0, 0, format!("gzip: {e}")))?;
    if out.len() as u64 > MAX_INFLATED {
        return Err(Error::parse(
            path,
            0,
            0,
            format!("gzip: inflates beyond {MAX_INFLATED} bytes"),
        ));
    }
    Ok(out)
}

/// The name of the compressed file: `map.txt.gz` → `map.txt`.
pub(super) fn inner_name(path: &Path) -> PathBuf {
    match path.extension().and_then(|e| e.to_str()) {
        Some(e) if e.eq_ignore_ascii_case("gz") || e.eq_ignore_ascii_case("gzip") => {
            path.with_extension("")
        }
        _ => path.to_path_buf(),
    }
}
