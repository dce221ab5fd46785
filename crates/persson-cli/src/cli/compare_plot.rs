//! The figures of `persson compare`, drawn from its typed reports.

use persson_studies::output::Files;
use persson_studies::validation::{Comparison, KappaStudy};

use super::compare_args::{KappaArgs, MainArgs};



fn xy(x: &[f64], y: &[f64]) -> Vec<(f64, f64)> {
    x.iter().copied().zip(y.iter().copied()).collect()
}

/// A/A0 against σ0 (`--plot`) and the pressure distribution (`--plot-histogram[-log]`).
pub fn comparison(a: &MainArgs, r: &Comparison, files: &mut Files) -> anyhow::Result<()> {
    use persson_studies::plot::{Axis, Encode, Figure, Series, Style};
    use persson_studies::validation::asperity;
    use persson_studies::validation::report::AreaTheory;
    let p = &r.nominal_pressure;
    a.plot.draw(files, || {
        let mut curves: Vec<(&str, &[f64])> = r
            .theories
            .iter()
            .filter(|t| !matches!(t.theory, AreaTheory::BushLinear | AreaTheory::PerssonLinear))
            .map(|t| (t.theory.label(), t.contact_fraction.as_slice()))
            .collect();
        // The asperity theories (GW, BGT, with σY the overlap model) beside them.
        curves.extend(
            r.asperity
                .curves
                .iter()
                .filter(|c| c.not_computed.is_none())
                .map(|c| (asperity::label(c.theory), c.contact_fraction.as_slice())),
        );
        let law = persson_studies::plot::LinearLaw {
            contact_modulus: r.contact_modulus,
            rms_slope: r.spectrum.rms_slope,
        };
        let mut fig = persson_studies::plot::area_vs_load(p, &curves, "unit of E*", Some(law))?;
        fig.title = "Contact area: theories, BEM and continuum limit".into();
        for g in &r.bem {
            fig.push(Series::new(
                format!("BEM {}²", g.grid),
                xy(p, &g.contact_fraction),
                Style::Markers,
            ));
        }
        let a_inf: Vec<f64> = r.extrapolated.iter().map(|c| c.contact_fraction).collect();
        fig.push(Series::line_markers("BEM, N → ∞", xy(p, &a_inf)));
        if let Some(d) = &r.data {
            fig.push(Series::markers(
                "your data",
                xy(&d.nominal_pressure, &d.contact_fraction),
            ));
        }
        if let Some(y) = r.yield_stress {
            // The plastic parts A_pl/A0: theory and BEM extrapolated.
            let theory: Vec<f64> = r
                .pressure_distribution
                .iter()
                .filter_map(|d| d.theory_plastic_fraction)
                .collect();
            let bem: Vec<f64> = r
                .extrapolated
                .iter()
                .filter_map(|c| c.plastic_fraction)
                .collect();
            let y = persson_studies::table::number(y, 4);
            fig.push(Series::new(
                format!("Persson A_pl/A0, σY = {y}"),
                xy(p, &theory),
                Style::Dashed,
            ));
            fig.push(Series::line_markers("BEM A_pl/A0, N → ∞", xy(p, &bem)));
        }
        Ok(fig)
    })?;
    // --leakage / --conductance: Q(σ0) and h(σ0) beside the --plot file.
    super::compare_transport::plot(a.plot.plot.as_deref(), r, files)?;
    let Some(d) = r.shown_distribution() else {
        return Ok(());
    };
    for (path, log) in [(&a.plot_histogram, false), (&a.plot_histogram_log, true)] {
        let Some(path) = path else { continue };
        let label = "P(σ) (1/unit of σ)";
        let y = if log {
            Axis::log(label)
        } else {
            Axis::linear(label)
        };
        let mut fig = Figure::new(
            format!("Pressure distribution at σ0 = {:.3e}", d.nominal_pressure),
            Axis::linear("contact pressure σ (unit of E*)"),
            y,
        );
        let bins: Vec<(f64, f64)> = d.bem.iter().map(|b| (b.sigma(), b.density)).collect();
        fig.push(Series::line_markers(format!("BEM {}²", d.grid), bins));
        let curve = &d.theory_curve;
        fig.push(Series::line(
            "Persson P(σ), flat start",
            xy(&curve.sigma, &curve.density),
        ));
        if let Some(h) = &r.data_histogram {
            fig.push(Series::markers("your histogram", xy(&h.sigma, &h.density)));
        }
        if let Some(y) = r.yield_stress {
            plastic_peaks(&mut fig, d, y);
        }
        files.write(path, &fig.encode(path)?)?;
    }
    Ok(())
}

/// The δ-peaks at σY (weight A_pl/A0) of the BEM and of the theory, each a
/// vertical bar at σY as high as one histogram bin of that weight (A_pl/Δσ),
/// labelled with A_pl/A0.
fn plastic_peaks(
    fig: &mut persson_studies::plot::Figure,
    d: &persson_studies::validation::report::PressureDistribution,
    y: f64,
) {
    use persson_studies::plot::{Series, Style, PALETTE};
    use persson_studies::table::number;
    let width = d
        .bem
        .first()
        .map_or(y / 40.0, |b| b.sigma_high - b.sigma_low);
    // Bottom of the bars: the smallest positive density drawn (log axes).
    let floor = d
        .bem
        .iter()
        .map(|b| b.density)
        .chain(d.theory_curve.density.iter().copied())
        .filter(|v| *v > 0.0)
        .fold(f64::INFINITY, f64::min);
    let floor = if floor.is_finite() { floor } else { 0.0 };
    for (who, a_pl, style, colour) in [
        ("BEM", d.bem_plastic_fraction, Style::Line, PALETTE[0]),
        (
            "Persson",
            d.theory_plastic_fraction,
            Style::Dashed,
            PALETTE[1],
        ),
    ] {
        let Some(a) = a_pl.filter(|a| *a > 0.0) else {
            continue;
        };
        let label = format!(
            "{who} δ-peak at σY = {}: A_pl/A0 = {}",
            number(y, 4),
            number(a, 3)
        );
        let bar = vec![(y, floor), (y, (a / width).max(floor))];
        fig.push(Series::new(label, bar, style).with_color(colour));
    }
}

/// κ against H with error bars, next to Persson's and Bush's κ (`--plot`).
pub fn kappa(a: &KappaArgs, r: &KappaStudy, files: &mut Files) -> anyhow::Result<()> {
    use persson_studies::plot::{Axis, Figure, Series, Style, PALETTE};
    a.plot.draw(files, || {
        let mut fig = Figure::new(
            "κ against the Hurst exponent (BEM, N → ∞)",
            Axis::linear("Hurst exponent H"),
            Axis::linear("κ"),
        );
        let points: Vec<(f64, f64)> = r
            .points
            .iter()
            .map(|p| (p.hurst, p.bem_extrapolated.kappa))
            .collect();
        fig.push(
            Series::line_markers("BEM, N → ∞ (± standard error)", points).with_color(PALETTE[0]),
        );
        for p in &r.points {
            let (k, se) = (
                p.bem_extrapolated.kappa,
                p.bem_extrapolated.standard_error.unwrap_or(0.0),
            );
            fig.push(
                Series::line("", vec![(p.hurst, k - se), (p.hurst, k + se)]).with_color(PALETTE[0]),
            );
        }
        for (label, k, style, colour) in [
            (
                "Bush et al.: √(2π)",
                r.kappa_bush,
                Style::Dashed,
                PALETTE[1],
            ),
            (
                "Persson: √(8/π)",
                r.kappa_persson,
                Style::Dotted,
                PALETTE[2],
            ),
        ] {
            fig.push(Series::new(label, vec![(0.0, k), (1.0, k)], style).with_color(colour));
        }
        Ok(fig)
    })
}
