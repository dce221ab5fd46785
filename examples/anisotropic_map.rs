//! Writes `docs/data/stretched.npy`, the anisotropic map of the guide
//! (`docs/anisotropy.md`): a periodic 128² self-affine surface (H 0.8, q_l =
//! 2π/L, q_r = 8·2π/L, q_s = 60·2π/L, rms slope 0.1 before stretching),
//! stretched by γ = 3 along 30° from x, side L = 1 mm, seed 7.
//!
//! `cargo run --release --example anisotropic_map`

use std::f64::consts::TAU;
use std::sync::Arc;

use persson::spectrum::{Amplitude, SelfAffine, Stretched};

fn main() -> persson::Result<()> {
    let l = 1e-3;
    let q = TAU / l;
    let iso = Arc::new(SelfAffine::new(
        q,
        8.0 * q,
        60.0 * q,
        0.8,
        Amplitude::RmsSlope(0.1),
    )?);
    let s = Stretched::new(iso, 3.0, 30f64.to_radians())?;
    let n = 128;
    let g = persson::bem::surface::synthesize_2d(&s, n, l, 7)?;
    persson::io::npy::write(
        std::path::Path::new("docs/data/stretched.npy"),
        n,
        n,
        &g.heights,
    )
}
