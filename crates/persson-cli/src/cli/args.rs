//! Flags shared by several subcommands: the spectrum and the material. They
//! build the scene file's [`SpectrumSpec`] and [`MaterialSpec`], whose one
//! `build()` serves flags and scenes alike.

use anyhow::bail;
use persson_studies::scene::{ConventionName, MaterialSpec, RoughContact, SpectrumSpec, EXAMPLE};

use super::files::{in_file, InFile};
pub use super::measured_args::MeasuredArgs;
use super::number::number;

/// The built-in example: a self-affine surface (H = 0.8, q_l = 1e4 1/m,
/// q_r = 1e5 1/m, q_s = 1e8 1/m, rms height 1 µm) on a body with E* = 1 GPa.
pub mod example {
    /// Nominal pressures, Pa.
    pub const PRESSURES: [f64; 6] = persson_studies::scene::EXAMPLE_PRESSURES;
}

/// The power spectrum: a self-affine model or a tabulated file.
#[derive(clap::Args, Debug, Clone, Default)]
pub struct SpectrumArgs {
    /// Use the built-in example where spectrum, modulus or pressures are not
    /// given: self-affine H = 0.8, q_l = 1e4, q_r = 1e5, q_s = 1e8 1/m, rms height
    /// 1 µm; E* = 1 GPa; σ0 = 1e4 … 1e8 Pa (up to 0.1 E*).
    #[arg(long)]
    pub example: bool,
    /// Hurst exponent H in (0, 1) of the self-affine spectrum.
    #[arg(long, allow_hyphen_values = true, value_parser = number)]
    pub hurst: Option<f64>,
    /// Lower cut-off q_l, 1/m.
    #[arg(long = "q-l", allow_hyphen_values = true, value_parser = number)]
    pub q_l: Option<f64>,
    /// Roll-off wavevector q_r, 1/m (default: q_l, no roll-off).
    #[arg(long = "q-r", allow_hyphen_values = true, value_parser = number)]
    pub q_r: Option<f64>,
    /// Upper cut-off q_s, 1/m.
    #[arg(long = "q-s", allow_hyphen_values = true, value_parser = number)]
    pub q_s: Option<f64>,
    /// Amplitude as rms height over [q_l, q_s], m.
    #[arg(long, group = "amplitude", allow_hyphen_values = true, value_parser = number)]
    pub rms_height: Option<f64>,
    /// Amplitude as rms slope over [q_l, q_s].
    #[arg(long, group = "amplitude", allow_hyphen_values = true, value_parser = number)]
    pub rms_slope: Option<f64>,
    /// Amplitude as C(q_r), m^4.
    #[arg(long = "c-r", group = "amplitude", allow_hyphen_values = true, value_parser = number)]
    pub c_r: Option<f64>,
    /// Tabulated spectrum: CSV with columns q (1/m) and C (m^4, Persson's normalisation
    /// unless --psd-convention says otherwise).
    #[arg(long, conflicts_with_all = ["hurst", "q_l", "q_r", "q_s", "amplitude"], value_parser = in_file)]
    pub psd: Option<InFile>,
    /// Convention of the --psd file.
    #[arg(long, value_enum, default_value_t = ConventionName::Persson, requires = "psd")]
    pub psd_convention: ConventionName,
    /// Side L (m) of the periodic surface, for --psd-convention grid.
    #[arg(long, requires = "psd", allow_hyphen_values = true, value_parser = number)]
    pub psd_size: Option<f64>,
    /// Anisotropic roughness: the spectrum stretched by γ > 0 along
    /// --lay-angle, C(q) = γ C(√((γ q_u)² + q_v²)); the area uses its angular
    /// average (Carbone et al. 2009), a synthesised BEM surface the plane.
    #[arg(long, value_name = "GAMMA", allow_hyphen_values = true, value_parser = number)]
    pub anisotropy: Option<f64>,
    /// Direction of the stretch (the lay for γ > 1), degrees from x.
    #[arg(long, value_name = "DEG", requires = "anisotropy", allow_hyphen_values = true, value_parser = number)]
    pub lay_angle: Option<f64>,
    #[command(flatten)]
    pub second: SecondBodyArgs,
}

/// The roughness of a second rough body: the contact sees C = C1 + C2.
#[derive(clap::Args, Debug, Clone, Default)]
pub struct SecondBodyArgs {
    /// Spectrum of the second rough body (CSV q, C as --psd): the contact's
    /// roughness is the sum C = C1 + C2.
    #[arg(long, conflicts_with = "surface2", value_parser = in_file)]
    pub psd2: Option<InFile>,
    /// Convention of the --psd2 file.
    #[arg(long, value_enum, default_value_t = ConventionName::Persson, requires = "psd2")]
    pub psd2_convention: ConventionName,
    /// Measured surface of the second rough body (its isotropic spectrum, the
    /// default conditioning): the contact's roughness is the sum C = C1 + C2.
    #[arg(long, value_parser = in_file)]
    pub surface2: Option<InFile>,
    /// Pixel size Δ of the --surface2 map (files that store their size need none), m.
    #[arg(long, requires = "surface2", allow_hyphen_values = true, value_parser = number)]
    pub pixel_size2: Option<f64>,
}

impl SecondBodyArgs {
    /// `first` alone, or the sum of `first` and the second body's spectrum.
    pub fn with(&self, first: SpectrumSpec) -> anyhow::Result<SpectrumSpec> {
        let second = if let Some(file) = &self.psd2 {
            if self.psd2_convention == ConventionName::Grid {
                bail!("--psd2-convention grid is not supported: convert the file to persson");
            }
            SpectrumSpec::Tabulated {
                file: file.to_path_buf(),
                convention: self.psd2_convention,
                size: None,
            }
        } else if let Some(file) = &self.surface2 {
            let mut m = persson_studies::scene::HeightMapSpec::new(file.to_path_buf());
            m.pixel_size = self.pixel_size2;
            SpectrumSpec::HeightMap(m)
        } else {
            return Ok(first);
        };
        Ok(SpectrumSpec::Sum {
            parts: vec![first, second],
        })
    }
}

impl SpectrumArgs {
    /// Whether the built-in example stands in for the spectrum (the
    /// self-affine flags given replace parts of it).
    pub fn is_example(&self) -> bool {
        self.psd.is_none() && self.example
    }

    /// Whether any spectrum is given (flags, a file or the example).
    pub fn is_given(&self) -> bool {
        self.example || self.psd.is_some() || self.hurst.is_some()
    }

    /// The scene file's spectrum entry for these flags.
    pub fn spec(&self) -> anyhow::Result<SpectrumSpec> {
        let mut first = self.spec_first()?;
        if let Some(gamma) = self.anisotropy {
            first = SpectrumSpec::Stretched {
                spectrum: Box::new(first),
                anisotropy: gamma,
                lay_angle: self.lay_angle,
            };
        }
        self.second.with(first)
    }

    /// The first body's spectrum entry (without `--psd2`/`--surface2`).
    fn spec_first(&self) -> anyhow::Result<SpectrumSpec> {
        if let Some(path) = &self.psd {
            if self.psd_convention == ConventionName::Grid && self.psd_size.is_none() {
                bail!("--psd-convention grid needs --psd-size L (m)");
            }
            return Ok(SpectrumSpec::Tabulated {
                file: path.to_path_buf(),
                convention: self.psd_convention,
                size: self.psd_size,
            });
        }
        if self.is_example() {
            return Ok(self.over_example());
        }
        let (Some(hurst), Some(q_l), Some(q_s)) = (self.hurst, self.q_l, self.q_s) else {
            let missing: Vec<&str> = [
                ("--hurst", self.hurst),
                ("--q-l", self.q_l),
                ("--q-s", self.q_s),
            ]
            .into_iter()
            .filter_map(|(flag, v)| v.is_none().then_some(flag))
            .collect();
            if missing.len() == 3 && self.q_r.is_none() {
                bail!("no spectrum: give --hurst, --q-l, --q-s and one of --rms-height, --rms-slope, --c-r; or --psd FILE; or --surface FILE; or --example");
            }
            bail!(
                "incomplete self-affine spectrum: missing {} (or add --example, whose spectrum the given flags then modify)",
                missing.join(", ")
            );
        };
        if self.rms_height.is_none() && self.rms_slope.is_none() && self.c_r.is_none() {
            bail!("no spectrum amplitude: give one of --rms-height, --rms-slope, --c-r");
        }
        Ok(SpectrumSpec::SelfAffine {
            hurst,
            q_l,
            q_r: self.q_r,
            q_s,
            rms_height: self.rms_height,
            rms_slope: self.rms_slope,
            c_r: self.c_r,
        })
    }

    /// The example's spectrum with the self-affine flags given in place of its
    /// values (a new --q-l without --q-r drops the example's roll-off; an
    /// amplitude flag replaces its rms height).
    fn over_example(&self) -> SpectrumSpec {
        let SpectrumSpec::SelfAffine {
            hurst,
            q_l,
            q_r,
            q_s,
            rms_height,
            rms_slope,
            c_r,
        } = SpectrumSpec::example()
        else {
            return SpectrumSpec::example();
        };
        let amplitude = self.rms_height.is_some() || self.rms_slope.is_some() || self.c_r.is_some();
        SpectrumSpec::SelfAffine {
            hurst: self.hurst.unwrap_or(hurst),
            q_l: self.q_l.unwrap_or(q_l),
            q_r: self.q_r.or(if self.q_l.is_some() { None } else { q_r }),
            q_s: self.q_s.unwrap_or(q_s),
            rms_height: if amplitude {
                self.rms_height
            } else {
                rms_height
            },
            rms_slope: if amplitude { self.rms_slope } else { rms_slope },
            c_r: if amplitude { self.c_r } else { c_r },
        }
    }

    /// A `--psd` file that could not be read as a spectrum but looks like a
    /// height map: say so, and name `--surface`.
    pub fn psd_hint(&self, e: persson::Error) -> anyhow::Error {
        match &self.psd {
            Some(path) if looks_like_height_map(path) => anyhow::anyhow!(
                "{e} ({} looks like a height map, not a spectrum: give it as --surface {})",
                path.display(),
                path.display()
            ),
            _ => e.into(),
        }
    }
}

/// The material: E* directly, or Young's moduli and Poisson ratios.
#[derive(clap::Args, Debug, Clone, Default)]
pub struct MaterialArgs {
    /// Contact modulus E*, 1/E* = Σ (1 − ν²)/E (same unit as the pressures).
    #[arg(long, alias = "modulus", allow_hyphen_values = true, value_parser = number, conflicts_with = "young")]
    pub contact_modulus: Option<f64>,
    /// Young's modulus E of the elastic body (against a rigid one unless --young2).
    #[arg(long, requires = "poisson", allow_hyphen_values = true, value_parser = number)]
    pub young: Option<f64>,
    /// Poisson ratio ν of the body (with --young; with --contact-modulus only
    /// where the stress below the surface needs it, default 0.3).
    #[arg(long, allow_hyphen_values = true, value_parser = number)]
    pub poisson: Option<f64>,
    /// Young's modulus of the second body.
    #[arg(long, requires_all = ["young", "poisson2"], allow_hyphen_values = true, value_parser = number)]
    pub young2: Option<f64>,
    /// Poisson ratio of the second body.
    #[arg(long, requires = "young2", allow_hyphen_values = true, value_parser = number)]
    pub poisson2: Option<f64>,
}

impl MaterialArgs {
    /// The scene file's material entry (`example` supplies E* when nothing is given).
    pub fn spec(&self, example: bool) -> anyhow::Result<MaterialSpec> {
        let m = MaterialSpec {
            contact_modulus: self.contact_modulus,
            young: self.young,
            poisson: self.poisson,
            young2: self.young2,
            poisson2: self.poisson2,
        };
        match (m.is_empty(), example) {
            (false, _) => Ok(m),
            (true, true) => Ok(MaterialSpec::example()),
            (true, false) => {
                bail!("no material: give --contact-modulus E* or --young E --poisson NU")
            }
        }
    }
}

/// The spectrum and the material of the flags, as the library's [`RoughContact`].
pub fn contact(s: &SpectrumArgs, m: &MaterialArgs) -> anyhow::Result<RoughContact> {
    measured_contact(s, &MeasuredArgs::default(), m)
}

/// As [`contact`], the spectrum from the measured surface if `--surface` is given.
pub fn measured_contact(
    s: &SpectrumArgs,
    h: &MeasuredArgs,
    m: &MaterialArgs,
) -> anyhow::Result<RoughContact> {
    let spectrum = spectrum_spec(s, h)?;
    let material = m.spec(s.example)?;
    let mut surface = RoughContact::new(&spectrum, &material).map_err(|e| s.psd_hint(e))?;
    if s.is_example() && surface.description.is_none() {
        surface.description = Some(format!("{EXAMPLE} (the given flags replace parts of it)"));
    }
    Ok(surface)
}

/// The spectrum entry: the measured surface's (its band cut at `--q-s`) or
/// the spectrum flags'.
pub fn spectrum_spec(s: &SpectrumArgs, h: &MeasuredArgs) -> anyhow::Result<SpectrumSpec> {
    match h.spectrum_spec(s.q_s)? {
        Some(spec) => s.second.with(spec),
        None => s.spec(),
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

/// Whether a file is a height map rather than a table of q and C: a map
/// format by its extension, binary content, or more than two columns in its
/// first line of data.
fn looks_like_height_map(path: &std::path::Path) -> bool {
    let ext = path
        .extension()
        .map(|e| e.to_string_lossy().to_lowercase())
        .unwrap_or_default();
    if [
        "npy", "x3p", "gsf", "xyz", "sdf", "opd", "datx", "plux", "tif", "tiff", "nc", "gz",
    ]
    .contains(&ext.as_str())
    {
        return true;
    }
    let Ok(bytes) = std::fs::read(path) else {
        return false;
    };
    let Ok(text) = std::str::from_utf8(&bytes) else {
        return true;
    };
    text.lines()
        .map(|l| l.split('#').next().unwrap_or("").trim())
        .find(|l| {
            !l.is_empty()
                && l.split([',', ' ', '\t', ';'])
                    .any(|c| c.parse::<f64>().is_ok())
        })
        .is_some_and(|l| {
            l.split([',', ' ', '\t', ';'])
                .filter(|c| !c.is_empty())
                .count()
                > 2
        })
}
