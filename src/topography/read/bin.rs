//! Little-endian fields of binary instrument files, read with bounds checks:
//! a field past the end is an error saying the file is truncated, never a
//! panic.

use std::path::Path;

use crate::error::{Error, Result};

/// A byte buffer read by offset, naming the file in its errors.
pub(crate) struct Bin<'b> {
    pub bytes: &'b [u8],
    pub path: &'b Path,
    /// The format, for the errors (`"Digital Surf .sur"`).
    pub format: &'static str,
}

impl<'b> Bin<'b> {
    /// `bytes` of the file `path` in `format`.
    pub fn new(bytes: &'b [u8], path: &'b Path, format: &'static str) -> Self {
        Bin {
            bytes,
            path,
            format,
        }
    }

    /// An error naming the file and the format.
    pub fn bad(&self, message: impl std::fmt::Display) -> Error {
        Error::parse(self.path, 0, 0, format!("{}: {message}", self.format))
    }

    /// `n` bytes at `offset`, or a truncation error naming `what`.
    pub fn slice(&self, offset: usize, n: usize, what: &str) -> Result<&'b [u8]> {
        offset
            .checked_add(n)
            .and_then(|end| self.bytes.get(offset..end))
            .ok_or_else(|| {
                self.bad(format!(
                    "truncated: {what} needs bytes {offset}..{} of a {}-byte file",
                    offset.saturating_add(n),
                    self.bytes.len()
                ))
            })
    }

    fn array<const N: usize>(&self, offset: usize, what: &str) -> Result<[u8; N]> {
        let s = self.slice(offset, N, what)?;
        let mut a = [0u8; N];
        a.copy_from_slice(s);
        Ok(a)
    }

    pub fn u16(&self, offset: usize, what: &str) -> Result<u16> {
        self.array(offset, what).map(u16::from_le_bytes)
    }

    pub fn i32(&self, offset: usize, what: &str) -> Result<i32> {
        self.array(offset, what).map(i32::from_le_bytes)
    }

    pub fn u32(&self, offset: usize, what: &str) -> Result<u32> {
        self.array(offset, what).map(u32::from_le_bytes)
    }

    pub fn f32(&self, offset: usize, what: &str) -> Result<f32> {
        self.array(offset, what).map(f32::from_le_bytes)
    }

    /// Big-endian u16.
    pub fn be_u16(&self, offset: usize, what: &str) -> Result<u16> {
        self.array(offset, what).map(u16::from_be_bytes)
    }

    /// Big-endian i16.
    pub fn be_i16(&self, offset: usize, what: &str) -> Result<i16> {
        self.array(offset, what).map(i16::from_be_bytes)
    }

    /// Big-endian u32.
    pub fn be_u32(&self, offset: usize, what: &str) -> Result<u32> {
        self.array(offset, what).map(u32::from_be_bytes)
    }

    /// Big-endian f32.
    pub fn be_f32(&self, offset: usize, what: &str) -> Result<f32> {
        self.array(offset, what).map(f32::from_be_bytes)
    }
}

/// `a × b` (× `c`) as a count of values, or `None` on overflow.
pub(crate) fn product(a: usize, b: usize, item: usize) -> Option<usize> {
    a.checked_mul(b)?.checked_mul(item)
}

/// The UTF-16LE code units of `b` (an odd last byte left out).
pub(crate) fn utf16_units(b: &[u8]) -> Vec<u16> {
    b.chunks_exact(2)
        .map(|c| u16::from_le_bytes([c[0], c[1]]))
        .collect()
}

/// `b` read as Latin-1: every byte is its own code point.
pub(crate) fn latin1(b: &[u8]) -> String {
    b.iter().map(|&c| char::from(c)).collect()
}
