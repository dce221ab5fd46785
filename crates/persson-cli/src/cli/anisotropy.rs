//! `persson anisotropy --surface FILE`: the Peklenik number and the ISO
//! 25178-2 texture parameters of a height map
//! ([`persson::topography::anisotropy`]); `--plot` draws its 2-D spectrum,
//! `--spectrum-2d` writes it as CSV or `.npy`.

use super::measured_args::MeasuredArgs;
use super::output::Format;

/// Arguments of `persson anisotropy`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    measured: MeasuredArgs,
    /// The built-in example instead of a map: the guide's stretched surface
    /// (self-affine H = 0.8, rms slope 0.1, stretched by γ = 3 along 30°,
    /// 128², L = 1 mm, seed 7), synthesised (needs the feature `bem`).
    #[arg(long, conflicts_with = "surface")]
    example: bool,
    /// Draw log10 C(q_x, q_y), the 2-D spectrum, with the lay (the principal
    /// direction) into this file (.svg or .png).
    #[arg(long, value_name = "FILE.svg|png", value_parser = super::files::out_file)]
    plot: Option<super::files::OutFile>,
    /// Write the 2-D spectrum: .csv as columns q_x, q_y, C (1/m, 1/m, m⁴), or
    /// .npy as the ny × nx array C with q = 0 at (ny/2, nx/2) and
    /// q = (index − n/2)·2π/L (numpy's fftshift order).
    #[arg(long = "spectrum-2d", value_name = "FILE.csv|npy", value_parser = super::files::out_file)]
    spectrum_2d: Option<super::files::OutFile>,
    #[command(flatten)]
    format: Format,
}

// The analysis (feature `topography`).
#[cfg_attr(not(feature = "topography"), path = "anisotropy/off.rs")]
mod run;
pub use run::run;
