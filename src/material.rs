//! Elastic materials and the contact modulus E*.

use crate::error::{check, Result};

/// One elastic body: Young's modulus E \[Pa\] and Poisson ratio ν ∈ (−1, 0.5].
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Body {
    /// Young's modulus E, Pa.
    pub young: f64,
    /// Poisson ratio ν.
    pub poisson: f64,
}

impl Body {
    /// `(1 − ν²)/E`, the body's compliance contribution to 1/E*; 0 for a
    /// rigid body. Errors name the fields `young{suffix}`, `poisson{suffix}`.
    fn compliance(&self, suffix: &str) -> Result<f64> {
        if self.young == f64::INFINITY {
            return Ok(0.0);
        }
        check::positive(&format!("young{suffix}"), self.young)?;
        check_poisson(&format!("poisson{suffix}"), self.poisson)?;
        Ok((1.0 - self.poisson * self.poisson) / self.young)
    }
}

/// A Poisson ratio ν ∈ (−1, 0.5] (thermodynamic stability of an isotropic
/// solid: bulk and shear moduli positive), the one check of every ν.
///
/// # Errors
/// [`crate::Error::InvalidParameter`] naming `name`.
pub fn check_poisson(name: &str, poisson: f64) -> Result<f64> {
    if poisson.is_finite() && poisson > -1.0 && poisson <= 0.5 {
        Ok(poisson)
    } else {
        Err(crate::Error::invalid(name, poisson, "in (-1, 0.5]"))
    }
}

/// The contact modulus E* of a frictionless contact.
///
/// # Formula
/// ```text
/// 1/E* = (1 − ν₁²)/E₁ + (1 − ν₂²)/E₂        (E₂ = ∞: a rigid counter-body)
/// ```
/// All results of the theory depend on the materials through E* only
/// (the crate docs, Conventions; docs/conventions.md).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Material {
    contact_modulus: f64,
}

impl Material {
    /// E* given directly, Pa (or any pressure unit used consistently).
    ///
    /// # Errors
    /// `contact_modulus` not finite and positive.
    pub fn new(contact_modulus: f64) -> Result<Self> {
        Ok(Material {
            contact_modulus: check::positive("contact_modulus", contact_modulus)?,
        })
    }

    /// One elastic body against a rigid one: E* = E/(1 − ν²).
    ///
    /// # Errors
    /// E not finite and positive, ν outside (−1, 0.5].
    ///
    /// # Examples
    /// ```
    /// let m = persson::Material::from_body(persson::material::Body { young: 3.0, poisson: 0.5 }).unwrap();
    /// assert!((m.contact_modulus() - 4.0).abs() < 1e-15);
    /// ```
    pub fn from_body(body: Body) -> Result<Self> {
        Self::from_bodies(
            body,
            Body {
                young: f64::INFINITY,
                poisson: 0.0,
            },
        )
    }

    /// Two elastic bodies.
    ///
    /// # Errors
    /// As [`Material::from_body`] for either body (the second's fields named
    /// `young2`, `poisson2`); both rigid.
    pub fn from_bodies(a: Body, b: Body) -> Result<Self> {
        let c = a.compliance("")? + b.compliance("2")?;
        if c <= 0.0 {
            return Err(crate::Error::invalid(
                "young",
                f64::INFINITY,
                "finite for at least one body",
            ));
        }
        Self::new(1.0 / c)
    }

    /// E*, in the unit of the moduli given.
    pub fn contact_modulus(&self) -> f64 {
        self.contact_modulus
    }
}
