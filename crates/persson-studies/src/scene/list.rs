//! The list of studies: one line per study generates the scene's
//! [`Outputs`], its [`SceneReport`], the dispatcher, the warnings, the
//! tables and the files (the macro [`studies!`](crate::study)). The order is
//! the order of the tables, of the report's JSON and of the computation.

use crate::study::studies;

studies! {
    /// Moments of the spectrum, a power-law fit and C(q).
    spectrum: crate::spectrum::Spectrum,
    /// κ of the linear low-load law; with spectrum, material and pressures
    /// also the linear contact fractions.
    kappa: crate::kappa::Kappa,
    /// A/A0 against the scene's nominal pressures (load curve).
    area: crate::area::Area,
    /// G(ζ) and A/A0 against magnification at one pressure.
    magnification: crate::magnification::Magnification,
    /// A/A0 against load for several contact-area theories.
    theories: crate::theories::Theories,
    /// Mean interfacial separation, stiffness and elastic energy against load.
    separation: crate::separation::Separation,
    /// P(u), the distribution of interfacial separations.
    separation_density: crate::separation_density::SeparationDensity,
    /// Stress distributions P(σ, ζ).
    stress: crate::stress::Stress,
    /// FFT-BEM rough contact at the scene's nominal pressures (feature `bem`).
    bem: crate::bem::Bem,
    /// FFT-BEM Hertz convergence, η per grid (feature `bem`).
    bem_hertz: crate::bem_hertz::BemHertz,
    /// The adhesive FFT-BEM along a path of mean gaps or approaches
    /// (`bem rough --work-of-adhesion`).
    bem_adhesion: crate::bem_adhesion::BemAdhesion,
    /// The map against random surfaces of its spectrum: the FFT-BEM on the
    /// scene's height map and on its surrogates (feature `bem`).
    surrogates: crate::surrogates::Surrogates,
    /// Adhesion: the stickiness energy balance and A/A0 against the scene's
    /// nominal pressures (which may be ≤ 0) with the pull-off stress.
    adhesion: crate::adhesion::Adhesion,
    /// Rubber friction μ and A/A0 against sliding velocity (needs `rubber`).
    friction: crate::friction::Friction,
    /// Thermal and electrical contact conductance against load, theory and
    /// (with `bem`) the FFT-BEM.
    conductance: crate::transport::Conductance,
    /// Leak rate of a static seal against load: critical junction, effective
    /// medium and (with `bem`) Reynolds flow on the FFT-BEM's gap.
    leakage: crate::transport::Leakage,
}
