//! Pull-off of a sphere from the adhesive FFT-BEM (`bem hertz
//! --work-of-adhesion`'s path, Maugis–Dugdale law) against Maugis's (1992)
//! exact pull-off force, over λ and N: the table of docs/adhesion.md.
//!
//! ```text
//! cargo run --release -p persson-studies --example adhesive_sphere [N…]
//! ```
//! R = 1, E* = 1, periodic cell L = 1 (and L = 2 at the same spacing, the
//! cell's own effect), Δγ = 1e-3 (the contact radius at pull-off is
//! Ā (πΔγR²/K)^{1/3} ≈ 0.13 Ā L), tolerance 1e-8; ρ from λ =
//! (Δγ/ρ)(9R/(2πΔγE*²))^{1/3}. Prints λ, L, N, F/(πRΔγ), Maugis's value,
//! F/F_MD − 1, the iterations and the seconds per path.

use persson::adhesion::MaugisDugdale;
use persson::bem::adhesive::AdhesiveOptions;
use persson_studies::bem_detail::{adhesive_sphere, LawKind};
use std::f64::consts::PI;

fn main() -> persson::Result<()> {
    let grids: Vec<usize> = std::env::args()
        .skip(1)
        .filter_map(|a| a.parse().ok())
        .collect();
    let grids = if grids.is_empty() {
        vec![64, 128, 256]
    } else {
        grids
    };
    let dg = 1e-3;
    let options = AdhesiveOptions {
        tolerance: 1e-8,
        max_iterations: 20_000,
    };
    println!("λ\tL\tN\tF/(πRΔγ)\tMaugis\tF/F_MD − 1\titerations\tseconds");
    for lambda in [0.3, 1.0, 3.0] {
        let rho = dg / lambda * (9.0 / (2.0 * PI * dg)).cbrt();
        let exact = MaugisDugdale::new(lambda)?.pull_off_force();
        let cells: Vec<(f64, usize)> = grids
            .iter()
            .map(|&n| (1.0, n))
            .chain(grids.last().map(|&n| (2.0, 2 * n)))
            .collect();
        for (size, n) in cells {
            let t = std::time::Instant::now();
            let r = adhesive_sphere(&[n], (size, 1.0, 1.0), (LawKind::Maugis, dg, rho), &options)?;
            let g = &r.per_grid[0];
            let iterations: usize = g.points.iter().map(|p| p.iterations).sum();
            println!(
                "{lambda}\t{size}\t{n}\t{:.5}\t{exact:.5}\t{:+.4}\t{iterations}\t{:.2}",
                g.reduced_pull_off_force,
                g.reduced_pull_off_force / exact - 1.0,
                t.elapsed().as_secs_f64()
            );
        }
    }
    Ok(())
}
