//! The grid I/O of `persson::io`: the one `.npy` reader and the one text
//! reader (decoding, header lines, rows, matrices) shared by the BEM and the
//! measured surfaces. Any bytes must give a matrix or an error, never a
//! panic; a matrix holds rows·cols values; an encoded matrix reads back.
//!
//! Seeds: `cargo +nightly fuzz run grid_io fuzz/corpus/grid_io tests/data tests/reference/data`
#![no_main]

use libfuzzer_sys::fuzz_target;
use persson::io::{npy, text};

fuzz_target!(|data: &[u8]| {
    let path = std::path::Path::new("fuzz");
    if let Ok(m) = npy::parse(path, data) {
        assert_eq!(m.values.len(), m.rows * m.cols);
        let again = npy::parse(path, &npy::encode(m.rows, m.cols, &m.values).unwrap()).unwrap();
        assert_eq!(again.values.len(), m.values.len());
        assert!(again
            .values
            .iter()
            .zip(&m.values)
            .all(|(a, b)| a == b || (a.is_nan() && b.is_nan())));
    }
    if let Ok(r) = text::rows(path, data) {
        assert!(!r.rows.is_empty());
        if let Ok(m) = r.into_matrix(path) {
            assert_eq!(m.values.len(), m.rows * m.cols);
        }
    }
    if let Ok(s) = std::str::from_utf8(data) {
        for tok in s.split_whitespace().take(64) {
            let u = text::resolution(tok);
            assert!(u.is_nan() || u >= 0.0, "{tok:?}: {u}");
        }
    }
});
