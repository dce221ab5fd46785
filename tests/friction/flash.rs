//! The flash temperature: closed-form limits, an independent quadrature of
//! the heat kernel, and the coupled problem against Runge–Kutta.

use super::*;

/// The closed-form flash limits (solver at 1e-11; measured ≤ 3e-15: the
/// integrands there are C's power laws times constants).
const FLASH_LIMIT_TOL: f64 = 1e-12;

/// The flash temperature against composite Simpson with 2×10⁵ intervals
/// (its h⁴ error ~1e-15; measured agreement 3e-14).
const SIMPSON_TOL: f64 = 1e-12;

/// The coupled flash problem against RK4 (its own error, from halving the
/// step, is ~2e-13; measured agreement ≤ 1.6e-13).
const RK4_TOL: f64 = 1e-11;

/// With a conductivity 10⁶ times rubber's the flash temperature is below
/// this (K) and μ changes by less than this relative amount.
const FAST_CONDUCTION_TOL: f64 = 1e-6;

/// R(x) = h/τ from the heat equation of the kernel's model, solved in the
/// Laplace domain and inverted numerically (mpmath, Talbot and de Hoog agree
/// to 40 digits; tests/reference/friction_heat_kernel.py): independent of the
/// k-integral and of the erf closed form in src/friction/heat.rs.
#[allow(clippy::excessive_precision)] // the references keep 20 digits
const R_FROM_THE_HEAT_EQUATION: [(f64, f64); 7] = [
    (0.02, 9.704_980_885_709_048_348_5e-1),
    (0.2, 7.490_916_537_044_985_852_3e-1),
    (0.7, 3.830_786_541_188_604_319_4e-1),
    (1.0, 2.597_854_681_927_137_206_1e-1),
    (2.0, 8.276_281_355_264_321_109_5e-2),
    (5.0, 1.333_333_333_330_273_017_8e-2),
    (20.0, 8.333_333_333_333_333_333_3e-4),
];

/// erf/erfcx are ≤ 2 ulp; the closed form's numerator cancels to ~3e-2 of
/// its terms at x = 0.1 (just above the series switch): ≤ 1e-14 relative.
const KERNEL_TOL: f64 = 1e-14;

/// The heat kernel against the heat equation it claims to solve (source
/// Q̇0 e^{−2qz} cos(qx) switched on for τ = π/(qv), insulated surface): the
/// short-time limit R → 1 (adiabatic), the long-time limit R → 1/(3x²)
/// (steady conduction) and five points between them.
#[test]
fn heat_kernel_solves_its_heat_equation() {
    for (x, want) in R_FROM_THE_HEAT_EQUATION {
        let r = persson::friction::heat_kernel_ratio(x);
        assert!(rel(r, want) <= KERNEL_TOL, "R({x}) = {r}, want {want}");
        // h(q) = τ R(x) with x² = π D q / v.
        let (q, v) = (1e5, 0.01);
        let d = x * x * v / (PI * q);
        let h = heat_kernel(q, v, d);
        assert!(rel(h, PI / (q * v) * want) <= KERNEL_TOL, "h at x {x}");
    }
}

/// The flash temperature of a temperature-independent rubber with γ = 1 (S = 1),
/// E = E1 + i E2 constant: ΔT = 4 v E2/((1 − ν²) ρc) ∫ q⁴ C h(q) dq.
/// Adiabatic (D → 0, h = π/(qv)): ΔT = 2 E2 h′²_rms/((1 − ν²) ρc).
/// Steady (x² = πDq/v ≫ 1, h = 1/(3Dq²)): ΔT = 4 v E2 m2/(3 (1 − ν²) κ).
#[test]
fn flash_temperature_limits_in_closed_form() {
    let s = spectrum();
    let (e2, rho, c) = (5e5, 1200.0, 1500.0);
    let opts = FrictionOptions {
        gamma: 1.0,
        ..options(1e-11)
    };
    let run = |kappa: f64, v: f64| {
        let rubber = Rubber::new(
            constant_modulus(2e6, e2),
            TemperatureShift::none(T_REF).unwrap(),
        )
        .with_thermal(Thermal::new(kappa, rho, c).unwrap());
        let f = Friction::new(&s, &rubber, &opts).unwrap();
        f.point(v, T_REF, 1e5).unwrap()
    };
    let slope2 = TAU * s.moment(3, 1e2, 1e7).unwrap().value;
    let p = run(1e-30, 1.0);
    let flash = p.flash.as_ref().unwrap();
    let adiabatic = 2.0 * e2 * slope2 / (0.75 * rho * c);
    assert!(
        rel(flash.flash_temperature, adiabatic) <= FLASH_LIMIT_TOL,
        "{} vs {adiabatic}",
        flash.flash_temperature
    );
    assert_eq!(flash.friction_coefficient, mu(&p)); // E does not depend on T
    let kappa = 1.8e3; // D = 1e-3 m²/s
    let (v, m2) = (1e-9, s.moment(2, 1e2, 1e7).unwrap().value);
    let steady = 4.0 * v * e2 * m2 / (3.0 * 0.75 * kappa);
    let got = run(kappa, v).flash.unwrap().flash_temperature;
    assert!(rel(got, steady) <= FLASH_LIMIT_TOL, "{got} vs {steady}");
}

/// Between the limits: the kernel integral by composite Simpson in ln q.
#[test]
fn flash_temperature_of_a_temperature_independent_rubber() {
    let s = spectrum();
    let (e2, kappa, rho, c, v) = (5e5, 0.25, 1200.0, 1500.0, 1e-2);
    let thermal = Thermal::new(kappa, rho, c).unwrap();
    let rubber = Rubber::new(
        constant_modulus(2e6, e2),
        TemperatureShift::none(T_REF).unwrap(),
    )
    .with_thermal(thermal);
    let opts = FrictionOptions {
        gamma: 1.0,
        ..options(1e-11)
    };
    let got = Friction::new(&s, &rubber, &opts)
        .unwrap()
        .point(v, T_REF, 1e5)
        .unwrap();
    let profile = &got.flash.as_ref().unwrap().profile;
    let d = thermal.thermal_diffusivity();
    let integrand = |x: f64| {
        let q = x.exp().clamp(1e2, 1e7); // e^{ln q} may round past the band
        q * q.powi(4) * s.c(q) * heat_kernel(q, v, d)
    };
    let k = 4.0 * v * e2 / (0.75 * rho * c);
    // Simpson on each side of the roll-off kink; 2×10⁵ intervals: error ~1e-15.
    let simpson = |a: f64, b: f64| {
        let n = 200_000;
        let h = (b - a) / n as f64;
        (0..=n)
            .map(|i| {
                integrand(a + i as f64 * h)
                    * if i == 0 || i == n {
                        1.0
                    } else if i % 2 == 1 {
                        4.0
                    } else {
                        2.0
                    }
            })
            .sum::<f64>()
            * h
            / 3.0
    };
    let (l, r, e) = (1e2f64.ln(), 1e3f64.ln(), 1e7f64.ln());
    let want = k * (simpson(l, r) + simpson(r, e));
    let last = profile.last().unwrap();
    assert!(
        rel(last.flash_temperature, want) <= SIMPSON_TOL,
        "{} vs {want}",
        last.flash_temperature
    );
    // The profile rises monotonically from 0 at ζ = 1.
    assert_eq!(profile[0].flash_temperature, 0.0);
    assert!(profile
        .windows(2)
        .all(|w| w[1].flash_temperature >= w[0].flash_temperature));
}

/// The coupled flash problem (WLF rubber: T_q feeds back into E in μ, G and
/// the heating) against a classical RK4 integration of the same ODE system in
/// ln q, written here from the public pieces (Prony::angular, heat_kernel,
/// the shift factors). RK4 at 2×10⁴ steps per segment, checked against 10⁴.
#[test]
fn flash_feedback_against_runge_kutta() {
    let s = spectrum();
    let sls = sls();
    let shift = TemperatureShift::wlf(T_REF, 8.86, 101.6).unwrap();
    let thermal = Thermal::new(0.25, 1200.0, 1500.0).unwrap();
    let rubber = Rubber::new(sls.clone(), shift.clone()).with_thermal(thermal);
    let (v, sigma0, gamma) = (0.3, 1e5, 0.5);
    let f = Friction::new(&s, &rubber, &options(1e-10)).unwrap();
    let p = f.point(v, T_REF, sigma0).unwrap();
    let flash = p.flash.as_ref().unwrap();
    let (k, d, rc) = (
        1.0 / (0.75 * sigma0),
        thermal.thermal_diffusivity(),
        thermal.volumetric_heat_capacity(),
    );
    // y = (T, G, μ); x = ln q.
    let rhs = |x: f64, y: [f64; 3]| -> [f64; 3] {
        let q = x.exp().clamp(1e2, 1e7);
        let a_t = shift.factors(y[0]).unwrap().shift_factor;
        let ang = sls.angular(a_t * q * v);
        let q4c = q.powi(4) * s.c(q);
        let pp = if y[1] > 0.0 {
            libm::erf(0.5 / y[1].sqrt())
        } else {
            1.0
        };
        let ss = gamma + (1.0 - gamma) * pp * pp;
        [
            4.0 * v * q * q4c * ss * ang.loss * heat_kernel(q, v, d) / (0.75 * rc),
            0.5 * q4c * ang.modulus_squared * k * k,
            2.0 * q4c * ss * pp * ang.loss * k,
        ]
    };
    let rk4 = |n: usize| {
        let mut y = [T_REF, 0.0, 0.0];
        for (a, b) in [(1e2f64.ln(), 1e3f64.ln()), (1e3f64.ln(), 1e7f64.ln())] {
            let h = (b - a) / n as f64;
            for i in 0..n {
                let x = a + i as f64 * h;
                let add = |y: [f64; 3], k: [f64; 3], c: f64| {
                    [y[0] + c * k[0], y[1] + c * k[1], y[2] + c * k[2]]
                };
                let k1 = rhs(x, y);
                let k2 = rhs(x + h / 2.0, add(y, k1, h / 2.0));
                let k3 = rhs(x + h / 2.0, add(y, k2, h / 2.0));
                let k4 = rhs(x + h, add(y, k3, h));
                for j in 0..3 {
                    y[j] += h / 6.0 * (k1[j] + 2.0 * k2[j] + 2.0 * k3[j] + k4[j]);
                }
            }
        }
        y
    };
    let (fine, coarse) = (rk4(20_000), rk4(10_000));
    // RK4's own error (fourth order: fine − coarse ≈ 15 × the fine error).
    let rk_err = |j: usize| (fine[j] - coarse[j]).abs();
    assert!(
        rk_err(2) <= RK4_TOL * fine[2],
        "RK4 not converged: {}",
        rk_err(2)
    );
    let dt = flash.flash_temperature;
    assert!(dt > 5.0, "a flash temperature worth testing: {dt}");
    assert!(
        (T_REF + dt - fine[0]).abs() <= RK4_TOL * dt + rk_err(0),
        "T: {} vs {}",
        T_REF + dt,
        fine[0]
    );
    assert!(
        rel(flash.friction_coefficient, fine[2]) <= RK4_TOL,
        "μ: {} vs {}",
        flash.friction_coefficient,
        fine[2]
    );
    assert!(
        rel(flash.g, fine[1]) <= RK4_TOL,
        "G: {} vs {}",
        flash.g,
        fine[1]
    );
    assert!(flash.converged);
}

/// With a conductivity a million times rubber's, the flash temperature
/// vanishes and μ returns to its isothermal value.
#[test]
fn flash_temperature_vanishes_with_fast_conduction() {
    let s = spectrum();
    let rubber = Rubber::new(sls(), TemperatureShift::wlf(T_REF, 8.86, 101.6).unwrap())
        .with_thermal(Thermal::new(2.5e5, 1200.0, 1500.0).unwrap());
    let p = Friction::new(&s, &rubber, &options(1e-10))
        .unwrap()
        .point(1e-3, T_REF, 1e5)
        .unwrap();
    let flash = p.flash.unwrap();
    assert!(
        flash.flash_temperature < FAST_CONDUCTION_TOL,
        "{}",
        flash.flash_temperature
    );
    assert!(
        rel(
            flash.friction_coefficient,
            p.isothermal.friction_coefficient
        ) <= FAST_CONDUCTION_TOL
    );
}

/// Flash heating beyond a shift table's last row extends a_T linearly in
/// ln a_T and says how far it went; the profile's top temperature is that.
#[test]
fn flash_beyond_the_shift_table_is_reported() {
    let s = spectrum();
    let table =
        ShiftTable::new(&[(280.0, 10.0, None), (295.0, 1.0, None), (300.0, 0.5, None)]).unwrap();
    let rubber = Rubber::new(sls(), TemperatureShift::table(295.0, table).unwrap())
        .with_thermal(Thermal::new(0.25, 1200.0, 1500.0).unwrap());
    let f = Friction::new(&s, &rubber, &options(1e-8)).unwrap();
    let p = f.point(1.0, 299.0, 1e5).unwrap();
    let flash = p.flash.unwrap();
    let top = 299.0 + flash.flash_temperature;
    assert!(top > 300.0, "not heated past the table: {top}");
    let reached = flash.shift_table_extended_to.expect("reported");
    assert!(
        reached > 300.0 && reached <= top * (1.0 + IDENTITY_TOL),
        "{reached} vs {top}"
    );
    assert!(p.isothermal.shift_table_extended_to.is_none());
}
