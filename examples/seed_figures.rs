//! Reproduce seed 001 (Persson, Bucher & Chiaia, PRB 65, 184106) Figs. 2–4:
//! the stress distribution P(σ) for a flat punch, a Hertz ball and a cylinder
//! at G = 0, 0.6 and 2, elastic, with the contact areas quoted in the captions.
//!
//! Run: `cargo run --release --example seed_figures [out.csv]`
//! Prints the areas (seed: 0.64/0.38, 0.62/0.38, 0.61/0.37; exact values in
//! ../shared/theory.md §3) and writes the curves (σ/σH, start, G, σH·P) as CSV.

use persson::stress::{Solver, Start};
use std::fmt::Write as _;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = std::env::args().nth(1);
    let mut csv = String::from("figure,start,g,sigma_over_sigma_h,density\n");
    println!(
        "{:<5} {:<9} {:>5} {:>12} {:>10}  method",
        "fig", "start", "G", "A/A0", "bound"
    );
    for (fig, name) in [(2, "flat"), (3, "hertz"), (4, "cylinder")] {
        let start = Start::from_name(name)?;
        for g in [0.0, 0.6, 2.0] {
            let sol = Solver::new(&start, g, None, 1e-12)?;
            let sigma: Vec<f64> = (0..=300).map(|i| 3.0 * i as f64 / 300.0).collect();
            let c = sol.curve(&sigma)?;
            println!(
                "{fig:<5} {name:<9} {g:>5} {:>12.9} {:>10.1e}  {}",
                c.contact_fraction, c.error_bound, c.method
            );
            for (s, p) in c.sigma.iter().zip(&c.density) {
                writeln!(csv, "{fig},{name},{g},{s},{p}")?;
            }
        }
    }
    if let Some(path) = out {
        std::fs::write(&path, csv)?;
        println!("curves written to {path}");
    }
    Ok(())
}
