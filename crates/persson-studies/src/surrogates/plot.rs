//! The figures of `surrogates`.

use persson::error::Result;

use super::SurrogatesReport;
use crate::plot::{Axis, Figure, Series, PALETTE};

/// A/A0 against σ0 on log axes: the map's, the surrogates' mean with a
/// band of ± two standard deviations (one surface's scatter), the theory.
///
/// # Errors
/// None in practice (the figure is built from the report alone).
pub fn area(r: &SurrogatesReport) -> Result<Figure> {
    let p = |f: &dyn Fn(&super::SurrogatePoint) -> f64| -> Vec<(f64, f64)> {
        r.points
            .iter()
            .map(|x| (x.nominal_pressure, f(x)))
            .collect()
    };
    Ok(Figure::new(
        format!("Map against {} {} surrogates", r.count, r.kind),
        Axis::log("nominal pressure σ0 (Pa)"),
        Axis::log("relative contact area A/A0"),
    )
    .with_series(Series::line_markers("map", p(&|x| x.map_contact_fraction)).with_color(PALETTE[0]))
    .with_series(
        Series::line("surrogates (mean)", p(&|x| x.surrogate_contact_fraction))
            .with_color(PALETTE[1]),
    )
    .with_series(
        Series::dashed(
            "surrogates ± 2 sd",
            p(&|x| x.surrogate_contact_fraction + 2.0 * x.surrogate_standard_deviation),
        )
        .with_color(PALETTE[1]),
    )
    .with_series(
        Series::dashed(
            "",
            p(&|x| x.surrogate_contact_fraction - 2.0 * x.surrogate_standard_deviation),
        )
        .with_color(PALETTE[1]),
    )
    .with_series(
        Series::line("Persson's theory", p(&|x| x.theory_contact_fraction)).with_color(PALETTE[6]),
    ))
}

/// P(p) of the map and of the pooled surrogates at the largest pressure,
/// p/σ0 on a linear axis and P on a log axis (where an exponential tail is a
/// straight line and a Gaussian one bends down).
///
/// # Errors
/// No pressure.
pub fn distribution(r: &SurrogatesReport) -> Result<Figure> {
    let Some(last) = r
        .points
        .iter()
        .max_by(|a, b| a.nominal_pressure.total_cmp(&b.nominal_pressure))
    else {
        return Err(persson::Error::Inconsistent {
            name: "surrogates".into(),
            requirement: "at least one pressure".into(),
        });
    };
    let s0 = last.nominal_pressure;
    let curve = |bins: &[(f64, f64, f64)]| -> Vec<(f64, f64)> {
        bins.iter()
            .filter(|b| b.2 > 0.0)
            .map(|b| (0.5 * (b.0 + b.1) / s0, b.2 * s0))
            .collect()
    };
    Ok(Figure::new(
        format!(
            "Pressure distribution at σ0 = {} Pa",
            crate::table::number(s0, 4)
        ),
        Axis::linear("p/σ0"),
        Axis::log("σ0 P(p)"),
    )
    .with_series(Series::line_markers("map", curve(&last.map_distribution)).with_color(PALETTE[0]))
    .with_series(
        Series::line("surrogates (pooled)", curve(&last.surrogate_distribution))
            .with_color(PALETTE[1]),
    ))
}
