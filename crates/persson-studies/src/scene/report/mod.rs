//! Typed reports: what each scene output (and the subcommand of the same
//! name) computed. Every report is `Serialize` (its JSON) and [`Tabulate`](crate::table::Tabulate)
//! (its text and CSV tables); the figures are drawn from them alone.

mod adhesion;
mod area;
mod bem;
mod friction;
mod separation;
mod spectrum;
mod stress;
mod transport;

pub use crate::area::{AreaReport, LoadPoint};
pub use adhesion::*;
pub use area::*;
pub use bem::*;
pub use friction::*;
pub use separation::*;
pub use spectrum::*;
pub use stress::*;
pub use transport::*;
