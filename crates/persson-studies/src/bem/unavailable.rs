//! The study `bem` in a build without the feature `bem`: refused.

use std::path::Path;

use persson::error::Result;

use super::spec::BemOutput;
use crate::output::Files;
use crate::study::{unavailable, Context};

pub use crate::study::Unavailable as Report;

pub fn run(_: &Context<'_>, _: &BemOutput) -> Result<Report> {
    Err(unavailable("bem", "bem"))
}

pub fn warnings(r: &Report) -> Vec<crate::warning::Warning> {
    match *r {}
}

pub fn entries<M: serde::ser::SerializeMap>(r: &Report, _: &mut M) -> Result<(), M::Error> {
    match *r {}
}

pub fn write(_: &BemOutput, r: &Report, _: &Context<'_>, _: &Path, _: &mut Files) -> Result<()> {
    match *r {}
}
