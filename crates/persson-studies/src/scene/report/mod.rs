//! Typed reports: what each scene output (and the subcommand of the same
//! name) computed. Every report is `Serialize` (its JSON) and [`Tabulate`](crate::table::Tabulate)
//! (its text and CSV tables); the figures are drawn from them alone.

pub use crate::adhesion::AdhesionReport;
pub use crate::area::{AreaReport, LoadPoint};
#[cfg(feature = "bem")]
pub use crate::bem_hertz::{BemHertzReport, BemHertzRow, BemHertzTable};
pub use crate::friction::FrictionReport;
pub use crate::kappa::{KappaReport, LinearPoint};
pub use crate::magnification::MagnificationReport;
pub use crate::separation::SeparationReport;
pub use crate::spectrum::{PowerLawFit, SpectrumPoint, SpectrumReport};
pub use crate::stress::{StressCurveReport, StressReport};
pub use crate::theories::{TheoriesReport, TheoryCurve};
pub use crate::transport::report::*;
