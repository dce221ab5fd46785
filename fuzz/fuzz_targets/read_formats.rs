//! Every reader of issue 40 (and those of .sdf, .tmd, .bcrf, gzip and
//! contact.engineering datasets): the first byte of the input chooses the
//! file name (so the extension chooses the format, the last name none: by
//! content), the rest are the file. Any input gives a topography with
//! finite heights and sizes or an error, never a panic, an overflow or an
//! allocation beyond what the file can hold.
//!
//! Seeds: the example files, each prefixed with the byte of its extension's
//! index in `NAMES` (run from the repository root):
//! `mkdir -p fuzz/corpus/read_formats; i=0; for e in frt-2.frt opd-1-crop.opd opdx-3.opdx mi-1-crop.mi stp-1-crop.stp top-1.top nid-1-crop.nid nms-1-crop.nms mnt-1-crop.mnt example_ps-crop.tiff mitutoyo_mock.xlsx multiple_data_sets-crop.h5 datx-float32.datx sdf-2-binary.sdf tmd-1.tmd bcrf-1-crop.bcrf matrix-4.txt.gz container-2.zip; do { printf "\\x$(printf %02x $i)"; cat tests/data/$e; } > fuzz/corpus/read_formats/$e; i=$((i + 1)); done`
//! `cargo +nightly fuzz run read_formats --features topography fuzz/corpus/read_formats -- -max_len=400000`
#![no_main]

use libfuzzer_sys::fuzz_target;
use persson::topography::read::{from_bytes, ReadOptions};

const NAMES: &[&str] = &[
    "f.frt", "f.opd", "f.opdx", "f.mi", "f.stp", "f.top", "f.nid", "f.nms", "f.mnt", "f.tiff",
    "f.xlsx", "f.h5", "f.datx", "f.sdf", "f.tmd", "f.bcrf", "f.txt.gz", "f.zip", "fuzz",
];

fuzz_target!(|data: &[u8]| {
    let Some((&first, bytes)) = data.split_first() else {
        return;
    };
    let name = NAMES[usize::from(first) % NAMES.len()];
    for channel in [None, Some("1".to_string())] {
        let options = ReadOptions {
            fill_undefined: bytes.len() < 1 << 16,
            channel,
            ..Default::default()
        };
        if let Ok(t) = from_bytes(std::path::Path::new(name), bytes, &options) {
            assert!(
                t.heights().iter().all(|h| h.is_finite()),
                "{name}: non-finite height"
            );
            assert!(
                t.lx() > 0.0 && t.lx().is_finite(),
                "{name}: Lx = {}",
                t.lx()
            );
            assert_eq!(t.heights().len(), t.nx() * t.ny());
        }
    }
});
