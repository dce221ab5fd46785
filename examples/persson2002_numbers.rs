//! Numbers from Persson, Bucher & Chiaia, Phys. Rev. B 65, 184106 (2002),
//! doi:10.1103/PhysRevB.65.184106, Sec. III, recomputed with the library:
//! `cargo run --release --example persson2002_numbers`.
//!
//! 1. Borri-Brunetto et al.: low-load slopes dA/dF_N at magnifications
//!    L/λ = 128, 64, 32, 16 relative to L/λ = 256, D_f = 2.3 (H = 0.7). The paper's
//!    "theoretical slopes" 1.23, 1.52, 1.87, 2.30 are the pure power law
//!    A ∝ (λ/L)^{1−H}; the numerical results it compares with are 1.24, 1.57, 1.93, 2.32.
//! 2. The rail–wheel estimate: E = 1e11 Pa, ν = 0.3, h0 = 0.95 µm (⟨h²⟩ = h0²/2),
//!    H = 0.5, q0 = 2e4 1/m, q_L = 2π/(1 cm), σ0 = 426 MPa, ζ = 400: "A ≈ 0.2 A0".

use persson::material::Body;
use persson::spectrum::{Amplitude, SelfAffine};
use persson::theory::Persson;
use persson::Material;

fn main() -> Result<(), persson::Error> {
    // 1. Low-load slope ∝ 1/rms slope(ζ) (A = κ σ0/(E* s) for any κ).
    // Self-affine up to the sample size: q_l = q_r = 2π/L, q = ζ q_l.
    let h = 0.7;
    let s = SelfAffine::new(1.0, 1.0, 1e12, h, Amplitude::RmsSlope(1.0))?;
    let m = Persson::new(&s, 1.0)?;
    let slope = |zeta: f64| m.slope_variance(zeta).map(|v| v.value.sqrt());
    println!("Borri-Brunetto slope ratios, D_f = 2.3 (Persson et al. 2002: theory 1.23 1.52 1.87 2.30; numerics 1.24 1.57 1.93 2.32)");
    println!(
        "{:>6} {:>22} {:>26}",
        "L/λ", "power law (λ/L)^(1-H)", "theory, q_l = 2π/L exactly"
    );
    for k in [128.0, 64.0, 32.0, 16.0] {
        // The pure power law is the limit of both magnifications ≫ 1.
        let far = 1e8;
        let asymptotic = slope(256.0 * far)? / slope(k * far)?;
        let full = slope(256.0)? / slope(k)?;
        println!("{k:>6} {asymptotic:>22.4} {full:>26.4}");
    }

    // 2. Rail–wheel: C0 from h0 with the paper's a-factor is equivalent to giving the rms
    // height h0/√2 over [q_L, ∞); q_s = 1e9 1/m stands in for ∞ (its effect is < 1e-6).
    let q_l = std::f64::consts::TAU / 0.01;
    let rms_height = 0.95e-6 / std::f64::consts::SQRT_2;
    let s = SelfAffine::new(q_l, 2e4, 1e9, 0.5, Amplitude::RmsHeight(rms_height))?;
    let steel = Body {
        young: 1e11,
        poisson: 0.3,
    };
    println!(
        "\nRail-wheel estimate at zeta = 400, sigma0 = 426 MPa (Persson et al. 2002: A ≈ 0.2 A0)"
    );
    for (label, e) in [
        (
            "one elastic body on a rigid one, E* = E/(1-nu^2)",
            Material::from_body(steel)?,
        ),
        (
            "two steel bodies, E* = E/(2(1-nu^2))",
            Material::from_bodies(steel, steel)?,
        ),
    ] {
        let a = Persson::new(&s, e.contact_modulus())?.point(400.0, 426e6)?;
        println!(
            "  {label:<52} G = {:>7.4}  A/A0 = {:.4}",
            a.g, a.contact_fraction
        );
    }
    Ok(())
}
