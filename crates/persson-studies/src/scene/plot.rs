//! Figures drawn from the typed reports alone (feature `plot`).

use crate::plot::{self, Axis, Figure, Series};
use crate::table::number;
use persson::error::Result;

use super::report::*;

pub use crate::area::figure as area;
pub use crate::magnification::{magnification_area, magnification_g};
pub use crate::separation::figure as separation;
pub use crate::spectrum::figure as spectrum;
pub use crate::stress::figure as stress;
pub use crate::theories::figure as theories;

/// FFT-BEM A/A0 against load with the Bush and Persson lines.
///
/// # Errors
/// An inconsistent report.
#[cfg(feature = "bem")]
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

/// C(q) of a measured surface with its Hurst fit over the band.
///
/// # Errors
/// An inconsistent report.
#[cfg(feature = "topography")]
pub fn measured_spectrum(a: &persson::topography::Analysis) -> Result<Figure> {
    let law = a.fit.map(|f| crate::plot::PowerLaw {
        prefactor: f.prefactor,
        exponent: -2.0 * (f.hurst + 1.0),
        q_range: Some((a.q_min, a.q_max)),
    });
    let mut fig = plot::spectrum(&a.psd.q, &a.psd.c, law)?;
    fig.title = match a.fit {
        Some(f) => format!(
            "Power spectrum C(q) of the measured surface, H = {} ± {}",
            number(f.hurst, 3),
            number(f.hurst_error, 2)
        ),
        None => "Power spectrum C(q) of the measured surface (no Hurst fit)".into(),
    };
    Ok(fig)
}

/// The spectra of several measurements and their combination (log–log):
/// each measurement's binned spectrum over its band, the combined one on top.
///
/// # Errors
/// A spectrum with no positive point.
pub fn multi_scale(r: &crate::scene::multiscale::MultiScaleReport) -> Result<Figure> {
    let mut fig = plot::spectrum(&r.q, &r.c, None)?;
    fig.title = format!(
        "Power spectrum C(q) combined from {} measurements",
        r.measurements.len()
    );
    if let Some(first) = fig.series.first_mut() {
        first.label = "combined".into();
    }
    for m in &r.measurements {
        let name = m
            .file
            .file_name()
            .map(|f| f.to_string_lossy().into_owned())
            .unwrap_or_default();
        fig.push(plot::Series::from_xy(name, &m.psd.q, &m.psd.c)?.with_style(plot::Style::Markers));
    }
    Ok(fig)
}

/// The positive (x, y) pairs of a curve: a log axis has no room for zero
/// (a sealed load's Q = 0 is in the table, not on the figure).
fn positive(points: impl Iterator<Item = (f64, Option<f64>)>) -> Vec<(f64, f64)> {
    points
        .filter_map(|(x, y)| y.map(|y| (x, y)))
        .filter(|&(x, y)| x > 0.0 && y > 0.0 && y.is_finite())
        .collect()
}

/// h(σ0) on log axes: the theory's conductances as lines, the BEM's at the
/// same loads as markers.
///
/// # Errors
/// None in practice (the figure is built from the report alone).
pub fn conductance(r: &ConductanceReport) -> Result<Figure> {
    let mut fig = Figure::new(
        "Contact conductance against load",
        Axis::log("nominal pressure σ0 (Pa)"),
        Axis::log("conductance h: W/(m² K) (thermal, gap), S/m² (electrical)"),
    );
    let th = &r.points;
    type Theory = fn(&persson::conductance::ConductancePoint) -> Option<f64>;
    type Bem = fn(&BemTransportPoint) -> Option<f64>;
    let curves: [(&str, Theory, Bem); 3] = [
        (
            "thermal h_c",
            |p| p.thermal_conductance,
            |p| p.thermal_conductance,
        ),
        (
            "electrical h_e",
            |p| p.electrical_conductance,
            |p| p.electrical_conductance,
        ),
        ("gap h_gap", |p| p.gap_conductance, |p| p.gap_conductance),
    ];
    for (label, f, g) in curves {
        let pts = positive(th.iter().map(|p| (p.nominal_pressure, f(p))));
        if pts.is_empty() {
            continue;
        }
        fig.push(Series::line(format!("{label}, theory"), pts));
        if let Some(b) = &r.bem {
            let pts = positive(b.points.iter().map(|p| (p.nominal_pressure, g(p))));
            fig.push(Series::markers(format!("{label}, BEM {}²", b.grid), pts));
        }
    }
    Ok(fig)
}

/// Rubber friction: μ against log v (top) and A/A0 against log v (bottom),
/// one curve per (T, σ0), dashed with the flash temperature.
///
/// # Errors
/// An empty report.
pub fn friction(r: &FrictionReport) -> Result<[Figure; 2]> {
    let mut mu = Figure::new(
        "Rubber friction μ(v)",
        Axis::log("sliding velocity v (m/s)"),
        Axis::linear("friction coefficient μ"),
    );
    let mut area = Figure::new(
        "Contact area at q1",
        Axis::log("sliding velocity v (m/s)"),
        Axis::log("contact fraction A/A0"),
    );
    let mut groups: Vec<(f64, f64)> = Vec::new();
    for p in &r.points {
        if !groups.contains(&(p.temperature, p.nominal_pressure)) {
            groups.push((p.temperature, p.nominal_pressure));
        }
    }
    for (t, s) in groups {
        let pts: Vec<_> = r
            .points
            .iter()
            .filter(|p| p.temperature == t && p.nominal_pressure == s)
            .collect();
        let label = format!("T = {} K, σ0 = {} Pa", number(t, 5), number(s, 4));
        let iso = |f: fn(&persson::friction::FrictionResult) -> f64| -> Vec<(f64, f64)> {
            pts.iter().map(|p| (p.velocity, f(&p.isothermal))).collect()
        };
        mu.push(Series::line(label.clone(), iso(|x| x.friction_coefficient)));
        area.push(Series::line(label.clone(), iso(|x| x.contact_fraction)));
        let flash = |f: fn(&persson::friction::FrictionResult) -> f64| -> Vec<(f64, f64)> {
            pts.iter()
                .filter_map(|p| p.flash.as_ref().map(|x| (p.velocity, f(x))))
                .collect()
        };
        let fm = flash(|x| x.friction_coefficient);
        if !fm.is_empty() {
            let l = format!("{label}, flash temperature");
            mu.push(Series::dashed(l.clone(), fm));
            area.push(Series::dashed(l, flash(|x| x.contact_fraction)));
        }
    }
    Ok([mu, area])
}

/// Q(σ0) on log axes: both theories as lines, Reynolds flow on the BEM's
/// gap as markers.
///
/// # Errors
/// None in practice (the figure is built from the report alone).
pub fn leakage(r: &LeakageReport) -> Result<Figure> {
    let mut fig = Figure::new(
        "Leak rate against load",
        Axis::log("nominal pressure σ0 (Pa)"),
        Axis::log("leak rate Q (m³/s)"),
    );
    let p = &r.points;
    fig.push(Series::line(
        format!(
            "critical junction, a_c = {}",
            number(r.percolation_threshold, 3)
        ),
        positive(
            p.iter()
                .map(|x| (x.nominal_pressure, Some(x.critical_junction.leak_rate))),
        ),
    ));
    fig.push(Series::dashed(
        "effective medium",
        positive(
            p.iter()
                .map(|x| (x.nominal_pressure, Some(x.effective_medium.leak_rate))),
        ),
    ));
    if let Some(b) = &r.bem {
        fig.push(Series::markers(
            format!("Reynolds flow on the BEM gap, {}²", b.grid),
            positive(b.points.iter().map(|x| (x.nominal_pressure, x.leak_rate))),
        ));
    }
    Ok(fig)
}

/// The log-binned patch-area distribution n(A) of each solve on log axes
/// (bin centres √(A_low A_high), the bins that hold a patch), with the
/// fitted exponent τ in the legend (Hyun, Pei, Molinari & Robbins 2004).
///
/// # Errors
/// None in practice (the figure is built from the report alone).
#[cfg(feature = "bem")]
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
#[cfg(feature = "bem")]
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
