//! The roughness of a scene: a self-affine spectrum, a tabulated one, or a
//! measured height map.

use std::path::PathBuf;

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

use super::{ByName, ConventionName, LengthUnitName};
use persson::error::Result;
use persson::names::{Detrend, Window};
use persson::spectrum::{Amplitude, SelfAffine, Spectrum, Sum, Tabulated};

use crate::warning::{self, Warning};

/// A value built from a scene's entry, with what was assumed to build it in
/// words (a measured surface's detrending, window, periodicity and band),
/// for report titles.
#[derive(Debug, Clone)]
#[non_exhaustive]
pub struct Described<T> {
    /// The value.
    pub value: T,
    /// What was assumed (`None`: nothing worth saying).
    pub description: Option<String>,
    /// The warnings of a measured surface's analysis (a resampled line scan,
    /// no Hurst fit, bins left out); empty for the others.
    pub warnings: Vec<crate::warning::Warning>,
}

/// The roughness of a scene.
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize, JsonSchema)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum SpectrumSpec {
    /// Self-affine with roll-off: C = C(q_r) for q_l ≤ q < q_r, C(q_r)(q/q_r)^(−2(H+1))
    /// up to q_s; exactly one amplitude (`rms_height`, `rms_slope` or `c_r`).
    SelfAffine {
        /// Hurst exponent H in (0, 1).
        hurst: f64,
        /// Lower cut-off q_l, 1/m.
        q_l: f64,
        /// Roll-off q_r, 1/m (default q_l: no roll-off).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        q_r: Option<f64>,
        /// Upper cut-off q_s, 1/m.
        q_s: f64,
        /// rms height over [q_l, q_s], m.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        rms_height: Option<f64>,
        /// rms slope over [q_l, q_s].
        #[serde(default, skip_serializing_if = "Option::is_none")]
        rms_slope: Option<f64>,
        /// C(q_r), m⁴.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        c_r: Option<f64>,
    },
    /// A tabulated spectrum: a CSV file of q and C (relative paths are
    /// relative to the scene file).
    Tabulated {
        /// The file.
        file: PathBuf,
        /// Its normalisation (default `persson`).
        #[serde(default)]
        convention: ConventionName,
        /// Side L (m) of the periodic surface, for the convention `grid`.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        size: Option<f64>,
    },
    /// A measured height map (or line scans): its isotropic spectrum serves
    /// every output, and `outputs.bem` solves on the map itself (relative
    /// paths are relative to the scene file).
    HeightMap(HeightMapSpec),
    /// Two (or more) rough bodies pressed together: the roughness of the
    /// contact is the sum of their spectra, C = C₁ + C₂ (each zero outside
    /// its band); `parts` are spectrum entries of any other kind.
    Sum {
        /// The bodies' spectra (at least two).
        parts: Vec<SpectrumSpec>,
    },
    /// Several measurements of one surface at different scales (a coarse
    /// large scan, a fine small one): each contributes its reliable band,
    /// and the spectrum is their mode-weighted mean over the overlaps.
    MultiScale {
        /// The measurements, each as a `height_map` entry (without `kind`).
        measurements: Vec<HeightMapSpec>,
    },
    /// An anisotropic surface: `spectrum` stretched by `anisotropy` (γ > 0)
    /// along the direction `lay_angle` (degrees from x),
    /// C(q) = γ C_iso(√((γ q_u)² + q_v²)) (the Peklenik number is γ or 1/γ).
    /// The contact area uses its angular average (Carbone et al. 2009); a
    /// synthesised BEM surface the whole plane.
    Stretched {
        /// The isotropic spectrum stretched (any other kind).
        spectrum: Box<SpectrumSpec>,
        /// The stretch γ > 0: the correlation length along the lay over the one across it.
        anisotropy: f64,
        /// The direction of the stretch, degrees from x towards y (default 0).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        lay_angle: Option<f64>,
    },
}

/// A measured surface, read with [`persson::topography::read()`] and
/// conditioned as [`persson::topography::analyse`] does (feature `topography`);
/// the same fields as the flags `--surface`, `--size`, `--pixel-size`,
/// `--periodic`, `--detrend`, `--window`, `--fill-undefined`, `--q-max`.
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct HeightMapSpec {
    /// The file: `.npy`, text matrix, `.xyz`, `.gsf`, `.x3p` or a two-column line scan.
    pub file: PathBuf,
    /// Physical size: `Lx` (square pixels) or `[Lx, Ly]`, m, `Lx` along a row of a
    /// `.npy` or text matrix (checked against the size of files that store one).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub size: Option<Sides>,
    /// Pixel size Δ (square pixels), m, instead of `size`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pixel_size: Option<f64>,
    /// Whether the surface repeats itself (default: not, a measurement).
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub periodic: bool,
    /// Detrending (default: plane for non-periodic maps, none for periodic ones).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<ByName<Detrend>>")]
    pub detrend: Option<Detrend>,
    /// Window (default: hann for non-periodic maps, none for periodic ones).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<ByName<Window>>")]
    pub window: Option<Window>,
    /// Fill undefined points by harmonic interpolation instead of failing.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub fill_undefined: bool,
    /// Upper end of the band, 1/m (default: the Nyquist wavevector π/Δ).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub q_max: Option<f64>,
    /// Unit of the heights of a file that states none (default m; a file's
    /// own unit must agree).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub height_unit: Option<LengthUnitName>,
    /// Unit of the x (and y) coordinates of a line scan or XYZ file that
    /// states none (default m).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub lateral_unit: Option<LengthUnitName>,
    /// Swap the axes of the map after reading (a row of the file becomes a
    /// column: for arrays saved in SurfaceTopography's `[ix, iy]` order).
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub transpose: bool,
    /// The channel of a multi-channel file (a data set of an HDF5 file), by
    /// name (case-insensitive) or index from 0 (default: the first height
    /// channel).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub channel: Option<String>,
    /// Tip radius R of the scanning probe, m: the band ends where the
    /// measured curvature is sharper than the tip (SurfaceTopography's
    /// reliability cut-off, safety factor 1/2).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tip_radius: Option<f64>,
}

/// A physical size: one side `Lx` (square pixels) or both `[Lx, Ly]`, m.
#[derive(Debug, Clone, Copy, PartialEq, Deserialize, Serialize, JsonSchema)]
#[serde(untagged, expecting = "a side Lx in m, or both sides as [Lx, Ly]")]
pub enum Sides {
    /// `Lx`; `Ly = Lx·ny/nx`.
    One(f64),
    /// `[Lx, Ly]`.
    Two([f64; 2]),
}

impl HeightMapSpec {
    /// A spec with every option at its default.
    pub fn new(file: PathBuf) -> Self {
        HeightMapSpec {
            file,
            size: None,
            pixel_size: None,
            periodic: false,
            detrend: None,
            window: None,
            fill_undefined: false,
            q_max: None,
            height_unit: None,
            lateral_unit: None,
            transpose: false,
            channel: None,
            tip_radius: None,
        }
    }

    /// The file as reports name it: with the channel read, `file#channel`
    /// (a measurement of a dataset, a channel of a multi-channel file).
    pub fn label(&self) -> PathBuf {
        match &self.channel {
            Some(c) => PathBuf::from(format!("{}#{c}", self.file.display())),
            None => self.file.clone(),
        }
    }
}

impl SpectrumSpec {
    /// The built-in example (see [`super::EXAMPLE`]).
    pub fn example() -> Self {
        SpectrumSpec::SelfAffine {
            hurst: 0.8,
            q_l: 1e4,
            q_r: Some(1e5),
            q_s: 1e8,
            rms_height: Some(1e-6),
            rms_slope: None,
            c_r: None,
        }
    }

    /// Build the spectrum (a height map's: its binned isotropic spectrum,
    /// feature `topography`).
    ///
    /// # Errors
    /// Missing or invalid fields (named as in the scene file); file errors.
    pub fn build(&self) -> Result<Box<dyn Spectrum>> {
        match self {
            SpectrumSpec::SelfAffine {
                hurst,
                q_l,
                q_r,
                q_s,
                rms_height,
                rms_slope,
                c_r,
            } => {
                let amp = match (rms_height, rms_slope, c_r) {
                    (Some(x), None, None) => Amplitude::RmsHeight(*x),
                    (None, Some(x), None) => Amplitude::RmsSlope(*x),
                    (None, None, Some(x)) => Amplitude::CR(*x),
                    _ => {
                        return Err(persson::Error::Inconsistent {
                            name: "rms_height, rms_slope, c_r".into(),
                            requirement: "give exactly one of them (the amplitude)".into(),
                        })
                    }
                };
                Ok(Box::new(SelfAffine::new(
                    *q_l,
                    q_r.unwrap_or(*q_l),
                    *q_s,
                    *hurst,
                    amp,
                )?))
            }
            SpectrumSpec::Tabulated {
                file,
                convention,
                size,
            } => Ok(Box::new(
                Tabulated::from_csv(file, convention.with(*size)?)
                    .map_err(|e| super::measured::in_file(file, e))?,
            )),
            SpectrumSpec::HeightMap(m) => m.spectrum(),
            SpectrumSpec::Sum { parts } => Ok(Box::new(Sum::new(
                parts
                    .iter()
                    .enumerate()
                    .map(|(i, p)| p.build().map_err(|e| in_part(i, e)))
                    .collect::<Result<_>>()?,
            )?)),
            SpectrumSpec::MultiScale { measurements } => {
                Ok(Box::new(super::multiscale::described(measurements)?.value))
            }
            SpectrumSpec::Stretched {
                spectrum,
                anisotropy,
                lay_angle,
            } => {
                let iso: std::sync::Arc<dyn Spectrum> = spectrum.build()?.into();
                Ok(Box::new(persson::spectrum::Stretched::new(
                    iso,
                    *anisotropy,
                    lay_angle.unwrap_or(0.0).to_radians(),
                )?))
            }
        }
    }

    /// As [`SpectrumSpec::build`], with what a measured surface assumed
    /// (detrend, window, periodicity, band) in words for the report titles.
    ///
    /// # Errors
    /// As [`SpectrumSpec::build`].
    pub fn build_described(&self) -> Result<Described<Box<dyn Spectrum>>> {
        match self {
            SpectrumSpec::HeightMap(m) => {
                let d = m.spectrum_described()?;
                Ok(Described {
                    value: Box::new(d.value),
                    description: d.description,
                    warnings: d.warnings,
                })
            }
            SpectrumSpec::Sum { parts } => {
                let mut built = Vec::with_capacity(parts.len());
                let (mut described, mut warnings) = (Vec::new(), Vec::new());
                for (i, p) in parts.iter().enumerate() {
                    let d = p.build_described().map_err(|e| in_part(i, e))?;
                    described.extend(d.description);
                    warnings.extend(d.warnings);
                    for w in spectrum_warnings(p, d.value.as_ref()) {
                        warning::push(&mut warnings, Some(w));
                    }
                    built.push(d.value);
                }
                let sum = Sum::new(built)?;
                warning::push(&mut warnings, Warning::sum_bands(&sum));
                Ok(Described {
                    value: Box::new(sum),
                    description: (!described.is_empty()).then(|| {
                        format!("two rough bodies, C = C1 + C2: {}", described.join("; "))
                    }),
                    warnings,
                })
            }
            SpectrumSpec::MultiScale { measurements } => {
                let d = super::multiscale::described(measurements)?;
                Ok(Described {
                    value: Box::new(d.value),
                    description: d.description,
                    warnings: d.warnings,
                })
            }
            _ => Ok(Described {
                value: self.build()?,
                description: None,
                warnings: Vec::new(),
            }),
        }
    }

    /// The input files the entry reads (tabulated spectra and height maps,
    /// those of a sum's parts too), to resolve relative paths.
    pub fn files_mut(&mut self) -> Vec<&mut PathBuf> {
        match self {
            SpectrumSpec::SelfAffine { .. } => vec![],
            SpectrumSpec::Tabulated { file, .. }
            | SpectrumSpec::HeightMap(HeightMapSpec { file, .. }) => {
                vec![file]
            }
            SpectrumSpec::Sum { parts } => parts.iter_mut().flat_map(|p| p.files_mut()).collect(),
            SpectrumSpec::MultiScale { measurements } => {
                measurements.iter_mut().map(|m| &mut m.file).collect()
            }
            SpectrumSpec::Stretched { spectrum, .. } => spectrum.files_mut(),
        }
    }

    /// Where C(q) has a kink inside the band (the roll-off), for the
    /// wavevector integrals of the mean separation.
    pub fn breaks(&self) -> Vec<f64> {
        match self {
            SpectrumSpec::SelfAffine { q_r: Some(q_r), .. } => vec![*q_r],
            SpectrumSpec::Sum { parts } => {
                let mut b: Vec<f64> = parts.iter().flat_map(|p| p.breaks()).collect();
                b.sort_by(f64::total_cmp);
                b.dedup();
                b
            }
            _ => vec![],
        }
    }
}

/// An error of the `i`-th part of a sum, named `parts[i].<field>`.
fn in_part(i: usize, e: persson::Error) -> persson::Error {
    crate::naming::prefix(&format!("parts[{i}]."), e)
}

/// The warnings a spectrum gives whatever is computed from it: the
/// normalisation a spectrum file was read in (and a C(q) that rises, as a
/// height profile would), and an rms slope over the band above 1.
pub fn spectrum_warnings(spec: &SpectrumSpec, s: &dyn Spectrum) -> Vec<Warning> {
    let mut w = Vec::new();
    if let SpectrumSpec::Tabulated {
        file, convention, ..
    } = spec
    {
        w.push(Warning::PsdConvention {
            file: file.clone(),
            convention: *convention,
        });
        let (c_first, c_last) = (s.c(s.q_min()), s.c(s.q_max()));
        if c_last >= c_first {
            w.push(Warning::RisingSpectrum {
                file: file.clone(),
                c_first,
                c_last,
            });
        }
    }
    if let Ok(m) = s.rms_slope(s.q_min(), s.q_max()) {
        warning::push(&mut w, Warning::steep_slope(m.value));
    }
    w
}
