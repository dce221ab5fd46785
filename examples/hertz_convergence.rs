//! Hertz convergence study: η, contact radius and peak pressure errors for
//! both boundaries over a range of grids, next to Table 1 of J. F. Molinari's
//! EPFL lecture "From single asperity to multi asperity contact".
//!
//! `cargo run --release --example hertz_convergence -- [N ...] [--tol T]`
//! (default grids 64 128 256 512 1024, tol 1e-12).

use persson::bem::{hertz, Boundary, Options};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut grids = Vec::new();
    let mut tol = 1e-12;
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        if a == "--tol" {
            tol = args.next().ok_or("--tol needs a value")?.parse()?;
        } else {
            grids.push(a.parse::<usize>()?);
        }
    }
    if grids.is_empty() {
        grids = vec![64, 128, 256, 512, 1024];
    }
    let opts = Options {
        tolerance: tol,
        ..Options::default()
    };
    println!(
        "boundary  grid  energy_error  Molinari   a_err      p0_err     fraction  iters  seconds"
    );
    for boundary in [Boundary::Free, Boundary::Periodic] {
        for &n in &grids {
            let r = hertz::validate(&hertz::HertzCase::new(n, boundary), &opts)?;
            let lecture = hertz::lecture_eta(n).map_or("-".to_string(), |v| format!("{v:.2e}"));
            println!(
                "{:<9} {:>5}  {:.3e}     {:<9}  {:.2e}   {:.2e}   {:.5}   {:>5}  {:.3}",
                format!("{boundary:?}").to_lowercase(),
                n,
                r.energy_error,
                lecture,
                r.contact_radius_error,
                r.peak_pressure_error,
                r.contact_fraction,
                r.iterations,
                r.seconds
            );
        }
    }
    Ok(())
}
