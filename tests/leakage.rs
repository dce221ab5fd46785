//! Leak rate and P(u): identities of the theory, an independent critical
//! junction, Bruggeman's closed form, Reynolds' equation on closed forms,
//! and bad input.

use persson::gap::{DensityOptions, SeparationDensity};
use persson::leakage::{bruggeman, CriticalJunction, Drive, EffectiveMedium, LeakStatus, Seal};
use persson::separation::Separation;
use persson::spectrum::{Amplitude, FnSpectrum, SelfAffine, Spectrum};
use persson::theory::Persson;
use persson::Error;

/// Agreement of the Gauss and Kronrod ζ-rules asked of P(u) (its default)
/// plus the q-integrals' 1e-9: identities of P(u) hold to 1e-8 relative.
const DENSITY_TOL: f64 = 1e-8;

fn spectrum() -> SelfAffine {
    SelfAffine::new(1e4, 4e4, 1e7, 0.8, Amplitude::RmsSlope(1.0)).unwrap()
}

fn seal() -> Seal {
    Seal {
        seal_width: 1e-3,
        seal_length: 2e-2,
        viscosity: 1e-3,
        drive: Drive::Liquid { pressure_drop: 1e5 },
    }
}

#[test]
fn separation_density_is_normalised_and_its_mean_is_the_separation() {
    let s = spectrum();
    let e_star = 1e9;
    let sep = Separation::new(&s, e_star).unwrap().with_breaks(&[4e4]);
    for p in [1e5, 1e6, 1e7, 1e8] {
        let opts = DensityOptions {
            breaks: vec![4e4],
            ..Default::default()
        };
        let d = SeparationDensity::new(&s, e_star, p, &opts).unwrap();
        // A(ζ1) + ∫P_nc = A(1) = 1
        let nc = d.non_contact_fraction();
        let norm = d.contact_fraction() + nc.value;
        assert!(
            (norm - 1.0).abs() <= nc.error.max(DENSITY_TOL),
            "{p}: {norm}"
        );
        // ∫(−A′)u1 dζ telescopes to ū of separation.rs
        let u = sep.mean_separation(p).unwrap().value;
        let m = d.unfolded_first_moment();
        assert!(
            (m.value - u).abs() <= DENSITY_TOL * u,
            "{p}: {} vs {u}",
            m.value
        );
        // the fold only adds: ∫uP = ū + shift, shift ≥ 0
        let shift = d.fold_shift().value;
        assert!(shift >= 0.0);
        assert!((d.first_moment().value - (u + shift)).abs() <= DENSITY_TOL * u);
        // the tabulated P_nc integrates to the same open area (Simpson on a
        // log grid from 1e-4 ū to the largest window; below it P_nc ≈ P_nc(0)).
        let top = d.largest_separation();
        let k = 4000;
        let (a, b) = ((1e-4 * u).ln(), top.ln());
        let xs: Vec<f64> = (0..=k)
            .map(|i| (a + (b - a) * i as f64 / k as f64).exp())
            .collect();
        let curve = d.curve(&xs);
        let (mut simpson, mut bound) = (0.0, 0.0);
        for i in 0..=k {
            let w = if i == 0 || i == k {
                1.0
            } else if i % 2 == 1 {
                4.0
            } else {
                2.0
            };
            simpson += w * curve[i].separation_density * xs[i];
            bound += w * curve[i].separation_density_error_bound * xs[i];
        }
        simpson *= (b - a) / (3.0 * k as f64);
        bound *= (b - a) / (3.0 * k as f64);
        let head = d.density(0.0);
        simpson += head.value * 1e-4 * u;
        bound += (head.error + head.value) * 1e-4 * u; // P_nc varies by O(itself) there
                                                       // Simpson on 4000 log-spaced points: 1e-5 relative (measured 1e-7)
        let tol = bound + 1e-5 * nc.value;
        assert!(
            (simpson - nc.value).abs() < tol,
            "{p}: {simpson} vs {} (±{tol})",
            nc.value
        );
    }
}

/// ū(ζ) of the cut problem from an independent path: a function spectrum
/// (moments by quadrature) on [ζq_l, q_s] and separation.rs at p(ζ) = σ0/A(ζ).
fn a_ubar(s: &SelfAffine, e_star: f64, p: f64, zeta: f64) -> (f64, f64) {
    let a = Persson::new(s, e_star)
        .unwrap()
        .contact_fraction(zeta, p)
        .unwrap()
        .fraction;
    let lo = zeta * s.q_min();
    let cut = FnSpectrum::new(|q| s.c(q), lo, s.q_max(), 1e-13)
        .unwrap()
        .with_breaks(&[s.q_r()]);
    let u = Separation::new(&cut, e_star)
        .unwrap()
        .with_tolerance(1e-12)
        .unwrap()
        .with_breaks(&[s.q_r()])
        .mean_separation(p / a)
        .unwrap()
        .value;
    (a, u)
}

#[test]
fn critical_junction_against_an_independent_derivative() {
    // u1 = d(Aū)/dA by a central difference in ζ (step 1e-4 ζ_c) on the
    // independent ū(ζ) above: truncation ~ (1e-4)² and cancellation
    // ~1e-12/1e-4: agreement to 1e-6 relative.
    let s = spectrum();
    let e_star = 1e9;
    let cj = CriticalJunction::new(&s, e_star, seal())
        .unwrap()
        .with_breaks(&[4e4]);
    for p in [1e6, 1e7, 3e7] {
        let pt = cj.point(p).unwrap();
        assert_eq!(pt.status, LeakStatus::Leaking);
        let zc = pt.critical_zeta.unwrap();
        // A(ζ_c) = a_c
        let a = Persson::new(&s, e_star)
            .unwrap()
            .contact_fraction(zc, p)
            .unwrap()
            .fraction;
        assert!((a - 0.42).abs() < 1e-12, "{a}");
        let h = 1e-4 * zc;
        let (a_hi, u_hi) = a_ubar(&s, e_star, p, zc + h);
        let (a_lo, u_lo) = a_ubar(&s, e_star, p, zc - h);
        let u1 = (a_hi * u_hi - a_lo * u_lo) / (a_hi - a_lo);
        let rel = (pt.critical_separation / u1 - 1.0).abs();
        assert!(rel < 1e-6, "{p}: {} vs {u1}", pt.critical_separation);
        // Q = (L_y/L_x) u1³ ΔP/(12η)
        let q = 20.0 * pt.critical_separation.powi(3) * 1e5 / 12e-3;
        assert!((pt.leak_rate - q).abs() <= 1e-14 * q);
        assert!(pt.leak_rate_error_bound < 1e-6 * q);
    }
}

#[test]
fn critical_junction_against_mpmath() {
    // tests/reference/critical_junction.py (mpmath, 30 digits): ζ_c and u1 at
    // σ0 = 1e7 Pa, E* = 1e9 Pa, a_c = 0.42 on `spectrum()`.
    const ZETA_C: f64 = 2.309_059_584_758_520_5;
    const U1: f64 = 1.055_936_513_130_348_1e-5;
    let s = spectrum();
    let cj = CriticalJunction::new(&s, 1e9, seal())
        .unwrap()
        .with_breaks(&[4e4]);
    let pt = cj.point(1e7).unwrap();
    let zc = pt.critical_zeta.unwrap();
    // ζ_c from closed-form moments and Newton: 1e-13 relative
    assert!((zc / ZETA_C - 1.0).abs() < 1e-13, "{zc}");
    // u1 from q-integrals at relative tolerance 1e-10: 1e-9 relative, and
    // within the reported bound
    let err = (pt.critical_separation - U1).abs();
    assert!(err < 1e-9 * U1, "{} vs {U1}", pt.critical_separation);
    assert!(
        err <= pt.critical_separation_error_bound,
        "{err:e} > {:e}",
        pt.critical_separation_error_bound
    );
}

#[test]
fn percolating_contact_gives_zero_leak_not_an_error() {
    let s = spectrum();
    let cj = CriticalJunction::new(&s, 1e9, seal()).unwrap();
    // σ0 so high that A/A0 > 0.42 at full magnification
    let p = 2e9;
    let pt = cj.point(p).unwrap();
    assert!(pt.contact_fraction > 0.42);
    assert_eq!(pt.status, LeakStatus::Sealed);
    assert_eq!(pt.leak_rate, 0.0);
    assert_eq!(pt.critical_zeta, None);
    let em = EffectiveMedium::new(&s, 1e9, seal(), DensityOptions::default()).unwrap();
    let pt = em.point(5e9).unwrap();
    assert!(pt.contact_fraction >= 0.5);
    assert_eq!(pt.status, LeakStatus::Sealed);
    assert_eq!(pt.leak_rate, 0.0);
}

#[test]
fn bruggeman_two_phase_closed_form() {
    // a at σ = 0, 1 − a at σ1: σ_eff = σ1(1 − 2a) for a < ½, else 0.
    for (a, s1) in [
        (0.0, 1.0),
        (0.1, 2.5e-18),
        (0.3, 7.0),
        (0.49, 1e10),
        (0.5, 1.0),
        (0.7, 3.0),
    ] {
        let got = bruggeman(&[(a, 0.0), (1.0 - a, s1)]).unwrap();
        let want = (s1 * (1.0 - 2.0 * a)).max(0.0);
        assert!((got - want).abs() <= 1e-12 * s1, "a = {a}: {got} vs {want}");
    }
    // one phase: itself
    assert!((bruggeman(&[(1.0, 4.0)]).unwrap() - 4.0).abs() < 1e-13);
}

#[test]
fn effective_medium_solves_its_equation() {
    let s = spectrum();
    let em = EffectiveMedium::new(&s, 1e9, seal(), DensityOptions::default()).unwrap();
    let d = SeparationDensity::new(&s, 1e9, 1e7, &DensityOptions::default()).unwrap();
    let pt = em.point_from(&d).unwrap();
    assert_eq!(pt.status, LeakStatus::Leaking);
    let se = pt.effective_flow_conductivity * 12e-3;
    let f = |u: f64| 1.0 - 2.0 * se / (u * u * u + se);
    let r = d.expectation(&f, 1e-11, 0.0).unwrap().value - d.contact_fraction();
    assert!(r.abs() < 1e-9, "{r}");
    let q = 20.0 * pt.effective_flow_conductivity * 1e5;
    assert!((pt.leak_rate - q).abs() <= 1e-14 * q);
}

#[test]
fn gas_drive_is_the_isothermal_square_law() {
    let d = Drive::Gas {
        inlet_pressure: 3e5,
        outlet_pressure: 1e5,
    };
    let want = (9e10 - 1e10) / 2e5;
    assert!((d.driving_pressure().unwrap() - want).abs() <= 1e-15 * want);
}

fn invalid_name(e: Error) -> String {
    match e {
        Error::InvalidParameter { name, .. } => name,
        other => panic!("expected InvalidParameter, got {other:?}"),
    }
}

#[test]
fn bad_input_names_the_field() {
    let s = spectrum();
    let base = seal();
    let cases: Vec<(Seal, &str)> = vec![
        (
            Seal {
                viscosity: 0.0,
                ..base
            },
            "viscosity",
        ),
        (
            Seal {
                viscosity: -1e-3,
                ..base
            },
            "viscosity",
        ),
        (
            Seal {
                viscosity: f64::NAN,
                ..base
            },
            "viscosity",
        ),
        (
            Seal {
                seal_width: 0.0,
                ..base
            },
            "seal_width",
        ),
        (
            Seal {
                seal_length: -1.0,
                ..base
            },
            "seal_length",
        ),
        (
            Seal {
                drive: Drive::Liquid { pressure_drop: 0.0 },
                ..base
            },
            "pressure_drop",
        ),
        (
            Seal {
                drive: Drive::Liquid {
                    pressure_drop: -5.0,
                },
                ..base
            },
            "pressure_drop",
        ),
        (
            Seal {
                drive: Drive::Gas {
                    inlet_pressure: 1e5,
                    outlet_pressure: 2e5,
                },
                ..base
            },
            "outlet_pressure",
        ),
        (
            Seal {
                drive: Drive::Gas {
                    inlet_pressure: 1e5,
                    outlet_pressure: 1e5,
                },
                ..base
            },
            "outlet_pressure",
        ),
        (
            Seal {
                drive: Drive::Gas {
                    inlet_pressure: -1.0,
                    outlet_pressure: 1e5,
                },
                ..base
            },
            "inlet_pressure",
        ),
    ];
    for (seal, name) in cases {
        let e = CriticalJunction::new(&s, 1e9, seal).err().unwrap();
        assert_eq!(invalid_name(e), name);
        let e = EffectiveMedium::new(&s, 1e9, seal, DensityOptions::default())
            .err()
            .unwrap();
        assert_eq!(invalid_name(e), name);
    }
    for t in [0.0, 1.0, -0.1, 1.5, f64::NAN] {
        let e = CriticalJunction::new(&s, 1e9, base)
            .unwrap()
            .with_threshold(t)
            .err()
            .unwrap();
        assert_eq!(invalid_name(e), "percolation_threshold");
    }
    let cj = CriticalJunction::new(&s, 1e9, base).unwrap();
    for p in [0.0, -1.0, f64::NAN] {
        assert_eq!(invalid_name(cj.point(p).unwrap_err()), "nominal_pressure");
    }
}

#[cfg(feature = "flow")]
mod reynolds {
    use persson::bem::reynolds::{flow, FlowDirection, GapField};
    use persson::Error;

    /// The closed forms below are of the discrete model; the direct solve
    /// leaves rounding only.
    const EXACT: f64 = 1e-10;

    const ETA: f64 = 2e-3;

    fn sigma(g: f64) -> f64 {
        g * g * g / (12.0 * ETA)
    }

    /// Harmonic mean of two node conductances (the face law).
    fn face(a: f64, b: f64) -> f64 {
        2.0 * a * b / (a + b)
    }

    #[test]
    fn uniform_slot_is_poiseuille() {
        for n in [3, 8, 33] {
            let g = 3e-7;
            let f = flow(
                &GapField::new(n, 1e-3, vec![g; n * n]).unwrap(),
                ETA,
                FlowDirection::Y,
            )
            .unwrap();
            assert!(f.percolates);
            let rel = f.effective_flow_conductivity / sigma(g) - 1.0;
            assert!(rel.abs() < EXACT, "{n}: {rel:e}");
            // Q through the cell: σ (N Δ) ΔP / ((N − 1) Δ)
        }
    }

    /// Gaps g(a) (a along the flow), the same in every line across.
    fn along(n: usize, g: impl Fn(usize) -> f64, dir: FlowDirection) -> GapField {
        let gap = (0..n * n)
            .map(|k| match dir {
                FlowDirection::X => g(k % n),
                FlowDirection::Y => g(k / n),
            })
            .collect();
        GapField::new(n, 1e-3, gap).unwrap()
    }

    #[test]
    fn gap_along_the_flow_is_resistances_in_series() {
        let n = 24;
        let g = |a: usize| 1e-7 * (1.0 + 0.9 * (a as f64 * 0.7).sin()) * (1.0 + a as f64);
        for dir in [FlowDirection::X, FlowDirection::Y] {
            let f = flow(&along(n, g, dir), ETA, dir).unwrap();
            // per line: conductance 1/Σ_faces 1/c; σ_eff = that × (N − 1)
            let r: f64 = (0..n - 1)
                .map(|a| 1.0 / face(sigma(g(a)), sigma(g(a + 1))))
                .sum();
            let want = (n - 1) as f64 / r;
            let rel = f.effective_flow_conductivity / want - 1.0;
            assert!(rel.abs() < EXACT, "{dir:?}: {rel:e}");
        }
    }

    #[test]
    fn gap_across_the_flow_is_conductances_in_parallel() {
        let n = 20;
        let g = |b: usize| 2e-7 * (1.5 + (b as f64 * 1.3).cos());
        for dir in [FlowDirection::X, FlowDirection::Y] {
            // across = the other index
            let across = match dir {
                FlowDirection::X => FlowDirection::Y,
                FlowDirection::Y => FlowDirection::X,
            };
            let f = flow(&along(n, g, across), ETA, dir).unwrap();
            let want: f64 = (0..n).map(|b| sigma(g(b))).sum::<f64>() / n as f64;
            let rel = f.effective_flow_conductivity / want - 1.0;
            assert!(rel.abs() < EXACT, "{dir:?}: {rel:e}");
        }
    }

    #[test]
    fn a_blocked_line_stops_the_flow_exactly() {
        let n = 16;
        for dir in [FlowDirection::X, FlowDirection::Y] {
            // every node of line a = 7 in contact (g = 0), the rest open
            let field = along(n, |a| if a == 7 { 0.0 } else { 1e-6 }, dir);
            let f = flow(&field, ETA, dir).unwrap();
            assert!(!f.percolates);
            assert_eq!(f.effective_flow_conductivity, 0.0);
            // the same line along the flow blocks nothing
            let other = match dir {
                FlowDirection::X => FlowDirection::Y,
                FlowDirection::Y => FlowDirection::X,
            };
            let f = flow(&field, ETA, other).unwrap();
            assert!(f.percolates);
            let want = sigma(1e-6) * (n - 1) as f64 / n as f64;
            assert!((f.effective_flow_conductivity / want - 1.0).abs() < EXACT);
        }
    }

    #[test]
    fn transposed_map_swaps_x_and_y() {
        let n = 40;
        // a rough, partly closed field
        let gap: Vec<f64> = (0..n * n)
            .map(|k| {
                let (i, j) = ((k / n) as f64, (k % n) as f64);
                (1e-6 * ((0.37 * i).sin() + (0.53 * j).cos() + 0.4 * (0.11 * i * j).sin())).max(0.0)
            })
            .collect();
        let field = GapField::new(n, 1e-3, gap).unwrap();
        let t = field.transposed();
        for (a, b) in [
            (FlowDirection::X, FlowDirection::Y),
            (FlowDirection::Y, FlowDirection::X),
        ] {
            let fa = flow(&field, ETA, a).unwrap();
            let fb = flow(&t, ETA, b).unwrap();
            assert_eq!(fa.percolates, fb.percolates);
            assert_eq!(fa.unknowns, fb.unknowns);
            let (x, y) = (
                fa.effective_flow_conductivity,
                fb.effective_flow_conductivity,
            );
            assert!(
                (x - y).abs() <= EXACT * x.abs().max(1e-30),
                "{a:?}: {x} vs {y}"
            );
            // the two solves differ only by rounding, which the bounds cover
            let bound = fa.effective_flow_conductivity_error_bound
                + fb.effective_flow_conductivity_error_bound;
            assert!((x - y).abs() <= bound, "{:e} vs {bound:e}", x - y);
        }
    }

    #[test]
    fn bad_gap_field_names_the_field() {
        let name = |e: Error| match e {
            Error::InvalidParameter { name, .. } => name,
            other => panic!("{other:?}"),
        };
        assert_eq!(
            name(GapField::new(4, 1.0, vec![1.0; 15]).unwrap_err()),
            "gap"
        );
        assert_eq!(
            name(GapField::new(4, 1.0, vec![-1.0; 16]).unwrap_err()),
            "gap"
        );
        assert_eq!(
            name(GapField::new(4, 0.0, vec![1.0; 16]).unwrap_err()),
            "size"
        );
        let f = GapField::new(4, 1.0, vec![1.0; 16]).unwrap();
        for eta in [0.0, -1.0, f64::NAN] {
            assert_eq!(
                name(flow(&f, eta, FlowDirection::X).unwrap_err()),
                "viscosity"
            );
        }
    }
}
