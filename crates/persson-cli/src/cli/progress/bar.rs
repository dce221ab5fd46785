//! The terminal's progress bar (indicatif).

/// A bar over solves.
pub struct Bar(indicatif::ProgressBar);

impl Bar {
    /// A bar over `total` solves.
    pub fn solves(total: usize) -> Self {
        let bar = indicatif::ProgressBar::new(total as u64);
        if let Ok(style) =
            indicatif::ProgressStyle::with_template("{bar:30} {pos}/{len} solves {msg} [{elapsed}]")
        {
            bar.set_style(style);
        }
        Bar(bar)
    }

    /// At solve `done`, showing `message()`.
    pub fn show(&self, done: usize, message: &dyn Fn() -> String) {
        self.0.set_position(done as u64);
        self.0.set_message(message());
    }

    /// Remove the display.
    pub fn finish(&self) {
        self.0.finish_and_clear();
    }
}
