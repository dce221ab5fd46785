//! The study `bem_adhesion` in a build without the feature `bem`: refused.

use persson::error::Result;

use super::spec::BemAdhesionOutput;
use crate::study::{unavailable, Context};

pub use crate::study::Unavailable as Report;

pub fn bem_adhesion(_: &Context<'_>, _: &BemAdhesionOutput) -> Result<Report> {
    Err(unavailable("bem_adhesion", "bem"))
}

pub fn warnings(r: &Report) -> Vec<crate::warning::Warning> {
    match *r {}
}
