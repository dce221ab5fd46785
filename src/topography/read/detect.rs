//! The format of a file: by an unambiguous extension, else by content; and
//! the binary formats persson does not read, named as such.

use std::path::Path;

use super::{
    al3d, bcr, datx, di, frt, gsf, gwy, hdf5, metropro, mi, mitutoyo, mnt, netcdf, nid, nms, opdx,
    park, sdf, sur, tmd, wsxm, wyko, Format,
};
use crate::error::{Error, Result};

/// Extensions of binary instrument formats persson does not read (a `.zip`
/// that is a contact.engineering dataset is read before this list is
/// consulted; a `.tif` goes by its content: a Park Systems TIFF is read, a
/// plain one is refused by `MAGICS`).
const UNSUPPORTED: &[&str] = &[
    "plux", "lext", "vk3", "vk4", "vk6", "vk7", "zon", "zmg", "os3d", "oir", "poir", "jpk", "mat",
    "ezd", "mdt", "xls", "zip", "npz", "hgt", "dzi", "qep", "nmm", "ps",
];

/// Leading bytes of binary formats persson does not read, with their names
/// (checked after the formats it reads: an HDF5 file is read as `.h5` or
/// `.datx`, a Park Systems TIFF as such).
const MAGICS: &[(&[u8], &str)] = &[
    (b"GWYO", "Gwyddion 1 .gwy"),
    (b"II*\x00", "TIFF"),
    (b"MM\x00*", "TIFF"),
    (b"MATLAB", "MATLAB .mat"),
    (b"VK3_", "Keyence .vk3"),
    (b"VK4_", "Keyence .vk4"),
    (b"VK6", "Keyence .vk6"),
    (b"VK7", "Keyence .vk7"),
    (b"KPK0", "Keyence .zon"),
    (b"KPK1", "Keyence .zon"),
    (b"Zeta-Instruments", "KLA Zeta .zmg"),
    (b"OmniSurf3D", "OmniSurf3D .os3d"),
    (b"\x01\xb0\x93\xff", "NT-MDT .mdt"),
    (b"\x1f\x8b", "gzip-compressed twice"),
];

/// What persson reads, for the error on a format it does not.
pub(crate) const READS: &str = "persson reads .npy, text (a matrix, XYZ triples or a line \
     scan, in .txt, .csv, .dat, .asc or .xyz), Gwyddion .gsf and .gwy, Digital Surf .sur and \
     Mountains .mnt, Zygo MetroPro .dat and .datx, NetCDF .nc, HDF5 .h5, Alicona .al3d, \
     Sensofar .plu, Igor binary wave .ibw (Asylum Research), Bruker Nanoscope .spm/.di/.000, \
     Bruker Dektak .opdx, Wyko .opd, FRT MicroProf .frt, Molecular Imaging .mi, WSxM \
     .stp/.top, Nanosurf .nid, NanoFocus .nms, Park Systems .tiff, Mitutoyo SurfTest .xlsx, \
     ISO 25178-71 .sdf, TrueMap .tmd, BCR-STM .bcr/.bcrf and ISO 25178-72 .x3p, each also \
     gzip-compressed (.gz), and contact.engineering datasets (.zip); export to GSF or x3p \
     with Gwyddion or SurfaceTopography";

fn unsupported(path: &Path, what: &str) -> Error {
    Error::parse(path, 0, 0, format!("unsupported format ({what}): {READS}"))
}

/// The format of `bytes` read from `path` (module docs).
///
/// # Errors
/// [`Error::Parse`] "unsupported format (…)" for an extension or content
/// of a binary format persson does not read, or binary data that is none
/// of the formats it reads.
pub(crate) fn format(path: &Path, bytes: &[u8]) -> Result<Format> {
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    match ext.as_deref() {
        Some("npy") => return Ok(Format::Npy),
        Some("gsf") => return Ok(Format::Gsf),
        Some("x3p") => return Ok(Format::X3p),
        Some("xyz") => return Ok(Format::Xyz),
        Some("gwy") => return Ok(Format::Gwy),
        Some("sur") => return Ok(Format::Sur),
        Some("nc") => return Ok(Format::NetCdf),
        Some("al3d") => return Ok(Format::Al3d),
        Some("plu" | "apx") => return Ok(Format::Plu),
        Some("ibw") => return Ok(Format::Ibw),
        Some("spm" | "di") => return Ok(Format::Nanoscope),
        Some("sdf") => return Ok(Format::Sdf),
        Some("tmd") => return Ok(Format::TrueMap),
        Some("bcr" | "bcrf") => return Ok(Format::Bcr),
        Some("frt") => return Ok(Format::Frt),
        Some("mi") => return Ok(Format::Mi),
        Some("stp" | "top" | "wsxm") => return Ok(Format::Wsxm),
        Some("opdx") => return Ok(Format::Opdx),
        Some("tiff") => return Ok(Format::ParkTiff),
        Some("xlsx") => return Ok(Format::Mitutoyo),
        Some("mnt") => return Ok(Format::Mountains),
        Some("opd") => return Ok(Format::Wyko),
        Some("nid") => return Ok(Format::Nanosurf),
        Some("nms") => return Ok(Format::NanoFocus),
        Some("h5" | "hdf5") => return Ok(Format::Hdf5),
        Some("datx") => return Ok(Format::Datx),
        Some(e) if UNSUPPORTED.contains(&e) => return Err(unsupported(path, &format!(".{e}"))),
        _ => {}
    }
    if bytes.starts_with(crate::io::npy::MAGIC) {
        return Ok(Format::Npy);
    }
    if bytes.starts_with(gsf::MAGIC) {
        return Ok(Format::Gsf);
    }
    if metropro::MAGICS.iter().any(|m| bytes.starts_with(m)) {
        return Ok(Format::MetroPro);
    }
    if bytes.starts_with(netcdf::MAGIC) {
        return Ok(Format::NetCdf);
    }
    if bytes.starts_with(gwy::MAGIC) {
        return Ok(Format::Gwy);
    }
    if bytes.starts_with(sur::MAGIC) || bytes.starts_with(sur::MAGIC_COMPRESSED) {
        return Ok(Format::Sur);
    }
    if bcr::is_bcr(bytes) {
        return Ok(Format::Bcr);
    }
    if bytes.starts_with(tmd::MAGIC) {
        return Ok(Format::TrueMap);
    }
    if bytes.starts_with(sdf::MAGIC_ASCII) || bytes.starts_with(sdf::MAGIC_BINARY) {
        return Ok(Format::Sdf);
    }
    if bytes.starts_with(di::MAGIC) {
        return Ok(Format::Nanoscope);
    }
    if bytes.starts_with(al3d::MAGIC) {
        return Ok(Format::Al3d);
    }
    for (sniff, format) in [
        (frt::sniff as fn(&[u8]) -> bool, Format::Frt),
        (mi::sniff, Format::Mi),
        (wsxm::sniff, Format::Wsxm),
        (opdx::sniff, Format::Opdx),
        (park::sniff, Format::ParkTiff),
        (mitutoyo::sniff, Format::Mitutoyo),
        (mnt::sniff, Format::Mountains),
        (wyko::sniff, Format::Wyko),
        (nid::sniff, Format::Nanosurf),
        (nms::sniff, Format::NanoFocus),
        (datx::sniff, Format::Datx),
        (hdf5::sniff, Format::Hdf5),
    ] {
        if sniff(bytes) {
            return Ok(format);
        }
    }
    if bytes.starts_with(b"PK\x03\x04") {
        return Ok(Format::X3p);
    }
    if let Some((_, name)) = MAGICS.iter().find(|(m, _)| bytes.starts_with(m)) {
        return Err(unsupported(path, name));
    }
    let text_bom = bytes.starts_with(b"\xFF\xFE") || bytes.starts_with(b"\xFE\xFF");
    if !text_bom && bytes.contains(&0) {
        let what = match ext.as_deref() {
            Some(e) => format!(".{e}, binary data"),
            None => "binary data".into(),
        };
        return Err(unsupported(path, &what));
    }
    Ok(Format::Text)
}
