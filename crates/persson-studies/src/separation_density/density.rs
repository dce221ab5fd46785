//! The distribution of interfacial separations P(u) as its own output
//! (`persson separation --separation-density`): the contact's δ weight A/A0
//! at u = 0 and the continuous part P_nc(u) on a grid of separations, with
//! the two identities that check it, the normalisation A/A0 + ∫P_nc du = 1
//! and the first moment ∫u P(u) du = ū + s_fold, where s_fold ≥ 0 is what
//! the fold of each magnification's Gaussian at u = 0 adds (Almqvist,
//! Campañá, Prodanov & Persson, J. Mech. Phys. Solids 59, 2355 (2011);
//! [`persson::gap`] module docs).
//!
//! The separations run from 0 to min(u_window, ∫u P du + 6 h_rms), u_window
//! the largest any magnification's window reaches: beyond ū + 6 h_rms the
//! density is negligible.

use serde::Serialize;

use crate::contact::RoughContact;
use crate::table::{Table, Tabulate};
use crate::Warning;
use persson::error::{check, Result};
use persson::gap::{DensityOptions, DensityPoint, SeparationDensity};

/// P(u) at one nominal pressure.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct DensityCurve {
    /// σ0.
    pub nominal_pressure: f64,
    /// A/A0, the δ weight of P(u) at u = 0.
    pub contact_fraction: f64,
    /// 1 − A/A0 = ∫ P_nc du.
    pub non_contact_fraction: f64,
    /// Its error bound.
    pub non_contact_fraction_error_bound: f64,
    /// ū of the theory (Persson 2007), m.
    pub mean_separation: f64,
    /// ∫ u P(u) du, m (= ū + `fold_shift`: a check).
    pub separation_first_moment: f64,
    /// Its error bound, m.
    pub separation_first_moment_error_bound: f64,
    /// s_fold, what the fold at u = 0 adds to the first moment, m.
    pub fold_shift: f64,
    /// P_nc(u) on `points` separations from 0 to the largest where P_nc is
    /// not negligible.
    pub points: Vec<DensityPoint>,
}

/// P(u) at every nominal pressure asked for.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct SeparationDensityReport {
    /// E*.
    pub contact_modulus: f64,
    /// One curve per σ0.
    pub curves: Vec<DensityCurve>,
    /// Remarks on the input.
    #[serde(skip)]
    pub warnings: Vec<Warning>,
}

/// P(u) of `surface` at each of `pressures`, on `points` ≥ 2 separations each.
///
/// # Errors
/// An empty or non-positive pressure list, `points` < 2, a bad tolerance
/// (each named), quadrature failures.
pub fn separation_density(
    surface: &RoughContact,
    pressures: &[f64],
    points: usize,
    tolerance: f64,
) -> Result<SeparationDensityReport> {
    if points < 2 {
        return Err(persson::Error::invalid(
            "density_points",
            points as f64,
            ">= 2 separations",
        ));
    }
    if pressures.is_empty() {
        return Err(persson::Error::invalid(
            "nominal_pressure",
            f64::NAN,
            "a non-empty list",
        ));
    }
    let options = DensityOptions {
        tolerance: check::tolerance("tolerance", tolerance)?,
        breaks: surface.breaks.clone(),
        ..DensityOptions::default()
    };
    let (q_l, q_s) = surface.band();
    let rms_height = surface.spectrum.rms_height(q_l, q_s)?.value;
    let curves = pressures
        .iter()
        .map(|&p| {
            let d = SeparationDensity::new(
                surface.spectrum.as_ref(),
                surface.contact_modulus,
                check::positive("nominal_pressure", p)?,
                &options,
            )?;
            let (nc, moment) = (d.non_contact_fraction(), d.first_moment());
            let top = d.largest_separation().min(moment.value + 6.0 * rms_height);
            let us: Vec<f64> = (0..points)
                .map(|i| top * i as f64 / (points - 1) as f64)
                .collect();
            Ok(DensityCurve {
                nominal_pressure: p,
                contact_fraction: d.contact_fraction(),
                non_contact_fraction: nc.value,
                non_contact_fraction_error_bound: nc.error,
                mean_separation: d.mean_separation().value,
                separation_first_moment: moment.value,
                separation_first_moment_error_bound: moment.error,
                fold_shift: d.fold_shift().value,
                points: d.curve(&us),
            })
        })
        .collect::<Result<Vec<_>>>()?;
    Ok(SeparationDensityReport {
        contact_modulus: surface.contact_modulus,
        curves,
        warnings: surface.warnings(pressures, &[]),
    })
}

impl Tabulate for SeparationDensityReport {
    fn tables(&self) -> Vec<Table> {
        let mut t = Table::new(
            "separation_density",
            "P(u): the contact's weight A/A0 at u = 0 and the continuous part P_nc \
             (JSON: P_nc on a grid of u per σ0)",
        )
        .column("nominal_pressure", "σ0")
        .column("contact_fraction", "A/A0")
        .column("non_contact_fraction", "∫P_nc du")
        .column("mean_separation", "ū (m)")
        .column("separation_first_moment", "∫u P du (m)")
        .column("fold_shift", "s_fold (m)")
        .column("largest_separation", "u_max (m)");
        for c in &self.curves {
            t.push(vec![
                c.nominal_pressure.into(),
                c.contact_fraction.into(),
                c.non_contact_fraction.into(),
                c.mean_separation.into(),
                c.separation_first_moment.into(),
                c.fold_shift.into(),
                c.points.last().map_or(0.0, |p| p.separation).into(),
            ]);
        }
        vec![t]
    }
}
