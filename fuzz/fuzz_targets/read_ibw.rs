//! The Igor binary wave .ibw reader: any bytes named `fuzz.ibw` (and the same bytes under
//! a name without extension, detected by content) give a topography with
//! finite heights and sizes or an error, never a panic, an overflow or an
//! allocation beyond the file's size.
//!
//! Seeds: `tests/data/*.ibw` (run from the repository root; libFuzzer
//! writes new inputs to the first directory, the seeds are copied there):
//! `mkdir -p fuzz/corpus/read_ibw && cp tests/data/*.ibw fuzz/corpus/read_ibw/`
//! `cargo +nightly fuzz run read_ibw --features topography fuzz/corpus/read_ibw -- -max_len=3000000`
#![no_main]

use libfuzzer_sys::fuzz_target;
use persson::topography::read::{from_bytes, ReadOptions};

fuzz_target!(|data: &[u8]| {
    for (name, fill) in [("fuzz.ibw", true), ("fuzz", false)] {
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
