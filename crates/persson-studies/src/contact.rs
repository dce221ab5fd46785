//! The rough contact every theory's study runs on: the spectrum of the rigid
//! rough surface and the contact modulus E* of the elastic body pressed on
//! it, built once from the scene's (or the flags') inputs.

use persson::error::Result;
use persson::material::Material;
use persson::spectrum::Spectrum;
use persson::theory::Persson;

use crate::input::{spectrum_warnings, HeightMapSpec, MaterialSpec, SpectrumSpec, EXAMPLE};
use crate::naming::prefix;
use crate::warning::{self, Warning};

/// A rough contact, the input of the theories: the spectrum of the rigid
/// rough surface, the contact modulus E* of the elastic body pressed on it,
/// and what they are (`persson::bem::GridSurface` is the BEM's height map, a
/// different thing). Called `Surface` in persson 0.3.
pub struct RoughContact {
    /// The roughness spectrum.
    pub spectrum: Box<dyn Spectrum>,
    /// E*.
    pub contact_modulus: f64,
    /// Kinks of C(q) inside the band (the roll-off), for the separation integrals.
    pub breaks: Vec<f64>,
    /// What the surface is (the built-in example says so), shown in titles.
    pub description: Option<String>,
    /// Remarks on the spectrum (its file's convention, a steep slope), passed
    /// on to every report of this surface.
    pub warnings: Vec<Warning>,
    /// The measured map the spectrum was taken from, if any: the asperity
    /// theories take their moments from its heights.
    pub height_map: Option<HeightMapSpec>,
}

impl RoughContact {
    /// Build from the flags' (or a scene's) spectrum and material.
    ///
    /// # Errors
    /// As [`SpectrumSpec::build`] and [`MaterialSpec::build`].
    pub fn new(spectrum: &SpectrumSpec, material: &MaterialSpec) -> Result<Self> {
        Self::named(spectrum, material, "", "")
    }

    /// As [`RoughContact::new`], naming the fields with the prefixes of their sections.
    pub(crate) fn named(
        spectrum: &SpectrumSpec,
        material: &MaterialSpec,
        spectrum_section: &str,
        material_section: &str,
    ) -> Result<Self> {
        let built = spectrum
            .build_described()
            .map_err(|e| prefix(spectrum_section, e))?;
        let (s, measured, measured_warnings) = (built.value, built.description, built.warnings);
        let m: Material = material.build().map_err(|e| prefix(material_section, e))?;
        let description = (*spectrum == SpectrumSpec::example()
            && *material == MaterialSpec::example())
        .then(|| EXAMPLE.to_string())
        .or(measured);
        let mut warnings = measured_warnings;
        for w in spectrum_warnings(spectrum, s.as_ref()) {
            warning::push(&mut warnings, Some(w));
        }
        Ok(RoughContact {
            spectrum: s,
            contact_modulus: m.contact_modulus(),
            breaks: spectrum.breaks(),
            description,
            warnings,
            height_map: match spectrum {
                SpectrumSpec::HeightMap(m) => Some(m.clone()),
                _ => None,
            },
        })
    }

    /// The surface's warnings with those of the nominal pressures and the
    /// magnifications of one output.
    pub(crate) fn warnings(&self, pressures: &[f64], zetas: &[f64]) -> Vec<Warning> {
        let mut w = self.warnings.clone();
        warning::push(
            &mut w,
            Warning::high_pressure(pressures, self.contact_modulus),
        );
        let zeta_max = self.spectrum.q_max() / self.spectrum.q_min();
        warning::push(&mut w, Warning::zeta_beyond_band(zetas, zeta_max));
        w
    }

    pub(crate) fn model(&self) -> Result<Persson<'_>> {
        Persson::new(self.spectrum.as_ref(), self.contact_modulus)
    }

    pub(crate) fn band(&self) -> (f64, f64) {
        (self.spectrum.q_min(), self.spectrum.q_max())
    }
}
