//! The free half-space's 2N × 2N circulant and its exact inverse, applied
//! on the whole padded grid: the operator of the gap-based (adhesive)
//! iteration on the free boundary.

use super::{love_cell, signed};
use crate::bem::fft::Fft2;
use crate::error::Result;

/// The free half-space on the 2N × 2N circulant of Love's cell kernel
/// (the matrix that [`Boundary::Free`](super::Boundary::Free)'s operator embeds), applied on the
/// whole padded grid, and its exact inverse.
///
/// # Why the padded grid
/// The gap formulation needs the stiffness 𝒦 = 𝒢⁻¹. Of the free operator
/// only the N × N window block is physical, and its inverse is not a
/// convolution. On the padded grid the circulant C is positive definite
/// (its multiplier is positive) and C⁻¹ is one FFT convolution; the nodes
/// outside the window carry a displacement but no pressure (they never
/// touch and do not attract): the stationarity of Π in those displacements
/// is p = C⁻¹u = 0 there, so the window pressures p produce u = 𝒢p exactly
/// (the DC-FFT of Liu, Wang & Liu, Wear 243, 101 (2000), read backwards).
#[derive(Debug)]
pub(crate) struct Padded {
    m: usize,
    fft: Fft2,
    /// C's multiplier, `(m/2 + 1) × m` (column k_j, then k_i), times 1/m².
    compliance: Vec<f64>,
}

impl Padded {
    pub(crate) fn new(n: usize, size: f64, e_star: f64) -> Result<Self> {
        let m = 2 * n;
        let mut fft = Fft2::new(m, m)?;
        let c = size / n as f64 / (std::f64::consts::PI * e_star);
        let norm = 1.0 / (m as f64 * m as f64);
        let mut compliance = vec![0.0; fft.nc() * m];
        fft.convolve(
            &mut |i, row| {
                let si = signed(i, m) as f64;
                for (j, v) in row.iter_mut().enumerate() {
                    *v = c * love_cell(si, signed(j, m) as f64);
                }
            },
            &mut |kj, col| {
                for (ki, z) in col.iter().enumerate() {
                    compliance[kj * m + ki] = z.re * norm;
                }
            },
            None,
        );
        Ok(Padded { m, fft, compliance })
    }

    /// y = C x (`stiffness` false) or C⁻¹ x, on the m × m grid.
    pub(crate) fn apply(&mut self, stiffness: bool, x: &[f64], y: &mut [f64]) -> Result<()> {
        let m = self.m;
        self.apply_rows(
            stiffness,
            &mut |i, row| row.copy_from_slice(&x[i * m..(i + 1) * m]),
            &mut |i, row| y[i * m..(i + 1) * m].copy_from_slice(row),
        )
    }

    /// [`Padded::apply`] row by row: `fill(i, row)` writes row i of x, then
    /// `emit(i, row)` receives row i of y.
    pub(crate) fn apply_rows(
        &mut self,
        stiffness: bool,
        fill: &mut dyn FnMut(usize, &mut [f64]),
        emit: &mut dyn FnMut(usize, &[f64]),
    ) -> Result<()> {
        let m = self.m;
        let norm = 1.0 / (m as f64 * m as f64);
        let c = &self.compliance;
        self.fft.convolve(
            fill,
            &mut |kj, col| {
                let mk = &c[kj * m..(kj + 1) * m];
                if stiffness {
                    for (z, v) in col.iter_mut().zip(mk) {
                        *z *= norm * norm / v;
                    }
                } else {
                    for (z, v) in col.iter_mut().zip(mk) {
                        *z *= v;
                    }
                }
            },
            Some(emit),
        );
        Ok(())
    }
}
