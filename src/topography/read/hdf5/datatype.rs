//! HDF5 datatype messages, and the numbers stored in a numeric type.
//!
//! A datatype message opens with 8 bytes: class (low nibble) and version
//! (high nibble), 24 class bit fields, the element size in bytes; the
//! properties follow, their length depending on the class. Decoded: fixed-point
//! integers (class 0: byte order, sign), IEEE floats (class 1: byte order;
//! VAX order refused), fixed-length strings (class 3), variable-length
//! strings (class 9 with type 1), compounds (class 6, versions 1–3: version 1
//! members may be arrays of up to 4 dimensions) and arrays (class 10). The
//! other classes (time, bit field, opaque, reference, enumeration, other
//! variable-length types) are kept as their class and size, their encoded
//! length skipped; a class above 10 is an error.
//! The crate's own decoding is not used: it is wrong for version 1 compounds
//! and misses array types in version 3 ones.

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
