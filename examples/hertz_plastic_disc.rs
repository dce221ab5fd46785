//! The Hertz ball with a yield stress below its elastic peak pressure
//! (σY = 0.8 p₀, free boundary, a = 0.1 L, R = L = E* = 1): the radius of the
//! plastic disc (from the number of nodes at σY, c = √(n Δ²/π)) and of the
//! whole contact, as the grid is refined.
//!
//! `cargo run --release --example hertz_plastic_disc [-- 64 128 256 512]`

#[cfg(not(feature = "bem"))]
fn main() {
    eprintln!("hertz_plastic_disc needs the feature bem");
}

#[cfg(feature = "bem")]
fn main() -> persson::Result<()> {
    use persson::bem::{hertz::HertzCase, Boundary, Control, Operator, Options, Solver};
    let grids: Vec<usize> = std::env::args()
        .skip(1)
        .filter_map(|a| a.parse().ok())
        .collect();
    let grids = if grids.is_empty() {
        vec![64, 128, 256, 512]
    } else {
        grids
    };
    println!("    N   plastic radius c/a   contact radius/a   A_pl/A0       iterations   s");
    for n in grids {
        let case = HertzCase::new(n, Boundary::Free);
        let y = 0.8 * case.peak_pressure();
        let opts = Options {
            tolerance: 1e-12,
            yield_stress: Some(y),
            ..Options::default()
        };
        let mut s = Solver::new(Operator::new(Boundary::Free, n, 1.0, 1.0)?);
        let sol = s.solve(
            &case.heights(),
            Control::MeanPressure(case.mean_pressure()),
            &opts,
        )?;
        let cell = 1.0 / (n * n) as f64;
        let radius = |f: f64| (f / cell * cell / std::f64::consts::PI).sqrt();
        let a = case.contact_radius;
        println!(
            "{n:>5}   {:>18.5}   {:>16.5}   {:.6e}   {:>10}   {:.3}",
            radius(sol.plastic_fraction) / a,
            radius(sol.contact_fraction) / a,
            sol.plastic_fraction,
            sol.iterations,
            sol.seconds
        );
    }
    Ok(())
}
