//! The Rust examples of the README and of the user guide (`docs/`), compiled
//! and run as doctests so that they cannot go stale. Only built for
//! `cargo test` (rustdoc's doctest pass); a page with a ```` ```rust ````
//! block must be included here (`crates/persson-cli/tests/docs.rs` checks it).

/// The README's tour.
#[doc = include_str!("../../../README.md")]
pub struct Readme;

/// The guide's page on the library.
#[doc = include_str!("../../../docs/library.md")]
pub struct Library;
