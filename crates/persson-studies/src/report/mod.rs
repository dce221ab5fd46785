//! Error against run time, and the stability sweep over extreme inputs.
//!
//! [`accuracy`] measures, for every numerical method and each setting of its
//! accuracy knob, the achieved error against an independent reference and the
//! wall time, so users can pick their point on the curve. [`stability`] runs
//! the extreme and stiff cases, family by family, and compares each with its
//! reference where one exists: is every output finite, does every error
//! bound hold?

use persson::error::Result;

mod accuracy;
#[cfg(feature = "bem")]
mod bem;
mod core;
mod friction;
mod stability;
mod stress;
mod transport;

pub use accuracy::*;
pub use stability::*;

pub use transport::accuracy as transport_accuracy;

/// The accuracy report of every numerical method in this build.
///
/// # Errors
/// The first method that fails.
pub fn accuracy(extent: Extent) -> Result<AccuracyReport> {
    let mut methods = vec![core::g_quadrature(extent)?];
    methods.extend(stress::accuracy(extent)?);
    methods.push(friction::friction_quadrature(extent)?);
    #[cfg(feature = "bem")]
    methods.extend(bem::accuracy(extent)?);
    methods.extend(transport::accuracy(extent)?);
    Ok(AccuracyReport { methods })
}

/// Every extreme case of this build: the core's and the stress distributions'.
///
/// # Errors
/// An input the library rejects (none of these should be).
pub fn stability() -> Result<StabilityReport> {
    let mut cases = core::stability()?;
    cases.extend(stress::stability()?);
    Ok(StabilityReport::new(cases))
}
