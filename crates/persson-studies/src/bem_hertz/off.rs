//! The study `bem_hertz` in a build without the feature `bem`: refused.

use std::path::Path;

use persson::error::Result;

use super::BemHertzOutput;
use crate::output::Files;

pub use crate::study::Unavailable as Report;

pub fn bem_hertz(_: &BemHertzOutput) -> Result<Report> {
    Err(crate::study::unavailable("bem_hertz", "bem"))
}

pub fn warnings(r: &Report) -> Vec<crate::warning::Warning> {
    match *r {}
}

pub fn write(_: &BemHertzOutput, r: &Report, _: &Path, _: &mut Files) -> Result<()> {
    match *r {}
}
