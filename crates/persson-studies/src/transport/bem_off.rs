//! The FFT-BEM's transport values in a build without the feature `flow`:
//! asking for them is an error naming the feature.

use crate::contact::RoughContact;
use persson::error::{Error, Result};

use super::report::BemTransportReport;
use super::request::TransportRequest;
use super::spec::TransportBem;

fn left_out() -> Error {
    Error::Inconsistent {
        name: "bem".into(),
        requirement: "needs a persson built with the `flow` feature".into(),
    }
}

/// Refused: needs the feature `flow`.
///
/// # Errors
/// Always.
pub fn on_contact(
    _: &RoughContact,
    _: &[f64],
    _: &TransportBem,
    _: &TransportRequest,
) -> Result<BemTransportReport> {
    Err(left_out())
}

// What the BEM's own commands name (feature `bem` without `flow`).
cfg_feature! {
    "bem",
    pub use with_bem::*;
    mod with_bem {
    use persson::bem::rough::{Observer, RoughProgress};
    use persson::bem::surface::GridSurface;
    use persson::bem::Solution;
    use persson::error::Result;

    use super::super::report::{BemTransportPoint, BemTransportReport};
    use super::super::request::TransportRequest;
    use super::left_out;

    /// Never made: [`TransportObserver::new`] refuses.
    pub struct TransportObserver<'a>(
        std::convert::Infallible,
        std::marker::PhantomData<&'a mut ()>,
    );

    impl<'a> TransportObserver<'a> {
        /// Refused: needs the feature `flow`.
        ///
        /// # Errors
        /// Always.
        pub fn new(
            _: &'a mut dyn Observer,
            _: usize,
            _: f64,
            _: f64,
            _: &[f64],
            _: f64,
            _: TransportRequest,
        ) -> Result<Self> {
            Err(left_out())
        }

        /// Never called.
        pub fn into_points(self) -> Vec<BemTransportPoint> {
            match self.0 {}
        }
    }

    impl Observer for TransportObserver<'_> {
        fn iteration(&mut self, _: RoughProgress) {
            match self.0 {}
        }

        fn solution(&mut self, _: usize, _: &Solution) -> Result<()> {
            match self.0 {}
        }
    }

    /// Refused: needs the feature `flow`.
    ///
    /// # Errors
    /// Always.
    pub fn transport(
        _: &GridSurface,
        _: Option<u64>,
        _: f64,
        _: &[f64],
        _: f64,
        _: &TransportRequest,
    ) -> Result<BemTransportReport> {
        Err(left_out())
    }
}
}
