//! How a stress distribution was evaluated, as data: which representation
//! gave the density (start condition, sine series, image sum and its
//! quadrature) and which gave each fraction (closed form, power series,
//! quadrature, sine series, image sum), with their sizes (terms, images,
//! nodes). Every result of [`super::Solver`] carries one; its
//! [`std::fmt::Display`] is the one-line description for people, its JSON
//! form the same facts as tagged objects (`{"kind": "sine_series", "terms": 12}`).

use std::fmt;

use serde::Serialize;

/// "1 image", "3 images".
fn count(n: usize, one: &str, many: &str) -> String {
    format!("{n} {}", if n == 1 { one } else { many })
}

/// How the image kernel Q(x) = ∫₀¹ P0(u)[φ(x − u) − φ(x + u)] du is evaluated.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
#[non_exhaustive]
pub enum ImageQuadrature {
    /// In closed form (flat start; Hertz start up to w = 2).
    ClosedForm,
    /// One Gauss–Legendre rule over the support (Hertz start, w > 2).
    GaussLegendre {
        /// Nodes of the rule.
        nodes: usize,
    },
    /// One Gauss–Legendre rule in s = sin θ (cylinder start, wide kernel).
    GaussLegendreSine {
        /// Nodes of the rule.
        nodes: usize,
    },
    /// Gauss–Legendre/Gauss–Jacobi rules on the window |s − u| ≤ L w
    /// (cylinder start, narrow kernel).
    WindowedGauss {
        /// L, the window's half-width in units of w.
        window_half_width: f64,
    },
    /// Adaptive Gauss–Kronrod on each segment (tabulated start).
    AdaptiveGaussKronrod,
}

impl fmt::Display for ImageQuadrature {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ImageQuadrature::ClosedForm => write!(f, "closed-form images"),
            ImageQuadrature::GaussLegendre { nodes } => {
                write!(f, "quadrature images (Gauss-Legendre, {nodes} nodes)")
            }
            ImageQuadrature::GaussLegendreSine { nodes } => write!(
                f,
                "quadrature images (Gauss-Legendre in s = sin θ, {nodes} nodes)"
            ),
            ImageQuadrature::WindowedGauss { window_half_width } => write!(
                f,
                "quadrature images (windowed Gauss-Legendre/Gauss-Jacobi, |s - u| <= {window_half_width:.2} w)"
            ),
            ImageQuadrature::AdaptiveGaussKronrod => {
                write!(f, "quadrature images (adaptive Gauss-Kronrod per segment)")
            }
        }
    }
}

/// How the density P(s) is evaluated.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
#[non_exhaustive]
pub enum DensityMethod {
    /// G = 0: the start condition itself.
    StartCondition,
    /// The Fourier sine series (finite σY).
    SineSeries {
        /// Terms of the series.
        terms: usize,
    },
    /// The method of images: one absorbing wall at σ = 0 (elastic) or two
    /// (σ = 0 and σ = σY).
    ImageSum {
        /// 1 (elastic) or 2 (with a yield stress).
        walls: usize,
        /// How each image is evaluated.
        quadrature: ImageQuadrature,
        /// With two walls: the most images any density value of a curve
        /// needed (`None` before a curve is evaluated, and with one wall).
        #[serde(skip_serializing_if = "Option::is_none")]
        images: Option<usize>,
    },
}

impl fmt::Display for DensityMethod {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            DensityMethod::StartCondition => write!(f, "start condition (G = 0)"),
            DensityMethod::SineSeries { terms } => write!(f, "sine series ({terms} terms)"),
            DensityMethod::ImageSum {
                walls,
                quadrature,
                images,
            } => {
                if *walls > 1 {
                    write!(f, "image sum (two walls), ")?;
                }
                write!(f, "{quadrature}")?;
                match images {
                    Some(k) => write!(f, " (at most {})", count(*k, "image", "images")),
                    None => Ok(()),
                }
            }
        }
    }
}

/// How one fraction (A_el/A0 or A_pl/A0) is evaluated.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
#[non_exhaustive]
pub enum FractionMethod {
    /// G = 0: the start condition (A_el/A0 = 1, A_pl/A0 = 0).
    StartCondition,
    /// The erf closed form of A∞ (flat start; Hertz for a narrow kernel).
    ErfClosedForm,
    /// A power series of A∞ (Hertz for a wide kernel, cylinder).
    PowerSeries,
    /// Adaptive Gauss–Kronrod quadrature of A∞ (cylinder, tabulated starts).
    AdaptiveQuadrature,
    /// The sine series (finite σY).
    SineSeries {
        /// Terms of the series.
        terms: usize,
    },
    /// The sum over images of two absorbing walls (finite σY).
    ImageSum {
        /// Images summed.
        images: usize,
    },
}

impl fmt::Display for FractionMethod {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            FractionMethod::StartCondition => write!(f, "start condition"),
            FractionMethod::ErfClosedForm => write!(f, "erf closed form"),
            FractionMethod::PowerSeries => write!(f, "power series"),
            FractionMethod::AdaptiveQuadrature => write!(f, "adaptive quadrature"),
            FractionMethod::SineSeries { terms } => write!(f, "sine series ({terms} terms)"),
            FractionMethod::ImageSum { images } => {
                write!(f, "image sum ({})", count(*images, "image", "images"))
            }
        }
    }
}

/// How both fractions are evaluated: A_el/A0 (the contact fraction when
/// elastic) and, with a yield stress, A_pl/A0.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[non_exhaustive]
pub struct FractionMethods {
    /// How A_el/A0 is evaluated.
    pub elastic_fraction: FractionMethod,
    /// How A_pl/A0 is evaluated (`None`: elastic or G = 0, A_pl/A0 = 0 exactly).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub plastic_fraction: Option<FractionMethod>,
}

impl fmt::Display for FractionMethods {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match (self.elastic_fraction, self.plastic_fraction) {
            (FractionMethod::StartCondition, _) => write!(f, "start condition"),
            (el, None) => write!(f, "contact fraction: {el}"),
            (el, Some(pl)) => write!(f, "contact fraction: {el}; plastic fraction: {pl}"),
        }
    }
}

/// How a stress curve was evaluated: its density and both fractions.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[non_exhaustive]
pub struct StressMethod {
    /// How the density values are evaluated.
    pub density: DensityMethod,
    /// How the fractions are evaluated.
    #[serde(flatten)]
    pub fractions: FractionMethods,
}

impl fmt::Display for StressMethod {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "density: {}; {}", self.density, self.fractions)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The descriptions for people, one per representation, and the tagged
    /// JSON of one of them.
    #[test]
    fn descriptions_and_tags() {
        let m = StressMethod {
            density: DensityMethod::ImageSum {
                walls: 2,
                quadrature: ImageQuadrature::ClosedForm,
                images: Some(3),
            },
            fractions: FractionMethods {
                elastic_fraction: FractionMethod::SineSeries { terms: 12 },
                plastic_fraction: Some(FractionMethod::ImageSum { images: 1 }),
            },
        };
        assert_eq!(
            m.to_string(),
            "density: image sum (two walls), closed-form images (at most 3 images); \
             contact fraction: sine series (12 terms); plastic fraction: image sum (1 image)"
        );
        let json = serde_json::to_value(m).unwrap();
        assert_eq!(json["density"]["kind"], "image_sum");
        assert_eq!(json["density"]["quadrature"]["kind"], "closed_form");
        assert_eq!(json["elastic_fraction"]["terms"], 12);
        assert_eq!(json["plastic_fraction"]["images"], 1);
        let elastic = FractionMethods {
            elastic_fraction: FractionMethod::ErfClosedForm,
            plastic_fraction: None,
        };
        assert_eq!(elastic.to_string(), "contact fraction: erf closed form");
        assert_eq!(
            ImageQuadrature::WindowedGauss {
                window_half_width: 6.2345
            }
            .to_string(),
            "quadrature images (windowed Gauss-Legendre/Gauss-Jacobi, |s - u| <= 6.23 w)"
        );
    }
}
