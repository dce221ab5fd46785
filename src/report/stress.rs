//! The stress distributions' entries (sine series, image quadrature) and
//! their extreme cases.

use super::{AccuracyRow, Extent, StabilityCase};
use crate::error::Result;

/// Error against time of the stress-distribution methods.
pub(super) fn accuracy(_extent: Extent) -> Result<Vec<AccuracyRow>> {
    Ok(Vec::new())
}

/// Extreme cases of the stress distributions.
pub(super) fn stability() -> Result<Vec<StabilityCase>> {
    Ok(Vec::new())
}
