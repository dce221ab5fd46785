//! HDF5 attributes (compact storage) and string values.
//!
//! An attribute message (versions 1–3) holds the attribute's name, its
//! datatype and dataspace messages and its value; in version 1 each of the
//! three is padded to a multiple of 8 bytes. Attributes in dense storage (a
//! fractal heap named by the attribute info message) and shared datatypes
//! or dataspaces are refused. A string is fixed-length (trailing NULs and
//! spaces dropped) or variable-length: a reference (length, global heap
//! collection address, object index) into a global heap, whose size is
//! checked before the collection is parsed (`offset + size` must not
//! overflow).

use std::rc::Rc;

use rustyhdf5_format::global_heap::GlobalHeapCollection;
use rustyhdf5_format::message_type::MessageType;
use rustyhdf5_format::object_header::ObjectHeader;

use super::datatype::{datatype, Type};
use super::file::{message, H5};
use super::guard::guarded;
use crate::error::Result;

/// An attribute: its type, number of elements and raw value.
pub(crate) struct Attr {
    pub ty: Type,
    pub count: usize,
    pub data: Vec<u8>,
}

impl H5<'_> {
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
