//! The friction problem: one spectrum, one rubber, γ, the tolerance and the
//! resolved cut-off, validated by [`Friction::new`](super::Friction::new) in
//! `theory.rs` and read by the panel march (`march.rs`). A leaf of the
//! friction module, so that the march does not depend on the theory that
//! drives it.

use super::angular::AngularModel;
use super::rubber::Rubber;
use crate::spectrum::Spectrum;

/// Persson's rubber-friction theory for one spectrum and one rubber.
///
/// See the [module documentation](super) for the equations, the method and
/// the references.
pub struct Friction<'a> {
    pub(crate) spectrum: &'a dyn Spectrum,
    pub(crate) rubber: &'a Rubber,
    pub(crate) gamma: f64,
    pub(crate) tolerance: f64,
    pub(crate) q1: f64,
    pub(crate) breaks: Vec<f64>,
    pub(crate) points_per_decade: usize,
    pub(crate) angular: AngularModel<'a>,
    /// ln ω_i of a master curve (empty for a Prony series).
    pub(crate) table_ln: Vec<f64>,
}
