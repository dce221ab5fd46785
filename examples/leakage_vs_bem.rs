//! Theory against the exact BEM answer for leakage and conductance on
//! synthesised self-affine surfaces (as Dapp, Lücke, Persson & Müser, PRL 108,
//! 244301 (2012) did for the critical junction).
//!
//! `cargo run --release --example leakage_vs_bem [N] [seeds]` (defaults 256, 4).
//!
//! For each seed and load: the BEM contact (periodic, tolerance 1e-10), its
//! exact flow conductivity (Reynolds on the gap, mean of x and y), its exact
//! stiffness (linear solve on the contact set) and gap conductance (gas law);
//! beside them the critical-junction and effective-medium σ_eff and the
//! theory's stiffness and gap conductance for the same spectrum. Ratios are
//! theory / BEM, means over the seeds (with the spread, min–max).

use persson::bem::reynolds::{flow, FlowDirection, GapField};
use persson::bem::rough::{solve, Observer, RoughOptions};
use persson::bem::stiffness::{contact_stiffness, StiffnessOptions};
use persson::bem::surface::synthesize;
use persson::bem::{Boundary, Operator, Solution};
use persson::conductance::{gap_conductance, gap_conductance_of_field, GapLaw};
use persson::gap::{DensityOptions, SeparationDensity};
use persson::leakage::{CriticalJunction, Drive, EffectiveMedium, Seal};
use persson::separation::Separation;
use persson::spectrum::{Amplitude, SelfAffine};
use persson::theory::Persson;

/// One BEM solve: (A/A0, σ_eff, K/A0, h_gap, percolates).
type Row = (f64, f64, f64, f64, bool);

/// Keeps each converged solution.
struct Keep(Vec<Solution>);

impl Observer for Keep {
    fn solution(&mut self, _index: usize, solution: &Solution) -> persson::Result<()> {
        self.0.push(solution.clone());
        Ok(())
    }
}

fn main() -> persson::Result<()> {
    let args: Vec<String> = std::env::args().collect();
    let n: usize = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(256);
    let seeds: u64 = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(4);
    // L = 1 mm, q_l = 2π/L, roll-off at 4 q_l (16 roll-off patches in the
    // cell), q_s = N/8 · q_l (8 nodes per shortest wavelength), H = 0.8,
    // h'_rms = 0.1; E* = 10 MPa (a rubber seal).
    let size = 1e-3;
    let q_l = std::f64::consts::TAU / size;
    let q_r = 4.0 * q_l;
    let q_s = (n / 8) as f64 * q_l;
    let slope = 0.1;
    let spectrum = SelfAffine::new(q_l, q_r, q_s, 0.8, Amplitude::RmsSlope(slope))?;
    let e_star = 1e7;
    let eta = 1e-3;
    let seal = Seal {
        seal_width: size,
        seal_length: size,
        viscosity: eta,
        drive: Drive::Liquid { pressure_drop: 1e5 },
    };
    let gas = GapLaw::Gas {
        gas_conductivity: 0.026,
        mean_free_path: 6.8e-8,
    };
    let ratios = [0.01, 0.02, 0.04, 0.07, 0.1, 0.15, 0.2, 0.25, 0.3];
    let pressures: Vec<f64> = ratios.iter().map(|r| r * e_star * slope).collect();
    let density_opts = DensityOptions {
        breaks: vec![q_r],
        ..Default::default()
    };
    let cj = CriticalJunction::new(&spectrum, e_star, seal)?.with_breaks(&[q_r]);
    let em = EffectiveMedium::new(&spectrum, e_star, seal, density_opts.clone())?;
    let sep = Separation::new(&spectrum, e_star)?.with_breaks(&[q_r]);
    let theory = Persson::new(&spectrum, e_star)?;

    let mut bem: Vec<Vec<Row>> = vec![Vec::new(); pressures.len()];
    let options = RoughOptions::default();
    for seed in 0..seeds {
        let surface = synthesize(&spectrum, n, size, seed)?;
        let mut keep = Keep(Vec::new());
        solve(&surface, e_star, &pressures, &options, &mut keep)?;
        let mut op = Operator::new(Boundary::Periodic, n, size, e_star)?;
        for (i, sol) in keep.0.iter().enumerate() {
            let field = GapField::from_solution(sol, n, size)?;
            let fx = flow(&field, eta, FlowDirection::X)?;
            let fy = flow(&field, eta, FlowDirection::Y)?;
            let sigma = 0.5 * (fx.effective_flow_conductivity + fy.effective_flow_conductivity);
            let k = contact_stiffness(&mut op, &sol.pressure, &StiffnessOptions::default())?;
            let h = gap_conductance_of_field(field.gap(), &sol.pressure, &gas)?;
            bem[i].push((
                sol.contact_fraction,
                sigma,
                k.stiffness,
                h,
                fx.percolates || fy.percolates,
            ));
        }
    }
    println!(
        "N = {n}, {seeds} seeds, L = 1 mm, q_r = 4 q_l, q_s = {} q_l, H = 0.8, h'_rms = {slope}, E* = 10 MPa",
        n / 8
    );
    println!("ratios theory/BEM: geometric mean over seeds [min, max]; σ_eff ratios over the seeds whose BEM gap percolates");
    println!(
        "{:>8} {:>7} {:>7} {:>5} {:>26} {:>26} {:>24} {:>24}",
        "σ0/E*h'",
        "A_bem",
        "A_th",
        "perc",
        "σ_CJ/σ_bem",
        "σ_EMT/σ_bem",
        "K_th/K_bem",
        "h_gap,th/h_gap,bem"
    );
    for (i, &p) in pressures.iter().enumerate() {
        let rows = &bem[i];
        let a_bem = rows.iter().map(|r| r.0).sum::<f64>() / rows.len() as f64;
        let a_th = theory.contact_fraction(theory.zeta_max(), p)?.fraction;
        let c = cj.point(p)?;
        let sigma_cj = c.critical_separation.powi(3) / (12.0 * eta);
        let d = SeparationDensity::new(&spectrum, e_star, p, &density_opts)?;
        let e = em.point_from(&d)?;
        let k_th = sep.stiffness(p)?.value;
        let h_th = gap_conductance(&d, &gas)?.value;
        let perc: Vec<_> = rows.iter().filter(|r| r.4 && r.1 > 0.0).collect();
        let stat = |v: Vec<f64>| -> String {
            if v.is_empty() {
                return "–".into();
            }
            // geometric mean: the BEM's σ_eff scatters over decades near percolation
            let m = (v.iter().map(|x| x.ln()).sum::<f64>() / v.len() as f64).exp();
            let lo = v.iter().cloned().fold(f64::INFINITY, f64::min);
            let hi = v.iter().cloned().fold(f64::NEG_INFINITY, f64::max);
            format!("{m:.3} [{lo:.3}, {hi:.3}]")
        };
        println!(
            "{:>8} {:>7.4} {:>7.4} {:>5} {:>26} {:>26} {:>24} {:>24}",
            ratios[i],
            a_bem,
            a_th,
            format!("{}/{}", perc.len(), rows.len()),
            stat(perc.iter().map(|r| sigma_cj / r.1).collect()),
            stat(
                perc.iter()
                    .map(|r| e.effective_flow_conductivity / r.1)
                    .collect()
            ),
            stat(rows.iter().map(|r| k_th / r.2).collect()),
            stat(rows.iter().map(|r| h_th / r.3).collect()),
        );
    }
    Ok(())
}
