//! The asperity theories in [`super::compare`]: overlap, Greenwood &
//! Williamson and Bush, Gibson & Thomas from the moments of the compared
//! (clipped) spectrum, beside the BEM's continuum limit A∞.
//!
//! # What it reports
//! For each theory its A/A0 at the compared pressures and the ratio
//! A/A0 ÷ A∞ (the agreement); the surface's asperity parameters (m0, m2, m4,
//! α, summit density and curvature); and the warnings of the theories'
//! assumptions (Nayak's α small, contacts coalescing above A/A0 = 0.1). The
//! overlap model has no elasticity: its load law is the hardness law
//! σ0 = σY A/A0 and it is compared only with a yield stress (then against
//! the saturated BEM, whose A/A0 tends to σ0/σY as σY falls).
//!
//! A theory that fails (a separation search that does not converge) is
//! reported with its reason instead of stopping the comparison.
//!
//! # References
//! G. Carbone, F. Bottiglione, J. Mech. Phys. Solids 56, 2555 (2008),
//! doi:10.1016/j.jmps.2008.03.011: GW, BGT and Persson against numerics in
//! the same way.

use serde::Serialize;

use crate::asperity::{warnings, AsperityModel, AsperityParameters, AsperitySettings};
use crate::naming::names::TheoryName;
use crate::table::{Cell, Table};
use crate::warning::Warning;
use persson::spectrum::Spectrum;

/// One asperity theory at the compared pressures.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct AsperityCurve {
    /// overlap, greenwood-williamson or bush.
    pub theory: TheoryName,
    /// A/A0 at each pressure (empty when `not_computed`).
    pub contact_fraction: Vec<f64>,
    /// A/A0 ÷ A∞ (the BEM's continuum limit) at each pressure.
    pub ratio_to_continuum: Vec<f64>,
    /// Separation d of the flat from the mean plane, m (unit of L).
    pub separation: Vec<f64>,
    /// Why the theory has no curve.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub not_computed: Option<String>,
}

/// The asperity theories against the BEM.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct AsperityComparison {
    /// The compared spectrum's moments and summit statistics.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub parameters: Option<AsperityParameters>,
    /// One curve per theory: greenwood-williamson, bush, and (with σY) overlap.
    pub curves: Vec<AsperityCurve>,
    /// The theories' assumptions that fail on this surface and load range.
    pub warnings: Vec<Warning>,
}

/// The asperity theories of `band` (the compared spectrum) at `pressures`,
/// against `a_inf` (the BEM's continuum limit at the same pressures).
pub(crate) fn asperity_comparison(
    band: &dyn Spectrum,
    contact_modulus: f64,
    yield_stress: Option<f64>,
    pressures: &[f64],
    a_inf: &[f64],
) -> AsperityComparison {
    let mut theories = vec![TheoryName::GreenwoodWilliamson, TheoryName::Bush];
    if yield_stress.is_some() {
        theories.push(TheoryName::Overlap);
    }
    let mut out = AsperityComparison {
        parameters: None,
        curves: Vec::new(),
        warnings: Vec::new(),
    };
    for theory in theories {
        let mut settings = AsperitySettings::new(theory);
        settings.yield_stress = yield_stress;
        let curve = AsperityModel::from_spectrum(band, None, contact_modulus, &settings)
            .and_then(|m| m.pressure_curve(pressures).map(|p| (m, p)));
        match curve {
            Ok((model, points)) => {
                if out.parameters.is_none() {
                    out.parameters = model.parameters.clone();
                }
                for w in warnings(&model, &points) {
                    if !out.warnings.contains(&w) {
                        out.warnings.push(w);
                    }
                }
                let a: Vec<f64> = points.iter().map(|p| p.contact_fraction).collect();
                out.curves.push(AsperityCurve {
                    theory,
                    ratio_to_continuum: a.iter().zip(a_inf).map(|(t, b)| t / b).collect(),
                    contact_fraction: a,
                    separation: points.iter().map(|p| p.separation).collect(),
                    not_computed: None,
                });
            }
            Err(e) => out.curves.push(AsperityCurve {
                theory,
                contact_fraction: Vec::new(),
                ratio_to_continuum: Vec::new(),
                separation: Vec::new(),
                not_computed: Some(e.to_string()),
            }),
        }
    }
    out
}

/// The short label of an asperity theory in a table heading or a legend.
pub fn label(t: TheoryName) -> &'static str {
    match t {
        TheoryName::GreenwoodWilliamson => "GW",
        TheoryName::Bush => "BGT",
        TheoryName::Overlap => "overlap",
        _ => "?",
    }
}

/// The table: σ0, A∞, and per theory A/A0 and its ratio to A∞.
pub(crate) fn asperity_table(
    c: &AsperityComparison,
    pressures: &[f64],
    a_inf: &[f64],
    saturated: bool,
) -> Table {
    let mut t = Table::new(
        "area_asperity",
        format!(
            "Asperity theories against the BEM's continuum limit A∞{} (GW: Greenwood & \
             Williamson 1966, BGT: Bush, Gibson & Thomas 1975)",
            if saturated { ", saturated" } else { "" }
        ),
    );
    if let Some(p) = &c.parameters {
        t = t
            .scalar(
                "bandwidth_parameter",
                "α = m0 m4/m2²",
                p.summits.bandwidth_parameter,
            )
            .scalar(
                "summit_density",
                "summit density η",
                p.summits.summit_density,
            );
    }
    if !saturated {
        t = t.scalar(
            "overlap",
            "overlap",
            "with --yield-stress only (its load law σ0 = σY A/A0)",
        );
    }
    t = t.column("nominal_pressure", "σ0").column("bem", "A∞");
    let shown: Vec<&AsperityCurve> = c
        .curves
        .iter()
        .filter(|k| k.not_computed.is_none())
        .collect();
    for k in &c.curves {
        if let Some(reason) = &k.not_computed {
            let key = format!("{}_not_computed", k.theory.to_string().replace('-', "_"));
            t = t.scalar(
                &key,
                &format!("{} not computed", label(k.theory)),
                reason.as_str(),
            );
        }
    }
    for k in &shown {
        let key = k.theory.to_string().replace('-', "_");
        t = t
            .column(&format!("contact_fraction_{key}"), label(k.theory))
            .column_digits(
                &format!("ratio_{key}"),
                &format!("{}/A∞", label(k.theory)),
                3,
            );
    }
    for (i, (&p, &a)) in pressures.iter().zip(a_inf).enumerate() {
        let mut row = vec![Cell::Num(p), Cell::Num(a)];
        for k in &shown {
            row.push(Cell::Num(k.contact_fraction[i]));
            row.push(Cell::Num(k.ratio_to_continuum[i]));
        }
        t.push(row);
    }
    t
}
