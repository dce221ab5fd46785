//! Measurements in a build without the feature `topography`: refused.

use persson::error::Result;

use super::super::HeightMapSpec;
use super::MultiScaleReport;

/// Without the feature `topography` measured surfaces cannot be read.
pub fn multi_scale(_: &[HeightMapSpec]) -> Result<MultiScaleReport> {
    Err(persson::Error::Inconsistent {
        name: "kind = multi_scale".into(),
        requirement: "measured surfaces need persson built with the feature `topography`".into(),
    })
}
