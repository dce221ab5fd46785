//! Nanosurf `.nid`.

use std::path::Path;

use super::{Raw, ReadOptions};
use crate::error::{Error, Result};

/// Whether `bytes` start as this format's files do.
pub(crate) fn sniff(_bytes: &[u8]) -> bool {
    false
}

pub(crate) fn parse(path: &Path, _bytes: &[u8], _options: &ReadOptions) -> Result<Raw> {
    Err(Error::parse(path, 0, 0, "not read yet".to_string()))
}
