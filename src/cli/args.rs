//! Flags shared by several subcommands: the spectrum and the material.

use std::path::PathBuf;

use anyhow::{bail, Context};
use persson::spectrum::{Amplitude, Convention, SelfAffine, Spectrum, Tabulated};
use persson::Material;

/// The built-in example: a self-affine surface (H = 0.8, q_l = 1e4 1/m,
/// q_r = 1e5 1/m, q_s = 1e8 1/m, rms height 1 µm) on a body with E* = 1e9 Pa.
pub mod example {
    /// Hurst exponent.
    pub const HURST: f64 = 0.8;
    /// Lower cut-off, 1/m.
    pub const Q_L: f64 = 1e4;
    /// Roll-off, 1/m.
    pub const Q_R: f64 = 1e5;
    /// Upper cut-off, 1/m.
    pub const Q_S: f64 = 1e8;
    /// rms height, m.
    pub const RMS_HEIGHT: f64 = 1e-6;
    /// Contact modulus, Pa.
    pub const CONTACT_MODULUS: f64 = 1e9;
    /// Nominal pressures, Pa.
    pub const PRESSURES: [f64; 6] = [1e4, 1e5, 1e6, 1e7, 1e8, 3e8];
}

/// The power spectrum: a self-affine model or a tabulated file.
#[derive(clap::Args, Debug, Clone, Default)]
pub struct SpectrumArgs {
    /// Use the built-in example (spectrum, modulus and pressures not given).
    #[arg(long)]
    pub example: bool,
    /// Hurst exponent H in (0, 1) of the self-affine spectrum.
    #[arg(long, allow_negative_numbers = true)]
    pub hurst: Option<f64>,
    /// Lower cut-off q_l, 1/m.
    #[arg(long = "q-l", allow_negative_numbers = true)]
    pub q_l: Option<f64>,
    /// Roll-off wavevector q_r, 1/m (default: q_l, no roll-off).
    #[arg(long = "q-r", allow_negative_numbers = true)]
    pub q_r: Option<f64>,
    /// Upper cut-off q_s, 1/m.
    #[arg(long = "q-s", allow_negative_numbers = true)]
    pub q_s: Option<f64>,
    /// Amplitude as rms height over [q_l, q_s], m.
    #[arg(long, group = "amplitude", allow_negative_numbers = true)]
    pub rms_height: Option<f64>,
    /// Amplitude as rms slope over [q_l, q_s].
    #[arg(long, group = "amplitude", allow_negative_numbers = true)]
    pub rms_slope: Option<f64>,
    /// Amplitude as C(q_r), m^4.
    #[arg(long = "c-r", group = "amplitude", allow_negative_numbers = true)]
    pub c_r: Option<f64>,
    /// Tabulated spectrum: CSV with columns q (1/m) and C (m^4, Persson's normalisation
    /// unless --psd-convention says otherwise).
    #[arg(long, conflicts_with_all = ["hurst", "q_l", "q_r", "q_s", "amplitude"])]
    pub psd: Option<PathBuf>,
    /// Convention of the --psd file.
    #[arg(long, value_enum, default_value_t = PsdConvention::Persson, requires = "psd")]
    pub psd_convention: PsdConvention,
    /// Side L (m) of the periodic surface, for --psd-convention grid.
    #[arg(long, requires = "psd", allow_negative_numbers = true)]
    pub psd_size: Option<f64>,
}

/// Spectrum conventions accepted on the command line.
#[derive(clap::ValueEnum, Debug, Clone, Copy, Default, PartialEq, Eq)]
pub enum PsdConvention {
    /// Persson: q in 1/m, C in m^4.
    #[default]
    Persson,
    /// SurfaceTopography / contact.engineering: C_Persson = C / (2π)².
    SurfaceTopography,
    /// 1D profile spectrum of an isotropic surface (m^3).
    Profile1d,
    /// Dimensionless FFT grid: k in units of 2π/L, C_Persson = (L/2π)² φ(k); needs --psd-size.
    Grid,
}

impl SpectrumArgs {
    /// Build the spectrum from the flags.
    pub fn build(&self) -> anyhow::Result<Box<dyn Spectrum>> {
        if let Some(path) = &self.psd {
            let conv = match self.psd_convention {
                PsdConvention::Persson => Convention::Persson,
                PsdConvention::SurfaceTopography => Convention::SurfaceTopography,
                PsdConvention::Profile1d => Convention::Profile1D,
                PsdConvention::Grid => Convention::Grid {
                    size: self
                        .psd_size
                        .context("--psd-convention grid needs --psd-size L (m)")?,
                },
            };
            return Ok(Box::new(Tabulated::from_csv(path, conv)?));
        }
        if self.example && self.hurst.is_none() && self.q_l.is_none() {
            use example::*;
            return Ok(Box::new(SelfAffine::new(
                Q_L,
                Q_R,
                Q_S,
                HURST,
                Amplitude::RmsHeight(RMS_HEIGHT),
            )?));
        }
        let (Some(h), Some(q_l), Some(q_s)) = (self.hurst, self.q_l, self.q_s) else {
            bail!("no spectrum: give --hurst, --q-l, --q-s and one of --rms-height, --rms-slope, --c-r; or --psd FILE; or --example");
        };
        let amp = match (self.rms_height, self.rms_slope, self.c_r) {
            (Some(x), _, _) => Amplitude::RmsHeight(x),
            (_, Some(x), _) => Amplitude::RmsSlope(x),
            (_, _, Some(x)) => Amplitude::CR(x),
            _ => bail!("no spectrum amplitude: give one of --rms-height, --rms-slope, --c-r"),
        };
        Ok(Box::new(SelfAffine::new(
            q_l,
            self.q_r.unwrap_or(q_l),
            q_s,
            h,
            amp,
        )?))
    }
}

/// The material: E* directly, or Young's moduli and Poisson ratios.
#[derive(clap::Args, Debug, Clone, Default)]
pub struct MaterialArgs {
    /// Contact modulus E* (same unit as the pressures).
    #[arg(long, allow_negative_numbers = true, conflicts_with_all = ["young", "poisson"])]
    pub modulus: Option<f64>,
    /// Young's modulus E of the elastic body (against a rigid one unless --young2).
    #[arg(long, requires = "poisson", allow_negative_numbers = true)]
    pub young: Option<f64>,
    /// Poisson ratio ν of the body.
    #[arg(long, requires = "young", allow_negative_numbers = true)]
    pub poisson: Option<f64>,
    /// Young's modulus of the second body.
    #[arg(long, requires_all = ["young", "poisson2"], allow_negative_numbers = true)]
    pub young2: Option<f64>,
    /// Poisson ratio of the second body.
    #[arg(long, requires = "young2", allow_negative_numbers = true)]
    pub poisson2: Option<f64>,
}

impl MaterialArgs {
    /// Build the material (`example` supplies E* when nothing is given).
    pub fn build(&self, example: bool) -> anyhow::Result<Material> {
        use persson::material::Body;
        if let Some(e) = self.modulus {
            return Ok(Material::new(e)?);
        }
        if let (Some(young), Some(poisson)) = (self.young, self.poisson) {
            let a = Body { young, poisson };
            return Ok(match (self.young2, self.poisson2) {
                (Some(young), Some(poisson)) => Material::from_bodies(a, Body { young, poisson })?,
                _ => Material::from_body(a)?,
            });
        }
        if example {
            return Ok(Material::new(example::CONTACT_MODULUS)?);
        }
        bail!("no material: give --modulus E* or --young E --poisson NU")
    }
}

/// Nominal pressures from the flags, or the example's.
pub fn pressures(given: &[f64], example: bool) -> anyhow::Result<Vec<f64>> {
    if !given.is_empty() {
        return Ok(given.to_vec());
    }
    if example {
        return Ok(example::PRESSURES.to_vec());
    }
    bail!("no nominal pressure: give --pressure P (repeatable or comma-separated)")
}
