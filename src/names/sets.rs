//! The closed sets of the optional modules: the BEM's boundary, patch
//! connectivity and cohesive law (feature `bem`), a measured surface's
//! detrending and window (feature `topography`). They are declared here, at
//! every feature setting, so that a scene names them whatever the build;
//! each is re-exported where its module uses it (`bem::Boundary`,
//! `topography::Window`), which also holds its methods.

use super::{named, Named};
use crate::error::{Error, Result};

/// Boundary condition of the elastic half-space at the edges of the grid.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Boundary {
    /// The grid is one period of an infinite periodic system.
    Periodic,
    /// The grid is a window of an infinite half-space, loaded only inside it.
    Free,
}

named! {
    Boundary, "boundary", "Boundary condition of the FFT-BEM." {
        Periodic = "periodic": "Periodic surface (the rough-contact default).",
        Free = "free": "Free (non-periodic) surface, zero-padded (the Hertz default).",
    }
}

impl std::str::FromStr for Boundary {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self> {
        Boundary::from_name(s).ok_or_else(|| Error::Inconsistent {
            name: "boundary".into(),
            requirement: format!("one of {}; got {s:?}", listed::<Boundary>()),
        })
    }
}

/// Which neighbours join cells into one patch.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Connectivity {
    /// Edge neighbours only.
    #[default]
    Four,
    /// Edge and corner neighbours.
    Eight,
}

named! {
    Connectivity, "connectivity", "Neighbourhood of a contact patch." {
        Four = "four": "Edge neighbours only.",
        Eight = "eight": "Edge and corner neighbours.",
    }
}

/// Which cohesive law of the adhesive BEM, by name (its parameters apart):
/// `bem::adhesive::CohesiveLaw`'s variants.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum LawKind {
    /// Maugis–Dugdale: constant attraction Δγ/ρ for gaps below ρ.
    #[default]
    Maugis,
    /// Exponential: attraction (Δγ/ρ) e^{−g/ρ}.
    Exponential,
}

named! {
    LawKind, "adhesion_law", "Cohesive law of the adhesive FFT-BEM." {
        Maugis = "maugis": "Maugis–Dugdale: attraction Δγ/ρ for gaps below ρ.",
        Exponential = "exponential": "Exponential: attraction (Δγ/ρ) e^{−g/ρ}.",
    }
}

/// The least-squares trend removed before the spectrum and the statistics.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Detrend {
    /// Heights as they are.
    None,
    /// The mean height.
    Mean,
    /// The least-squares plane (tilt and offset); a line per profile for line scans.
    Plane,
    /// The least-squares quadratic (`x², xy, y²` as well); per profile for line scans.
    Curvature,
}

named! {
    Detrend, "detrend", "Least-squares detrending of a measured surface." {
        None = "none": "Heights as they are.",
        Mean = "mean": "The mean height.",
        Plane = "plane": "The least-squares plane.",
        Curvature = "curvature": "The least-squares quadratic.",
    }
}

impl std::str::FromStr for Detrend {
    type Err = String;
    fn from_str(s: &str) -> std::result::Result<Self, String> {
        named_or_message(s)
    }
}

/// The window applied before the Fourier transform.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Window {
    /// No window (periodic surfaces).
    None,
    /// Hann (raised cosine).
    Hann,
    /// Blackman (lower side lobes, wider main lobe).
    Blackman,
}

named! {
    Window, "window", "Window applied before the spectrum of a measured surface." {
        None = "none": "No window.",
        Hann = "hann": "Radial Hann window.",
        Blackman = "blackman": "Radial Blackman window.",
    }
}

impl std::str::FromStr for Window {
    type Err = String;
    fn from_str(s: &str) -> std::result::Result<Self, String> {
        named_or_message(s)
    }
}

/// `T` by its name, or a message naming the set and its names
/// (`unknown window "hamming": one of none, hann, blackman`).
fn named_or_message<T: Named>(s: &str) -> std::result::Result<T, String> {
    T::from_name(s).ok_or_else(|| format!("unknown {} {s:?}: one of {}", T::SET, listed::<T>()))
}

/// `a, b, c`: the names of `T`.
fn listed<T: Named>() -> String {
    T::names().collect::<Vec<_>>().join(", ")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_name_parses_and_an_unknown_one_lists_the_set() {
        assert_eq!("hann".parse::<Window>(), Ok(Window::Hann));
        assert_eq!("curvature".parse::<Detrend>(), Ok(Detrend::Curvature));
        assert_eq!(
            "hamming".parse::<Window>(),
            Err("unknown window \"hamming\": one of none, hann, blackman".to_string())
        );
        assert_eq!(
            "cubic".parse::<Detrend>(),
            Err("unknown detrend \"cubic\": one of none, mean, plane, curvature".to_string())
        );
        assert!("torus".parse::<Boundary>().is_err());
    }
}
