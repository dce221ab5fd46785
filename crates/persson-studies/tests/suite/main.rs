//! The studies' integration tests, one module per subject, built as one
//! test binary (one link instead of one per file).

// The one oracle of the workspace's tests (the root crate's tests/common).
#[path = "../../../../tests/common/oracle.rs"]
mod oracle;

mod bem_fallback;
mod bem_plot;
mod compare;
mod compare_bem;
mod dataset;
mod ensemble;
mod plot;
mod report;
mod report_transport;
mod scene;
mod scene_bem;
mod stress_map;
mod surrogates;
mod topography;
