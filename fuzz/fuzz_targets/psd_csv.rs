//! PSD CSV reader: any bytes must give a spectrum or an error, never a panic;
//! a spectrum must give finite moments.
#![no_main]

use libfuzzer_sys::fuzz_target;
use persson::spectrum::{Convention, Spectrum, Tabulated};

fuzz_target!(|data: &[u8]| {
    for conv in [Convention::Persson, Convention::Profile1D, Convention::Grid { size: 1e-3 }] {
        if let Ok(t) = Tabulated::from_csv_bytes(std::path::Path::new("fuzz.csv"), data, conv) {
            let m = t.moment(3, t.q_min(), t.q_max()).expect("exact moments cannot fail");
            assert!(m.value >= 0.0, "negative moment {m:?}");
        }
    }
});
