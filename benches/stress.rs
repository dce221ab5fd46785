//! A 1000-point stress curve at tol 1e-12, including set-up and both
//! fractions (goal: < 1 ms for each start).
//!
//! Run: `cargo bench --bench stress`

use persson::stress::{Solver, Start};

fn main() {
    divan::main();
}

const STARTS: [&str; 3] = ["flat", "hertz", "cylinder"];

fn curve(name: &str, g: f64, r: Option<f64>) -> f64 {
    let st = Start::from_name(name).unwrap();
    let sol = Solver::new(&st, g, r, 1e-12).unwrap();
    let grid = sol.grid(1000);
    let c = sol.curve(&grid).unwrap();
    c.contact_fraction + c.scaled_density[500]
}

/// Elastic, G = 0.6 (Persson, Bucher & Chiaia, Phys. Rev. B 65, 184106 (2002), Figs. 2–4).
#[divan::bench(args = STARTS)]
fn elastic_g_0_6(name: &str) -> f64 {
    curve(divan::black_box(name), 0.6, None)
}

/// Elastic, G = 2 (Persson, Bucher & Chiaia 2002, Figs. 2–4).
#[divan::bench(args = STARTS)]
fn elastic_g_2(name: &str) -> f64 {
    curve(divan::black_box(name), 2.0, None)
}

/// σY/σH = 1e3 at G = 1e-6 (image sum, narrow kernel).
#[divan::bench(args = STARTS)]
fn yield_1e3_g_1e_6(name: &str) -> f64 {
    curve(divan::black_box(name), 1e-6, Some(1e3))
}

/// σY/σH = 1.5 at G = 0.6 (sine series).
#[divan::bench(args = STARTS)]
fn yield_1_5_g_0_6(name: &str) -> f64 {
    curve(divan::black_box(name), 0.6, Some(1.5))
}

/// σY/σH = 1.01 at G = 0.01 (series density, image fractions).
#[divan::bench(args = STARTS)]
fn yield_1_01_g_0_01(name: &str) -> f64 {
    curve(divan::black_box(name), 0.01, Some(1.01))
}
