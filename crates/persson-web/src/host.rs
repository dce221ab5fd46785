//! What the host page provides: a clock and a progress display.

use persson_studies::progress::Progress;

#[cfg(target_arch = "wasm32")]
#[link(wasm_import_module = "env")]
extern "C" {
    fn persson_now_ms() -> f64;
    fn persson_progress(step: u32, steps: u32, iteration: u32, residual: f64);
}

/// Hand the page's clock to the numerics (once).
pub fn install_clock() {
    #[cfg(target_arch = "wasm32")]
    // SAFETY: an import the page defines, taking nothing.
    persson::clock::set_source(|| unsafe { persson_now_ms() });
}

/// Tell the page where a long study is.
pub fn progress(p: &Progress) {
    #[cfg(target_arch = "wasm32")]
    {
        let n = |v: usize| u32::try_from(v).unwrap_or(u32::MAX);
        // SAFETY: an import the page defines, taking numbers only.
        unsafe { persson_progress(n(p.step), n(p.steps), n(p.iteration), p.residual) };
    }
    #[cfg(not(target_arch = "wasm32"))]
    let _ = p;
}
