//! A data set's bytes: its layout message, chunk index and filter pipeline.
//!
//! Layout messages 3 and 4 are read by `rustyhdf5-format`: contiguous,
//! compact and chunked storage, the chunk indexes (a v1 B-tree for version
//! 3; single chunk, implicit, fixed array or extensible array for version
//! 4) and the filters (deflate, shuffle, Fletcher32). Before the crate reads
//! the data, its size is checked: at most the file's length, or for chunked
//! data 1032 times it (deflate's largest ratio); a contiguous block must lie
//! in the file and hold exactly the data set; a chunked layout's dimensions,
//! chunk index and every chunk are checked where the crate would panic on
//! them (see the `guard` module).

use rustyhdf5_format::chunked_read::{self, ChunkInfo};
use rustyhdf5_format::data_layout::DataLayout;
use rustyhdf5_format::data_read;
use rustyhdf5_format::dataspace::Dataspace;
use rustyhdf5_format::datatype::Datatype as CrateType;
use rustyhdf5_format::extensible_array::{self, ExtensibleArrayHeader};
use rustyhdf5_format::filter_pipeline::FilterPipeline;
use rustyhdf5_format::fixed_array::{self, FixedArrayHeader};
use rustyhdf5_format::message_type::MessageType;
use rustyhdf5_format::object_header::ObjectHeader;

use super::datatype::{numbers, Type};
use super::file::{message, H5};
use super::guard::guarded;
use crate::error::Result;

/// Deflate's largest compression ratio: the bound on a chunked data set's size.
const DEFLATE_RATIO: usize = 1032;

impl H5<'_> {
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
}
