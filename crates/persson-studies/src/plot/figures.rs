//! Builders for the standard figures, from plain data.
//!
//! Each returns a [`Figure`] with the labels, units and scales of its kind;
//! the caller may add series (e.g. BEM points as [`Series::markers`]),
//! change the title or fix a range before calling [`super::render`].

use super::{Axis, Figure, Rgb, Series, Style};
use persson::kappa::Kappa;
use persson::Result;

/// Dark grey for reference lines (fits, the Bush law), so they do not take a
/// palette colour.
const REFERENCE: Rgb = Rgb(60, 60, 60);

/// Black for the Persson law, which lies on the theory at low load and must
/// show through it.
const REFERENCE_STRONG: Rgb = Rgb(0, 0, 0);

/// The line styles given to successive curves of a family, so that the
/// curves stay distinguishable in greyscale.
const FAMILY_STYLES: [Style; 3] = [Style::Line, Style::Dashed, Style::Dotted];

/// A power law `C(q) = prefactor · q^exponent` (a fit to a spectrum).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PowerLaw {
    /// The prefactor, in m⁴ · mᵉˣᵖᵒⁿᵉⁿᵗ (so that C is in m⁴ with q in 1/m).
    pub prefactor: f64,
    /// The exponent, −2(H + 1) for a self-affine surface.
    pub exponent: f64,
    /// The q interval (1/m) the fit was made on, where it is drawn;
    /// `None` draws it over the whole data range.
    pub q_range: Option<(f64, f64)>,
}

impl PowerLaw {
    /// `prefactor · q^exponent`, evaluated through logarithms so that
    /// extreme prefactors do not overflow on the way.
    pub fn eval(&self, q: f64) -> f64 {
        (self.prefactor.ln() + self.exponent * q.ln()).exp()
    }
}

/// The surface data for the low-load linear laws A/A0 = κ σ0 / (E* √⟨|∇h|²⟩).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LinearLaw {
    /// E*, in the unit of the pressures.
    pub contact_modulus: f64,
    /// √⟨|∇h|²⟩ of the surface, dimensionless.
    pub rms_slope: f64,
}

/// Pairs `x` with each curve's values, checking lengths.
fn paired(x: &[f64], ys: &[(&str, &[f64])], styles: &[Style]) -> Result<Vec<Series>> {
    ys.iter()
        .enumerate()
        .map(|(i, (label, y))| {
            Ok(Series::from_xy(*label, x, y)?.with_style(styles[i % styles.len()]))
        })
        .collect()
}

/// The stress distribution P(σ, ζ) against σ/σH, one curve per ζ (like
/// Figs. 2–4 of Persson, Bucher & Chiaia 2002).
///
/// `sigma` is σ/σH; each curve is `(label, P)` with P in units of 1/σH.
/// Curves cycle through solid, dashed and dotted lines.
///
/// # Errors
/// [`persson::Error::Inconsistent`] if a curve's length differs from `sigma`'s.
///
/// # References
/// B. N. J. Persson, F. Bucher, B. Chiaia, PRB 65, 184106 (2002), Figs. 2–4.
pub fn stress_family(sigma: &[f64], curves: &[(&str, &[f64])]) -> Result<Figure> {
    let mut fig = Figure::new(
        "Stress distribution P(σ, ζ)",
        Axis::linear("normal stress σ/σH"),
        Axis::linear("P(σ, ζ) (1/σH)"),
    );
    fig.series = paired(sigma, curves, &FAMILY_STYLES)?;
    Ok(fig)
}

/// The contact fraction A/A0 against the magnification ζ, log–log.
///
/// # Errors
/// [`persson::Error::Inconsistent`] if a curve's length differs from `zeta`'s.
pub fn area_vs_zeta(zeta: &[f64], curves: &[(&str, &[f64])]) -> Result<Figure> {
    let mut fig = Figure::new(
        "Contact area against magnification",
        Axis::log("magnification ζ = q/qL"),
        Axis::log("contact fraction A/A0"),
    );
    fig.series = paired(zeta, curves, &FAMILY_STYLES)?;
    Ok(fig)
}

/// G(ζ) against the magnification ζ, log–log.
///
/// # Errors
/// [`persson::Error::Inconsistent`] if a curve's length differs from `zeta`'s.
///
/// # References
/// Persson, Bucher & Chiaia (2002), Eq. 2.
pub fn g_vs_zeta(zeta: &[f64], curves: &[(&str, &[f64])]) -> Result<Figure> {
    let mut fig = Figure::new(
        "G(ζ) = (π/4)(E*/σ0)² ∫ q³C(q) dq",
        Axis::log("magnification ζ = q/qL"),
        Axis::log("G(ζ) (dimensionless)"),
    );
    fig.series = paired(zeta, curves, &FAMILY_STYLES)?;
    Ok(fig)
}

/// The contact fraction A/A0 against the nominal pressure σ0, log–log, with
/// the Bush and Persson low-load lines when `linear` is given.
///
/// `pressure_unit` names the unit of `pressure` (and of E*), e.g. `"Pa"` or
/// `"E*"`. The linear laws are drawn over the pressure range of the data
/// where they stay below A/A0 = 1.
///
/// # Formula
/// ```text
/// A/A0 = κ σ0 / (E* √⟨|∇h|²⟩),  κ_Bush = √(2π),  κ_Persson = √(8/π)
/// ```
///
/// # Errors
/// [`persson::Error::Inconsistent`] if a curve's length differs from `pressure`'s;
/// [`persson::Error::InvalidParameter`] if E* or the rms slope is not positive.
///
/// # References
/// Persson, Bucher & Chiaia (2002), Sec. IV; Bush, Gibson & Thomas, Wear 35, 87 (1975).
pub fn area_vs_load(
    pressure: &[f64],
    curves: &[(&str, &[f64])],
    pressure_unit: &str,
    linear: Option<LinearLaw>,
) -> Result<Figure> {
    let mut fig = Figure::new(
        "Contact area against load",
        Axis::log(format!("nominal pressure σ0 ({pressure_unit})")),
        Axis::log("contact fraction A/A0"),
    );
    fig.series = paired(pressure, curves, &[Style::Line])?;
    if let Some(law) = linear {
        persson::error::check::positive("contact_modulus", law.contact_modulus)?;
        persson::error::check::positive("rms_slope", law.rms_slope)?;
        let (lo, hi) = positive_extent(pressure);
        for (kappa, label, style, color) in [
            (
                Kappa::Bush,
                "Bush et al.: κ = √(2π)",
                Style::Dashed,
                REFERENCE,
            ),
            (
                Kappa::Persson,
                "Persson: κ = √(8/π)",
                Style::Dotted,
                REFERENCE_STRONG,
            ),
        ] {
            let full = law.contact_modulus * law.rms_slope / kappa.value();
            let top = hi.min(full);
            let points = if lo < top {
                vec![
                    (
                        lo,
                        kappa.linear_fraction(lo, law.contact_modulus, law.rms_slope),
                    ),
                    (
                        top,
                        kappa.linear_fraction(top, law.contact_modulus, law.rms_slope),
                    ),
                ]
            } else {
                Vec::new()
            };
            fig.push(Series::new(label, points, style).with_color(color));
        }
    }
    Ok(fig)
}

/// The power spectrum C(q) against q, log–log, with an optional power-law
/// fit drawn dashed over its own q range (or the data's).
///
/// # Errors
/// [`persson::Error::Inconsistent`] if `q` and `c` differ in length;
/// [`persson::Error::InvalidParameter`] if the fit's prefactor is not positive
/// or its exponent not finite.
pub fn spectrum(q: &[f64], c: &[f64], fit: Option<PowerLaw>) -> Result<Figure> {
    let mut fig = Figure::new(
        "Power spectrum C(q)",
        Axis::log("wavevector q (1/m)"),
        Axis::log("C(q) (m⁴)"),
    );
    let style = if q.len() <= 40 {
        Style::LineMarkers
    } else {
        Style::Line
    };
    fig.push(Series::from_xy("C(q)", q, c)?.with_style(style));
    if let Some(law) = fit {
        persson::error::check::positive("prefactor", law.prefactor)?;
        if !law.exponent.is_finite() {
            return Err(persson::Error::invalid("exponent", law.exponent, "finite"));
        }
        let (lo, hi) = law.q_range.unwrap_or_else(|| positive_extent(q));
        let n = 50;
        let points = if lo > 0.0 && lo < hi {
            (0..=n)
                .map(|i| {
                    let q = lo * (hi / lo).powf(i as f64 / n as f64);
                    (q, law.eval(q))
                })
                .collect()
        } else {
            Vec::new()
        };
        let exponent = format!("{:.2}", law.exponent).replace('-', "−");
        let label = format!("power-law fit C ∝ q^{exponent}");
        fig.push(Series::dashed(label, points).with_color(REFERENCE));
    }
    Ok(fig)
}

/// Error against wall-clock time for several methods, log–log, lines with
/// markers (an accuracy–cost plot).
///
/// Each method is `(name, [(seconds, error)])`.
pub fn error_vs_time(methods: &[(&str, &[(f64, f64)])]) -> Figure {
    let mut fig = Figure::new(
        "Accuracy against cost",
        Axis::log("wall-clock time (s)"),
        Axis::log("relative error"),
    );
    for (name, points) in methods {
        fig.push(Series::line_markers(*name, points.to_vec()));
    }
    fig
}

/// The smallest and largest finite positive value (or (∞, −∞) if none).
fn positive_extent(v: &[f64]) -> (f64, f64) {
    v.iter()
        .copied()
        .filter(|x| x.is_finite() && *x > 0.0)
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| {
            (a.min(x), b.max(x))
        })
}
