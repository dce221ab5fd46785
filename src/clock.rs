//! Wall-clock time of a computation, on every target.
//!
//! The solvers report the seconds they took ([`crate::bem::Solution`]'s
//! `seconds`). `std::time::Instant` panics on `wasm32-unknown-unknown`,
//! which has no clock of its own: there a host (the browser page) hands its
//! clock to [`set_source`] (JavaScript's `performance.now()`, in ms), and
//! without one every duration reads zero. Elsewhere [`Instant`] is the
//! standard library's.

use std::time::Duration;

#[cfg(all(target_arch = "wasm32", target_os = "unknown"))]
static SOURCE: std::sync::OnceLock<fn() -> f64> = std::sync::OnceLock::new();

/// Give the clock of a host without one: `now_ms` returns milliseconds from
/// any fixed origin (JavaScript's `performance.now()`). Only the first call
/// counts; on targets with a clock it is ignored.
pub fn set_source(now_ms: fn() -> f64) {
    #[cfg(all(target_arch = "wasm32", target_os = "unknown"))]
    let _ = SOURCE.set(now_ms);
    #[cfg(not(all(target_arch = "wasm32", target_os = "unknown")))]
    let _ = now_ms;
}

/// A point in time, to measure the [`Duration`] since it.
#[derive(Debug, Clone, Copy)]
pub struct Instant {
    #[cfg(not(all(target_arch = "wasm32", target_os = "unknown")))]
    at: std::time::Instant,
    #[cfg(all(target_arch = "wasm32", target_os = "unknown"))]
    at_ms: f64,
}

impl Instant {
    /// Now.
    pub fn now() -> Self {
        #[cfg(not(all(target_arch = "wasm32", target_os = "unknown")))]
        return Self {
            at: std::time::Instant::now(),
        };
        #[cfg(all(target_arch = "wasm32", target_os = "unknown"))]
        return Self { at_ms: host_ms() };
    }

    /// The time since `self` (zero on a host that gave no clock).
    pub fn elapsed(&self) -> Duration {
        #[cfg(not(all(target_arch = "wasm32", target_os = "unknown")))]
        return self.at.elapsed();
        #[cfg(all(target_arch = "wasm32", target_os = "unknown"))]
        return Duration::from_secs_f64(((host_ms() - self.at_ms) / 1e3).max(0.0));
    }
}

#[cfg(all(target_arch = "wasm32", target_os = "unknown"))]
fn host_ms() -> f64 {
    SOURCE.get().map_or(0.0, |now| now())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn elapsed_grows() {
        let t = Instant::now();
        std::thread::sleep(Duration::from_millis(2));
        assert!(t.elapsed() >= Duration::from_millis(2));
    }
}
