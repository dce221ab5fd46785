//! Typed reports: what each scene output (and the subcommand of the same
//! name) computed. Every report is `Serialize` (its JSON) and [`Tabulate`](crate::table::Tabulate)
//! (its text and CSV tables); the figures are drawn from them alone.

mod adhesion;
mod bem;
mod friction;
mod spectrum;
mod stress;
mod transport;

pub use crate::area::{AreaReport, LoadPoint};
pub use crate::kappa::{KappaReport, LinearPoint};
pub use crate::magnification::MagnificationReport;
pub use crate::separation::SeparationReport;
pub use crate::theories::{TheoriesReport, TheoryCurve};
pub use adhesion::*;
pub use bem::*;
pub use friction::*;
pub use spectrum::*;
pub use stress::*;
pub use transport::*;
