//! Where the 100-load P(u) curves spend their time (issue 23): the table's
//! construction, the per-load P(u) from the table, the fixed point set, and
//! 40 sums over the points (about the Newton root's count per load).
//!
//! `cargo run --release --example flow_phases` (the spectrum and loads of
//! `benches/flow.rs`). Prints wall times of three repeats; state the load
//! average beside any figure quoted.

use persson::gap::{PointSet, SeparationTable, TableOptions};
use persson::spectrum::{Amplitude, SelfAffine};
use std::time::Instant;

fn main() -> persson::Result<()> {
    let s = SelfAffine::new(1e4, 4e4, 1e7, 0.8, Amplitude::RmsSlope(1.0))?;
    let loads: Vec<f64> = (0..100)
        .map(|i| 1e9 * 10f64.powf(-4.0 + 3.5 * f64::from(i) / 99.0))
        .collect();
    let options = TableOptions {
        breaks: vec![4e4],
        ..Default::default()
    };
    for _ in 0..3 {
        let t = Instant::now();
        let table = SeparationTable::new(&s, 1e9, loads[0], &options)?;
        let t_table = t.elapsed();
        let t = Instant::now();
        let densities = loads
            .iter()
            .map(|&p| table.density(p))
            .collect::<persson::Result<Vec<_>>>()?;
        let t_density = t.elapsed();
        let t = Instant::now();
        let points: Vec<PointSet> = densities.iter().map(PointSet::new).collect();
        let t_points = t.elapsed();
        let t = Instant::now();
        let mut total = 0.0;
        for (set, d) in points.iter().zip(&densities) {
            let c = d.mean_separation().value.powi(3);
            for _ in 0..40 {
                // (u³ − c)/(u³ + c) as 1 − 2c/(u³ + c): finite where u³ overflows
                total += set.sum2(|u| (1.0 - 2.0 * c / (u.powi(3) + c), 0.0)).0;
            }
        }
        let t_sums = t.elapsed();
        println!(
            "zeta-nodes {}: table {t_table:?}; P(u) x100 {t_density:?}; \
             point sets x100 {t_points:?}; 40 sums x100 {t_sums:?} (checksum {total:.3})",
            table.zeta_nodes()
        );
    }
    Ok(())
}
