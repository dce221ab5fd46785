//! The Hertz ball with a yield stress below its elastic peak pressure
//! (σY = 0.8 p₀, free boundary, a_H = 0.1 L, R = L = E* = 1, tolerance
//! 1e-12): the radius c of the plastic disc (node count, c = √(n_pl Δ²/π)),
//! the contact radius and the approach per grid, against the 1-D
//! axisymmetric solution of examples/hertz_plastic_rings.py
//! (c/a_H = 0.7402 ± 0.0002, δ/δ_H = 1.0104824).
//!
//! `cargo run --release --example hertz_plastic_disc [-- 64 128 256 512]`
//! (`-- --ratio 0.6 …` for another σY/p₀).

#[cfg(not(feature = "bem"))]
fn main() {
    eprintln!("hertz_plastic_disc needs the feature bem");
}

#[cfg(feature = "bem")]
fn main() -> persson::Result<()> {
    use persson::bem::{hertz, Boundary, Options};
    let args: Vec<String> = std::env::args().skip(1).collect();
    let ratio = args
        .iter()
        .position(|a| a == "--ratio")
        .and_then(|k| args.get(k + 1))
        .and_then(|v| v.parse().ok())
        .unwrap_or(0.8);
    let grids: Vec<usize> = args.iter().filter_map(|a| a.parse().ok()).collect();
    let grids: Vec<usize> = if grids.is_empty() {
        vec![64, 128, 256, 512]
    } else {
        grids.into_iter().filter(|&n| n >= 8).collect()
    };
    let case = hertz::HertzCase::new(grids[0], Boundary::Free);
    let opts = Options {
        tolerance: 1e-12,
        ..Options::default()
    };
    let r = hertz::plastic_disc(
        &case,
        &grids,
        ratio * case.peak_pressure(),
        &opts,
        &mut |_, _| {},
    )?;
    let a = case.contact_radius;
    let delta_h = a * a / case.radius;
    println!("σY/p₀ = {ratio}");
    println!("    N   c/a_H     Δc/cell   contact radius/a_H   δ/δ_H        A_pl/A0       iterations   s");
    for row in &r.rows {
        let cell = case.size / row.grid as f64;
        println!(
            "{:>5}   {:.5}   {:>7}   {:>18.5}   {:.7}   {:.6e}   {:>10}   {:.3}",
            row.grid,
            row.plastic_radius_ratio,
            row.plastic_radius_change
                .map_or("–".to_string(), |d| format!("{:+.3}", d / cell)),
            row.contact_radius / a,
            row.approach / delta_h,
            row.plastic_fraction,
            row.iterations,
            row.seconds
        );
    }
    Ok(())
}
