//! HDF5 `.h5`: every rank-2 numeric data set is a channel.
//!
//! The container is read with the pure-Rust `rustyhdf5-format` crate: the
//! superblock (versions 0–3), object headers (v1, v2 with continuations),
//! old-style (symbol table) and new-style (compact or dense link) groups, and
//! the data of contiguous, compact and chunked data sets (layout messages 3
//! and 4, their chunk indexes, the deflate and shuffle filters). Datatypes,
//! dataspaces and attributes are decoded here (the crate's own decoding of
//! compound types is wrong for version 1 compounds and misses array types in
//! version 3 ones): integers and IEEE floats of either byte order, fixed and
//! variable-length strings, compounds, arrays.
//!
//! | module | what it reads |
//! |---|---|
//! | this one | the `.h5` reader: which data sets are channels, which one is read |
//! | `file` | the open file [`H5`]: superblock, object headers, groups, dataspaces |
//! | `datatype` | datatype messages ([`Type`]) and numbers of a type ([`numbers`]) |
//! | `attribute` | attribute messages and strings (fixed, or variable-length in a global heap) |
//! | `layout` | a data set's bytes: layout message, chunk index, filter pipeline |
//! | `guard` | the backstop for the crate's panics on damaged files |
//!
//! # What is read
//! The channels are the rank-2 data sets of integers or floats with no
//! empty dimension, visited depth-first with each group's members in name
//! order (as h5py's `visititems`); a channel is named by its path
//! (`group/heights`). [`ReadOptions::channel`] picks one by that path, by
//! its last component, or by its index; the default is the first. The
//! first index of a data set of shape `(n0, n1)` runs along x: `nx = n0`,
//! `ny = n1`, `h[ix, iy] = data[ix·n1 + iy]`. HDF5 states no physical size and
//! no unit: both are the caller's. NaN values are undefined.
//!
//! Not read: layout message 5 (HDF5 2.0 with `libver="latest"`), attributes
//! in dense storage, external or virtual storage, filters other than
//! deflate/shuffle/Fletcher32; each is an error naming it. A chunked data
//! set whose decompressed size is over 1032 times the file (deflate's
//! largest ratio) is refused before anything is allocated; others are
//! checked against the file's length.
//!
//! # Damaged files
//! `rustyhdf5-format` 1.93 panics on some damaged files instead of
//! returning an error. Where it would, the file is checked before the crate
//! is called (the chunk index is walked first and every chunk checked against
//! the file; a global heap's size is checked), and every call into the crate
//! on file data runs under a guard that turns a panic into an error naming the
//! file and "HDF5: damaged …" (the `guard` module lists the panics).
//!
//! # References
//! The HDF5 file format specification 3.0 (The HDF Group); SurfaceTopography's
//! `IO/H5.py` (the channels, their order and the axis order).

mod attribute;
mod datatype;
mod file;
mod guard;
mod layout;

use std::path::Path;

pub(crate) use datatype::{numbers, Type};
pub(crate) use file::H5;

use super::{channel, Raw, ReadOptions};
use crate::error::Result;

/// The HDF5 signature.
pub(crate) const MAGIC: &[u8] = b"\x89HDF\r\n\x1a\n";

/// Whether `bytes` start as this format's files do (the HDF5 signature at 0).
pub(crate) fn sniff(bytes: &[u8]) -> bool {
    bytes.starts_with(MAGIC)
}

pub(crate) fn parse(path: &Path, bytes: &[u8], options: &ReadOptions) -> Result<Raw> {
    let h5 = H5::open(path, bytes, "HDF5")?;
    let sets = h5.datasets()?;
    let mut channels = Vec::new();
    for (name, header) in &sets {
        let shape = h5.shape(header)?;
        let numeric = matches!(
            h5.datatype(header)?.0,
            Type::Int { .. } | Type::Float { .. }
        );
        if shape.len() == 2 && shape.iter().all(|&n| n > 0) && numeric {
            channels.push((name.as_str(), header));
        }
    }
    let listed: Vec<(&str, bool)> = channels.iter().map(|(n, _)| (*n, true)).collect();
    let wanted = options
        .channel
        .as_deref()
        .map(|w| w.trim().trim_start_matches('/'));
    let index = match wanted.and_then(|w| by_last_component(&listed, w)) {
        Some(i) => i,
        None => channel::choose(&listed, wanted).map_err(|e| h5.bad(e))?,
    };
    let (name, header) = channels[index];
    let (shape, values) = h5.read_f64(header, name)?;
    let (nx, ny) = (shape[0], shape[1]);
    // data[ix·ny + iy] (x is the first index) to heights[iy·nx + ix].
    let mut heights = vec![0.0; values.len()];
    for (i, &v) in values.iter().enumerate() {
        heights[(i % ny) * nx + i / ny] = v;
    }
    Ok(Raw::map(nx, ny, heights))
}

/// The channel whose path ends in `/wanted`, when its full path is not `wanted`.
fn by_last_component(channels: &[(&str, bool)], wanted: &str) -> Option<usize> {
    let w = wanted.trim().trim_start_matches('/');
    if channels.iter().any(|(n, _)| n.eq_ignore_ascii_case(w)) {
        return None;
    }
    let hits: Vec<usize> = (0..channels.len())
        .filter(|&i| {
            let n = channels[i].0;
            n.rsplit('/')
                .next()
                .is_some_and(|l| l.eq_ignore_ascii_case(w))
        })
        .collect();
    (hits.len() == 1).then(|| hits[0])
}
