//! κ of the linear low-load law A/A0 = κ σ0 / (E* √⟨|∇h|²⟩).

/// The proportionality constant of the low-load contact area.
///
/// # Formula
/// ```text
/// A/A0 = κ σ0 / (E* √⟨|∇h|²⟩),  κ_Bush = √(2π) ≈ 2.5066,  κ_Persson = √(8/π) ≈ 1.5958
/// ```
/// Persson's value is the G → ∞ limit of erf(1/(2√G)) = (πG)^{−1/2}
/// (Persson, Bucher & Chiaia, Phys. Rev. B 65, 184106 (2002), Eq. 4, Sec. IV); numerical (BEM/GFMD) results lie between the two,
/// about 2 (Campañá & Müser, EPL 77, 38005 (2007), doi:10.1209/0295-5075/77/38005).
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Kappa {
    /// Bush, Gibson & Thomas, Wear 35, 87 (1975): √(2π).
    Bush,
    /// Persson, J. Chem. Phys. 115, 3840 (2001): √(8/π).
    Persson,
}

impl Kappa {
    /// The value of κ.
    ///
    /// # Examples
    /// ```
    /// use persson::kappa::Kappa;
    /// assert!((Kappa::Bush.value() - 2.5066282746310002).abs() < 1e-15);
    /// ```
    pub fn value(self) -> f64 {
        match self {
            Kappa::Bush => (2.0 * std::f64::consts::PI).sqrt(),
            Kappa::Persson => (8.0 / std::f64::consts::PI).sqrt(),
        }
    }

    /// κ σ0 / (E* rms slope), the linear-regime contact fraction (not capped at 1).
    pub fn linear_fraction(self, pressure: f64, contact_modulus: f64, rms_slope: f64) -> f64 {
        self.value() * pressure / (contact_modulus * rms_slope)
    }

    /// [`Kappa::linear_fraction`], refused where it (or Bush's, the larger)
    /// overflows f64: σ0/E* ≤ f64::MAX h'_rms/√(2π).
    ///
    /// # Errors
    /// [`crate::Error::InvalidParameter`] naming `nominal_pressure`, or
    /// `contact_modulus` when E* is beyond 1e±30, with that bound.
    ///
    /// # Examples
    /// ```
    /// use persson::kappa::Kappa;
    /// assert!(Kappa::Persson.checked_linear_fraction(1e6, 1e9, 0.1).is_ok());
    /// let e = Kappa::Bush.checked_linear_fraction(1e7, 1e-300, 0.1).unwrap_err();
    /// assert!(e.to_string().contains("contact_modulus"));
    /// ```
    pub fn checked_linear_fraction(
        self,
        pressure: f64,
        contact_modulus: f64,
        rms_slope: f64,
    ) -> crate::Result<f64> {
        check_linear_laws(contact_modulus, pressure, rms_slope)?;
        Ok(self.linear_fraction(pressure, contact_modulus, rms_slope))
    }
}

/// Refuse a σ0/E* for which the linear laws κ σ0/(E* h'_rms) beside A/A0
/// overflow (E* = 1e-300 at σ0 = 1e7 gave A/A0 Bush linear = ∞).
///
/// # Bound
/// κ σ0/(E* h'_rms) ≤ f64::MAX for κ ≤ κ_Bush = √(2π) (the larger κ):
/// σ0/E* ≤ f64::MAX h'_rms/√(2π), tested as the law itself evaluates.
///
/// # Errors
/// [`crate::Error::InvalidParameter`] naming `nominal_pressure`, or
/// `contact_modulus` when E* is beyond 1e±30 ([`crate::error::ratio_culprit`]).
pub(crate) fn check_linear_laws(
    contact_modulus: f64,
    pressure: f64,
    rms_slope: f64,
) -> crate::Result<()> {
    // h'_rms = 0 (ζ = 1: no roughness resolved yet) leaves the laws
    // undefined, not overflowing: that point keeps its +∞ as before
    if rms_slope <= 0.0
        || Kappa::Bush
            .linear_fraction(pressure, contact_modulus, rms_slope)
            .is_finite()
    {
        return Ok(());
    }
    let ratio = f64::MAX / Kappa::Bush.value() * rms_slope;
    let why = format!(
        "so that the linear laws κ σ0/(E* h'_rms) (h'_rms = {}) stay finite in f64",
        crate::error::approx(rms_slope)
    );
    Err(
        match crate::error::ratio_culprit(contact_modulus, pressure) {
            "contact_modulus" => crate::Error::invalid(
                "contact_modulus",
                contact_modulus,
                format!(
                    "at least {} (σ0 = {}) {why}",
                    crate::error::approx(pressure / ratio),
                    crate::error::num(pressure)
                ),
            ),
            _ => crate::Error::invalid(
                "nominal_pressure",
                pressure,
                format!(
                    "at most {} (E* = {}) {why}",
                    crate::error::approx(ratio * contact_modulus),
                    crate::error::num(contact_modulus)
                ),
            ),
        },
    )
}
