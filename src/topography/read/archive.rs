//! Members of zip archives (`.x3p`, `.xlsx`, contact.engineering datasets),
//! read whole but bounded, one policy for all: a member may inflate to at
//! most [`MAX_RATIO`] times its compressed size (deflate's largest ratio,
//! so no genuine member exceeds it) and never beyond `limit` bytes (the
//! caller's: [`MAX_MEMBER`] for data, less for XML that is parsed into a
//! tree). A member that claims or reaches more is an error, read no further:
//! a small archive cannot make the reader allocate gigabytes.

use std::io::{Cursor, Read};
use std::path::Path;

use crate::error::{Error, Result};

/// An archive read from memory.
pub(crate) type Archive<'b> = zip::ZipArchive<Cursor<&'b [u8]>>;

/// Deflate's largest compression ratio (258-byte matches of 2 bits, ~1032:1).
pub(crate) const MAX_RATIO: u64 = 1032;

/// The largest member read for data (2 GiB, as a gzip-compressed file).
pub(crate) const MAX_MEMBER: u64 = 1 << 31;

/// The member `name` of `zip`, whole, at most `limit` bytes and
/// [`MAX_RATIO`] times its compressed size; errors name `path` and start
/// with `format`.
pub(crate) fn member(
    zip: &mut Archive,
    path: &Path,
    format: &str,
    name: &str,
    limit: u64,
) -> Result<Vec<u8>> {
    let bad = |m: String| Error::parse(path, 0, 0, format!("{format}: {m}"));
    let file = zip
        .by_name(name)
        .map_err(|e| bad(format!("the archive has no readable member {name:?}: {e}")))?;
    let bound = limit.min(file.compressed_size().saturating_mul(MAX_RATIO).max(4096));
    if file.size() > bound {
        return Err(bad(format!(
            "member {name:?} claims {} bytes from {} compressed: more than {bound} is not read",
            file.size(),
            file.compressed_size()
        )));
    }
    let mut data = Vec::new();
    file.take(bound + 1)
        .read_to_end(&mut data)
        .map_err(|e| bad(format!("member {name:?} is unreadable or truncated: {e}")))?;
    if data.len() as u64 > bound {
        return Err(bad(format!(
            "member {name:?} inflates beyond {bound} bytes"
        )));
    }
    Ok(data)
}

#[cfg(test)]
mod tests {
    use std::io::Write;

    use super::*;

    fn zip_of(name: &str, bytes: &[u8]) -> Vec<u8> {
        let mut zw = zip::ZipWriter::new(Cursor::new(Vec::new()));
        let o = zip::write::SimpleFileOptions::default()
            .compression_method(zip::CompressionMethod::Deflated);
        zw.start_file(name, o).unwrap();
        zw.write_all(bytes).unwrap();
        zw.finish().unwrap().into_inner()
    }

    #[test]
    fn members_are_bounded_by_the_limit_and_the_ratio() {
        let zeros = vec![0u8; 1 << 20];
        let bytes = zip_of("z", &zeros);
        let mut zip = Archive::new(Cursor::new(&bytes[..])).unwrap();
        let p = Path::new("a.zip");
        assert_eq!(
            member(&mut zip, p, "F", "z", MAX_MEMBER).unwrap().len(),
            1 << 20
        );
        let e = member(&mut zip, p, "F", "z", 1000).unwrap_err().to_string();
        assert!(
            e.starts_with("a.zip") && e.contains("F: member \"z\" claims 1048576 bytes"),
            "{e}"
        );
        let e = member(&mut zip, p, "F", "y", MAX_MEMBER)
            .unwrap_err()
            .to_string();
        assert!(e.contains("no readable member \"y\""), "{e}");
    }
}
