//! Reproduce Figs. 2–4 of Persson, Bucher & Chiaia, Phys. Rev. B 65, 184106 (2002),
//! doi:10.1103/PhysRevB.65.184106:
//! the stress distribution P(σ) for a flat punch, a Hertz ball and a cylinder
//! at G = 0, 0.6 and 2, elastic, with the contact areas quoted in the captions.
//!
//! Run: `cargo run --release --example persson2002_figures [out.csv] [plot-dir]`
//! Prints the areas (the paper's captions: 0.64/0.38, 0.62/0.38, 0.61/0.37; exact values in
//! docs/stress.md), writes the curves (figure, start, G, σ/σH, σH·P)
//! as CSV, and with the `plot` feature draws fig2_flat.svg, fig3_hertz.svg and
//! fig4_cylinder.svg into `plot-dir`. G = 0 is the start itself (the flat
//! start's δ is drawn as zero).

use persson::stress::{Solver, Start};
use std::fmt::Write as _;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = std::env::args().nth(1);
    let plot_dir = std::env::args().nth(2);
    let mut csv = String::from("figure,start,g,sigma_over_sigma_h,density\n");
    println!(
        "{:<5} {:<9} {:>5} {:>12} {:>10}  method",
        "fig", "start", "G", "A/A0", "bound"
    );
    for (fig, name) in [(2, "flat"), (3, "hertz"), (4, "cylinder")] {
        let start = Start::from_name(name)?;
        let mut family: Vec<(String, Vec<f64>)> = Vec::new();
        let mut grid = Vec::new();
        for g in [0.0, 0.6, 2.0] {
            let sol = Solver::new(&start, g, None, 1e-12)?;
            let sigma: Vec<f64> = (0..=300).map(|i| 3.0 * i as f64 / 300.0).collect();
            let c = sol.curve(&sigma)?;
            println!(
                "{fig:<5} {name:<9} {g:>5} {:>12.9} {:>10.1e}  {}",
                c.contact_fraction, c.error_bound, c.method
            );
            for (s, p) in c.sigma_ratio.iter().zip(&c.scaled_density) {
                writeln!(csv, "{fig},{name},{g},{s},{p}")?;
            }
            family.push((
                format!("G = {g}, A/A0 = {:.3}", c.contact_fraction),
                c.scaled_density,
            ));
            grid = sigma;
        }
        if let Some(dir) = &plot_dir {
            draw(dir, fig, name, &grid, &family)?;
        }
    }
    if let Some(path) = out {
        std::fs::write(&path, csv)?;
        println!("curves written to {path}");
    }
    Ok(())
}

#[cfg(feature = "plot")]
fn draw(
    dir: &str,
    fig: u32,
    name: &str,
    sigma: &[f64],
    family: &[(String, Vec<f64>)],
) -> Result<(), Box<dyn std::error::Error>> {
    let curves: Vec<(&str, &[f64])> = family
        .iter()
        .map(|(l, p)| (l.as_str(), p.as_slice()))
        .collect();
    let mut figure = persson_studies::plot::stress_family(sigma, &curves)?;
    figure.title = format!("Persson, Bucher & Chiaia (2002) Fig. {fig}: {name} start");
    let path = std::path::Path::new(dir).join(format!("fig{fig}_{name}.svg"));
    persson_studies::plot::render(&figure, &path)?;
    println!("plot written to {}", path.display());
    Ok(())
}

#[cfg(not(feature = "plot"))]
fn draw(
    _dir: &str,
    _fig: u32,
    _name: &str,
    _sigma: &[f64],
    _family: &[(String, Vec<f64>)],
) -> Result<(), Box<dyn std::error::Error>> {
    Err("plots need the `plot` feature".into())
}
