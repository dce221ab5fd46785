//! # persson-studies
//!
//! The studies built on the [`persson`] numerics: what the `persson` command
//! line and the Python package run and show. The numerics crate computes
//! numbers with their error bounds; this crate turns a request into those
//! computations and their results into reports.
//!
//! | module | what it holds |
//! |---|---|
//! | [`scene`] | scene files: one calculation described in a versioned JSON document, and running it |
//! | [`validation`] | validation of numerical codes: continuum extrapolation, κ fits, scoring a user's data against the theories, and (feature `bem`) the theories against the BEM at several resolutions of one surface |
//! | [`report`] | error against run time of every method, and the stability sweep over extreme inputs |
//! | [`table`] | the one table type every report renders to, as aligned text or CSV, and the tables of the numerics' results |
//! | [`output`] | the one output layer: every file a run writes is checked against its inputs and other outputs before computing, and written only when the whole run has succeeded |
//! | [`warning`] | [`Warning`]: a remark on the input (a pressure near E*, a slope above 1, ζ beyond the band, a spectrum file's convention) that never changes a number, carried by the reports |
//! | [`plot`] | figures from the typed reports, as data in every build; drawn as SVG or PNG with the feature `plot` |
//! | [`input`], [`naming`], [`contact`] | what every study reads: the material, the roughness (one map, several measurements combined, a spectrum), the rubber; the closed sets of names; the rough contact built once from them |
//! | [`progress`] | the hook through which a long study reports its progress to a front-end that runs scenes |
//! | [`surrogates`] and the other study folders | one study each: spec, run, report, figures ([`study`]) |
//!
//! Conventions, units and names are those of the numerics crate (see its
//! documentation): SI units, C(q) in Persson's normalisation, σ0 the nominal
//! mean pressure, one name per quantity.
//!
//! Errors are the numerics' [`Error`] (re-exported here): a scene or a figure
//! fails for the same reasons, with the same typed fields, as the computation
//! behind it.

#![warn(missing_docs)]

/// Items of one feature, gated once for the group (as tokio's `cfg_rt!`):
/// `cfg_feature!("bem", pub mod x; pub use x::Y;)`.
macro_rules! cfg_feature {
    ($feature:literal, $($item:item)*) => {
        $( #[cfg(feature = $feature)] $item )*
    };
}

// The README's and the guide's Rust examples, as doctests.
#[cfg(all(doctest, feature = "bem", feature = "topography"))]
mod guide;

pub mod adhesion;
pub mod area;
pub mod asperity;
pub mod bem;
pub mod bem_adhesion;
#[cfg(feature = "bem")]
pub mod bem_detail;
pub mod bem_hertz;
pub mod contact;
pub mod friction;
pub mod input;
pub mod kappa;
pub mod magnification;
pub mod naming;
pub mod output;
pub mod plot;
pub mod progress;
pub mod report;
pub mod scene;
pub mod separation;
pub mod separation_density;
pub mod spectrum;
pub mod stress;
pub mod study;
pub mod surrogates;
pub mod table;
pub mod theories;
pub mod transport;
pub mod validation;
pub mod warning;

pub use persson::{Error, Result};
pub use warning::Warning;
