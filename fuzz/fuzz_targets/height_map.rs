//! Height-map reader (.npy and text): any bytes must give a surface or an
//! error, never a panic; a surface must be square, finite and its rms height
//! and slope finite.
#![no_main]

use libfuzzer_sys::fuzz_target;
use persson::bem::surface::height_map_from_bytes;

fuzz_target!(|data: &[u8]| {
    for name in ["fuzz.npy", "fuzz.txt"] {
        if let Ok(s) = height_map_from_bytes(std::path::Path::new(name), data, 1.0) {
            assert_eq!(s.heights.len(), s.n * s.n);
            assert!(s.heights.iter().all(|h| h.is_finite()));
            assert!(!s.rms_height().is_nan(), "rms height NaN");
            let _ = s.rms_slope();
        }
    }
});
