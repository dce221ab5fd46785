//! Stress below the surface: the full stress tensor of the elastic
//! half-space under a solved surface pressure, on planes and along a
//! vertical line; von Mises and maximum shear, and where a material of
//! uniaxial yield stress Y first yields.
//!
//! # What it solves
//! The half-space z > 0 (z the depth, m) is loaded by the nodal pressures p
//! (compressive positive, in any pressure unit) of an `N × N` grid of side L,
//! rows along x (x = iΔ) and columns along y (y = jΔ), Δ = L/N; stresses are
//! tensile positive (σ_zz = −p at the surface). Periodic: the grid is one
//! period; free: an isolated load on a window of an infinite half-space,
//! piecewise constant on the cells as in the BEM's free operator
//! ([`super::kernel`]). The Poisson ratio ν of the loaded body is needed here
//! (the contact problem itself needs only E*).
//!
//! # Formula
//! ```text
//! σ(x, z) = Σ_q M(q, z) p̂(q) e^{iq·x} / N²                 (periodic: Fourier multipliers M)
//! σ(x_i, z) = Σ_j K(x_i − x_j, z) p_j                       (free: exact cell integrals K, zero-padded to 2N)
//! σ_vM = √(½[(σxx − σyy)² + (σyy − σzz)² + (σzz − σxx)²] + 3(σxy² + σxz² + σyz²))
//! τ_max = (σ₁ − σ₃)/2
//! ```
//! One mode p̂ e^{iq·x}, q = q(n_x, n_y), is plane strain in the plane of q
//! (E = e^{−qz}; ξ along q, η across):
//! ```text
//! σ_ξξ = −(1 − qz) E p̂,  σ_ηη = −2ν E p̂,  σ_zz = −(1 + qz) E p̂,  σ_ξz = i qz E p̂
//! q = 0:  σ_zz = −p̄,  σ_xx = σ_yy = −ν p̄/(1 − ν)      (no mean in-plane strain; Tamaas' choice too)
//! ```
//! (odd multipliers zero at the Nyquist wavevector). K is the exact stress
//! of a uniform pressure on a cell from Boussinesq's potentials
//! ψ₁ = ∫∫ p ln(ρ + z), ψ = ∫∫ p/ρ (Johnson 1985, §3.2):
//! ```text
//! σ_xx = [2ν ψ_z − z ψ_xx − (1 − 2ν) ψ₁_xx]/2π,   σ_zz = [ψ_z − z ψ_zz]/2π
//! σ_xy = −[(1 − 2ν) ψ₁_xy + z ψ_xy]/2π,   σ_xz = −z ψ_xz/2π       (yy, yz: x ↔ y)
//! ```
//! each derivative a corner sum of closed forms over the cell. Stress is
//! linear in p, so under a load scaled by λ the material first yields (von
//! Mises) at λ = Y / max σ_vM.
//!
//! # Method
//! Periodic: one forward real FFT of p, then per plane six multiplied
//! inverse FFTs. Free: the cell kernels are evaluated once per depth on one
//! quadrant of offsets (their parity in x and y gives the others), each is
//! transformed on the 2N × 2N grid, multiplied by the transform of the
//! zero-padded p and transformed back (Liu, Wang & Liu's DC-FFT; no
//! periodic images). Along a vertical line the same sums run directly.
//! Every FFT is the BEM's planned `Fft2` (module `bem::fft`).
//!
//! # Accuracy
//! Exact for the discrete load (cell-constant p, free) or the band-limited
//! field (periodic) up to rounding; against a continuous load the error is
//! that of resolving p on the grid: the Hertz axis stresses converge with N
//! as reported in tests/subsurface.rs.
//!
//! # References
//! - K. L. Johnson, *Contact Mechanics* (CUP 1985): §3.2 (Boussinesq), §3.4
//!   and §4.2 (the Hertz stresses on the axis; τ_max ≈ 0.31 p0 at z ≈ 0.48 a
//!   for ν = 0.3).
//! - S. Liu, Q. Wang, G. Liu, Wear 243, 101 (2000): DC-FFT.
//! - Tamaas (Frérot, Anciaux, Rey, Pham-Ba, Molinari, JOSS 5, 2121 (2020)):
//!   volume operators for the same problem (compared in tests/reference).

mod green;

use rustfft::num_complex::Complex64;

use super::fft::Fft2;
use super::kernel::Boundary;
use crate::error::{check, Error, Result};

/// Number of independent stress components (xx, yy, zz, xy, xz, yz).
pub(crate) const COMPONENTS: usize = green::COMPONENTS;

/// The six stress components at one point, xx, yy, zz, xy, xz, yz.
type Tensor = [f64; COMPONENTS];

/// The stress on one plane z = depth.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
#[non_exhaustive]
pub struct StressPlane {
    /// Depth z, m.
    pub depth: f64,
    /// σ_xx, σ_yy, σ_zz, σ_xy, σ_xz, σ_yz, each `N × N` row-major (unit of p).
    pub stress: [Vec<f64>; COMPONENTS],
    /// Von Mises stress, `N × N`.
    pub von_mises_stress: Vec<f64>,
    /// Maximum shear stress (σ₁ − σ₃)/2, `N × N`.
    pub max_shear_stress: Vec<f64>,
    /// The plane's maxima.
    pub summary: PlaneSummary,
}

/// The largest value of a field and where it is.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Extremum {
    /// The value (unit of p).
    pub value: f64,
    /// Depth z, m.
    pub depth: f64,
    /// Position (x, y), m.
    pub position: [f64; 2],
    /// Node (row, column).
    pub node: [usize; 2],
}

/// The maxima of one plane.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct PlaneSummary {
    /// Depth z, m.
    pub depth: f64,
    /// Largest von Mises stress.
    pub von_mises_stress: Extremum,
    /// Largest maximum shear stress.
    pub max_shear_stress: Extremum,
    /// Fraction of the plane where σ_vM ≥ Y (with a yield stress).
    pub yielded_fraction: Option<f64>,
}

/// Where and at which load factor the subsurface first yields (von Mises).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct FirstYield {
    /// Uniaxial yield stress Y (unit of p).
    pub tensile_yield_stress: f64,
    /// Y / max σ_vM: the factor on the load at which yield starts (< 1: it has).
    pub load_factor: f64,
    /// Whether the given load already yields somewhere (max σ_vM ≥ Y).
    pub yielded: bool,
    /// The point of the largest σ_vM.
    pub at: Extremum,
}

/// Summaries of several planes and the overall maxima.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
#[non_exhaustive]
pub struct SubsurfaceReport {
    /// Boundary of the half-space.
    pub boundary: Boundary,
    /// Poisson ratio ν.
    pub poisson: f64,
    /// One summary per depth, in the order given.
    pub planes: Vec<PlaneSummary>,
    /// Largest von Mises stress over the planes.
    pub max_von_mises_stress: Extremum,
    /// Largest maximum shear over the planes.
    pub max_shear_stress: Extremum,
    /// First yield, when a yield stress was given.
    pub first_yield: Option<FirstYield>,
}

/// The stress at one depth of a vertical line.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct LinePoint {
    /// Depth z, m.
    pub depth: f64,
    /// σ_xx, σ_yy, σ_zz, σ_xy, σ_xz, σ_yz (unit of p).
    pub stress: Tensor,
    /// Von Mises stress.
    pub von_mises_stress: f64,
    /// Maximum shear stress.
    pub max_shear_stress: f64,
}

/// A pressure field ready for stress evaluations (its transform computed once).
pub struct Subsurface {
    n: usize,
    size: f64,
    boundary: Boundary,
    poisson: f64,
    pressure: Vec<f64>,
    /// Transform of p (periodic: N grid; free: zero-padded 2N grid).
    spectrum: Vec<Complex64>,
    /// Plan with N live rows (periodic: N; free: 2N grid, N rows).
    fft: Fft2,
    /// Free only: plan of the full 2N grid for the kernels.
    kernel_fft: Option<Fft2>,
}

impl std::fmt::Debug for Subsurface {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Subsurface")
            .field("n", &self.n)
            .field("size", &self.size)
            .field("boundary", &self.boundary)
            .field("poisson", &self.poisson)
            .finish()
    }
}

impl Subsurface {
    /// Prepare the stress evaluation of the `n × n` nodal pressure field
    /// `pressure` (row-major, compressive positive) on a grid of side `size`
    /// (m), for a body of Poisson ratio `poisson`.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] naming `grid` (n < 2), `size`, `poisson`
    /// (not in (−1, 0.5]) or a non-finite `pressure[i, j]`;
    /// [`Error::Inconsistent`] if `pressure.len() != n²`.
    pub fn new(
        pressure: &[f64],
        n: usize,
        size: f64,
        boundary: Boundary,
        poisson: f64,
    ) -> Result<Self> {
        check::positive("size", size)?;
        if n < 2 {
            return Err(Error::invalid("grid", n as f64, ">= 2"));
        }
        crate::material::check_poisson("poisson", poisson)?;
        if pressure.len() != n * n {
            return Err(Error::Inconsistent {
                name: "pressure".into(),
                requirement: format!("N² = {} values, got {}", n * n, pressure.len()),
            });
        }
        if let Some(k) = pressure.iter().position(|p| !p.is_finite()) {
            return Err(Error::invalid(
                format!("pressure[{}, {}]", k / n, k % n),
                pressure[k],
                "finite",
            ));
        }
        let nf = match boundary {
            Boundary::Periodic => n,
            Boundary::Free => 2 * n,
        };
        let mut fft = Fft2::new(nf, n)?;
        let mut x = vec![0.0; n * nf];
        for i in 0..n {
            x[i * nf..i * nf + n].copy_from_slice(&pressure[i * n..(i + 1) * n]);
        }
        let mut spectrum = vec![Complex64::new(0.0, 0.0); fft.spectrum_len()];
        fft.forward(&mut x, &mut spectrum)?;
        let kernel_fft = match boundary {
            Boundary::Periodic => None,
            Boundary::Free => Some(Fft2::new(nf, nf)?),
        };
        Ok(Subsurface {
            n,
            size,
            boundary,
            poisson,
            pressure: pressure.to_vec(),
            spectrum,
            fft,
            kernel_fft,
        })
    }

    /// Check a depth: finite, > 0 and ≤ the side L.
    fn check_depth(&self, depth: f64) -> Result<f64> {
        if depth.is_finite() && depth > 0.0 && depth <= self.size {
            Ok(depth)
        } else {
            Err(Error::invalid(
                "depth",
                depth,
                format!("in (0, size = {}] m", self.size),
            ))
        }
    }

    /// The stress tensor, von Mises and maximum shear on the plane z = `depth`.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] naming `depth` unless 0 < depth ≤ L.
    pub fn plane(&mut self, depth: f64) -> Result<StressPlane> {
        let z = self.check_depth(depth)?;
        let sigma = match self.boundary {
            Boundary::Periodic => self.periodic_plane(z)?,
            Boundary::Free => self.free_plane(z)?,
        };
        let n2 = self.n * self.n;
        let mut vm = vec![0.0; n2];
        let mut ms = vec![0.0; n2];
        for k in 0..n2 {
            let t = [
                sigma[0][k],
                sigma[1][k],
                sigma[2][k],
                sigma[3][k],
                sigma[4][k],
                sigma[5][k],
            ];
            vm[k] = green::von_mises(&t);
            ms[k] = green::max_shear(&t);
        }
        let summary = PlaneSummary {
            depth: z,
            von_mises_stress: self.extremum(&vm, z),
            max_shear_stress: self.extremum(&ms, z),
            yielded_fraction: None,
        };
        Ok(StressPlane {
            depth: z,
            stress: sigma,
            von_mises_stress: vm,
            max_shear_stress: ms,
            summary,
        })
    }

    /// Summaries of the planes at `depths`, the overall maxima and, with a
    /// uniaxial yield stress Y, where the subsurface first yields.
    ///
    /// # Errors
    /// `depths` empty; a depth out of (0, L]; `tensile_yield_stress` not
    /// finite and > 0.
    pub fn report(
        &mut self,
        depths: &[f64],
        tensile_yield_stress: Option<f64>,
    ) -> Result<SubsurfaceReport> {
        if depths.is_empty() {
            return Err(Error::invalid("depth", f64::NAN, "at least one depth"));
        }
        if let Some(y) = tensile_yield_stress {
            check::positive("tensile_yield_stress", y)?;
        }
        for &d in depths {
            self.check_depth(d)?;
        }
        let mut planes = Vec::with_capacity(depths.len());
        for &d in depths {
            let p = self.plane(d)?;
            let mut s = p.summary;
            if let Some(y) = tensile_yield_stress {
                let yielded = p.von_mises_stress.iter().filter(|&&v| v >= y).count();
                s.yielded_fraction = Some(yielded as f64 / p.von_mises_stress.len() as f64);
            }
            planes.push(s);
        }
        let best = |f: fn(&PlaneSummary) -> Extremum| {
            planes
                .iter()
                .map(f)
                .fold(f(&planes[0]), |a, b| if b.value > a.value { b } else { a })
        };
        let max_vm = best(|s| s.von_mises_stress);
        let first_yield = tensile_yield_stress.map(|y| FirstYield {
            tensile_yield_stress: y,
            load_factor: y / max_vm.value,
            yielded: max_vm.value >= y,
            at: max_vm,
        });
        Ok(SubsurfaceReport {
            boundary: self.boundary,
            poisson: self.poisson,
            max_von_mises_stress: max_vm,
            max_shear_stress: best(|s| s.max_shear_stress),
            planes,
            first_yield,
        })
    }

    /// The stress along the vertical line through node `node` = (row,
    /// column) at each depth.
    ///
    /// # Errors
    /// A depth out of (0, L]; `node` outside the grid (named `node`).
    pub fn line(&self, node: [usize; 2], depths: &[f64]) -> Result<Vec<LinePoint>> {
        let n = self.n;
        if node[0] >= n || node[1] >= n {
            return Err(Error::invalid(
                "node",
                node[0].max(node[1]) as f64,
                format!("< grid = {n}"),
            ));
        }
        depths
            .iter()
            .map(|&d| {
                let z = self.check_depth(d)?;
                let sigma = match self.boundary {
                    Boundary::Periodic => self.periodic_point(node, z),
                    Boundary::Free => self.free_point(node, z),
                };
                Ok(LinePoint {
                    depth: z,
                    stress: sigma,
                    von_mises_stress: green::von_mises(&sigma),
                    max_shear_stress: green::max_shear(&sigma),
                })
            })
            .collect()
    }

    fn extremum(&self, field: &[f64], z: f64) -> Extremum {
        let (k, v) = field
            .iter()
            .enumerate()
            .fold((0, f64::NEG_INFINITY), |(bk, bv), (k, &v)| {
                if v > bv {
                    (k, v)
                } else {
                    (bk, bv)
                }
            });
        let d = self.size / self.n as f64;
        let (i, j) = (k / self.n, k % self.n);
        Extremum {
            value: v,
            depth: z,
            position: [i as f64 * d, j as f64 * d],
            node: [i, j],
        }
    }

    /// Signed wavevector index of FFT index k on an m-point axis.
    fn signed(k: usize, m: usize) -> f64 {
        if k <= m / 2 {
            k as f64
        } else {
            k as f64 - m as f64
        }
    }

    /// Periodic plane: six multiplied inverse transforms (e^{−qz} once per mode).
    fn periodic_plane(&mut self, z: f64) -> Result<[Vec<f64>; COMPONENTS]> {
        let n = self.n;
        let nc = n / 2 + 1;
        let dq = std::f64::consts::TAU / self.size;
        let norm = 1.0 / (n * n) as f64;
        let nu = self.poisson;
        // Per mode (column-major as the spectrum): q_x, q_y, q, e^{−qz}.
        let modes: Vec<[f64; 4]> = (0..nc * n)
            .map(|k| {
                let (kj, ki) = (k / n, k % n);
                let (qx, qy) = (dq * Self::signed(ki, n), dq * kj as f64);
                let q = qx.hypot(qy);
                let nyquist = n.is_multiple_of(2) && (ki == n / 2 || kj == n / 2);
                // A negative q flags the Nyquist modes (odd multipliers vanish).
                [qx, qy, if nyquist { -q } else { q }, (-q * z).exp()]
            })
            .collect();
        let mut out: [Vec<f64>; COMPONENTS] = Default::default();
        let mut spec = vec![Complex64::new(0.0, 0.0); self.spectrum.len()];
        for (c, field) in out.iter_mut().enumerate() {
            for ((s, &p), m) in spec.iter_mut().zip(&self.spectrum).zip(&modes) {
                let (re, im) = green::multiplier(c, m[0], m[1], m[2], m[3], z, nu);
                *s = p * Complex64::new(re * norm, im * norm);
            }
            *field = vec![0.0; n * n];
            self.fft.inverse(&mut spec, field)?;
        }
        Ok(out)
    }

    /// Periodic stress at one node by the direct Fourier sum.
    fn periodic_point(&self, node: [usize; 2], z: f64) -> Tensor {
        let n = self.n;
        let nc = n / 2 + 1;
        let dq = std::f64::consts::TAU / self.size;
        let d = self.size / n as f64;
        let (x, y) = (node[0] as f64 * d, node[1] as f64 * d);
        let mut acc = [0.0; COMPONENTS];
        for kj in 0..nc {
            // Columns 1 … n/2−1 of the half spectrum stand for ±k_j.
            let weight = if kj == 0 || (n.is_multiple_of(2) && kj == n / 2) {
                1.0
            } else {
                2.0
            };
            for ki in 0..n {
                let nyquist = n.is_multiple_of(2) && (ki == n / 2 || kj == n / 2);
                let (qx, qy) = (dq * Self::signed(ki, n), dq * kj as f64);
                let m = green::multipliers(qx, qy, z, self.poisson, nyquist);
                let phase = Complex64::from_polar(1.0, qx * x + qy * y);
                let pp = self.spectrum[kj * n + ki] * phase;
                for c in 0..COMPONENTS {
                    acc[c] += weight * (pp * Complex64::new(m[c].0, m[c].1)).re;
                }
            }
        }
        acc.map(|v| v / (n * n) as f64)
    }

    /// Free plane: kernels on the 2N grid, DC-FFT. The xx, zz, xy and xz
    /// kernels are transformed; yy and yz are their transposes (K_yy(x, y) =
    /// K_xx(y, x)), read from the same spectra.
    fn free_plane(&mut self, z: f64) -> Result<[Vec<f64>; COMPONENTS]> {
        let n = self.n;
        let nf = 2 * n;
        let quadrants = green::free_quadrants(n, self.size / n as f64, z, self.poisson);
        let kfft = self
            .kernel_fft
            .as_mut()
            .ok_or_else(|| Error::Inconsistent {
                name: "subsurface".into(),
                requirement: "a free grid has a kernel transform".into(),
            })?;
        let mut kspec = vec![Complex64::new(0.0, 0.0); kfft.spectrum_len()];
        let mut spec = vec![Complex64::new(0.0, 0.0); kfft.spectrum_len()];
        let mut work = vec![0.0; nf * nf];
        let mut rows = vec![0.0; n * nf];
        let mut out: [Vec<f64>; COMPONENTS] = Default::default();
        let norm = 1.0 / (nf * nf) as f64;
        let nc = n + 1;
        // (kernel quadrant, parity, output, transposed output)
        let plan: [green::KernelPlan; 4] = [
            (0, (1.0, 1.0), 0, Some(1)),
            (1, (1.0, 1.0), 2, None),
            (2, (-1.0, -1.0), 3, None),
            (3, (-1.0, 1.0), 4, Some(5)),
        ];
        for (q, parity, c, transposed) in plan {
            green::fill_circulant(&quadrants[q], n, parity, &mut work);
            kfft.forward(&mut work, &mut kspec)?;
            for (target, swap) in std::iter::once((c, false)).chain(transposed.map(|t| (t, true))) {
                for kj in 0..nc {
                    for ki in 0..nf {
                        let k = if swap {
                            // K̂_yy(k_x, k_y) = K̂_xx(k_y, k_x); even in its second index.
                            let ky = if ki <= n { ki } else { nf - ki };
                            ky * nf + kj
                        } else {
                            kj * nf + ki
                        };
                        spec[kj * nf + ki] = kspec[k] * self.spectrum[kj * nf + ki] * norm;
                    }
                }
                self.fft.inverse(&mut spec, &mut rows)?;
                let mut field = vec![0.0; n * n];
                for i in 0..n {
                    field[i * n..(i + 1) * n].copy_from_slice(&rows[i * nf..i * nf + n]);
                }
                out[target] = field;
            }
        }
        Ok(out)
    }

    /// Free stress at one node by the direct sum over the loaded cells.
    fn free_point(&self, node: [usize; 2], z: f64) -> Tensor {
        let n = self.n;
        let d = self.size / n as f64;
        let mut acc = [0.0; COMPONENTS];
        for (k, &p) in self.pressure.iter().enumerate() {
            if p == 0.0 {
                continue;
            }
            let (x, y) = (
                (node[0] as f64 - (k / n) as f64) * d,
                (node[1] as f64 - (k % n) as f64) * d,
            );
            let s = green::unit_cell(x, y, z, d, self.poisson);
            for c in 0..COMPONENTS {
                acc[c] += p * s[c];
            }
        }
        acc
    }
}
