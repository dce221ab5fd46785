//! Anisotropy: the 2-D spectrum, Peklenik number, Str and Std of maps, the
//! stretched spectrum and G(ζ) on a 2-D spectrum (Carbone et al. 2009).

use std::f64::consts::TAU;
use std::sync::Arc;

use persson::bem::surface::{synthesize, synthesize_2d};
use persson::spectrum::anisotropic::{g_2d, slope_tensor_2d, slope_variance_2d};
use persson::spectrum::{Amplitude, Radial, SelfAffine, Spectrum, Spectrum2d, Stretched};
use persson::theory::Persson;
use persson::topography::{anisotropy, Conditioning, Topography};

/// The 2-D integral of an isotropic C and the closed-form moment agree to
/// the 1e-13 (both are converged to ~1e-15).
const ISO_G: f64 = 1e-13;
/// A 90° rotation of a map permutes its Fourier modes exactly; the FFTs of
/// the two layouts round differently (relative ~1e-13 of the largest C).
const ROTATION: f64 = 1e-10;
/// The angular average's moments (φ quadrature of exact moments) against the
/// nested 2-D quadrature (converged to 1e-11 relative: the edges of the
/// stretched band cross the disc).
const AVERAGE_VS_2D: f64 = 1e-9;
/// The same for a sum of a stretched and an isotropic part: the inner
/// quadratures cross both parts' roll-off kinks (not split there, the trait
/// does not know q_r); measured 1.8e-8 at ζ = 30 against the exact moments.
const SUM_VS_2D: f64 = 1e-7;

fn iso(q_l: f64, q_r: f64, q_s: f64) -> Arc<SelfAffine> {
    Arc::new(SelfAffine::new(q_l, q_r, q_s, 0.8, Amplitude::RmsSlope(0.1)).unwrap())
}

fn map(s: &dyn Spectrum2d, n: usize, seed: u64) -> Topography {
    let g = synthesize_2d(s, n, 1.0, seed).unwrap();
    Topography::map(n, n, 1.0, 1.0, g.heights, true).unwrap()
}

fn stats(t: &Topography) -> persson::topography::Anisotropy {
    anisotropy(t, Conditioning::for_topography(t)).unwrap()
}

#[test]
fn isotropic_c_reproduces_g() {
    let s = iso(TAU, 4.0 * TAU, 200.0 * TAU);
    let p = Persson::new(s.as_ref(), 1.0).unwrap();
    for zeta in [1.5, 4.0, 37.0, 200.0] {
        let today = p.g(zeta, 0.01).unwrap().value;
        let two_d = g_2d(&Radial(s.as_ref()), zeta, 1.0, 0.01).unwrap().value;
        let rel = (two_d / today - 1.0).abs();
        println!("ζ {zeta}: G {today:e}, 2-D {two_d:e}, rel {rel:e}");
        assert!(rel < ISO_G, "ζ {zeta}: {rel:e}");
        // The stretched spectrum with γ = 1 is the isotropic one.
        let st = Stretched::new(s.clone(), 1.0, 0.3).unwrap();
        let g1 = Persson::new(&st, 1.0).unwrap().g(zeta, 0.01).unwrap().value;
        assert!((g1 / today - 1.0).abs() < ISO_G, "γ = 1, ζ {zeta}");
    }
}

#[test]
fn stretched_average_is_the_2d_integral() {
    let s = iso(TAU, 4.0 * TAU, 200.0 * TAU);
    for (gamma, angle) in [(2.5, 0.5), (0.4, -1.0), (7.0, 0.0)] {
        let st = Stretched::new(s.clone(), gamma, angle).unwrap();
        let p = Persson::new(&st, 1.0).unwrap();
        for zeta in [1.2, 3.0, 50.0, p.zeta_max()] {
            let avg = p.slope_variance(zeta).unwrap().value;
            let two_d = slope_variance_2d(&st, zeta).unwrap().value;
            let rel = (avg / two_d - 1.0).abs();
            println!("γ {gamma}, ζ {zeta}: {avg:e} vs {two_d:e}: {rel:e}");
            assert!(rel < AVERAGE_VS_2D, "γ {gamma}, ζ {zeta}: {rel:e}");
        }
        // Heights keep their variance: ∫ d²q C = 2π ∫ q C̄ dq = ⟨h²⟩_iso.
        let h2 = TAU * st.moment(1, 0.0, f64::INFINITY).unwrap().value;
        let h2_iso = TAU * s.moment(1, 0.0, f64::INFINITY).unwrap().value;
        assert!((h2 / h2_iso - 1.0).abs() < AVERAGE_VS_2D, "γ {gamma}: ⟨h²⟩");
        // ⟨|∇h|²⟩ = (1 + γ⁻²)/2 ⟨|∇h_iso|²⟩ (h_u = h_iso,u/γ).
        let s2 = TAU * st.moment(3, 0.0, f64::INFINITY).unwrap().value;
        let s2_iso = TAU * s.moment(3, 0.0, f64::INFINITY).unwrap().value;
        let e = 0.5 * (1.0 + gamma.powi(-2)) * s2_iso;
        assert!((s2 / e - 1.0).abs() < AVERAGE_VS_2D, "γ {gamma}: slopes");
    }
}

#[test]
fn bad_gamma_is_an_error_naming_it() {
    let s = iso(TAU, 4.0 * TAU, 200.0 * TAU);
    for g in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        let e = Stretched::new(s.clone(), g, 0.0).unwrap_err().to_string();
        assert!(e.contains("anisotropy"), "{e}");
    }
}

#[test]
fn synthesis_is_seeded_and_isotropic_synthesis_unchanged() {
    let s = iso(TAU, 4.0 * TAU, 40.0 * TAU);
    let a = synthesize(s.as_ref(), 32, 1.0, 3).unwrap();
    let b = synthesize_2d(&Radial(s.as_ref()), 32, 1.0, 3).unwrap();
    assert_eq!(a.heights, b.heights);
    let st = Stretched::new(s, 3.0, 0.2).unwrap();
    let c = synthesize_2d(&st, 32, 1.0, 3).unwrap();
    let d = synthesize_2d(&st, 32, 1.0, 3).unwrap();
    assert_eq!(c.heights, d.heights);
    assert_ne!(c.heights, a.heights);
}

/// The map rotated by 90° counterclockwise: h'(x, y) = h(y, −x).
fn rotated(t: &Topography) -> Topography {
    let n = t.nx();
    let h = t.heights();
    let mut r = vec![0.0; n * n];
    for iy in 0..n {
        for ix in 0..n {
            // h'(ix, iy) = h(iy, −ix mod n)
            r[iy * n + ix] = h[((n - ix) % n) * n + iy];
        }
    }
    Topography::map(n, n, t.lx(), t.ly(), r, true).unwrap()
}

#[test]
fn rotated_map_rotates_spectrum_and_std() {
    let s = iso(TAU, 8.0 * TAU, 60.0 * TAU);
    let st = Stretched::new(s, 3.0, 30f64.to_radians()).unwrap();
    let t = map(&st, 128, 11);
    let r = rotated(&t);
    let (a, b) = (stats(&t), stats(&r));
    let cmax = a.spectrum.c.iter().cloned().fold(0.0, f64::max);
    let n = 128isize;
    for ky in -n / 2..n / 2 {
        for kx in -n / 2..n / 2 {
            // ĥ'(q) = ĥ(R⁻¹q): C'(kx, ky) = C(ky, −kx).
            let d = (b.spectrum.at(kx, ky) - a.spectrum.at(ky, -kx)).abs();
            assert!(d < ROTATION * cmax, "({kx}, {ky}): {d:e}");
        }
    }
    let turn = (b.texture_direction - a.texture_direction).rem_euclid(180.0);
    println!(
        "Std {} → {}, Peklenik {} → {}, Str {} → {}",
        a.texture_direction,
        b.texture_direction,
        a.peklenik_number,
        b.peklenik_number,
        a.texture_aspect_ratio,
        b.texture_aspect_ratio
    );
    assert!((turn - 90.0).abs() < 1e-9, "Std turned by {turn}");
    assert!((a.peklenik_number / b.peklenik_number - 1.0).abs() < ROTATION);
    assert!(half_turn(a.principal_direction + 90.0, b.principal_direction) < 1e-6);
    assert!((a.texture_aspect_ratio - b.texture_aspect_ratio).abs() < 0.02);
}

/// Peklenik number of one 256² synthesised map against its γ: the moment
/// form's scatter over 6 seeds was ±1.3 % (γ = 2); 3 % is ~3 sd.
const PEKLENIK_STAT: f64 = 0.03;
/// Principal direction of one map: measured within ±0.6° of the lay.
const DIRECTION_STAT: f64 = 1.5;
/// Str of one map: 1 − Str of isotropic maps was 0.02–0.065 (min/max of 360
/// noisy decay lengths is biased below 1); stretched maps scatter as much.
const STR_STAT: f64 = 0.1;
/// Std of one map (from the noisy angular spectrum): measured within ±9°.
const STD_STAT: f64 = 15.0;

/// |a − b| on the half turn, degrees.
fn half_turn(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(180.0);
    d.min(180.0 - d)
}

#[test]
fn statistics_of_synthesised_maps() {
    let s = iso(TAU, 16.0 * TAU, 60.0 * TAU);
    for (gamma, lay) in [(1.0, f64::NAN), (2.0, 0.0), (2.0, 30.0), (0.5, 0.0)] {
        let angle = if lay.is_nan() { 0.0 } else { lay };
        let st = Stretched::new(s.clone(), gamma, angle.to_radians()).unwrap();
        // The lay runs along the stretch for γ > 1, across it for γ < 1.
        let lay = if gamma < 1.0 { angle + 90.0 } else { angle };
        let p = gamma.max(1.0 / gamma);
        for seed in 1..=3 {
            let a = stats(&map(&st, 256, seed));
            let msg = format!("γ {gamma}, θ {angle}, seed {seed}: {a:?}");
            println!("{msg}");
            assert!((a.peklenik_number / p - 1.0).abs() < PEKLENIK_STAT, "{msg}");
            assert!(
                (a.texture_aspect_ratio - 1.0 / p).abs() < STR_STAT / p,
                "{msg}"
            );
            if gamma != 1.0 {
                assert!(
                    half_turn(a.principal_direction, lay) < DIRECTION_STAT,
                    "{msg}"
                );
                assert!(half_turn(a.texture_direction, lay) < STD_STAT, "{msg}");
            }
        }
    }
}

#[test]
fn map_stretched_by_its_pixel_size() {
    // The same heights on a map twice as long in x: h'(x, y) = h(x/2, y),
    // Peklenik and 1/Str double (up to the isotropic map's own scatter).
    let s = iso(TAU, 16.0 * TAU, 60.0 * TAU);
    let t = map(&Radial(s.as_ref()), 256, 5);
    let wide = Topography::map(256, 256, 2.0, 1.0, t.heights().to_vec(), true).unwrap();
    let (a, b) = (stats(&t), stats(&wide));
    println!("{a:?}\n{b:?}");
    assert!((b.peklenik_number / (2.0 * a.peklenik_number) - 1.0).abs() < PEKLENIK_STAT);
    assert!(half_turn(b.principal_direction, 0.0) < DIRECTION_STAT);
    assert!((b.texture_aspect_ratio - 0.5).abs() < STR_STAT / 2.0);
    assert!(half_turn(b.texture_direction, 0.0) < STD_STAT);
}

#[test]
fn too_small_or_too_smooth_for_str() {
    let s = iso(TAU, 4.0 * TAU, 60.0 * TAU);
    let t = map(&Radial(s.as_ref()), 256, 1);
    let small = Topography::map(6, 6, 1.0, 1.0, t.heights()[..36].to_vec(), true).unwrap();
    let e = anisotropy(&small, Conditioning::for_topography(&small))
        .unwrap_err()
        .to_string();
    assert!(e.contains("texture_aspect_ratio"), "{e}");
    // Ridges along y with a faint ripple along x: the autocorrelation
    // stays near 1 along y; pure ridges have no Peklenik number.
    let ridges = |ripple: f64| {
        let n = 32;
        let h: Vec<f64> = (0..n * n)
            .map(|k| {
                let (x, y) = ((k % n) as f64 / n as f64, (k / n) as f64 / n as f64);
                (TAU * x).cos() + ripple * (TAU * y).cos()
            })
            .collect();
        let t = Topography::map(n, n, 1.0, 1.0, h, true).unwrap();
        anisotropy(&t, Conditioning::for_topography(&t))
            .unwrap_err()
            .to_string()
    };
    let e = ridges(0.01);
    assert!(e.contains("texture_aspect_ratio"), "{e}");
    let e = ridges(0.0);
    assert!(e.contains("peklenik_number"), "{e}");
}

/// R(r) = 2π ∫ q C(q) J₀(q r) dq of an isotropic spectrum (its
/// autocorrelation function), by composite Simpson over [q_l, q_r] and
/// [q_r, q_s] (C is smooth on each; ≤ 30 periods of J₀ over the band).
fn autocorrelation(s: &SelfAffine, r: f64) -> f64 {
    let simpson = |a: f64, b: f64| {
        let n = 4000;
        let h = (b - a) / n as f64;
        let f = |q: f64| q * s.c(q) * libm::j0(q * r);
        let mut sum = f(a) + f(b);
        for k in 1..n {
            sum += if k % 2 == 1 { 4.0 } else { 2.0 } * f(a + k as f64 * h);
        }
        sum * h / 3.0
    };
    TAU * (simpson(s.q_min(), s.q_r()) + simpson(s.q_r(), s.q_max()))
}

/// The first r at which `f(r)/f(0)` falls to [`persson::topography::STR_THRESHOLD`]
/// (steps of 1e-4 of the map side, then linear interpolation).
fn decay_length(f: impl Fn(f64) -> f64) -> f64 {
    let s = persson::topography::STR_THRESHOLD;
    let f0 = f(0.0);
    let (mut r, mut prev) = (0.0, 1.0);
    loop {
        let next = r + 1e-4;
        let v = f(next) / f0;
        if v <= s {
            return r + 1e-4 * (prev - s) / (prev - v);
        }
        (r, prev) = (next, v);
    }
}

/// Bug fixed: a sum of a stretched and an isotropic spectrum (two bodies,
/// one with a lay) synthesised an isotropic surface. The synthesised map must
/// carry the summed 2-D spectrum: its Peklenik number, principal direction
/// and Str against the spectrum's own (closed-form slope tensor; ACF from the
/// Hankel transform of each part), within the one-map scatter measured above.
#[test]
fn sum_with_a_stretched_part_is_synthesised_anisotropic() {
    use persson::spectrum::Sum;
    let (gamma, lay) = (2.5, 30.0f64);
    // Stretched band from q_l/γ = 2π (the map's lowest mode) to q_s.
    let a = Arc::new(
        SelfAffine::new(
            gamma * TAU,
            16.0 * TAU,
            60.0 * TAU,
            0.8,
            Amplitude::RmsSlope(0.1),
        )
        .unwrap(),
    );
    let b = Arc::new(
        SelfAffine::new(TAU, 16.0 * TAU, 60.0 * TAU, 0.8, Amplitude::RmsSlope(0.07)).unwrap(),
    );
    let st = Stretched::new(a.clone(), gamma, lay.to_radians()).unwrap();
    let sum = Sum::new(vec![Box::new(st), Box::new(*b.as_ref())]).unwrap();
    assert!(sum.as_2d().is_some(), "the sum is anisotropic");
    // Its plane integrates to the angular average's moments (C̄ = Σ C̄_i).
    let q_l = Spectrum::q_min(&sum);
    for zeta in [2.0, 30.0] {
        let plane = slope_variance_2d(sum.as_2d().unwrap(), zeta).unwrap().value;
        let average = TAU * sum.moment(3, q_l, zeta * q_l).unwrap().value;
        assert!(
            (plane / average - 1.0).abs() < SUM_VS_2D,
            "ζ {zeta}: {plane:e} {average:e}"
        );
    }
    // Slope tensor of the sum in the lay's frame (u along, v across):
    // ∫ q_u² C = s_a²/(2γ²) + s_b²/2, ∫ q_v² C = s_a²/2 + s_b²/2.
    let sa2 = a.rms_slope(a.q_min(), a.q_max()).unwrap().value.powi(2);
    let sb2 = b.rms_slope(b.q_min(), b.q_max()).unwrap().value.powi(2);
    let peklenik = ((sa2 + sb2) / (sa2 / (gamma * gamma) + sb2)).sqrt();
    // Autocorrelation along the lay R_a(r/γ) + R_b(r), across R_a(r) + R_b(r).
    let along = decay_length(|r| autocorrelation(&a, r / gamma) + autocorrelation(&b, r));
    let across = decay_length(|r| autocorrelation(&a, r) + autocorrelation(&b, r));
    let str_ref = across / along;
    // The nested quadrature of the plane's slope tensor gives the same.
    let (p2d, dir2d) = slope_tensor_2d(sum.as_2d().unwrap())
        .unwrap()
        .principal()
        .unwrap();
    assert!((p2d / peklenik - 1.0).abs() < SUM_VS_2D, "{p2d} {peklenik}");
    assert!(half_turn(dir2d, lay) < 1e-6, "{dir2d}");
    println!("spectrum: Peklenik {peklenik}, Str {str_ref} ({across} / {along})");
    let mut str_mean = 0.0;
    for seed in 1..=3 {
        let g = synthesize(&sum, 256, 1.0, seed).unwrap();
        let t = Topography::map(256, 256, 1.0, 1.0, g.heights, true).unwrap();
        let m = stats(&t);
        let msg = format!("seed {seed}: {m:?}");
        println!("{msg}");
        assert!(
            (m.peklenik_number / peklenik - 1.0).abs() < PEKLENIK_STAT,
            "{msg}"
        );
        assert!(
            half_turn(m.principal_direction, lay) < DIRECTION_STAT,
            "{msg}"
        );
        // One map's Str scatters by ±0.03–0.06 (absolute) about its mean.
        assert!((m.texture_aspect_ratio - str_ref).abs() < STR_STAT, "{msg}");
        assert!(half_turn(m.texture_direction, lay) < STD_STAT, "{msg}");
        str_mean += m.texture_aspect_ratio / 3.0;
    }
    // Three maps: the scatter of the mean is ~1/√3 of one map's.
    assert!(
        (str_mean - str_ref).abs() < 0.5 * STR_STAT,
        "mean Str {str_mean}"
    );
}

#[test]
fn stretching_an_anisotropic_spectrum_is_an_error() {
    use persson::spectrum::Sum;
    let s = iso(TAU, 4.0 * TAU, 60.0 * TAU);
    let st = Stretched::new(s.clone(), 2.0, 0.0).unwrap();
    let sum: Arc<dyn Spectrum> =
        Arc::new(Sum::new(vec![Box::new(st), Box::new(*s.as_ref())]).unwrap());
    let e = Stretched::new(sum, 2.0, 0.0).unwrap_err().to_string();
    assert!(e.contains("spectrum") && e.contains("anisotropic"), "{e}");
}

/// Rounding of the FFT sums of a 256² map (relative to the trace).
const MAP_TENSOR: f64 = 1e-10;

#[test]
fn slope_tensor_of_a_stretched_spectrum_and_of_its_surface() {
    let s = iso(TAU, 4.0 * TAU, 60.0 * TAU);
    for (gamma, lay) in [(2.5, 30.0f64), (0.4, -50.0), (1.5, 95.0)] {
        let st = Stretched::new(s.clone(), gamma, lay.to_radians()).unwrap();
        // Closed form: the eigenvalues s²/(2γ²) along the stretch and s²/2
        // across, so γ (or 1/γ) and the lay; trace = 2π m₃ of C̄.
        let m = slope_tensor_2d(&st).unwrap();
        let (p, dir) = m.principal().unwrap();
        let lay_ref = if gamma < 1.0 { lay + 90.0 } else { lay };
        let trace = TAU
            * st.moment(3, Spectrum::q_min(&st), Spectrum::q_max(&st))
                .unwrap()
                .value;
        println!("γ {gamma}: {m:?} → {p}, {dir}°");
        assert!(
            (p / gamma.max(1.0 / gamma) - 1.0).abs() < AVERAGE_VS_2D,
            "{p}"
        );
        assert!(half_turn(dir, lay_ref) < 1e-7, "{dir}");
        assert!(((m.xx + m.yy) / trace - 1.0).abs() < AVERAGE_VS_2D);
        // A synthesised surface's tensor (half spectrum, bem FFT) against the
        // map statistics' (full-plane FFT of the same heights) and rms slope.
        let g = synthesize(&st, 256, 1.0, 4).unwrap();
        let t = g.slope_tensor().unwrap();
        let tr = t.xx + t.yy;
        assert!((tr / g.rms_slope().unwrap().powi(2) - 1.0).abs() < MAP_TENSOR);
        let (pm, dm) = t.principal().unwrap();
        let a = stats(&Topography::map(256, 256, 1.0, 1.0, g.heights.clone(), true).unwrap());
        assert!(
            (pm / a.peklenik_number - 1.0).abs() < MAP_TENSOR,
            "{pm} {a:?}"
        );
        assert!(half_turn(dm, a.principal_direction) < 1e-6, "{dm} {a:?}");
    }
}
