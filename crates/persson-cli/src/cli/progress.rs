//! The one progress display of long solves on stderr: a bar or spinner on a
//! terminal (feature `progress`), and for long runs whose stderr is a file
//! one line per solve.

use std::io::IsTerminal;

use persson::bem::Iteration;

/// Progress of a run of solves.
pub struct Progress {
    #[cfg(feature = "progress")]
    bar: indicatif::ProgressBar,
    /// `(prefix, total)` of the per-solve log lines, when logging.
    log: Option<(&'static str, usize)>,
    last: Option<usize>,
}

impl Progress {
    /// A spinner for a single solve described by `what`.
    #[allow(unused_variables)]
    pub fn spinner(what: &str) -> Self {
        Progress {
            #[cfg(feature = "progress")]
            bar: {
                let bar = indicatif::ProgressBar::new_spinner();
                bar.set_message(what.to_string());
                bar
            },
            log: None,
            last: None,
        }
    }

    /// A bar over `total` solves; with `log_prefix`, when stderr is not a
    /// terminal, one line per solve (for long runs written to a log).
    pub fn solves(total: usize, log_prefix: Option<&'static str>) -> Self {
        let log = log_prefix
            .filter(|_| !std::io::stderr().is_terminal())
            .map(|p| (p, total));
        #[cfg(feature = "progress")]
        let bar = {
            let bar = indicatif::ProgressBar::new(total as u64);
            if let Ok(style) = indicatif::ProgressStyle::with_template(
                "{bar:30} {pos}/{len} solves {msg} [{elapsed}]",
            ) {
                bar.set_style(style);
            }
            bar
        };
        Progress {
            #[cfg(feature = "progress")]
            bar,
            log,
            last: None,
        }
    }

    /// One solver iteration of solve number `done` (from 0), described by `what`.
    #[allow(unused_variables)]
    pub fn update(&mut self, done: usize, what: &dyn Fn() -> String, it: Iteration) {
        if let Some((prefix, total)) = self.log {
            if self.last != Some(done) {
                self.last = Some(done);
                eprintln!("{prefix}: solve {}/{total}: {}", done + 1, what());
            }
        }
        #[cfg(feature = "progress")]
        if it.iteration.is_multiple_of(10) {
            self.bar.set_position(done as u64);
            self.bar.set_message(format!(
                "{}: iteration {} ε {:.1e} A/A0 {:.4}",
                what(),
                it.iteration,
                it.residual,
                it.contact_fraction
            ));
        }
    }

    /// Remove the display.
    pub fn finish(&self) {
        #[cfg(feature = "progress")]
        self.bar.finish_and_clear();
    }
}
