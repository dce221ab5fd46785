//! The command line's integration tests, one module per subject, built as
//! one test binary (one link instead of one per file). The guide's pages
//! run apart, in `tests/docs.rs`: they change the working directory.

mod common;

mod anisotropy_cli;
mod asperity;
mod bad_input;
mod bem;
mod bem_adhesion;
mod bem_detail;
mod bem_plot;
mod bem_yield;
mod cli;
mod compare_adhesion;
mod compare_bem;
mod compare_table;
mod compare_transport;
mod compare_yield;
mod examples;
mod friction;
mod front_ends;
mod names;
mod non_finite;
mod plot;
mod scene;
mod separation_density;
mod stress;
mod surface_cli;
mod surrogates;
mod theories;
mod transport;
mod warnings;
