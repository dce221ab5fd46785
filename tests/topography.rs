//! Measured surfaces.
