//! A pressure map beside its histogram (`persson bem rough --plot`): the
//! map as a heatmap with a colour bar (no contact in grey, the plastic
//! nodes at p = σY in red), and the histogram P(σ) with the plastic δ-peak
//! at σY drawn as a red bar labelled with its weight A_pl/A0.
//!
//! Like [`super::Figure`] a [`MapFigure`] is plain data, drawn
//! into an `.svg` or `.png` file ([`super::Encode`]) or by
//! [`super::render_svg_string`] into a string.
//!
//! Maps finer than [`MAP_CELLS`] per side are drawn in blocks of k × k
//! nodes: the block's mean pressure, red when more than half of its nodes
//! are at σY, grey when none is in contact.

/// Most cells per side drawn in the map (finer maps are averaged in blocks).
pub const MAP_CELLS: usize = 128;

/// The default size in pixels of a map figure, width × height.
pub const MAP_SIZE: (u32, u32) = (1100, 500);

/// Label of the colour bar (and of the histogram's σ axis), before the unit.
pub const PRESSURE_LABEL: &str = "contact pressure p";

/// A pressure map and its histogram, as plain data.
#[derive(Debug, Clone, PartialEq)]
pub struct MapFigure {
    /// Title over the whole figure.
    pub title: String,
    /// Nodes per side N of the map.
    pub grid: usize,
    /// Side L of the map (unit of `length_unit`).
    pub side: f64,
    /// Unit of lengths, e.g. `"unit of L"` or `"m"`.
    pub length_unit: String,
    /// Unit of pressures, e.g. `"unit of E*"`.
    pub pressure_unit: String,
    /// Nodal pressures, row-major `p[i·N + j]` (i along y, j along x).
    pub pressure: Vec<f64>,
    /// Yield stress σY: nodes at p ≥ σY are drawn as plastic.
    pub yield_stress: Option<f64>,
    /// Histogram bins `(σ low, σ high, P(σ))` (below σY with a yield stress).
    pub bins: Vec<(f64, f64, f64)>,
    /// Weight A_pl/A0 of the δ-peak at σY (with a yield stress).
    pub plastic_fraction: Option<f64>,
    /// Size in pixels, width × height.
    pub size: (u32, u32),
}

/// The map figure of a rough contact: the last solve's pressure field (kept
/// by [`persson::bem::rough::rough_contact_mapped`]) and its histogram (the
/// report's bins, or 50 bins of the field), the plastic peak with a yield
/// stress.
///
/// # Errors
/// [`crate::Error::Inconsistent`] when the report kept no pressure field.
#[cfg(feature = "bem")]
pub fn rough_map(r: &persson::bem::rough::RoughReport) -> crate::Result<MapFigure> {
    use persson::bem::histogram::{pressure_histogram, saturated_histogram};
    let map = r
        .pressure_map
        .as_ref()
        .ok_or_else(|| crate::Error::Inconsistent {
            name: "pressure map".into(),
            requirement: "kept by bem::rough::rough_contact_mapped".into(),
        })?;
    let point = r.points.get(map.index);
    let bins = match (point.and_then(|p| p.histogram.clone()), r.yield_stress) {
        (Some(b), _) => b,
        (None, Some(y)) => saturated_histogram(&map.pressure, 50, y)?.bins,
        (None, None) => pressure_histogram(&map.pressure, 50)?,
    };
    let plastic_fraction = r.yield_stress.map(|y| {
        map.pressure.iter().filter(|&&p| p >= y).count() as f64 / map.pressure.len() as f64
    });
    let n = r.grid;
    let mut title = format!(
        "FFT-BEM pressure, {n}×{n} {}, σ0 = {}",
        r.boundary.name(),
        crate::table::number(map.nominal_pressure, 4)
    );
    if let Some(y) = r.yield_stress {
        title.push_str(&format!(
            ", σY = {} (red: p = σY)",
            crate::table::number(y, 4)
        ));
    }
    Ok(MapFigure {
        title,
        grid: n,
        side: r.size,
        // SI (README, Conventions): lengths in m; pressures in Pa, or in
        // units of E* when E* = 1.
        length_unit: "m".into(),
        pressure_unit: if r.contact_modulus == 1.0 { "E*" } else { "Pa" }.into(),
        pressure: map.pressure.clone(),
        yield_stress: r.yield_stress,
        bins: bins
            .iter()
            .map(|b| (b.sigma_low, b.sigma_high, b.density))
            .collect(),
        plastic_fraction,
        size: MAP_SIZE,
    })
}

/// A tick label in the tables' number style (`1e8`, `0.0125`, `2.5e-9`):
/// plotters' default prints `100000000.0` and rounds 1e-8 to `0.0`.
pub(crate) fn tick(v: f64) -> String {
    crate::table::number(v, 3)
}
