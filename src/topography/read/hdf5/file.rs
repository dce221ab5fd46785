//! An open HDF5 file: superblock, object headers, groups and dataspaces.
//!
//! The groups are old-style (a symbol table message: a v1 B-tree and a local
//! heap) or new-style (link messages, compact or in a fractal heap); both are
//! resolved by `rustyhdf5-format`, and their members sorted by name, as
//! h5py's `visititems` visits them. Dataspace messages (versions 1 and 2) are
//! decoded here: the dimensions are `length size`-byte little-endian fields;
//! a null dataspace (version 2, type 2) reads as one empty dimension.

use std::cell::RefCell;
use std::collections::{HashMap, HashSet};
use std::path::Path;
use std::rc::Rc;

use rustyhdf5_format::global_heap::GlobalHeapCollection;
use rustyhdf5_format::message_type::MessageType;
use rustyhdf5_format::object_header::{HeaderMessage, ObjectHeader};
use rustyhdf5_format::superblock::Superblock;
use rustyhdf5_format::symbol_table::SymbolTableMessage;
use rustyhdf5_format::{group_v1, group_v2};

use super::super::bin::Bin;
use super::datatype::{datatype, Type};
use super::guard::guarded;
use super::sniff;
use crate::error::{Error, Result};

/// Deepest group nesting followed (a loop of hard links ends here).
const MAX_DEPTH: usize = 32;

/// An open HDF5 file: its bytes and superblock; errors name the file and
/// the format.
pub(crate) struct H5<'b> {
    pub f: Bin<'b>,
    pub(super) sb: Superblock,
    /// Global heap collections parsed so far, by address (a table of
    /// variable-length strings refers to one collection row after row).
    pub(super) heaps: RefCell<HashMap<usize, Rc<GlobalHeapCollection>>>,
}

impl<'b> H5<'b> {
    /// The file's superblock (at offset 0).
    pub(crate) fn open(path: &'b Path, bytes: &'b [u8], format: &'static str) -> Result<Self> {
        let f = Bin::new(bytes, path, format);
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
        let mut seen = HashSet::new();
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
    pub(super) fn dataspace(&self, b: &[u8]) -> Result<(Vec<usize>, usize)> {
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
}

/// The first message of type `t` in an object header.
pub(super) fn message(header: &ObjectHeader, t: MessageType) -> Option<&HeaderMessage> {
    header.messages.iter().find(|m| m.msg_type == t)
}

/// Whether an object header is a group's (link info, link or symbol table
/// messages).
fn is_group(header: &ObjectHeader) -> bool {
    header.messages.iter().any(|m| {
        matches!(
            m.msg_type,
            MessageType::LinkInfo | MessageType::Link | MessageType::SymbolTable
        )
    })
}
