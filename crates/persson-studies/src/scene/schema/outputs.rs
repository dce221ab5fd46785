//! What a scene asks for: one struct per output, absent outputs not computed.

pub use crate::adhesion::AdhesionOutput;
pub use crate::area::AreaOutput;
pub use crate::bem::{BemOutput, PatchesOutput, SubsurfaceOutput};
pub use crate::bem_adhesion::BemAdhesionOutput;
pub use crate::bem_hertz::BemHertzOutput;
pub use crate::friction::{FrictionOutput, VelocityRange};
pub use crate::kappa::KappaOutput;
pub use crate::magnification::MagnificationOutput;
pub use crate::separation::SeparationOutput;
pub use crate::separation_density::SeparationDensityOutput;
pub use crate::spectrum::SpectrumOutput;
pub use crate::stress::{BallSpec, CylinderSpec, StressOutput};
pub use crate::theories::TheoriesOutput;
