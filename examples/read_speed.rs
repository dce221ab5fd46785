//! Read a measured-surface file, for timing the whole process side by side
//! with SurfaceTopography (`tests/reference/read_speed.py`, the same work):
//!
//! ```text
//! cargo build --release --example read_speed
//! time target/release/examples/read_speed FILE [--fill]
//! time python3 tests/reference/read_speed.py FILE [--fill]
//! ```
//!
//! Without `--fill` the heights as read (undefined points NaN,
//! [`persson::topography::read::as_read`]); with it, the topography with
//! undefined points filled by harmonic interpolation. Prints the grid and
//! the rms of the defined heights about their mean, m.

use std::path::Path;

use persson::topography::read::{as_read, read, ReadOptions};

fn rms(h: &[f64]) -> f64 {
    let d: Vec<f64> = h.iter().copied().filter(|h| h.is_finite()).collect();
    let mean = d.iter().sum::<f64>() / d.len() as f64;
    (d.iter().map(|h| (h - mean).powi(2)).sum::<f64>() / d.len() as f64).sqrt()
}

fn main() -> persson::Result<()> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let Some(file) = args.first() else {
        eprintln!("usage: read_speed FILE [--fill]");
        std::process::exit(2);
    };
    let path = Path::new(file);
    if args.iter().any(|a| a == "--fill") {
        let o = ReadOptions {
            fill_undefined: true,
            ..Default::default()
        };
        let t = read(path, &o)?;
        println!("{} × {}: rms {:e} m", t.nx(), t.ny(), rms(t.heights()));
    } else {
        let r = as_read(path, &ReadOptions::default())?;
        println!("{} × {}: rms {:e} m", r.nx, r.ny, rms(&r.heights));
    }
    Ok(())
}
