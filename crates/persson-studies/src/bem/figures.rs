//! The figures of `bem` (features `bem` and `plot`): A/A0 against load,
//! the patch areas and the stress below the surface.

use persson::error::Result;

use crate::plot::{self, positive, Axis, Figure, Series};
use crate::table::number;

/// FFT-BEM A/A0 against load with the Bush and Persson lines.
///
/// # Errors
/// An inconsistent report.
pub fn bem(r: &persson::bem::rough::RoughReport) -> Result<Figure> {
    let p: Vec<f64> = r.points.iter().map(|x| x.nominal_pressure).collect();
    let a: Vec<f64> = r.points.iter().map(|x| x.contact_fraction).collect();
    let label = format!("FFT-BEM, {0}×{0} {1}", r.grid, r.boundary.name());
    let law = crate::plot::LinearLaw {
        contact_modulus: r.contact_modulus,
        rms_slope: r.surface_rms_slope,
    };
    plot::area_vs_load(&p, &[(label.as_str(), &a)], "unit of E*", Some(law))
}

/// The log-binned patch-area distribution n(A) of each solve on log axes
/// (bin centres √(A_low A_high), the bins that hold a patch), with the
/// fitted exponent τ in the legend (Hyun, Pei, Molinari & Robbins 2004).
///
/// # Errors
/// None in practice (the figure is built from the report alone).
pub fn patch_areas(r: &crate::bem_detail::PatchReport) -> Result<Figure> {
    let mut fig = Figure::new(
        format!("Contact-patch areas, {}² grid", r.grid),
        Axis::log("patch area A (m²)"),
        Axis::log("n(A) (1/m²)"),
    );
    for p in &r.points {
        let tau = p
            .patch_area_exponent
            .map(|t| format!(", τ = {}", number(t, 3)))
            .unwrap_or_default();
        fig.push(Series::line_markers(
            format!("σ0 = {}{tau}", number(p.nominal_pressure, 4)),
            positive(
                p.area_distribution
                    .iter()
                    .filter(|b| b.count > 0)
                    .map(|b| ((b.area_low * b.area_high).sqrt(), Some(b.density))),
            ),
        ));
    }
    Ok(fig)
}

/// The largest von Mises stress (line) and maximum shear (dashed) on each
/// plane against its depth, one pair per solve.
///
/// # Errors
/// None in practice (the figure is built from the report alone).
pub fn subsurface_profiles(r: &crate::bem_detail::SubsurfaceStudy) -> Result<Figure> {
    let mut fig = Figure::new(
        "Stress below the surface: plane maxima against depth",
        Axis::linear("depth z (m)"),
        Axis::linear("stress (unit of the pressure)"),
    );
    for p in &r.points {
        let s = number(p.nominal_pressure, 4);
        let planes = &p.report.planes;
        fig.push(Series::line_markers(
            format!("max σ_vM, σ0 = {s}"),
            planes
                .iter()
                .map(|q| (q.depth, q.von_mises_stress.value))
                .collect(),
        ));
        fig.push(Series::dashed(
            format!("max τ, σ0 = {s}"),
            planes
                .iter()
                .map(|q| (q.depth, q.max_shear_stress.value))
                .collect(),
        ));
    }
    Ok(fig)
}
