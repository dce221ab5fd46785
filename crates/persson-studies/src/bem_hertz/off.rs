//! The study `bem_hertz` in a build without the feature `bem`: refused.

use persson::error::Result;

use super::{BemHertzOutput, BemHertzReport};

pub fn bem_hertz(_: &BemHertzOutput) -> Result<BemHertzReport> {
    Err(crate::study::unavailable("bem_hertz", "bem"))
}
