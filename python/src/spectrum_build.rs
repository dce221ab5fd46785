//! How a `persson.Spectrum` is built, as the CLI and scenes build it: from
//! a scene's spectrum specification, a table, a sum of spectra or a measured
//! map's analysis, with the warnings the CLI gives for the same spectrum.

use std::path::Path;
use std::sync::Arc;

use persson::spectrum::{Spectrum as _, Tabulated};
use persson::topography as topo;
use persson_studies::scene::SpectrumSpec;
use pyo3::prelude::*;

use crate::convert::{err, value_error};
use crate::spectrum::{Measured, Shared, Spectrum};
use crate::state::Recipe;

impl Spectrum {
    /// A tabulated spectrum with its warnings: a measured map's first (as
    /// the CLI lists them), then a slope above 1.
    pub(crate) fn tabulated_spectrum(
        t: Tabulated,
        description: Option<String>,
        measured: Option<Measured>,
    ) -> Self {
        let points = t.points().collect();
        let mut warnings = measured
            .as_ref()
            .map(Measured::warnings)
            .unwrap_or_default();
        let steep = t
            .rms_slope(t.q_min(), t.q_max())
            .ok()
            .and_then(|m| persson_studies::Warning::steep_slope(m.value));
        if let Some(w) = steep {
            if !warnings.contains(&w) {
                warnings.push(w);
            }
        }
        Spectrum {
            shared: Shared(Arc::new(t)),
            breaks: vec![],
            description,
            recipe: Recipe::Points(points),
            warnings,
            measured,
        }
    }

    pub(crate) fn from_spec(spec: &SpectrumSpec) -> PyResult<Self> {
        let mut s = Self::from_spec_quiet(spec)?;
        // As the CLI's surface (RoughContact): a measured map's warnings
        // first (a sum's or a multi-scale set's: those its parts gave), then
        // the spectrum's own.
        let own = std::mem::take(&mut s.warnings);
        s.warnings = match (&s.measured, spec) {
            (Some(m), _) => m.warnings(),
            // A dataset named as a height map is a multi-scale set.
            (
                None,
                SpectrumSpec::Sum { .. }
                | SpectrumSpec::MultiScale { .. }
                | SpectrumSpec::HeightMap(_),
            ) => own,
            (None, _) => vec![],
        };
        for w in persson_studies::scene::run::spectrum_warnings(spec, &s.shared) {
            if !s.warnings.contains(&w) {
                s.warnings.push(w);
            }
        }
        Ok(s)
    }

    fn from_spec_quiet(spec: &SpectrumSpec) -> PyResult<Self> {
        match spec {
            SpectrumSpec::SelfAffine { .. } | SpectrumSpec::Stretched { .. } => {
                let built = spec.build_described().map_err(err)?;
                Ok(Spectrum {
                    shared: Shared(Arc::from(built.value)),
                    breaks: spec.breaks(),
                    description: built.description,
                    recipe: Recipe::SelfAffine(
                        serde_json::to_string(spec).map_err(|e| value_error(e.to_string()))?,
                    ),
                    warnings: vec![],
                    measured: None,
                })
            }
            // As SpectrumSpec::build, keeping the concrete Tabulated.
            SpectrumSpec::Tabulated {
                file,
                convention,
                size,
            } => {
                let t =
                    Tabulated::from_csv(file, convention.with(*size).map_err(err)?).map_err(err)?;
                Ok(Self::tabulated_spectrum(t, None, None))
            }
            // As HeightMapSpec::spectrum_described, keeping the notes.
            SpectrumSpec::HeightMap(m) => {
                if let Some(measurements) = m.dataset_measurements().map_err(err)? {
                    return Self::multi_scale(&measurements);
                }
                let a = m.analyse().map_err(err)?;
                // The file's name in an error, as HeightMapSpec's (in_file).
                if let Err(e) = a.psd.to_tabulated() {
                    let name = m.file.display().to_string();
                    return Err(err(if e.to_string().contains(&name) {
                        e
                    } else {
                        persson::Error::parse(&m.file, 0, 0, e.to_string())
                    }));
                }
                Self::from_analysis(a, &m.file)
            }
            SpectrumSpec::MultiScale { measurements } => Self::multi_scale(measurements),
            SpectrumSpec::Sum { parts } => {
                let parts: Vec<Spectrum> =
                    parts.iter().map(Self::from_spec).collect::<PyResult<_>>()?;
                Self::sum_of(&parts)
            }
        }
    }

    /// The combined spectrum of several measurements, with their warnings.
    fn multi_scale(measurements: &[persson_studies::scene::HeightMapSpec]) -> PyResult<Self> {
        let d = persson_studies::input::multiscale::described(measurements).map_err(err)?;
        let mut s = Self::tabulated_spectrum(d.value, d.description, None);
        for w in d.warnings {
            if !s.warnings.contains(&w) {
                s.warnings.push(w);
            }
        }
        Ok(s)
    }

    /// The sum C = C1 + C2 + … of built spectra (two rough bodies).
    pub(crate) fn sum_of(parts: &[Spectrum]) -> PyResult<Self> {
        let sum = persson::spectrum::Sum::new(
            parts
                .iter()
                .map(|p| Box::new(p.shared.clone()) as Box<dyn persson::Spectrum>)
                .collect(),
        )
        .map_err(err)?;
        let mut warnings: Vec<persson_studies::Warning> = Vec::new();
        for w in parts
            .iter()
            .flat_map(|p| p.warnings.clone())
            .chain(persson_studies::Warning::sum_bands(&sum))
        {
            if !warnings.contains(&w) {
                warnings.push(w);
            }
        }
        let mut breaks: Vec<f64> = parts.iter().flat_map(|p| p.breaks.clone()).collect();
        breaks.sort_by(f64::total_cmp);
        breaks.dedup();
        Ok(Spectrum {
            shared: Shared(Arc::new(sum)),
            breaks,
            description: Some(format!(
                "two rough bodies, C = C1 + C2 ({} spectra)",
                parts.len()
            )),
            recipe: Recipe::Sum(parts.iter().map(|p| p.recipe.clone()).collect()),
            warnings,
            measured: None,
        })
    }

    /// The spectrum of a measured map's analysis, described and with its
    /// warnings, `file` naming the input (a path, or `(array)`, `(topography)`).
    pub(crate) fn from_analysis(a: topo::Analysis, file: &Path) -> PyResult<Self> {
        let s = a.psd.to_tabulated().map_err(err)?;
        let description = Some(persson_studies::scene::describe(file, &a));
        let notes = Measured {
            file: file.to_path_buf(),
            notes: a.notes,
        };
        Ok(Self::tabulated_spectrum(s, description, Some(notes)))
    }
}
