//! The figures of `conductance` and `leakage` (feature `plot`).

use persson::error::Result;

use super::{BemTransportPoint, ConductanceReport, LeakageReport};
use crate::plot::positive;
use crate::plot::{Axis, Figure, Series};
use crate::table::number;

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
