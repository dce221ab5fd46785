//! One saturated (yield stress) solve of a height map, for
//! `examples/tamaas_compare.py --yield-stress …`: reads the `.npy` heights
//! (side L = 1, E* = 1, periodic), solves at the mean pressure with
//! 0 ≤ p ≤ σY and prints one JSON line (fractions, iterations, residual,
//! seconds, whether the preconditioned solver fell back); writes the
//! pressure field to the given `.npy`. A sixth argument `plain` selects the
//! plain Polonsky–Keer method (default: preconditioned).
//!
//! `cargo run --release --features bem --example saturated_solve -- \
//!     heights.npy pressure yield_stress tolerance pressure_out.npy [plain]`

#[cfg(not(feature = "bem"))]
fn main() {
    eprintln!("saturated_solve needs the feature bem");
}

#[cfg(feature = "bem")]
fn main() -> persson::Result<()> {
    use persson::bem::surface::read_height_map;
    use persson::bem::{Boundary, Control, Method, Operator, Options, Solver};
    use persson::io::npy;
    use std::path::Path;

    let a: Vec<String> = std::env::args().collect();
    if a.len() != 6 && a.len() != 7 {
        eprintln!(
            "usage: saturated_solve heights.npy pressure yield_stress tolerance out.npy [plain]"
        );
        std::process::exit(2);
    }
    let method = match a.get(6).map(String::as_str) {
        Some("plain") => Method::Plain,
        _ => Method::default(),
    };
    let num = |s: &str| s.parse::<f64>().expect("a number");
    let surf = read_height_map(Path::new(&a[1]), 1.0)?;
    let opts = Options {
        tolerance: num(&a[4]),
        yield_stress: Some(num(&a[3])),
        ..Options::default()
    };
    let mut solver =
        Solver::with_method(Operator::new(Boundary::Periodic, surf.n, 1.0, 1.0)?, method);
    let sol = solver.solve(&surf.heights, Control::MeanPressure(num(&a[2])), &opts)?;
    npy::write(Path::new(&a[5]), surf.n, surf.n, &sol.pressure)?;
    println!(
        "{{\"contact_fraction\": {:e}, \"elastic_fraction\": {:e}, \"plastic_fraction\": {:e}, \
         \"plastic_displacement_mean\": {:e}, \"plastic_displacement_max\": {:e}, \
         \"iterations\": {}, \"residual\": {:e}, \"seconds\": {:e}, \"fallback\": {}}}",
        sol.contact_fraction,
        sol.elastic_fraction,
        sol.plastic_fraction,
        sol.plastic_displacement_mean,
        sol.plastic_displacement_max,
        sol.iterations,
        sol.residual,
        sol.seconds,
        sol.fallback.is_some()
    );
    Ok(())
}
