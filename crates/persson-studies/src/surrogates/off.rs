//! The study `surrogates` in a build without the feature `bem`: refused.

use persson::error::Result;

use super::{SurrogatesOutput, SurrogatesReport};
use crate::study::{unavailable, Context};

/// Refused: the surrogates need the BEM (feature `bem`).
///
/// # Errors
/// Always.
pub fn surrogates(_: &Context<'_>, _: &SurrogatesOutput) -> Result<SurrogatesReport> {
    Err(unavailable("surrogates", "bem"))
}
