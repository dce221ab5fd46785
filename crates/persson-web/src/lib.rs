//! The persson studies as one WebAssembly module, for the static page in
//! `web/` (`docs/web.md`).
//!
//! The page builds a scene, exactly the JSON `persson run` reads, hands the
//! module the user's files and the scene, and draws the report the module
//! returns. So the browser computes through the same code path as
//! `persson run`: [`run::run`] is [`persson_studies::scene::Scene::run`] with
//! the command's text, warnings and `--json` report beside it.
//!
//! # Binding
//! A plain C ABI ([`abi`]): byte buffers in the module's memory, UTF-8 JSON
//! across. The page needs no generated glue and the build no tool beyond
//! cargo and the `wasm32-unknown-unknown` target; every call takes and
//! returns one JSON document, which the page parses anyway.
//!
//! # What the host gives
//! Two imports from the module `env`: `persson_now_ms() -> f64` (the clock,
//! `performance.now()`: the solvers' reported times) and
//! `persson_progress(step, steps, iteration, residual)` (a BEM solve's
//! progress, once per iteration). Natively they are no-ops.

pub mod abi;
mod host;
pub mod run;
