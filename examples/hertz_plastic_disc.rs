//! scratch
#[cfg(not(feature = "bem"))]
fn main() {}

#[cfg(feature = "bem")]
fn main() -> persson::Result<()> {
    use persson::bem::{hertz::HertzCase, Boundary, Control, Operator, Options, Solver};
    let args: Vec<String> = std::env::args().skip(1).collect();
    let tol: f64 = args[0].parse().unwrap();
    let a_ratio: f64 = args[1].parse().unwrap();
    let grids: Vec<usize> = args[2..].iter().filter_map(|a| a.parse().ok()).collect();
    println!("tol {tol:e} a {a_ratio}");
    println!("    N   c_count/a   c_fitp/a  c_fitd/a  a_count/a a_fit/a  iters  s");
    for n in grids {
        let mut case = HertzCase::new(n, Boundary::Free);
        case.contact_radius = a_ratio;
        let y = 0.8 * case.peak_pressure();
        let opts = Options {
            tolerance: tol,
            yield_stress: Some(y),
            ..Options::default()
        };
        let mut s = Solver::new(Operator::new(Boundary::Free, n, 1.0, 1.0)?);
        let sol = s.solve(
            &case.heights(),
            Control::MeanPressure(case.mean_pressure()),
            &opts,
        )?;
        let a = case.contact_radius;
        let dx = 1.0 / n as f64;
        let radius = |f: f64| (f / std::f64::consts::PI).sqrt();
        let c0 = radius(sol.plastic_fraction);
        let rr = case.radii();
        // fit (Y-p)^2 = m (r - c) over elastic nodes c0 < r < c0 + 0.25 a
        let fit = |xs: &[(f64, f64)]| {
            let m = xs.len() as f64;
            let (sx, sy) = xs.iter().fold((0.0, 0.0), |s, v| (s.0 + v.0, s.1 + v.1));
            let (mx, my) = (sx / m, sy / m);
            let (mut sxy, mut sxx) = (0.0, 0.0);
            for v in xs {
                sxy += (v.0 - mx) * (v.1 - my);
                sxx += (v.0 - mx).powi(2);
            }
            let b = sxy / sxx;
            mx - my / b
        };
        let pts: Vec<(f64, f64)> = sol
            .pressure
            .iter()
            .zip(&rr)
            .filter(|(&p, &r)| p < y && p > 0.0 && r > c0 && r < c0 + 0.2 * a)
            .map(|(&p, &r)| (r, (y - p).powi(2)))
            .collect();
        let cp = fit(&pts);
        let ptd: Vec<(f64, f64)> = sol
            .pressure
            .iter()
            .zip(&rr)
            .zip(&sol.gap)
            .filter(|((&p, &r), _)| p >= y && r > c0 - 0.3 * a)
            .map(|((_, &r), &g)| (r, (-g).max(0.0).powf(2.0 / 3.0)))
            .collect();
        let cd = fit(&ptd);
        // contact edge: fit p^2 vs r^2 near a
        let pta: Vec<(f64, f64)> = sol
            .pressure
            .iter()
            .zip(&rr)
            .filter(|(&p, &r)| p > 0.0 && p < y && r > 0.9 * a)
            .map(|(&p, &r)| (r * r, p * p))
            .collect();
        let af = fit(&pta).sqrt();
        let _ = dx;
        if std::env::var("PROFILE").is_ok() {
            let row = n / 2;
            for j in n / 2..n {
                let k = row * n + j;
                let r = rr[k];
                if r > 0.5 * a && r < 1.05 * a {
                    println!(
                        "  r/a {:.4}  1-p/Y {:.3e}  gap {:.3e}",
                        r / a,
                        1.0 - sol.pressure[k] / y,
                        sol.gap[k]
                    );
                }
            }
        }
        println!(
            "{n:>5}   {:.5}   {:.5}   {:.5}   {:.5}   {:.5}  {:>5}  {:.3}",
            c0 / a,
            cp / a,
            cd / a,
            radius(sol.contact_fraction) / a,
            af / a,
            sol.iterations,
            sol.seconds
        );
    }
    Ok(())
}
