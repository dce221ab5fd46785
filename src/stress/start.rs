//! Start conditions P0(σ) = P(σ, ζ = 1): flat punch, Hertz ball, cylinder, table.
//!
//! All starts are stored dimensionless: s = σ/σH with σH the largest pressure
//! in the nominal contact (the Hertz peak pressure; σH = σ0 for the flat
//! punch; the last abscissa of a table), and densities in units of 1/σH.

use crate::error::{check, Error, Result};
use crate::reference::{Ball, Cylinder};

/// A start condition P0(s), s = σ/σH.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum Start {
    /// Flat punch: P0 = δ(s − 1), σ0 = σH.
    Flat,
    /// Hertz ball: P0 = 2s for s < 1 (Persson, Bucher & Chiaia, Phys. Rev. B 65,
    /// 184106 (2002), Eq. 9), σ0 = 2σH/3.
    Hertz,
    /// Cylinder: P0 = s (1 − s²)^{−1/2} for s < 1 (Persson, Bucher & Chiaia,
    /// Phys. Rev. B 65, 184106 (2002), Eq. 12), σ0 = πσH/4.
    Cylinder,
    /// A tabulated, piecewise linear P0.
    Tabulated(TabulatedStart),
}

impl Start {
    /// The start named `flat`, `hertz` or `cylinder`.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for any other name.
    pub fn from_name(name: &str) -> Result<Self> {
        match name {
            "flat" => Ok(Start::Flat),
            "hertz" | "ball" => Ok(Start::Hertz),
            "cylinder" => Ok(Start::Cylinder),
            _ => Err(Error::Inconsistent {
                name: "start".into(),
                requirement: format!("one of flat, hertz, cylinder (got `{name}`)"),
            }),
        }
    }

    /// Short name: that of its [`StartKind`].
    pub fn name(&self) -> &'static str {
        self.kind().name()
    }

    /// Which start this is, without its data.
    pub fn kind(&self) -> StartKind {
        match self {
            Start::Flat => StartKind::Flat,
            Start::Hertz => StartKind::Hertz,
            Start::Cylinder => StartKind::Cylinder,
            Start::Tabulated(_) => StartKind::Tabulated,
        }
    }

    /// σ0/σH, the mean pressure in units of the peak pressure.
    ///
    /// # Formula
    /// ```text
    /// σ0/σH = ∫ s P0(s) ds:  flat 1, Hertz 2/3, cylinder π/4
    /// ```
    pub fn mean_ratio(&self) -> f64 {
        match self {
            Start::Flat => 1.0,
            Start::Hertz => 2.0 / 3.0,
            Start::Cylinder => std::f64::consts::FRAC_PI_4,
            Start::Tabulated(t) => t.mean,
        }
    }

    /// P0(s) in units of 1/σH (0 for the flat start, whose P0 is a δ).
    pub fn density(&self, s: f64) -> f64 {
        match self {
            Start::Flat => 0.0,
            Start::Hertz => {
                if (0.0..1.0).contains(&s) {
                    2.0 * s
                } else {
                    0.0
                }
            }
            Start::Cylinder => {
                if (0.0..1.0).contains(&s) {
                    s / ((1.0 - s) * (1.0 + s)).sqrt()
                } else {
                    0.0
                }
            }
            Start::Tabulated(t) => t.eval(s),
        }
    }
}

/// The kind of a [`Start`], a label from a closed set: serialised and
/// displayed as `flat`, `hertz`, `cylinder` or `tabulated`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, serde::Serialize)]
#[serde(rename_all = "lowercase")]
#[non_exhaustive]
pub enum StartKind {
    /// [`Start::Flat`].
    Flat,
    /// [`Start::Hertz`].
    Hertz,
    /// [`Start::Cylinder`].
    Cylinder,
    /// [`Start::Tabulated`].
    Tabulated,
}

impl StartKind {
    /// The label: `flat`, `hertz`, `cylinder` or `tabulated`.
    pub fn name(self) -> &'static str {
        match self {
            StartKind::Flat => "flat",
            StartKind::Hertz => "hertz",
            StartKind::Cylinder => "cylinder",
            StartKind::Tabulated => "tabulated",
        }
    }
}

impl std::fmt::Display for StartKind {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// A tabulated start density, piecewise linear between the points, zero beyond
/// the last one.
#[derive(Debug, Clone, PartialEq)]
pub struct TabulatedStart {
    /// Abscissae s = σ/σH, ascending, last = 1.
    pub(crate) s: Vec<f64>,
    /// Densities in 1/σH.
    pub(crate) p: Vec<f64>,
    /// σ0/σH.
    pub(crate) mean: f64,
    /// σH in the user's unit.
    pub(crate) peak: f64,
}

impl TabulatedStart {
    /// A start from pressures `sigma` (any unit, ascending, ≥ 0) and densities
    /// `density` (1/that unit), normalised to 1 within `tol`.
    ///
    /// # Formula
    /// ```text
    /// σH = σ_last,   s = σ/σH,   ∫ P0 dσ = Σ (σᵢ₊₁ − σᵢ)(Pᵢ + Pᵢ₊₁)/2 = 1 ± tol
    /// ```
    /// The table is scaled by 1/∫P0 so that it is exactly normalised.
    ///
    /// # Errors
    /// Fewer than two points, lengths differ, σ not ascending/finite/≥ 0,
    /// a density negative or non-finite, or ∫P0 dσ ≠ 1 within `tol`; `tol`
    /// outside [1e-15, 0.1] (named `table_normalisation`, the option that
    /// sets it).
    pub fn new(sigma: &[f64], density: &[f64], tol: f64) -> Result<Self> {
        check::tolerance("table_normalisation", tol)?;
        if sigma.len() < 2 || sigma.len() != density.len() {
            return Err(Error::Inconsistent {
                name: "start table".into(),
                requirement: format!(
                    "at least two points and as many densities as pressures (got {} and {})",
                    sigma.len(),
                    density.len()
                ),
            });
        }
        for (i, &v) in sigma.iter().enumerate() {
            check::non_negative("start pressure", v)?;
            if i > 0 && v <= sigma[i - 1] {
                return Err(Error::invalid(
                    "start pressure",
                    v,
                    format!(
                        "strictly greater than the previous one ({:e})",
                        sigma[i - 1]
                    ),
                ));
            }
        }
        for &p in density {
            check::non_negative("start density", p)?;
        }
        let peak = sigma[sigma.len() - 1];
        let mut norm = 0.0;
        for i in 1..sigma.len() {
            norm += 0.5 * (sigma[i] - sigma[i - 1]) * (density[i] + density[i - 1]);
        }
        if (norm - 1.0).abs() > tol || norm.is_nan() {
            return Err(Error::Inconsistent {
                name: "start density".into(),
                requirement: format!("must integrate to 1 within {tol:e} (integral = {norm})"),
            });
        }
        let s: Vec<f64> = sigma.iter().map(|v| v / peak).collect();
        let p: Vec<f64> = density.iter().map(|v| v * peak / norm).collect();
        let mut mean = 0.0;
        for i in 1..s.len() {
            let (a, b, pa, pb) = (s[i - 1], s[i], p[i - 1], p[i]);
            // ∫ s (linear) ds over a segment, exact: (b − a)(pa(2a + b) + pb(a + 2b))/6
            mean += (b - a) * (pa * (2.0 * a + b) + pb * (a + 2.0 * b)) / 6.0;
        }
        Ok(TabulatedStart { s, p, mean, peak })
    }

    /// σH, the largest tabulated pressure (user's unit).
    pub fn peak_pressure(&self) -> f64 {
        self.peak
    }

    /// P0(s) by linear interpolation (1/σH).
    pub fn eval(&self, s: f64) -> f64 {
        let n = self.s.len();
        if !(s >= self.s[0] && s <= self.s[n - 1]) {
            return 0.0;
        }
        let i = self.s.partition_point(|&v| v <= s).clamp(1, n - 1);
        let (a, b) = (self.s[i - 1], self.s[i]);
        let t = (s - a) / (b - a);
        self.p[i - 1] + t * (self.p[i] - self.p[i - 1])
    }

    /// Segments (a, b) of the table.
    pub(crate) fn segments(&self) -> impl Iterator<Item = (f64, f64)> + '_ {
        self.s.windows(2).map(|w| (w[0], w[1]))
    }
}

/// The macroscopic (Hertz) contact of a body on a nominally flat substrate:
/// the start condition with its peak pressure σH, mean pressure σ0 and size.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct HertzContact {
    /// The start condition.
    pub start: Start,
    /// σH, peak pressure (Pa).
    pub peak_pressure: f64,
    /// σ0, mean pressure over the nominal contact (Pa).
    pub nominal_pressure: f64,
    /// Contact radius a (ball) or half-width a (cylinder), m.
    pub contact_radius: f64,
}

impl HertzContact {
    /// A ball of radius `radius` (m) pressed with `load` (N) on E* (Pa): the
    /// start of [`crate::reference::Ball::from_load`].
    ///
    /// # Formula
    /// ```text
    /// a = (3 F R / (4 E*))^{1/3},   σH = 3F/(2π a²),   σ0 = F/(π a²) = 2σH/3
    /// ```
    /// # Errors
    /// Any argument not finite and positive.
    ///
    /// # References
    /// K. L. Johnson, *Contact Mechanics* (CUP 1985), Eqs. 4.22–4.24.
    ///
    /// # Examples
    /// ```
    /// let c = persson::stress::HertzContact::ball(0.01, 10.0, 1e9).unwrap();
    /// assert!((c.nominal_pressure / c.peak_pressure - 2.0 / 3.0).abs() < 1e-15);
    /// assert!((c.contact_radius / 4.217163326508746e-4 - 1.0).abs() < 1e-14);
    /// ```
    pub fn ball(radius: f64, load: f64, contact_modulus: f64) -> Result<Self> {
        let b = Ball::from_load(radius, load, contact_modulus)?;
        Ok(HertzContact {
            start: Start::Hertz,
            peak_pressure: b.peak_pressure,
            nominal_pressure: b.nominal_pressure(),
            contact_radius: b.contact_radius,
        })
    }

    /// A cylinder of radius `radius` (m) pressed with `load_per_length` (N/m):
    /// the start of [`crate::reference::Cylinder::from_load_per_length`].
    ///
    /// # Formula
    /// ```text
    /// a = (4 F' R / (π E*))^{1/2},   σH = 2F'/(π a),   σ0 = F'/(2a) = πσH/4
    /// ```
    /// # Errors
    /// Any argument not finite and positive.
    ///
    /// # References
    /// K. L. Johnson, *Contact Mechanics* (CUP 1985), Eqs. 4.43–4.45.
    pub fn cylinder(radius: f64, load_per_length: f64, contact_modulus: f64) -> Result<Self> {
        let c = Cylinder::from_load_per_length(radius, load_per_length, contact_modulus)?;
        Ok(HertzContact {
            start: Start::Cylinder,
            peak_pressure: c.peak_pressure,
            nominal_pressure: c.nominal_pressure(),
            contact_radius: c.half_width,
        })
    }
}
