//! Asperity theories (issue 27): overlap, Greenwood–Williamson, Bush–Gibson–Thomas,
//! and the spectral moments behind them.
//!
//! References are mpmath values from `tests/reference/asperity_reference.py`
//! (parabolic-cylinder closed form of F_n, Johnson's elliptic Hertz via
//! ellipk/ellipe, the Kac–Rice summit density by quadrature, nested
//! quadrature of the BGT integrals), independent of the crate's methods.

#![allow(clippy::excessive_precision)] // reference values keep all mpmath digits

use persson::asperity::{
    gw_integral, AsperityTheory, Bush, EllipticHertz, GreenwoodWilliamson, Overlap,
    SpectralMoments, SummitParameters, Validity,
};
use persson::spectrum::{Amplitude, SelfAffine, Spectrum};
use persson::{Error, Estimate};

/// The claim for overlap and GW against closed forms: 1e-12 relative.
const CLAIM: f64 = 1e-12;
/// F_n against the mpmath closed form: the trapezoid and continued fraction
/// are good to ~2e-15; a few ulps more from the products.
const FN_TOL: f64 = 1e-13;
/// BGT against nested mpmath quadrature: the summit table's claim (1e-12
/// against the direct integrals, which run at 1e-12); measured 6e-14.
const BGT_TOL: f64 = 1e-12;

/// (n, h, F_n(h)): mpmath pcfd closed form (asperity_reference.py `fn`).
const GW_INTEGRALS: [(f64, f64, f64); 54] = [
    (0.0, -6.0, 9.9999999901341235496e-1),
    (0.0, -2.0, 9.772498680518207928e-1),
    (0.0, -0.5, 6.9146246127401310364e-1),
    (0.0, 0.0, 5.0e-1),
    (0.0, 0.7, 2.4196365222307301475e-1),
    (0.0, 2.0, 2.27501319481792072e-2),
    (0.0, 5.0, 2.8665157187919391167e-7),
    (0.0, 12.0, 1.7764821120776789977e-33),
    (0.0, 30.0, 4.9067139271481870595e-198),
    (0.5, -6.0, 2.4407444514282802884),
    (0.5, -2.0, 1.3566405981393806541),
    (0.5, -0.5, 6.4666945350328506781e-1),
    (0.5, 0.0, 4.1108947933122927617e-1),
    (0.5, 0.7, 1.6909406264381488589e-1),
    (0.5, 2.0, 1.2480040296439066797e-2),
    (0.5, 5.0, 1.1014563207789280641e-7),
    (0.5, 12.0, 4.5179239763646809092e-34),
    (0.5, 30.0, 7.9314845871808665025e-199),
    (1.0, -6.0, 6.0000000001563569796),
    (1.0, -2.0, 2.0084907026168296375),
    (1.0, -0.5, 6.9779655740130602959e-1),
    (1.0, 0.0, 3.9894228040143267794e-1),
    (1.0, 0.7, 1.4287937681061014678e-1),
    (1.0, 2.0, 8.49070261682963755e-3),
    (1.0, 5.0, 5.3461655338328149539e-8),
    (1.0, 12.0, 1.4605201169845547802e-34),
    (1.0, 30.0, 1.6319567340914011894e-199),
    (1.5, -6.0, 1.4850864472910895278e+1),
    (1.5, -2.0, 3.1112928856875989277),
    (1.5, -0.5, 8.2444842018571123171e-1),
    (1.5, 0.0, 4.3001999366225976769e-1),
    (1.5, 0.7, 1.3630541608655985347e-1),
    (1.5, 2.0, 6.6481776235870931432e-3),
    (1.5, 5.0, 3.033850561878484851e-8),
    (1.5, 12.0, 5.5532172406447139555e-35),
    (1.5, 30.0, 3.9547990870299807613e-200),
    (2.0, -6.0, 3.6999999999951554233e+1),
    (2.0, -2.0, 4.9942312732854800679),
    (2.0, -0.5, 1.0403607399746661184),
    (2.0, 0.0, 5.0e-1),
    (2.0, 0.7, 1.41948088455645912e-1),
    (2.0, 2.0, 5.7687267145199321003e-3),
    (2.0, 5.0, 1.9343295187553163976e-8),
    (2.0, 12.0, 2.3857971696213261513e-35),
    (2.0, 30.0, 1.0843724873983491482e-200),
    (2.5, -6.0, 9.2766303514607792102e+1),
    (2.5, -2.0, 8.2575466685842688366),
    (2.5, -0.5, 1.3822283903477832176),
    (2.5, 0.0, 6.1663421899684391425e-1),
    (2.5, 0.7, 1.5822730270513043141e-1),
    (2.5, 2.0, 5.4237051974844139094e-3),
    (2.5, 5.0, 1.3525920022914967058e-8),
    (2.5, 12.0, 1.1302527577336461732e-35),
    (2.5, 30.0, 3.2829619681357469735e-201),
];

fn f(n: f64, h: f64) -> f64 {
    GW_INTEGRALS
        .iter()
        .find(|r| r.0 == n && r.1 == h)
        .map(|r| r.2)
        .unwrap()
}

fn rel(a: f64, b: f64) -> f64 {
    ((a - b) / b).abs()
}

#[test]
fn gw_integrals_against_mpmath() {
    for &(n, h, v) in &GW_INTEGRALS {
        let got = gw_integral(n, h).unwrap();
        assert!(rel(got, v) < FN_TOL, "F_{n}({h}) = {got:e}, mpmath {v:e}");
    }
    assert!(gw_integral(0.75, 0.0).is_err());
    assert!(gw_integral(1.0, f64::NAN).is_err());
}

#[test]
fn overlap_of_gaussian_heights_is_f0() {
    let (s, y) = (2e-6, 3e8);
    let m = Overlap::gaussian(s, y).unwrap();
    for &(n, h, v) in GW_INTEGRALS.iter().filter(|r| r.0 == 0.0 && r.1 < 12.0) {
        let _ = n;
        let p = m.at_separation(h * s).unwrap();
        assert!(rel(p.contact_fraction, v) < CLAIM, "h = {h}");
        assert!(rel(p.nominal_pressure, y * v) < CLAIM, "h = {h}");
        // The hardness law inverted: the cut at σ0 = σY·F_0(h) is h σ (the
        // inverse is ill-conditioned where F_0 → 1, so check its fraction).
        let q = m.at_pressure(y * v).unwrap();
        let back = m.at_separation(q.separation).unwrap().contact_fraction;
        assert!(rel(back, v) < CLAIM, "h = {h}: {}", q.separation / s);
        if h >= 0.0 {
            assert!(
                (q.separation - h * s).abs() < CLAIM * s,
                "h = {h}: {}",
                q.separation / s
            );
        }
        assert!(p.contact_number_density.is_none() && p.validity.is_empty());
    }
    assert!(m.at_pressure(1.01 * y).is_err());
    assert!(m.at_separation(f64::NAN).is_err());
}

#[test]
fn overlap_of_a_map_counts_heights() {
    // Heights 0..9 (mean 4.5): above the cut d = 0 (i.e. h > 4.5) are 5, 6, 7, 8, 9.
    let h: Vec<f64> = (0..10).map(f64::from).collect();
    let m = Overlap::from_heights(&h, 2.0).unwrap();
    assert_eq!(m.at_separation(0.0).unwrap().contact_fraction, 0.5);
    assert_eq!(m.at_separation(3.5).unwrap().contact_fraction, 0.1); // only 9 (4.5 above the mean)
    assert_eq!(m.at_separation(4.5).unwrap().contact_fraction, 0.0);
    assert_eq!(m.at_separation(-10.0).unwrap().contact_fraction, 1.0);
    // σ0 = 0.6 = σY·0.3: the cut is the 7th of 10 sorted heights (2.5 above the mean), with 3 above.
    let p = m.at_pressure(0.6).unwrap();
    assert_eq!(p.separation, 1.5);
    assert_eq!(m.at_separation(p.separation).unwrap().contact_fraction, 0.3);
    assert!(Overlap::from_heights(&[1.0, f64::NAN], 1.0).is_err());
}

fn summits() -> SummitParameters {
    SummitParameters {
        summit_density: 3.0e10,
        summit_radius: 2.0e-5,
        summit_mean_height: 1.0e-7,
        summit_rms_height: 4.0e-7,
    }
}

#[test]
fn greenwood_williamson_against_closed_forms() {
    let s = summits();
    let e = 2.0e9;
    let gw = GreenwoodWilliamson::new(s, e).unwrap();
    let pi = std::f64::consts::PI;
    for &h in &[-6.0, -2.0, -0.5, 0.0, 0.7, 2.0, 5.0, 12.0, 30.0] {
        let d = s.summit_mean_height + h * s.summit_rms_height;
        let p = gw.at_separation(d).unwrap();
        let n = s.summit_density * f(0.0, h);
        let a = pi * s.summit_density * s.summit_radius * s.summit_rms_height * f(1.0, h);
        let load = 4.0 / 3.0
            * s.summit_density
            * e
            * s.summit_radius.sqrt()
            * s.summit_rms_height.powf(1.5)
            * f(1.5, h);
        assert!(rel(p.contact_number_density.unwrap(), n) < CLAIM, "h = {h}");
        assert!(rel(p.contact_fraction, a) < CLAIM, "h = {h}");
        assert!(rel(p.nominal_pressure, load) < CLAIM, "h = {h}");
        if h < 12.0 {
            // Round trip through the pressure search.
            let q = gw.at_pressure(load).unwrap();
            assert!(
                (q.separation - d).abs() < CLAIM * s.summit_rms_height.max(d.abs()),
                "h = {h}"
            );
            assert!(rel(q.contact_fraction, a) < 1e-11, "h = {h}");
        }
    }
}

/// (α, η m2/m4, ⟨ξ⟩, Var ξ, ⟨u⟩) of the summits by Kac–Rice quadrature
/// (asperity_reference.py `summits`; m0 = m2 = 1, m4 = α; ξ = h/√m0, u = κ̄/√m4).
const SUMMITS: [(f64, f64, f64, f64, f64); 3] = [
    (
        1.6,
        3.0629383078988447195e-2,
        1.7841241161527711145,
        4.3949640235373820999e-1,
        1.5045055561273500985,
    ),
    (
        5.0,
        3.0629383078988447195e-2,
        1.0092530088080640193,
        8.206388487531962272e-1,
        1.5045055561273500985,
    ),
    (
        20.0,
        3.0629383078988447195e-2,
        5.0462650440403200965e-1,
        9.551597121882990568e-1,
        1.5045055561273500985,
    ),
];

#[test]
fn summit_statistics_against_kac_rice() {
    for &(alpha, eta, mean, var, u) in &SUMMITS {
        // Scale the moments so that every factor is exercised: m0 = 4e-12, m2 = 9e-4.
        let (m0, m2) = (4e-12, 9e-4);
        let m4 = alpha * m2 * m2 / m0;
        let s = SpectralMoments::new(m0, m2, m4).unwrap().summits();
        assert!(rel(s.bandwidth_parameter, alpha) < CLAIM);
        assert!(rel(s.summit_density, eta * m4 / m2) < CLAIM, "α = {alpha}");
        assert!(
            rel(s.summit_mean_height, mean * m0.sqrt()) < CLAIM,
            "α = {alpha}"
        );
        assert!(
            rel(s.summit_rms_height, (var * m0).sqrt()) < CLAIM,
            "α = {alpha}"
        );
        assert!(
            rel(s.summit_curvature, u * m4.sqrt()) < CLAIM,
            "α = {alpha}"
        );
        assert!(rel(s.summit_radius * s.summit_curvature, 1.0) < 1e-15);
    }
}

#[test]
fn moments_of_a_self_affine_spectrum_against_closed_forms() {
    // No roll-off: C = C_l (q/q_l)^{−2(H+1)} on [q_l, q_s];
    // ∫ q^k C dq = C_l q_l^{2H+2} (q_s^e − q_l^e)/e, e = k − 2H − 1.
    let (ql, qs, hurst, c_l) = (1e4, 1e7, 0.7, 1e-30);
    let s = SelfAffine::new(ql, ql, qs, hurst, Amplitude::CR(c_l)).unwrap();
    let mk = |k: f64| {
        let e = k - 2.0 * hurst - 1.0;
        c_l * ql.powf(2.0 * hurst + 2.0) * (qs.powf(e) - ql.powf(e)) / e
    };
    let pi = std::f64::consts::PI;
    let (m0, m2, m4) = (2.0 * pi * mk(1.0), pi * mk(3.0), 0.75 * pi * mk(5.0));
    let m = SpectralMoments::from_spectrum(&s).unwrap();
    assert!(rel(m.m0, m0) < CLAIM && rel(m.m2, m2) < CLAIM && rel(m.m4, m4) < CLAIM);
    // The crate's rms values: m0 = h_rms², m2 = h'_rms²/2, m4 = (3/8) h''_rms².
    let r = |e: persson::Result<Estimate>| e.unwrap().value;
    assert!(rel(m.m0, r(s.rms_height(ql, qs)).powi(2)) < CLAIM);
    assert!(rel(m.m2, 0.5 * r(s.rms_slope(ql, qs)).powi(2)) < CLAIM);
    assert!(rel(m.m4, 0.375 * r(s.rms_curvature(ql, qs)).powi(2)) < CLAIM);
    // GW parameters, written out from the closed-form moments.
    let alpha = m0 * m4 / (m2 * m2);
    let sum = m.summits();
    assert!(rel(sum.bandwidth_parameter, alpha) < CLAIM);
    assert!(rel(sum.summit_density, m4 / (6.0 * pi * 3f64.sqrt() * m2)) < CLAIM);
    assert!(rel(sum.summit_radius, 0.375 * (pi / m4).sqrt()) < CLAIM);
    assert!(rel(sum.summit_mean_height, 4.0 * (m0 / (pi * alpha)).sqrt()) < CLAIM);
    assert!(
        rel(
            sum.summit_rms_height,
            (m0 * (1.0 - 0.896_805_756_2 / alpha)).sqrt()
        ) < 1e-10
    );
    // α grows like (q_s/q_l)^{2H} for a broad band (Nayak's measure of breadth).
    assert!(alpha > 1e3);
}

#[test]
fn map_moments_are_exact_for_cosines() {
    // h = a cos(q_x x) + b cos(q_x x + q_y y) on a periodic n × n grid: finite
    // differences have the symbols s(q) = (2/Δ) sin(qΔ/2) and s(q)² for D².
    let n = 32;
    let (dx, dy) = (1e-6, 2e-6);
    let tau = std::f64::consts::TAU;
    let (kx, ky) = (3.0, 5.0);
    let (qx, qy) = (tau * kx / (n as f64 * dx), tau * ky / (n as f64 * dy));
    let (a, b) = (2e-8, 1e-8);
    let mut h = Vec::with_capacity(n * n);
    for j in 0..n {
        for i in 0..n {
            let (x, y) = (i as f64 * dx, j as f64 * dy);
            h.push(a * (qx * x).cos() + b * (qx * x + qy * y + 0.3).cos());
        }
    }
    let mm = SpectralMoments::from_heights(&h, n, n, dx, dy, true).unwrap();
    let s = |q: f64, d: f64| 2.0 / d * (0.5 * q * d).sin();
    let m0 = 0.5 * (a * a + b * b);
    let m2 = 0.5 * (0.5 * (a * a + b * b) * s(qx, dx).powi(2) + 0.5 * b * b * s(qy, dy).powi(2));
    let m4 = 0.5 * (0.5 * (a * a + b * b) * s(qx, dx).powi(4) + 0.5 * b * b * s(qy, dy).powi(4));
    assert!(rel(mm.moments.m0, m0) < CLAIM);
    assert!(rel(mm.moments.m2, m2) < CLAIM);
    assert!(rel(mm.moments.m4, m4) < CLAIM);
    // Smooth map: coarsening by 2 changes m4 little, no flag.
    let ratio = mm.curvature_resolution_ratio.unwrap();
    let coarse = 0.5
        * (0.5 * (a * a + b * b) * s(qx, 2.0 * dx).powi(4) + 0.5 * b * b * s(qy, 2.0 * dy).powi(4));
    assert!(rel(ratio, coarse / m4) < CLAIM);
    assert!(mm.validity.is_empty());
}

#[test]
fn a_map_rough_at_the_pixel_is_flagged_and_a_coarse_map_is_an_error() {
    // Alternating pixels (the Nyquist mode) plus a slope: m4 is all pixel scale.
    let n = 16;
    let h: Vec<f64> = (0..n * n)
        .map(|k| if (k % n + k / n) % 2 == 0 { 1.0 } else { -1.0 })
        .collect();
    let mm = SpectralMoments::from_heights(&h, n, n, 1.0, 1.0, true).unwrap();
    assert!(matches!(
        mm.validity[0],
        Validity::CurvatureUnresolved { .. }
    ));
    match SpectralMoments::from_heights(&[0.0, 1.0, 0.5, 0.2], 2, 2, 1.0, 1.0, false) {
        Err(Error::InvalidParameter { name, .. }) => assert_eq!(name, "m4"),
        other => panic!("{other:?}"),
    }
    let plane: Vec<f64> = (0..25).map(|k| (k % 5) as f64).collect();
    match SpectralMoments::from_heights(&plane, 5, 5, 1.0, 1.0, false) {
        Err(Error::InvalidParameter { name, .. }) => assert_eq!(name, "m4"),
        other => panic!("{other:?}"),
    }
}

/// C ∝ q^{−5} with no upper cut-off: m0 and m2 exist, m4 = (3π/4)∫ q⁵ C dq diverges.
struct Unbounded;

impl Spectrum for Unbounded {
    fn c(&self, q: f64) -> f64 {
        q.powf(-5.0) // H = 1.5: m0, m2 finite, m4 = ∫ q⁰ dq diverges
    }
    fn q_min(&self) -> f64 {
        1.0
    }
    fn q_max(&self) -> f64 {
        f64::INFINITY
    }
    fn moment(&self, k: i32, a: f64, _b: f64) -> persson::Result<Estimate> {
        let e = f64::from(k) - 4.0;
        let value = if e < 0.0 {
            -a.powf(e) / e
        } else {
            f64::INFINITY
        };
        Ok(Estimate { value, error: 0.0 })
    }
}

#[test]
fn a_spectrum_without_finite_fourth_moment_is_an_error_naming_m4() {
    match SpectralMoments::from_spectrum(&Unbounded) {
        Err(Error::InvalidParameter {
            name, requirement, ..
        }) => {
            assert_eq!(name, "m4", "{requirement}");
            assert!(requirement.contains("q_s"), "{requirement}");
        }
        other => panic!("{other:?}"),
    }
}

const KAPPA_BUSH: f64 = 2.506_628_274_631_000_2;

#[test]
fn bush_low_load_limit_is_kappa_bush() {
    for alpha in [1.6, 2.0, 5.0, 10.0, 100.0, 1e4] {
        let m = SpectralMoments::new(1e-12, 1e-3, alpha * 1e-6 / 1e-12).unwrap();
        for hertz in [EllipticHertz::Exact, EllipticHertz::GeometricMean] {
            let k = Bush::new(&m, 3e6, hertz).unwrap().low_load_kappa().unwrap();
            assert!(
                (k - KAPPA_BUSH).abs() < CLAIM,
                "α = {alpha}, {hertz:?}: κ = {k:.17}"
            );
        }
    }
    assert!((persson::kappa::Kappa::Bush.value() - KAPPA_BUSH).abs() < 1e-15);
}

#[test]
fn bush_kappa_approaches_its_limit_from_above_at_finite_load() {
    // κ(δ) − √(2π) shrinks as the load falls (δ grows) and is small by δ = 100.
    let m = SpectralMoments::new(1.0, 1.0, 10.0).unwrap();
    let b = Bush::new(&m, 1.0, EllipticHertz::Exact).unwrap();
    let mut last = f64::INFINITY;
    for delta in [1.0, 2.0, 4.0, 10.0, 100.0] {
        let k = b.kappa_at(delta).unwrap();
        let gap = (k - KAPPA_BUSH).abs();
        assert!(gap < last, "δ = {delta}: κ = {k}");
        last = gap;
    }
    assert!(last < 1e-2, "{last}");
}

#[test]
fn bush_counts_every_summit_at_high_load() {
    // δ → −∞: n → η = m4/(6π√3 m2) (Nayak), independent of the kernels' F.
    let m = SpectralMoments::new(1.0, 1.0, 5.0).unwrap();
    let eta = m.summits().summit_density;
    for hertz in [EllipticHertz::Exact, EllipticHertz::GeometricMean] {
        let b = Bush::new(&m, 1.0, hertz).unwrap();
        let p = b.at_separation(-12.0).unwrap();
        assert!(
            rel(p.contact_number_density.unwrap(), eta) < CLAIM,
            "{hertz:?}"
        );
    }
}

/// BGT at α = 5 (m0 = m2 = 1, m4 = 5, E* = 1): (exact Hertz, δ, n, A/A0, σ0),
/// nested mpmath quadrature (asperity_reference.py `bgt`).
const BGT: [(bool, f64, f64, f64, f64); 8] = [
    (
        true,
        -1.0,
        1.5120086692728059e-1,
        3.5474340751461925e-1,
        3.7803525072650433e-1,
    ),
    (
        true,
        0.0,
        1.3288211241972407e-1,
        1.7901791278411305e-1,
        1.6108621428517303e-1,
    ),
    (
        true,
        1.0,
        7.6927037363670158e-2,
        5.6040730770166379e-2,
        4.3102358985660982e-2,
    ),
    (
        true,
        2.5,
        7.7624176751981895e-3,
        2.4602090127350254e-3,
        1.6078757863424825e-3,
    ),
    (
        false,
        -1.0,
        1.5120086692728059e-1,
        3.616042216216128e-1,
        3.6835688503419982e-1,
    ),
    (
        false,
        0.0,
        1.3288211241972407e-1,
        1.8231411834116144e-1,
        1.5718581710879232e-1,
    ),
    (
        false,
        1.0,
        7.6927037363670158e-2,
        5.6979231437398719e-2,
        4.2157147477080721e-2,
    ),
    (
        false,
        2.5,
        7.7624176751981895e-3,
        2.4923423431664393e-3,
        1.5803728913494604e-3,
    ),
];

#[test]
fn bush_against_nested_quadrature() {
    let m = SpectralMoments::new(1.0, 1.0, 5.0).unwrap();
    for &(exact, delta, n, a, load) in &BGT {
        let hertz = if exact {
            EllipticHertz::Exact
        } else {
            EllipticHertz::GeometricMean
        };
        let b = Bush::new(&m, 1.0, hertz).unwrap();
        let p = b.at_separation(delta).unwrap();
        assert!(
            rel(p.contact_number_density.unwrap(), n) < BGT_TOL,
            "{exact} δ = {delta}"
        );
        assert!(rel(p.contact_fraction, a) < BGT_TOL, "{exact} δ = {delta}");
        assert!(
            rel(p.nominal_pressure, load) < BGT_TOL,
            "{exact} δ = {delta}"
        );
        let q = b.at_pressure(load).unwrap();
        assert!((q.separation - delta).abs() < 1e-9, "{exact} δ = {delta}");
    }
}

/// The summit-table path against the direct u-integrals: the table's claim.
const TABLE_TOL: f64 = 1e-12;

#[test]
fn bush_summit_table_matches_the_direct_integrals() {
    for alpha in [4.0, 6.0, 20.0, 1e5] {
        let m = SpectralMoments::new(1.0, 1.0, alpha).unwrap();
        for hertz in [EllipticHertz::Exact, EllipticHertz::GeometricMean] {
            let b = Bush::new(&m, 1.0, hertz).unwrap();
            for i in 0..=36 {
                let delta = -6.0 + 0.5 * f64::from(i);
                let fast = b.scaled_integrals(delta).unwrap();
                let direct = b.scaled_integrals_direct(delta).unwrap();
                for j in 0..3 {
                    assert!(
                        rel(fast[j], direct[j]) < TABLE_TOL,
                        "α = {alpha}, {hertz:?}, δ = {delta}, {j}"
                    );
                }
            }
        }
    }
}

/// The table of ln J/φ in δ (−6 ≤ δ ≤ 12) at points off its Chebyshev
/// nodes (a step incommensurate with the pieces) against the direct
/// u-integrals, the summit-table path beside it, and its own error estimate.
#[test]
fn bush_separation_table_matches_the_direct_integrals_off_its_nodes() {
    for alpha in [4.0, 7.3, 1e3] {
        let m = SpectralMoments::new(1.0, 1.0, alpha).unwrap();
        for hertz in [EllipticHertz::Exact, EllipticHertz::GeometricMean] {
            let b = Bush::new(&m, 1.0, hertz).unwrap();
            let slow = b.clone().with_separation_table(false);
            assert_eq!(slow.separation_table_tail(), None);
            let tail = b.separation_table_tail().unwrap();
            assert!(tail < 1e-13, "α = {alpha}, {hertz:?}: tail {tail}");
            for i in 0..=41 {
                let delta = -6.0 + 18.0 * (f64::from(i) + 0.3137) / 42.0;
                let fast = b.scaled_integrals(delta).unwrap();
                let summit = slow.scaled_integrals(delta).unwrap();
                let direct = b.scaled_integrals_direct(delta).unwrap();
                for j in 0..3 {
                    assert!(
                        rel(fast[j], direct[j]) < TABLE_TOL,
                        "α = {alpha}, {hertz:?}, δ = {delta}, {j}"
                    );
                    assert!(
                        rel(summit[j], direct[j]) < TABLE_TOL,
                        "α = {alpha}, {hertz:?}, δ = {delta}, {j}"
                    );
                }
            }
        }
    }
}

#[test]
fn bush_pressure_curve_is_the_same_with_and_without_the_separation_table() {
    let m = SpectralMoments::new(1.0, 1.0, 12.0).unwrap();
    let b = Bush::new(&m, 1.0, EllipticHertz::Exact).unwrap();
    let slow = b.clone().with_separation_table(false);
    let p: Vec<f64> = (0..30)
        .map(|i| 1e-6 * 10f64.powf(0.2 * f64::from(i)))
        .collect();
    for (f, s) in b
        .pressure_curve(&p)
        .unwrap()
        .iter()
        .zip(&slow.pressure_curve(&p).unwrap())
    {
        assert!((f.separation - s.separation).abs() < 1e-12, "{f:?} {s:?}");
        assert!(rel(f.contact_fraction, s.contact_fraction) < 1e-12);
    }
}

#[test]
fn bush_pressure_curve_agrees_with_single_points() {
    let m = SpectralMoments::new(1.0, 1.0, 30.0).unwrap();
    let b = Bush::new(&m, 2.0, EllipticHertz::Exact).unwrap();
    let p: Vec<f64> = (0..25)
        .map(|i| 1e-6 * 10f64.powf(0.25 * f64::from(i)))
        .collect();
    let curve = b.pressure_curve(&p).unwrap();
    for (c, &sigma) in curve.iter().zip(&p) {
        let single = b.at_pressure(sigma).unwrap();
        assert!(
            (c.separation - single.separation).abs() < 1e-12,
            "σ0 = {sigma}"
        );
        // The separation reproduces the pressure asked for.
        let back = b.at_separation(c.separation).unwrap().nominal_pressure;
        assert!(rel(back, sigma) < 1e-12, "σ0 = {sigma}: {back}");
    }
}

#[test]
fn validity_flags() {
    let small = SpectralMoments::new(1.0, 1.0, 3.0).unwrap();
    let gw = GreenwoodWilliamson::from_moments(&small, 1.0).unwrap();
    let p = gw.at_separation(-3.0).unwrap();
    assert!(p.contact_fraction > 0.1);
    assert!(matches!(p.validity[0], Validity::SmallBandwidth { .. }));
    assert!(matches!(p.validity[1], Validity::Coalescence { .. }));
    let broad = SpectralMoments::new(1.0, 1.0, 50.0).unwrap();
    let gw = GreenwoodWilliamson::from_moments(&broad, 1.0).unwrap();
    assert!(gw.at_separation(3.0).unwrap().validity.is_empty());
    let json = serde_json::to_string(&p.validity).unwrap();
    assert!(json.contains("\"kind\":\"small-bandwidth\""), "{json}");
}

#[test]
fn bad_input_names_the_field() {
    let name = |e: Error| match e {
        Error::InvalidParameter { name, .. } => name,
        other => panic!("{other:?}"),
    };
    assert_eq!(name(SpectralMoments::new(0.0, 1.0, 1.0).unwrap_err()), "m0");
    assert_eq!(
        name(SpectralMoments::new(1.0, 1.0, 1.0).unwrap_err()),
        "bandwidth_parameter"
    );
    let m = SpectralMoments::new(1.0, 1.0, 5.0).unwrap();
    assert_eq!(
        name(GreenwoodWilliamson::from_moments(&m, -1.0).unwrap_err()),
        "contact_modulus"
    );
    let gw = GreenwoodWilliamson::from_moments(&m, 1.0).unwrap();
    assert_eq!(
        name(gw.at_separation(f64::INFINITY).unwrap_err()),
        "separation"
    );
    assert_eq!(name(gw.at_pressure(0.0).unwrap_err()), "nominal_pressure");
    let ring = SpectralMoments::new(1.0, 1.0, 1.5).unwrap();
    assert_eq!(
        name(Bush::new(&ring, 1.0, EllipticHertz::Exact).unwrap_err()),
        "bandwidth_parameter"
    );
    assert_eq!(
        name(Overlap::gaussian(1.0, 0.0).unwrap_err()),
        "yield_stress"
    );
}

/// Greenwood & Tripp (1970): two rough surfaces act as one "composite"
/// surface. For independent Gaussian surfaces the gap h1 − h2 is Gaussian
/// with spectrum C1 + C2, so its moments are m_n1 + m_n2 and GW and BGT apply
/// to it unchanged (`SpectralMoments::combined`; McCool 1986 uses the same
/// sum). Checked three ways: the moments of the summed spectrum, the
/// √2-heights surface that two identical ones make, and GW's scaling laws
/// under h → √2 h (η and α unchanged, β and the heights ×√2, so A/A0 at a √2
/// larger separation is the same and σ0 is √2 larger).
#[test]
fn greenwood_tripp_composite_surface() {
    use persson::spectrum::Sum;
    let one = || SelfAffine::new(1e4, 4e4, 4e6, 0.8, Amplitude::RmsSlope(0.5)).unwrap();
    let other = SelfAffine::new(1e4, 2e4, 4e6, 0.5, Amplitude::RmsSlope(0.3)).unwrap();
    let m1 = SpectralMoments::from_spectrum(&one()).unwrap();
    let m2 = SpectralMoments::from_spectrum(&other).unwrap();
    // The summed spectrum's moments are the sum of the moments.
    let sum = Sum::new(vec![Box::new(one()), Box::new(other)]).unwrap();
    let ms = SpectralMoments::from_spectrum(&sum).unwrap();
    let mc = m1.combined(&m2);
    for (a, b) in [(ms.m0, mc.m0), (ms.m2, mc.m2), (ms.m4, mc.m4)] {
        assert!(rel(a, b) < CLAIM, "{a} {b}");
    }
    // Two identical surfaces: one surface of √2 the heights (rms slope ×√2).
    let two = m1.combined(&m1);
    let scaled = SelfAffine::new(
        1e4,
        4e4,
        4e6,
        0.8,
        Amplitude::RmsSlope(0.5 * std::f64::consts::SQRT_2),
    )
    .unwrap();
    let m_scaled = SpectralMoments::from_spectrum(&scaled).unwrap();
    for (a, b) in [
        (two.m0, m_scaled.m0),
        (two.m2, m_scaled.m2),
        (two.m4, m_scaled.m4),
    ] {
        assert!(rel(a, b) < CLAIM, "{a} {b}");
    }
    let (s1, s2) = (m1.summits(), two.summits());
    let r2 = std::f64::consts::SQRT_2;
    assert!(rel(s2.bandwidth_parameter, s1.bandwidth_parameter) < CLAIM);
    assert!(rel(s2.summit_density, s1.summit_density) < CLAIM);
    assert!(rel(s2.summit_curvature, r2 * s1.summit_curvature) < CLAIM);
    assert!(rel(s2.summit_rms_height, r2 * s1.summit_rms_height) < CLAIM);
    assert!(rel(s2.summit_mean_height, r2 * s1.summit_mean_height) < CLAIM);
    let e = 1e9;
    let (g1, g2) = (
        GreenwoodWilliamson::from_moments(&m1, e).unwrap(),
        GreenwoodWilliamson::from_moments(&two, e).unwrap(),
    );
    for k in [-1.0, 0.0, 1.0, 2.5] {
        let d = s1.summit_mean_height + k * s1.summit_rms_height;
        let (p1, p2) = (
            g1.at_separation(d).unwrap(),
            g2.at_separation(r2 * d).unwrap(),
        );
        assert!(rel(p2.contact_fraction, p1.contact_fraction) < CLAIM, "{k}");
        assert!(
            rel(p2.nominal_pressure, r2 * p1.nominal_pressure) < CLAIM,
            "{k}"
        );
        assert!(
            rel(
                p2.contact_number_density.unwrap(),
                p1.contact_number_density.unwrap()
            ) < CLAIM,
            "{k}"
        );
    }
}
