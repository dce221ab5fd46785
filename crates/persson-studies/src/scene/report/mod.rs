//! Typed reports: what each scene output (and the subcommand of the same
//! name) computed. Every report is `Serialize` (its JSON) and [`Tabulate`]
//! (its text and CSV tables); the figures are drawn from them alone.

use serde::Serialize;

use crate::table::{Table, Tabulate};

mod adhesion;
mod area;
mod bem;
mod friction;
mod separation;
mod spectrum;
mod stress;
mod transport;

pub use adhesion::*;
pub use area::*;
pub use bem::*;
pub use friction::*;
pub use separation::*;
pub use spectrum::*;
pub use stress::*;
pub use transport::*;

/// What a scene computed: one entry per output asked for.
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
#[non_exhaustive]
pub struct SceneReport {
    /// The scene's name.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub name: Option<String>,
    /// The scene's description.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub description: Option<String>,
    /// Spectrum summary.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub spectrum: Option<SpectrumReport>,
    /// Load curve.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub area: Option<AreaReport>,
    /// Magnification curve.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub magnification: Option<MagnificationReport>,
    /// κ values.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub kappa: Option<KappaReport>,
    /// Corrected-theory load curves.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub theories: Option<TheoriesReport>,
    /// Mean separation against load.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub separation: Option<SeparationReport>,
    /// P(u), the distribution of interfacial separations.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub separation_density: Option<super::separation_density::SeparationDensityReport>,
    /// Stress distributions.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub stress: Option<StressReport>,
    /// FFT-BEM rough contact (feature `bem`).
    #[cfg(feature = "bem")]
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bem: Option<persson::bem::rough::RoughReport>,
    /// Contact-patch statistics of the BEM's solves (feature `bem`).
    #[cfg(feature = "bem")]
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bem_patches: Option<crate::bem_detail::PatchReport>,
    /// Stress below the BEM's solves (feature `bem`).
    #[cfg(feature = "bem")]
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bem_subsurface: Option<crate::bem_detail::SubsurfaceStudy>,
    /// The von Mises maps of `bem_subsurface` to write (`stress_field`).
    #[cfg(feature = "bem")]
    #[serde(skip)]
    pub bem_stress_maps: Vec<crate::bem_detail::StressMap>,
    /// FFT-BEM Hertz convergence.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bem_hertz: Option<BemHertzReport>,
    /// The adhesive FFT-BEM along a path (feature `bem`).
    #[cfg(feature = "bem")]
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bem_adhesion: Option<crate::bem_detail::AdhesiveBemReport>,
    /// Adhesion (stickiness, adhesive contact area, pull-off).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub adhesion: Option<AdhesionReport>,
    /// Rubber friction.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub friction: Option<FrictionReport>,
    /// Contact conductance against load.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub conductance: Option<ConductanceReport>,
    /// Leak rate against load.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub leakage: Option<LeakageReport>,
    /// Remarks on the input (never a change of a number); the CLI prints them
    /// on stderr and in the top-level `warnings` of `--json`.
    #[serde(skip)]
    pub warnings: Vec<crate::warning::Warning>,
}

impl SceneReport {
    /// Gather the warnings of every output into the scene's, once each.
    pub(crate) fn collect_warnings(&mut self) {
        let lists = [
            self.spectrum.as_ref().map(|r| &r.warnings),
            self.kappa.as_ref().map(|r| &r.warnings),
            self.area.as_ref().map(|r| &r.warnings),
            self.magnification.as_ref().map(|r| &r.warnings),
            self.theories.as_ref().map(|r| &r.warnings),
            self.separation.as_ref().map(|r| &r.warnings),
            self.separation_density.as_ref().map(|r| &r.warnings),
            self.stress.as_ref().map(|r| &r.warnings),
            self.adhesion.as_ref().map(|r| &r.warnings),
            self.friction.as_ref().map(|r| &r.warnings),
            self.conductance.as_ref().map(|r| &r.warnings),
            self.leakage.as_ref().map(|r| &r.warnings),
        ];
        let mut all = std::mem::take(&mut self.warnings);
        for w in lists.into_iter().flatten().flatten() {
            crate::warning::push(&mut all, Some(w.clone()));
        }
        #[cfg(feature = "bem")]
        if let Some(r) = &self.bem {
            for w in crate::warning::of_rough(r) {
                crate::warning::push(&mut all, Some(w));
            }
        }
        #[cfg(feature = "bem")]
        if let Some(r) = &self.bem_adhesion {
            for w in crate::bem_detail::adhesive_warnings(r) {
                crate::warning::push(&mut all, Some(w));
            }
        }
        self.warnings = all;
    }
}

impl Tabulate for SceneReport {
    fn tables(&self) -> Vec<Table> {
        let mut out = Vec::new();
        #[cfg(feature = "bem")]
        let (bem, patches, subsurface, adhesive) = (
            self.bem.as_ref().map(|r| r as &dyn Tabulate),
            self.bem_patches.as_ref().map(|r| r as &dyn Tabulate),
            self.bem_subsurface.as_ref().map(|r| r as &dyn Tabulate),
            self.bem_adhesion.as_ref().map(|r| r as &dyn Tabulate),
        );
        #[cfg(not(feature = "bem"))]
        let (bem, patches, subsurface, adhesive) = (None, None, None, None);
        let parts: [Option<&dyn Tabulate>; 17] = [
            self.spectrum.as_ref().map(|r| r as &dyn Tabulate),
            self.kappa.as_ref().map(|r| r as &dyn Tabulate),
            self.area.as_ref().map(|r| r as &dyn Tabulate),
            self.magnification.as_ref().map(|r| r as &dyn Tabulate),
            self.theories.as_ref().map(|r| r as &dyn Tabulate),
            self.separation.as_ref().map(|r| r as &dyn Tabulate),
            self.separation_density.as_ref().map(|r| r as &dyn Tabulate),
            self.stress.as_ref().map(|r| r as &dyn Tabulate),
            bem,
            patches,
            subsurface,
            self.bem_hertz.as_ref().map(|r| r as &dyn Tabulate),
            adhesive,
            self.adhesion.as_ref().map(|r| r as &dyn Tabulate),
            self.friction.as_ref().map(|r| r as &dyn Tabulate),
            self.conductance.as_ref().map(|r| r as &dyn Tabulate),
            self.leakage.as_ref().map(|r| r as &dyn Tabulate),
        ];
        for p in parts.into_iter().flatten() {
            out.extend(p.tables());
        }
        out
    }
}
