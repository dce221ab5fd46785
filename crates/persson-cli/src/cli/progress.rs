//! The one progress display of long solves on stderr: a bar on a
//! terminal (feature `progress`), and for long runs whose stderr is a file
//! one line per solve.

use std::io::IsTerminal;

use persson::bem::Iteration;

// The terminal's bar (indicatif), or nothing without the feature `progress`.
#[cfg_attr(not(feature = "progress"), path = "progress/off.rs")]
mod bar;
use bar::Bar;

/// Progress of a run of solves.
pub struct Progress {
    bar: Bar,
    /// `(prefix, total)` of the per-solve log lines, when logging.
    log: Option<(&'static str, usize)>,
    last: Option<usize>,
}

impl Progress {
    /// A bar over `total` solves; with `log_prefix`, when stderr is not a
    /// terminal, one line per solve (for long runs written to a log).
    pub fn solves(total: usize, log_prefix: Option<&'static str>) -> Self {
        let log = log_prefix
            .filter(|_| !std::io::stderr().is_terminal())
            .map(|p| (p, total));
        Progress {
            bar: Bar::solves(total),
            log,
            last: None,
        }
    }

    /// One solver iteration of solve number `done` (from 0), described by `what`.
    pub fn update(&mut self, done: usize, what: &dyn Fn() -> String, it: Iteration) {
        self.log(done, what);
        if it.iteration.is_multiple_of(10) {
            self.bar.show(done, &|| {
                format!(
                    "{}: iteration {} ε {:.1e} A/A0 {:.4}",
                    what(),
                    it.iteration,
                    it.residual,
                    it.contact_fraction
                )
            });
        }
    }

    /// An iteration a study reported through its progress hook
    /// ([`persson_studies::progress`]), described by `what`.
    pub fn step(&mut self, p: &persson_studies::progress::Progress, what: &dyn Fn() -> String) {
        self.log(p.step, what);
        if p.iteration.is_multiple_of(10) {
            self.bar.show(p.step, &|| {
                format!("{}: iteration {} ε {:.1e}", what(), p.iteration, p.residual)
            });
        }
    }

    /// The per-solve log line of solve `done`, once, when logging.
    fn log(&mut self, done: usize, what: &dyn Fn() -> String) {
        if let Some((prefix, total)) = self.log {
            if self.last != Some(done) {
                self.last = Some(done);
                eprintln!("{prefix}: solve {}/{total}: {}", done + 1, what());
            }
        }
    }

    /// Remove the display.
    pub fn finish(&self) {
        self.bar.finish();
    }
}
