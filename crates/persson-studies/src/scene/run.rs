//! Computing the outputs: one function per output, shared by `persson run`
//! and the subcommand of the same name.

pub use crate::adhesion::adhesion;
pub use crate::area::area;
pub use crate::contact::RoughContact;
pub use crate::input::spectrum_warnings;
pub use crate::kappa::kappa;
pub use crate::magnification::magnification;
pub use crate::separation::separation;
pub use crate::spectrum::spectrum;
pub use crate::stress::{stress_dimensionless, stress_physical};
pub use crate::theories::theories;
