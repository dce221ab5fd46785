//! The `area` output with an asperity theory (overlap, Greenwood &
//! Williamson, Bush–Gibson–Thomas): its load curve beside Persson's, the
//! surface's asperity parameters, and its table.

use crate::asperity::{self as studies, AsperityModel, AsperitySettings};
use crate::table::{number, Table};
use crate::warning;
use persson::error::{Error, Result};
use persson::kappa::Kappa;

use super::{AreaOutput, AreaReport, LoadPoint};
use crate::contact::RoughContact;
use crate::table::{input_digits, surface_prefix};

/// The asperity model of `out.theory` for `surface`: from its height map's
/// heights when it has one, else from its spectrum up to ζ q_l.
fn model(surface: &RoughContact, out: &AreaOutput, zeta: Option<f64>) -> Result<AsperityModel> {
    let settings = AsperitySettings {
        yield_stress: out.yield_stress,
        tolerance: out
            .tolerance
            .unwrap_or(persson::asperity::bush::DEFAULT_TOLERANCE),
        ..AsperitySettings::new(out.theory)
    };
    if let Some(map) = &surface.height_map {
        if out.zeta.is_some() {
            return Err(Error::Inconsistent {
                name: "zeta".into(),
                requirement: "not used by an asperity theory on a height map (its moments are \
                              the map's own, at its pixel size)"
                    .into(),
            });
        }
        return from_map(map, surface.contact_modulus, &settings);
    }
    let q_max = zeta.map(|z| z * surface.spectrum.q_min());
    AsperityModel::from_spectrum(
        surface.spectrum.as_ref(),
        q_max,
        surface.contact_modulus,
        &settings,
    )
}

/// The model from a measured map's heights, detrended as its spectrum is.
#[cfg(feature = "topography")]
fn from_map(
    map: &crate::input::HeightMapSpec,
    e_star: f64,
    settings: &AsperitySettings,
) -> Result<AsperityModel> {
    use persson::topography::{Conditioning, Layout};
    let t = map.read()?;
    if t.layout() != Layout::Map {
        return Err(Error::invalid(
            "m4",
            f64::NAN,
            "from a 2-D map: line scans give no summit density (read a map of the surface)",
        ));
    }
    let detrend = map
        .detrend
        .unwrap_or(Conditioning::for_topography(&t).detrend);
    let h = t.detrended(detrend);
    let d = t.pixel_size();
    let (dx, dy) = (d[0], d.get(1).copied().unwrap_or(d[0]));
    AsperityModel::from_heights(
        &map.file,
        &h,
        [t.nx(), t.ny()],
        [dx, dy],
        t.periodic(),
        e_star,
        settings,
    )
}

#[cfg(not(feature = "topography"))]
fn from_map(
    _: &crate::input::HeightMapSpec,
    _: f64,
    _: &AsperitySettings,
) -> Result<AsperityModel> {
    Err(Error::Inconsistent {
        name: "kind = height_map".into(),
        requirement: "an asperity theory on a height map needs persson built with the feature \
                      `topography`"
            .into(),
    })
}

/// A/A0 of an asperity theory against the nominal pressures (`area` with
/// `theory` overlap, greenwood-williamson or bush), with Persson's original
/// A/A0 and the linear laws beside it.
///
/// # Errors
/// As [`AsperityModel::from_spectrum`] / [`AsperityModel::from_heights`]
/// (a missing m4 names `m4`; the overlap model needs `yield_stress`, the
/// others refuse it); ζ not above 1; γ given (asperity theories have none); a
/// pressure not finite and positive.
pub fn area(surface: &RoughContact, pressures: &[f64], out: &AreaOutput) -> Result<AreaReport> {
    if let Some(g) = out.gamma {
        return Err(Error::invalid(
            "gamma",
            g,
            format!("absent for the {} theory (it has no γ)", out.theory),
        ));
    }
    if out.yield_stress.is_some() && out.theory != crate::input::TheoryName::Overlap {
        return Err(Error::Inconsistent {
            name: "yield_stress".into(),
            requirement: format!(
                "only with the overlap theory (the hardness of its load law), not {}",
                out.theory
            ),
        });
    }
    if let Some(z) = out.zeta {
        if !(z.is_finite() && z > 1.0) {
            return Err(Error::invalid(
                "zeta",
                z,
                "> 1 for an asperity theory (its moments are those of [q_l, ζ q_l])",
            ));
        }
    }
    let persson = surface.model()?;
    let zeta = out.zeta.unwrap_or_else(|| persson.zeta_max());
    let model = model(surface, out, out.zeta)?;
    let curve = model.pressure_curve(pressures)?;
    let original = persson.load_curve(pressures, zeta)?;
    let (q_l, q_s) = (surface.spectrum.q_min(), surface.spectrum.q_max());
    let mut warnings = surface.warnings(pressures, &[zeta]);
    for w in studies::warnings(&model, &curve) {
        warning::push(&mut warnings, Some(w));
    }
    Ok(AreaReport {
        warnings,
        surface: surface.description.clone(),
        contact_modulus: surface.contact_modulus,
        rms_height: surface.spectrum.rms_height(q_l, q_s)?.value,
        rms_slope: surface.spectrum.rms_slope(q_l, q_s)?.value,
        kappa_bush: Kappa::Bush.value(),
        kappa_persson: Kappa::Persson.value(),
        theory: out.theory,
        gamma: None,
        kappa: model.low_load_kappa(),
        yield_stress: model.yield_stress,
        zeta,
        original_contact_fraction: original.iter().map(|p| p.contact_fraction).collect(),
        points: original
            .iter()
            .zip(&curve)
            .map(|(p, a)| LoadPoint::asperity(p, a, model.relative_error()))
            .collect(),
        asperity: model.parameters,
    })
}

/// Digits of the asperity table's scalars.
const DIGITS: usize = 6;

impl AreaReport {
    /// The table of an asperity theory: the surface's parameters as scalars,
    /// then σ0, A/A0, its bound, the separation, the contact density,
    /// Persson's A/A0 and the linear laws.
    pub(crate) fn asperity_table(&self) -> Table {
        let source = match self.asperity.as_ref().map(|a| &a.moments_from) {
            Some(studies::MomentSource::HeightMap { file }) => {
                format!("moments of the map {}", file.display())
            }
            Some(studies::MomentSource::Spectrum { q_min, q_max }) => format!(
                "moments of the spectrum over [{}, {}] 1/m",
                number(*q_min, 4),
                number(*q_max, 4)
            ),
            None => "Gaussian heights of the spectrum's rms height".into(),
        };
        let mut t = Table::new(
            "area",
            format!(
                "{}Contact area against nominal pressure ({} theory; {source}), E* = {}",
                surface_prefix(&self.surface),
                self.theory,
                number(self.contact_modulus, DIGITS),
            ),
        );
        if let Some(y) = self.yield_stress {
            t = t.scalar("yield_stress", "hardness σY (σ0 = σY A/A0)", y);
        }
        if let Some(a) = &self.asperity {
            let s = &a.summits;
            t = t
                .scalar("m0", "m0 = ⟨h²⟩", a.moments.m0)
                .scalar("m2", "m2 = ⟨h_x²⟩", a.moments.m2)
                .scalar("m4", "m4 = ⟨h_xx²⟩", a.moments.m4)
                .scalar(
                    "bandwidth_parameter",
                    "α = m0 m4/m2²",
                    s.bandwidth_parameter,
                )
                .scalar("summit_density", "summit density η", s.summit_density)
                .scalar(
                    "summit_curvature",
                    "mean summit curvature κ̄",
                    s.summit_curvature,
                )
                .scalar("summit_radius", "summit radius β", s.summit_radius)
                .scalar(
                    "summit_mean_height",
                    "summit mean height y_s",
                    s.summit_mean_height,
                )
                .scalar(
                    "summit_rms_height",
                    "summit rms height σ_s",
                    s.summit_rms_height,
                );
            if let Some(r) = a.curvature_resolution_ratio {
                t = t.scalar("curvature_resolution_ratio", "m4(2Δ)/m4(Δ)", r);
            }
        }
        t = t
            .scalar("kappa", "κ of the theory", self.kappa)
            .column_digits(
                "nominal_pressure",
                "σ0",
                input_digits(self.points.iter().map(|p| p.nominal_pressure)),
            )
            .column_digits("contact_fraction", "A/A0", 10)
            .column_digits("error_bound", "± bound", 2)
            .column("separation", "d (m)");
        let counted = self
            .points
            .iter()
            .any(|p| p.contact_number_density.is_some());
        if counted {
            t = t.column("contact_number_density", "n (1/m²)");
        }
        t = t
            .column("contact_fraction_original", "A/A0 Persson")
            .column("contact_fraction_bush_linear", "Bush linear");
        for p in &self.points {
            let mut row = vec![
                p.nominal_pressure.into(),
                p.contact_fraction.into(),
                p.error_bound.into(),
                p.separation.into(),
            ];
            if counted {
                row.push(p.contact_number_density.into());
            }
            row.push(p.contact_fraction_original.into());
            row.push(p.contact_fraction_bush_linear.into());
            t.push(row);
        }
        t
    }
}
