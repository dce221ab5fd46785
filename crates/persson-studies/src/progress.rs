//! Progress of a long study, for a front-end that shows it.
//!
//! The command line draws its own bars from the solvers' observers; a front-end
//! that only runs scenes (the browser page runs [`crate::scene::Scene::run`])
//! has no observer to pass. It installs a hook with [`observe`] around the run;
//! the BEM solves call it once per iteration. The hook is the thread's: other
//! threads' runs do not see it.

use std::cell::RefCell;

/// Where a long study is.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct Progress {
    /// The study's key (`bem`).
    pub study: &'static str,
    /// The solve under way (its index in the scene's pressures), from 0.
    pub step: usize,
    /// Number of solves.
    pub steps: usize,
    /// The solver's iteration in this solve, from 0.
    pub iteration: usize,
    /// Its convergence measure ε.
    pub residual: f64,
}

type Hook = Box<dyn FnMut(&Progress)>;

thread_local! {
    static HOOK: RefCell<Option<Hook>> = const { RefCell::new(None) };
}

/// Run `f` with `hook` called at each step of progress; the previous hook
/// (none, usually) is back afterwards.
pub fn observe<T>(hook: impl FnMut(&Progress) + 'static, f: impl FnOnce() -> T) -> T {
    let previous = HOOK.with(|h| h.borrow_mut().replace(Box::new(hook)));
    let out = f();
    HOOK.with(|h| *h.borrow_mut() = previous);
    out
}

/// Tell the hook, if one is installed (the BEM solves call it).
pub fn report(p: &Progress) {
    HOOK.with(|h| {
        if let Ok(mut hook) = h.try_borrow_mut() {
            if let Some(hook) = hook.as_mut() {
                hook(p);
            }
        }
    });
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::rc::Rc;

    #[test]
    fn the_hook_sees_reports_only_inside_observe() {
        let seen = Rc::new(RefCell::new(Vec::new()));
        let p = Progress {
            study: "bem",
            step: 1,
            steps: 3,
            iteration: 7,
            residual: 1e-3,
        };
        report(&p);
        let s = Rc::clone(&seen);
        let n = observe(
            move |p| s.borrow_mut().push(p.iteration),
            || {
                report(&p);
                report(&Progress { iteration: 8, ..p });
                2
            },
        );
        report(&p);
        assert_eq!(n, 2);
        assert_eq!(*seen.borrow(), vec![7, 8]);
    }
}
