//! The transport studies: `conductance` (thermal and electrical contact
//! conductance against load) and `leakage` (the leak rate of a static seal
//! against load), the theory's curves and, with the feature `flow`, the
//! FFT-BEM's values at the same loads. They share the gap's statistics, the
//! BEM's solves and their report.
//!
//! | module | what it holds |
//! |---|---|
//! | `conductance`, `leakage` | the two studies |
//! | `spec` | what a scene (or the subcommands) asks of them |
//! | `run` | the theory's curves, the transport properties and the seal |
//! | `request`, `bem` | what the BEM computes besides the contact (feature `flow`) |
//! | `report` | what they computed, with their tables |
//! | `plot` | their figures (feature `plot`) |

#[cfg_attr(not(feature = "flow"), path = "bem_off.rs")]
pub mod bem;
mod conductance;
mod leakage;
mod plot;
pub mod report;
mod request;
mod run;
mod spec;

pub use conductance::Conductance;
pub use leakage::Leakage;
pub use plot::{conductance as conductance_figure, leakage as leakage_figure};
pub use report::*;
pub use run::*;
pub use spec::*;
