//! Tables of the FFT-BEM's results ([`persson::bem`]): the rough-contact load
//! curve with its pressure histograms, and the Hertz ball with a yield stress.

use persson::bem::hertz::PlasticDiscReport;
use persson::bem::rough::{RoughReport, SurfaceOrigin};

use super::{number, Cell, Table, Tabulate};

impl Tabulate for PlasticDiscReport {
    fn tables(&self) -> Vec<Table> {
        let mut t = Table::new(
            "bem_hertz_plastic",
            format!(
                "Hertz ball with a yield stress (FFT-BEM, {} boundary): plastic disc p = σY of radius c",
                self.boundary.name(),
            ),
        )
        .scalar("radius", "R", self.radius)
        .scalar("contact_modulus", "E*", self.contact_modulus)
        .scalar("yield_stress", "σY", self.yield_stress)
        .scalar("yield_ratio", "σY/p₀_H", self.yield_ratio)
        .scalar("hertz_peak_pressure", "p₀_H", self.hertz_peak_pressure)
        .scalar("nominal_pressure", "σ0 = F/L²", self.nominal_pressure)
        .scalar("hertz_contact_radius", "a_H", self.hertz_contact_radius)
        .scalar("tolerance", "tolerance ε", self.tolerance)
        .column("grid", "N")
        .column_digits("plastic_radius_ratio", "c/a_H", 5)
        .column_digits("plastic_radius_change", "Δc (previous N)", 2)
        .column("contact_radius", "a")
        .column("approach", "δ")
        .column("contact_fraction", "A/A0")
        .column("elastic_fraction", "A_el/A0")
        .column("plastic_fraction", "A_pl/A0")
        .column("plastic_displacement_mean", "u_pl mean")
        .column("plastic_displacement_max", "u_pl max")
        .omittable(2)
        .column("iterations", "iterations")
        .omittable(3)
        .column_digits("residual", "residual", 2)
        .omittable(1)
        .column_digits("seconds", "time (s)", 3)
        .omittable(0);
        for r in &self.rows {
            t.push(vec![
                r.grid.into(),
                r.plastic_radius_ratio.into(),
                r.plastic_radius_change.into(),
                r.contact_radius.into(),
                r.approach.into(),
                r.contact_fraction.into(),
                r.elastic_fraction.into(),
                r.plastic_fraction.into(),
                r.plastic_displacement_mean.into(),
                r.plastic_displacement_max.into(),
                r.iterations.into(),
                r.residual.into(),
                r.seconds.into(),
            ]);
        }
        vec![t]
    }
}

impl Tabulate for RoughReport {
    fn tables(&self) -> Vec<Table> {
        let mut tables = vec![load_table(self)];
        tables.extend(histogram_table(self));
        tables
    }
}

/// The load curve: one row per nominal pressure (with σY, the split into
/// A_el and A_pl and the plastic displacement; a narrow text table leaves
/// out the time, the residual and u_pl max first).
fn load_table(r: &RoughReport) -> Table {
    let n = r.grid;
    let mut t = Table::new(
        "bem_rough",
        format!(
            "Rough contact (FFT-BEM, Polonsky & Keer 1999), {n}×{n} grid, {} boundary",
            r.boundary.name()
        ),
    )
    .scalar("grid", "N", n)
    .scalar("size", "L", r.size)
    .scalar("contact_modulus", "E*", r.contact_modulus)
    .scalar("tolerance", "tolerance ε", r.tolerance)
    .scalar(
        "surface_rms_height",
        "h_rms on the grid",
        r.surface_rms_height,
    )
    .scalar(
        "surface_rms_slope",
        "h'_rms on the grid",
        r.surface_rms_slope,
    );
    if let Some(y) = r.yield_stress {
        t = t.scalar("yield_stress", "σY", y);
    }
    match &r.surface {
        SurfaceOrigin::HeightMap { file } => t = t.scalar("file", "surface", file.as_str()),
        SurfaceOrigin::Synthesised { seed, spectrum } => {
            t = t.scalar("seed", "seed", Cell::Int(*seed as i64)).scalar(
                "q_s",
                "q_l … q_s",
                format!("{} … {}", number(spectrum.q_l, 6), number(spectrum.q_s, 6)),
            );
        }
        // A source added later prints no scalar until it has one here.
        _ => {}
    }
    let mut t = t
        .column("nominal_pressure", "σ0")
        .column("contact_fraction", "A/A0")
        .column("mean_separation", "ū")
        .column("approach", "δ")
        .column("iterations", "iterations")
        .omittable(3)
        .column_digits("residual", "residual", 2)
        .omittable(1)
        .column_digits("seconds", "time (s)", 3)
        .omittable(0);
    let saturated = r.yield_stress.is_some();
    if saturated {
        t = t
            .column("elastic_fraction", "A_el/A0")
            .column("plastic_fraction", "A_pl/A0")
            .column("plastic_displacement_mean", "u_pl mean")
            .column("plastic_displacement_max", "u_pl max")
            .omittable(2);
    }
    for p in &r.points {
        let mut row: Vec<Cell> = vec![
            p.nominal_pressure.into(),
            p.contact_fraction.into(),
            p.mean_separation.into(),
            p.approach.into(),
            p.iterations.into(),
            p.residual.into(),
            p.seconds.into(),
        ];
        if saturated {
            for v in [
                p.elastic_fraction,
                p.plastic_fraction,
                p.plastic_displacement_mean,
                p.plastic_displacement_max,
            ] {
                row.push(v.unwrap_or(0.0).into());
            }
        }
        t.push(row);
    }
    t
}

/// The pressure histograms of every solve, if asked for. With a yield
/// stress the δ-peak at σY is a row of its own (σ low = σ high = σY, no
/// density) with its weight in the column `plastic_fraction`, empty on the
/// bins' rows.
fn histogram_table(r: &RoughReport) -> Option<Table> {
    if !r.points.iter().any(|p| p.histogram.is_some()) {
        return None;
    }
    let saturated = r.yield_stress.is_some();
    let mut h = Table::new("bem_histogram", "Pressure histograms P(σ) of the FFT-BEM")
        .column("nominal_pressure", "σ0")
        .column("sigma_low", "σ low")
        .column("sigma_high", "σ high")
        .column("density", "P(σ)");
    if saturated {
        h = h.column("plastic_fraction", "A_pl/A0 (δ-peak at σY)");
    }
    for p in &r.points {
        let Some(bins) = &p.histogram else { continue };
        for b in bins {
            let mut row: Vec<Cell> = vec![
                p.nominal_pressure.into(),
                b.sigma_low.into(),
                b.sigma_high.into(),
                b.density.into(),
            ];
            if saturated {
                row.push(Cell::Empty);
            }
            h.push(row);
        }
        if let Some(y) = r.yield_stress {
            h.push(vec![
                p.nominal_pressure.into(),
                y.into(),
                y.into(),
                Cell::Empty,
                p.plastic_fraction.into(),
            ]);
        }
    }
    Some(h)
}
