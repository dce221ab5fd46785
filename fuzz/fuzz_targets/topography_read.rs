//! Measured-surface readers (every format, detection by content, text in
//! UTF-8/UTF-16/Latin-1, headers, units, x3p masks, line scans that are
//! resampled): any bytes under any name must give a topography or an error,
//! never a panic; a topography must have finite heights and sizes, and its
//! analysis (spectrum, statistics, Hurst fit, 1D → 2D conversion) must end in
//! a result or an error.
//!
//! Seeds: the instrument files of `tests/data/` (run from the repository
//! root; libFuzzer writes new inputs to the first directory):
//! `cargo +nightly fuzz run topography_read --features topography fuzz/corpus/topography_read tests/data`
#![no_main]

use libfuzzer_sys::fuzz_target;
use persson::topography::read::{from_bytes, ReadOptions, SizeSpec};
use persson::topography::{analyse, AnalysisOptions};

const NAMES: [&str; 11] = [
    "fuzz.npy", "fuzz.txt", "fuzz.csv", "fuzz.dat", "fuzz.xyz", "fuzz.gsf", "fuzz.x3p", "fuzz.gwy",
    "fuzz.sur", "fuzz.nc", "fuzz",
];

fuzz_target!(|data: &[u8]| {
    for (k, name) in NAMES.iter().enumerate() {
        let options = ReadOptions {
            size: (k % 2 == 0).then_some(SizeSpec::PixelSize(1e-6)),
            fill_undefined: k % 3 == 0,
            transpose: k == 1,
            ..Default::default()
        };
        let Ok(t) = from_bytes(std::path::Path::new(name), data, &options) else {
            continue;
        };
        assert!(t.heights().iter().all(|h| h.is_finite()), "{name}: non-finite height");
        assert!(t.lx() > 0.0 && t.lx().is_finite(), "{name}: Lx = {}", t.lx());
        assert_eq!(t.heights().len(), t.nx() * t.ny());
        // Large grids would make a fuzz run slow, not find more bugs.
        if t.heights().len() <= 1 << 16 {
            if let Ok(a) = analyse(&t, &AnalysisOptions::default()) {
                assert!(a.rms_height.is_finite() && a.rms_height >= 0.0, "{a:?}");
                assert!(a.hurst.is_none_or(|h| h > 0.0 && h < 1.0), "{a:?}");
            }
        }
    }
});
