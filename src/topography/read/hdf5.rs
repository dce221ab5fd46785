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
//! returning an error: a chunk address near `u64::MAX` wraps `address +
//! size` and a slice panics (`chunked_read.rs:69`), a chunked layout of
//! dimensionality 0 underflows `ndims - 1` (`chunked_read.rs:340`), a
//! fixed-array data block address past the end or a `max_nelmts_bits` of
//! 64 or more (`fixed_array.rs:129–147`), a global heap collection size
//! that overflows `offset + size` (`global_heap.rs:81`, with overflow
//! checks on). Those are checked here before the crate is called (the
//! chunk index is walked first and every chunk checked against the file),
//! and, as a backstop, every call into the crate on file data runs under
//! [`std::panic::catch_unwind`]: a panic is an error naming the file and
//! "HDF5: damaged …". A panic hook installed once (chaining to the one
//! before it) keeps such a caught panic's message off stderr, on the
//! thread that catches it only.
//!
//! # References
//! The HDF5 file format specification 3.0 (The HDF Group); SurfaceTopography's
//! `IO/H5.py` (the channels, their order and the axis order).

use std::cell::{Cell, RefCell};
use std::collections::HashMap;
use std::panic::{self, AssertUnwindSafe};
use std::path::Path;
use std::rc::Rc;
use std::sync::Once;

use rustyhdf5_format::chunked_read::{self, ChunkInfo};
use rustyhdf5_format::data_layout::DataLayout;
use rustyhdf5_format::data_read;
use rustyhdf5_format::dataspace::Dataspace;
use rustyhdf5_format::datatype::Datatype as CrateType;
use rustyhdf5_format::error::FormatError;
use rustyhdf5_format::extensible_array::{self, ExtensibleArrayHeader};
use rustyhdf5_format::filter_pipeline::FilterPipeline;
use rustyhdf5_format::fixed_array::{self, FixedArrayHeader};
use rustyhdf5_format::global_heap::GlobalHeapCollection;
use rustyhdf5_format::message_type::MessageType;
use rustyhdf5_format::object_header::ObjectHeader;
use rustyhdf5_format::superblock::Superblock;
use rustyhdf5_format::symbol_table::SymbolTableMessage;
use rustyhdf5_format::{group_v1, group_v2};

use super::bin::Bin;
use super::{channel, Raw, ReadOptions};
use crate::error::{Error, Result};

/// The HDF5 signature.
pub(crate) const MAGIC: &[u8] = b"\x89HDF\r\n\x1a\n";
/// Deflate's largest compression ratio: the bound on a chunked data set's size.
const DEFLATE_RATIO: usize = 1032;
/// Deepest group nesting followed (a loop of hard links ends here).
const MAX_DEPTH: usize = 32;

thread_local! {
    /// Whether this thread is inside [`quiet_catch`] (its panics are caught).
    static CATCHING: Cell<bool> = const { Cell::new(false) };
}

/// Runs `f` (a call into `rustyhdf5-format` on file data), a panic caught
/// and its message not printed (see the module docs).
fn quiet_catch<T>(f: impl FnOnce() -> T) -> std::thread::Result<T> {
    static HOOK: Once = Once::new();
    HOOK.call_once(|| {
        let previous = panic::take_hook();
        panic::set_hook(Box::new(move |info| {
            if !CATCHING.with(Cell::get) {
                previous(info);
            }
        }));
    });
    let outer = CATCHING.with(|c| c.replace(true));
    let result = panic::catch_unwind(AssertUnwindSafe(f));
    CATCHING.with(|c| c.set(outer));
    result
}

/// `f`, a call into `rustyhdf5-format` reading `what`: its error or panic
/// as an error naming the file (through `f.bad`).
fn guarded<T>(
    bin: &Bin,
    what: &str,
    f: impl FnOnce() -> std::result::Result<T, FormatError>,
) -> Result<T> {
    match quiet_catch(f) {
        Ok(Ok(v)) => Ok(v),
        Ok(Err(e)) => Err(bin.bad(format!("{what}: {e}"))),
        Err(_) => Err(bin.bad(if bin.format == "HDF5" {
            format!("damaged {what} (the HDF5 reader failed on it)")
        } else {
            format!("HDF5: damaged {what} (the HDF5 reader failed on it)")
        })),
    }
}

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

/// A decoded HDF5 datatype.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Type {
    Int {
        size: usize,
        signed: bool,
        be: bool,
    },
    Float {
        size: usize,
        be: bool,
    },
    /// Fixed-length string of `size` bytes.
    Str {
        size: usize,
    },
    /// Variable-length string (global heap reference).
    VlStr,
    Compound {
        size: usize,
        members: Vec<(String, usize, Type)>,
    },
    Array {
        count: usize,
        base: Box<Type>,
    },
    /// Anything else (class number, size).
    Other {
        class: u8,
        size: usize,
    },
}

impl Type {
    /// The size of one element in bytes (a variable-length string's
    /// reference: 4 + offset size + 4).
    pub(crate) fn size(&self, offset_size: usize) -> usize {
        match self {
            Type::Int { size, .. }
            | Type::Float { size, .. }
            | Type::Str { size }
            | Type::Compound { size, .. }
            | Type::Other { size, .. } => *size,
            Type::VlStr => 8 + offset_size,
            Type::Array { count, base } => count.saturating_mul(base.size(offset_size)),
        }
    }
}

/// An attribute: its type, number of elements and raw value.
pub(crate) struct Attr {
    pub ty: Type,
    pub count: usize,
    pub data: Vec<u8>,
}

/// An open HDF5 file: its bytes and superblock; errors name the file and
/// the format.
pub(crate) struct H5<'b> {
    pub f: Bin<'b>,
    sb: Superblock,
    /// Global heap collections parsed so far, by address (a table of
    /// variable-length strings refers to one collection row after row).
    heaps: RefCell<HashMap<usize, Rc<GlobalHeapCollection>>>,
}

impl<'b> H5<'b> {
    /// The file's superblock (at offset 0).
    pub(crate) fn open(path: &'b Path, bytes: &'b [u8], format: &'static str) -> Result<Self> {
        let f = Bin {
            bytes,
            path,
            format,
        };
        if !sniff(bytes) {
            return Err(f.bad("not an HDF5 file (no HDF5 signature at its start)"));
        }
        let sb = guarded(&f, "superblock", || Superblock::parse(bytes, 0))?;
        Ok(H5 {
            f,
            sb,
            heaps: RefCell::default(),
        })
    }

    pub(crate) fn bad(&self, message: impl std::fmt::Display) -> Error {
        self.f.bad(message)
    }

    pub(crate) fn offset_size(&self) -> usize {
        usize::from(self.sb.offset_size)
    }

    /// The object header at `address`.
    fn header(&self, address: u64) -> Result<ObjectHeader> {
        let at = usize::try_from(address)
            .ok()
            .filter(|&a| a < self.f.bytes.len())
            .ok_or_else(|| {
                self.bad(format!(
                    "truncated: an object header at {address} is past the end"
                ))
            })?;
        guarded(&self.f, &format!("object header at {address}"), || {
            ObjectHeader::parse(self.f.bytes, at, self.sb.offset_size, self.sb.length_size)
        })
    }

    /// The members of the group `header` (name, header address), by name.
    fn members(&self, header: &ObjectHeader) -> Result<Vec<(String, u64)>> {
        let (os, ls) = (self.sb.offset_size, self.sb.length_size);
        let bytes = self.f.bytes;
        let entries = if let Some(m) = message(header, MessageType::SymbolTable) {
            let stm = guarded(&self.f, "symbol table", || {
                SymbolTableMessage::parse(&m.data, os)
            })?;
            guarded(&self.f, "group", || {
                group_v1::resolve_v1_group_entries(bytes, &stm, os, ls)
            })?
        } else if is_group(header) {
            guarded(&self.f, "group", || {
                group_v2::resolve_v2_group_entries(bytes, header, os, ls)
            })?
        } else {
            return Ok(Vec::new());
        };
        let mut out: Vec<(String, u64)> = entries
            .into_iter()
            .map(|e| (e.name, e.object_header_address))
            .collect();
        out.sort_by(|a, b| a.0.as_bytes().cmp(b.0.as_bytes()));
        Ok(out)
    }

    /// Every data set (path without the leading `/`, header), depth-first
    /// with each group's members in name order.
    pub(crate) fn datasets(&self) -> Result<Vec<(String, ObjectHeader)>> {
        let mut out = Vec::new();
        let mut stack = vec![(String::new(), self.sb.root_group_address, 0usize)];
        let mut seen = std::collections::HashSet::new();
        while let Some((prefix, address, depth)) = stack.pop() {
            if !seen.insert(address) || depth > MAX_DEPTH {
                continue;
            }
            let header = self.header(address)?;
            if message(&header, MessageType::DataLayout).is_some() {
                out.push((prefix, header));
                continue;
            }
            for (name, child) in self.members(&header)?.into_iter().rev() {
                let p = if prefix.is_empty() {
                    name
                } else {
                    format!("{prefix}/{name}")
                };
                stack.push((p, child, depth + 1));
            }
        }
        Ok(out)
    }

    /// The object at `path` (`/a/b`), by walking the groups.
    pub(crate) fn object(&self, path: &str) -> Result<ObjectHeader> {
        let mut header = self.header(self.sb.root_group_address)?;
        for part in path.split('/').filter(|p| !p.is_empty()) {
            let members = self.members(&header)?;
            let (_, address) = members
                .iter()
                .find(|(n, _)| n == part)
                .ok_or_else(|| self.bad(format!("no object {path:?} (no {part:?})")))?;
            header = self.header(*address)?;
        }
        Ok(header)
    }

    /// The dimensions of a data set or attribute's dataspace message.
    pub(crate) fn shape(&self, header: &ObjectHeader) -> Result<Vec<usize>> {
        let m = message(header, MessageType::Dataspace)
            .ok_or_else(|| self.bad("a data set has no dataspace"))?;
        self.dataspace(&m.data).map(|(d, _)| d)
    }

    /// Dimensions and encoded length of a dataspace message.
    fn dataspace(&self, b: &[u8]) -> Result<(Vec<usize>, usize)> {
        let ls = usize::from(self.sb.length_size);
        let get = |i: usize| {
            b.get(i)
                .copied()
                .ok_or_else(|| self.bad("truncated: a dataspace"))
        };
        let (version, rank, flags) = (get(0)?, usize::from(get(1)?), get(2)?);
        let (start, kind) = match version {
            1 => (8, 1),
            2 => (4, get(3)?),
            v => return Err(self.bad(format!("dataspace version {v} is not read"))),
        };
        let mut dims = Vec::with_capacity(rank);
        for i in 0..rank {
            let at = start + i * ls;
            let field = b
                .get(at..at + ls)
                .ok_or_else(|| self.bad("truncated: a dataspace's dimensions"))?;
            let n = field
                .iter()
                .rev()
                .fold(0u64, |a, &x| (a << 8) | u64::from(x));
            dims.push(
                usize::try_from(n).map_err(|_| self.bad(format!("dimension {n} is too large")))?,
            );
        }
        let mut len = start + rank * ls;
        if flags & 1 != 0 {
            len += rank * ls;
        }
        if version == 1 && flags & 2 != 0 {
            len += rank * ls;
        }
        if kind == 2 {
            dims = vec![0];
        }
        Ok((dims, len))
    }

    /// The datatype of a data set, and the crate's reading of it.
    pub(crate) fn datatype(&self, header: &ObjectHeader) -> Result<(Type, usize)> {
        let m = message(header, MessageType::Datatype)
            .ok_or_else(|| self.bad("a data set has no datatype"))?;
        if m.flags & 2 != 0 {
            return Err(self.bad("a shared (committed) datatype is not read"));
        }
        datatype(&m.data).map_err(|e| self.bad(format!("datatype: {e}")))
    }

    /// The raw bytes of a data set (checked against the file's length first).
    pub(crate) fn read_raw(
        &self,
        header: &ObjectHeader,
        name: &str,
    ) -> Result<(Vec<usize>, Type, Vec<u8>)> {
        let (os, ls) = (self.sb.offset_size, self.sb.length_size);
        let shape = self.shape(header)?;
        let (ty, _) = self.datatype(header)?;
        let size = ty.size(self.offset_size());
        let total = shape
            .iter()
            .try_fold(size, |a, &n| a.checked_mul(n))
            .ok_or_else(|| self.bad(format!("{name}: {shape:?} elements are too many")))?;
        let layout_msg =
            message(header, MessageType::DataLayout).ok_or_else(|| self.bad("no layout"))?;
        if layout_msg.data.first() == Some(&5) {
            return Err(self.bad(format!(
                "{name}: layout message version 5 (HDF5 2.0) is not read"
            )));
        }
        let layout = guarded(&self.f, &format!("{name}: layout"), || {
            DataLayout::parse(&layout_msg.data, os, ls)
        })?;
        let limit = match layout {
            DataLayout::Chunked { .. } => self.f.bytes.len().saturating_mul(DEFLATE_RATIO),
            _ => self.f.bytes.len(),
        };
        if total > limit {
            return Err(self.bad(format!(
                "truncated: {name} needs {total} bytes, more than the {}-byte file holds",
                self.f.bytes.len()
            )));
        }
        if let DataLayout::Contiguous {
            address: Some(a),
            size: s,
        } = layout
        {
            if a.checked_add(s)
                .is_none_or(|end| end > self.f.bytes.len() as u64)
                || s != total as u64
            {
                return Err(self.bad(format!(
                    "truncated: {name}'s {s} bytes at {a} are past the end"
                )));
            }
        }
        let pipeline = match message(header, MessageType::FilterPipeline) {
            Some(m) => Some(guarded(&self.f, &format!("{name}: filters"), || {
                FilterPipeline::parse(&m.data)
            })?),
            None => None,
        };
        let crate_type = CrateType::Opaque {
            size: size as u32,
            tag: Vec::new(),
        };
        let dataspace = guarded(&self.f, &format!("{name}: dataspace"), || {
            Dataspace::parse(
                message(header, MessageType::Dataspace).map_or(&[][..], |m| &m.data),
                ls,
            )
        })?;
        if dataspace.dimensions.len() != shape.len()
            || dataspace
                .dimensions
                .iter()
                .zip(&shape)
                .any(|(&a, &b)| a != b as u64)
        {
            return Err(self.bad(format!("{name}: damaged dataspace")));
        }
        if let DataLayout::Chunked { .. } = layout {
            self.check_chunks(&layout, &shape, size, limit, name)?;
        }
        let raw = guarded(&self.f, &format!("{name}: data"), || {
            data_read::read_raw_data_full(
                self.f.bytes,
                &layout,
                &dataspace,
                &crate_type,
                pipeline.as_ref(),
                os,
                ls,
            )
        })?;
        if raw.len() != total {
            return Err(self.bad(format!(
                "{name}: {} bytes of data, {total} expected",
                raw.len()
            )));
        }
        Ok((shape, ty, raw))
    }

    /// Checks a chunked layout where `rustyhdf5-format` would panic on it:
    /// `rank + 1` chunk dimensions, none 0, a chunk of at most `limit`
    /// bytes, the chunk index in the file and sound (a fixed array's page
    /// bits under 64), every chunk's bytes in the file and its offsets in
    /// the data set.
    fn check_chunks(
        &self,
        layout: &DataLayout,
        shape: &[usize],
        size: usize,
        limit: usize,
        name: &str,
    ) -> Result<()> {
        let DataLayout::Chunked {
            chunk_dimensions: dims,
            btree_address,
            version,
            chunk_index_type,
            ..
        } = layout
        else {
            return Ok(());
        };
        let damaged = |what: &str| self.bad(format!("{name}: damaged chunked layout ({what})"));
        let (os, ls) = (self.sb.offset_size, self.sb.length_size);
        let len = self.f.bytes.len();
        if dims.len() != shape.len() + 1 {
            return Err(damaged(&format!(
                "{} chunk dimensions for rank {}",
                dims.len(),
                shape.len()
            )));
        }
        if dims.contains(&0) {
            return Err(damaged("a chunk dimension is 0"));
        }
        let spatial = &dims[..shape.len()];
        spatial
            .iter()
            .try_fold(size, |a, &d| a.checked_mul(d as usize))
            .filter(|&n| n <= limit && n <= u32::MAX as usize)
            .ok_or_else(|| damaged("a chunk is larger than the file allows"))?;
        let Some(address) = *btree_address else {
            return Ok(()); // the crate's error: no address
        };
        let at = usize::try_from(address)
            .ok()
            .filter(|&a| a < len)
            .ok_or_else(|| damaged(&format!("its chunk index at {address} is past the end")))?;
        let bytes = self.f.bytes;
        let what = format!("{name}: chunk index");
        let ds: Vec<u64> = shape.iter().map(|&n| n as u64).collect();
        let chunks: Vec<ChunkInfo> = match (version, chunk_index_type) {
            (3, _) => guarded(&self.f, &what, || {
                chunked_read::collect_chunk_info(bytes, address, dims.len(), os, ls)
            })?,
            (4, Some(3)) => {
                let h = guarded(&self.f, &what, || {
                    FixedArrayHeader::parse(bytes, at, os, ls)
                })?;
                let block_end = usize::try_from(h.data_block_address)
                    .ok()
                    .and_then(|a| a.checked_add(6 + usize::from(os)));
                if h.max_nelmts_bits >= 64 || block_end.is_none_or(|e| e > len) {
                    return Err(damaged("its fixed array"));
                }
                guarded(&self.f, &what, || {
                    fixed_array::read_fixed_array_chunks(
                        bytes,
                        &h,
                        &ds,
                        spatial,
                        size as u32,
                        os,
                        ls,
                    )
                })?
            }
            (4, Some(4)) => {
                let h = guarded(&self.f, &what, || {
                    ExtensibleArrayHeader::parse(bytes, at, os, ls)
                })?;
                if h.max_nelmts_bits >= 64
                    || h.max_dblk_nelmts_bits >= 64
                    || usize::try_from(h.index_block_address).is_ok_and(|a| a >= len)
                {
                    return Err(damaged("its extensible array"));
                }
                guarded(&self.f, &what, || {
                    extensible_array::read_extensible_array_chunks(
                        bytes,
                        &h,
                        &ds,
                        spatial,
                        size as u32,
                        os,
                        ls,
                    )
                })?
            }
            _ => return Ok(()), // single chunk, implicit: checked by the crate
        };
        for c in &chunks {
            let end = usize::try_from(c.address)
                .ok()
                .and_then(|a| a.checked_add(c.chunk_size as usize));
            if end.is_none_or(|e| e > len) {
                return Err(self.bad(format!(
                    "truncated: {name}'s chunk of {} bytes at {} is past the end",
                    c.chunk_size, c.address
                )));
            }
            if c.offsets.iter().zip(&ds).any(|(&o, &n)| o >= n.max(1)) {
                return Err(damaged("a chunk's offset is outside the data set"));
            }
        }
        Ok(())
    }

    /// A numeric data set as f64 (shape, values in storage order).
    pub(crate) fn read_f64(
        &self,
        header: &ObjectHeader,
        name: &str,
    ) -> Result<(Vec<usize>, Vec<f64>)> {
        let (shape, ty, raw) = self.read_raw(header, name)?;
        let values = numbers(&ty, &raw)
            .ok_or_else(|| self.bad(format!("{name}: {ty:?} is not a number type")))?;
        Ok((shape, values))
    }

    /// The attribute `name` of an object (compact storage), if it has one.
    pub(crate) fn attribute(&self, header: &ObjectHeader, name: &str) -> Result<Option<Attr>> {
        for m in header
            .messages
            .iter()
            .filter(|m| m.msg_type == MessageType::Attribute)
        {
            if m.flags & 2 != 0 {
                return Err(self.bad("a shared attribute is not read"));
            }
            let a = self.attribute_message(&m.data)?;
            if a.0 == name {
                return Ok(Some(a.1));
            }
        }
        if let Some(m) = message(header, MessageType::AttributeInfo) {
            // Version, flags, [max creation index], the fractal heap's address:
            // defined (not all ones) when attributes are in dense storage.
            let at = if m.data.get(1).is_some_and(|f| f & 1 != 0) {
                4
            } else {
                2
            };
            let heap = m.data.get(at..at + self.offset_size());
            if heap.is_none_or(|h| h.iter().any(|&b| b != 0xff)) {
                return Err(self.bad(format!(
                    "attribute {name:?}: attributes in dense storage are not read"
                )));
            }
        }
        Ok(None)
    }

    /// One attribute message: name and value.
    fn attribute_message(&self, b: &[u8]) -> Result<(String, Attr)> {
        let cut = || self.bad("truncated: an attribute message");
        let u16_at = |i: usize| {
            b.get(i..i + 2)
                .map(|s| usize::from(u16::from_le_bytes([s[0], s[1]])))
        };
        let version = *b.first().ok_or_else(cut)?;
        let (name_len, type_len, space_len) = (
            u16_at(2).ok_or_else(cut)?,
            u16_at(4).ok_or_else(cut)?,
            u16_at(6).ok_or_else(cut)?,
        );
        let (pad, mut at): (fn(usize) -> usize, usize) = match version {
            1 => (|n| n.div_ceil(8) * 8, 8),
            2 => (|n| n, 8),
            3 => (|n| n, 9),
            v => return Err(self.bad(format!("attribute message version {v} is not read"))),
        };
        if version >= 2 && b.get(1).is_some_and(|f| f & 3 != 0) {
            return Err(self.bad("an attribute with a shared datatype or dataspace is not read"));
        }
        let name_bytes = b.get(at..at + name_len).ok_or_else(cut)?;
        let name = String::from_utf8_lossy(name_bytes)
            .trim_end_matches('\0')
            .to_string();
        at += pad(name_len);
        let (ty, _) = datatype(b.get(at..at + type_len).ok_or_else(cut)?)
            .map_err(|e| self.bad(format!("attribute {name:?}: {e}")))?;
        at += pad(type_len);
        let (dims, _) = self.dataspace(b.get(at..at + space_len).ok_or_else(cut)?)?;
        at += pad(space_len);
        let count = dims
            .iter()
            .try_fold(1usize, |a, &n| a.checked_mul(n))
            .ok_or_else(cut)?;
        let len = count
            .checked_mul(ty.size(self.offset_size()))
            .ok_or_else(cut)?;
        let data = b.get(at..at.saturating_add(len)).ok_or_else(cut)?.to_vec();
        Ok((name, Attr { ty, count, data }))
    }

    /// The strings of `count` elements of type `ty` in `raw` (fixed-length,
    /// trailing NULs and spaces dropped, or variable-length).
    pub(crate) fn string(&self, ty: &Type, raw: &[u8]) -> Result<String> {
        match ty {
            Type::Str { .. } => Ok(String::from_utf8_lossy(raw)
                .trim_end_matches(['\0', ' '])
                .split('\0')
                .next()
                .unwrap_or_default()
                .to_string()),
            Type::VlStr => {
                let os = self.offset_size();
                let cut = || self.bad("truncated: a variable-length string");
                let len = raw.get(0..4).ok_or_else(cut)?;
                let len = u32::from_le_bytes([len[0], len[1], len[2], len[3]]) as usize;
                let addr = raw.get(4..4 + os).ok_or_else(cut)?;
                let addr = addr
                    .iter()
                    .rev()
                    .fold(0u64, |a, &x| (a << 8) | u64::from(x));
                let index = raw.get(4 + os..8 + os).ok_or_else(cut)?;
                let index = u32::from_le_bytes([index[0], index[1], index[2], index[3]]);
                if len == 0 {
                    return Ok(String::new());
                }
                let at = usize::try_from(addr)
                    .ok()
                    .filter(|&a| a < self.f.bytes.len())
                    .ok_or_else(cut)?;
                let heap = self.global_heap(at)?;
                let object = u16::try_from(index)
                    .ok()
                    .and_then(|i| heap.get_object(i))
                    .ok_or_else(cut)?;
                let s = object.data.get(..len).ok_or_else(cut)?;
                Ok(String::from_utf8_lossy(s)
                    .trim_end_matches('\0')
                    .to_string())
            }
            other => Err(self.bad(format!("{other:?} is not a string type"))),
        }
    }
}

impl H5<'_> {
    /// The global heap collection at `at` (< the file's length), parsed once.
    fn global_heap(&self, at: usize) -> Result<Rc<GlobalHeapCollection>> {
        if let Some(h) = self.heaps.borrow().get(&at) {
            return Ok(Rc::clone(h));
        }
        let ls = usize::from(self.sb.length_size);
        // The collection's size: `at + size` must not overflow.
        let size = self
            .f
            .bytes
            .get(at + 8..)
            .and_then(|b| b.get(..ls))
            .map(|b| b.iter().rev().fold(0u64, |a, &x| (a << 8) | u64::from(x)));
        if size.is_some_and(|n| {
            usize::try_from(n)
                .ok()
                .and_then(|n| at.checked_add(n))
                .is_none()
        }) {
            return Err(self.bad(format!("damaged global heap at {at}")));
        }
        let heap = Rc::new(guarded(&self.f, &format!("global heap at {at}"), || {
            GlobalHeapCollection::parse(self.f.bytes, at, self.sb.length_size)
        })?);
        self.heaps.borrow_mut().insert(at, Rc::clone(&heap));
        Ok(heap)
    }
}

fn message(
    header: &ObjectHeader,
    t: MessageType,
) -> Option<&rustyhdf5_format::object_header::HeaderMessage> {
    header.messages.iter().find(|m| m.msg_type == t)
}

fn is_group(header: &ObjectHeader) -> bool {
    header.messages.iter().any(|m| {
        matches!(
            m.msg_type,
            MessageType::LinkInfo | MessageType::Link | MessageType::SymbolTable
        )
    })
}

/// Integers or floats of `ty` in `raw` as f64, or `None` for other types.
pub(crate) fn numbers(ty: &Type, raw: &[u8]) -> Option<Vec<f64>> {
    let (size, be) = match *ty {
        Type::Int { size, be, .. } | Type::Float { size, be } => (size, be),
        _ => return None,
    };
    if !matches!(size, 1 | 2 | 4 | 8) || !raw.len().is_multiple_of(size) {
        return None;
    }
    let word = |c: &[u8]| {
        let mut a = [0u8; 8];
        if be {
            a[..size].copy_from_slice(c);
            a[..size].reverse();
        } else {
            a[..size].copy_from_slice(c);
        }
        u64::from_le_bytes(a)
    };
    let one = |c: &[u8]| -> f64 {
        let w = word(c);
        match *ty {
            Type::Float { size: 8, .. } => f64::from_bits(w),
            Type::Float { size: 4, .. } => f64::from(f32::from_bits(w as u32)),
            Type::Int { signed: true, .. } => {
                let shift = 64 - 8 * size as u32;
                ((w << shift) as i64 >> shift) as f64
            }
            _ => w as f64,
        }
    };
    if matches!(ty, Type::Float { size: 1 | 2, .. }) {
        return None;
    }
    Some(raw.chunks_exact(size).map(one).collect())
}

/// A datatype message: the type and its encoded length.
pub(crate) fn datatype(b: &[u8]) -> std::result::Result<(Type, usize), String> {
    datatype_at(b, 0)
}

fn datatype_at(b: &[u8], depth: usize) -> std::result::Result<(Type, usize), String> {
    if depth > 8 {
        return Err("datatypes nested too deeply".into());
    }
    let cut = || "truncated datatype".to_string();
    let head = b.get(0..8).ok_or_else(cut)?;
    let (class, version) = (head[0] & 0x0f, head[0] >> 4);
    let bits = u32::from_le_bytes([head[1], head[2], head[3], 0]);
    let size = u32::from_le_bytes([head[4], head[5], head[6], head[7]]) as usize;
    let be = bits & 1 != 0;
    Ok(match class {
        0 => (
            Type::Int {
                size,
                signed: bits & 8 != 0,
                be,
            },
            12,
        ),
        1 => {
            if bits & 0x40 != 0 {
                return Err("VAX-order floats are not read".into());
            }
            (Type::Float { size, be }, 20)
        }
        2 => (Type::Other { class, size }, 10),
        3 => (Type::Str { size }, 8),
        4 => (Type::Other { class, size }, 12),
        5 => (Type::Other { class, size }, 8 + (bits & 0xff) as usize),
        6 => compound(b, version, bits, size, depth)?,
        7 => (Type::Other { class, size }, 8),
        8 => {
            let (_, base_len) = datatype_at(b.get(8..).ok_or_else(cut)?, depth + 1)?;
            let n = (bits & 0xffff) as usize;
            let mut at = 8 + base_len;
            for _ in 0..n {
                let end = b
                    .get(at..)
                    .and_then(|r| r.iter().position(|&c| c == 0))
                    .ok_or_else(cut)?;
                at += if version >= 3 {
                    end + 1
                } else {
                    (end + 1).div_ceil(8) * 8
                };
            }
            (
                Type::Other { class, size },
                at + n.checked_mul(size).ok_or_else(cut)?,
            )
        }
        9 => {
            let (_, base_len) = datatype_at(b.get(8..).ok_or_else(cut)?, depth + 1)?;
            let t = if bits & 0x0f == 1 {
                Type::VlStr
            } else {
                Type::Other { class, size }
            };
            (t, 8 + base_len)
        }
        10 => {
            let rank = usize::from(*b.get(8).ok_or_else(cut)?);
            let dims_at = if version >= 3 { 9 } else { 12 };
            let mut count = 1usize;
            for i in 0..rank {
                let d = b
                    .get(dims_at + 4 * i..dims_at + 4 * i + 4)
                    .ok_or_else(cut)?;
                count = count
                    .checked_mul(u32::from_le_bytes([d[0], d[1], d[2], d[3]]) as usize)
                    .ok_or_else(cut)?;
            }
            let base_at = dims_at + 4 * rank + if version >= 3 { 0 } else { 4 * rank };
            let (base, base_len) = datatype_at(b.get(base_at..).ok_or_else(cut)?, depth + 1)?;
            (
                Type::Array {
                    count,
                    base: Box::new(base),
                },
                base_at + base_len,
            )
        }
        c => return Err(format!("datatype class {c} is not read")),
    })
}

/// A compound datatype (versions 1–3): its members and encoded length.
fn compound(
    b: &[u8],
    version: u8,
    bits: u32,
    size: usize,
    depth: usize,
) -> std::result::Result<(Type, usize), String> {
    let cut = || "truncated compound datatype".to_string();
    let n = (bits & 0xffff) as usize;
    let offset_len = match size {
        0..=0xff => 1,
        0x100..=0xffff => 2,
        0x1_0000..=0xff_ffff => 3,
        _ => 4,
    };
    let mut members = Vec::new();
    let mut at = 8;
    for _ in 0..n {
        let end = b
            .get(at..)
            .and_then(|r| r.iter().position(|&c| c == 0))
            .ok_or_else(cut)?;
        let name = String::from_utf8_lossy(&b[at..at + end]).into_owned();
        at += if version >= 3 {
            end + 1
        } else {
            (end + 1).div_ceil(8) * 8
        };
        let width = if version >= 3 { offset_len } else { 4 };
        let off = b.get(at..at + width).ok_or_else(cut)?;
        let offset = off
            .iter()
            .rev()
            .fold(0usize, |a, &x| (a << 8) | usize::from(x));
        at += width;
        let mut count = 1usize;
        if version == 1 {
            let rank = usize::from(*b.get(at).ok_or_else(cut)?);
            for i in 0..rank.min(4) {
                let d = b.get(at + 12 + 4 * i..at + 16 + 4 * i).ok_or_else(cut)?;
                count = count.saturating_mul(u32::from_le_bytes([d[0], d[1], d[2], d[3]]) as usize);
            }
            at += 28;
        }
        let (ty, len) = datatype_at(b.get(at..).ok_or_else(cut)?, depth + 1)?;
        at += len;
        let ty = if count == 1 {
            ty
        } else {
            Type::Array {
                count,
                base: Box::new(ty),
            }
        };
        members.push((name, offset, ty));
    }
    Ok((Type::Compound { size, members }, at))
}
