//! The Alicona .al3d reader: any bytes named `fuzz.al3d` (and the same bytes under
//! a name without extension, detected by content) give a topography with
//! finite heights and sizes or an error, never a panic, an overflow or an
//! allocation beyond the file's size.
//!
//! Seeds: `tests/data/al3d-1.al3d` (run from the repository root; libFuzzer
//! writes new inputs to the first directory, the seeds are copied there):
//! `mkdir -p fuzz/corpus/read_al3d && cp tests/data/al3d-1.al3d fuzz/corpus/read_al3d/`
//! `cargo +nightly fuzz run read_al3d --features topography fuzz/corpus/read_al3d -- -max_len=3000000`
#![no_main]

use libfuzzer_sys::fuzz_target;
use persson::topography::read::{from_bytes, ReadOptions};

fuzz_target!(|data: &[u8]| {
    for (name, fill) in [("fuzz.al3d", true), ("fuzz", false)] {
        let options = ReadOptions {
            fill_undefined: fill && data.len() < 1 << 16,
            ..Default::default()
        };
        if let Ok(t) = from_bytes(std::path::Path::new(name), data, &options) {
            assert!(t.heights().iter().all(|h| h.is_finite()), "{name}: non-finite height");
            assert!(t.lx() > 0.0 && t.lx().is_finite(), "{name}: Lx = {}", t.lx());
            assert_eq!(t.heights().len(), t.nx() * t.ny());
        }
    }
});
