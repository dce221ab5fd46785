//! The backstop for `rustyhdf5-format`'s panics on damaged files.
//!
//! `rustyhdf5-format` 1.93 panics on some damaged files instead of
//! returning an error: a chunk address near `u64::MAX` wraps `address +
//! size` and a slice panics (`chunked_read.rs:69`), a chunked layout of
//! dimensionality 0 underflows `ndims - 1` (`chunked_read.rs:340`), a
//! fixed-array data block address past the end or a `max_nelmts_bits` of
//! 64 or more (`fixed_array.rs:129–147`), a global heap collection size
//! that overflows `offset + size` (`global_heap.rs:81`, with overflow
//! checks on). Those are checked before the crate is called (the `layout`
//! and `attribute` modules), and, as a backstop, every call into the crate
//! on file data runs through [`guarded`], under
//! [`std::panic::catch_unwind`]: a panic is an error naming the file and
//! "HDF5: damaged …". A panic hook installed once (chaining to the one
//! before it) keeps such a caught panic's message off stderr, on the
//! thread that catches it only.

use std::cell::Cell;
use std::panic::{self, AssertUnwindSafe};
use std::sync::Once;

use rustyhdf5_format::error::FormatError;

use super::super::bin::Bin;
use crate::error::Result;

thread_local! {
    /// Whether this thread is inside [`quiet_catch`] (its panics are caught).
    static CATCHING: Cell<bool> = const { Cell::new(false) };
}

/// Runs `f` (a call into `rustyhdf5-format` on file data), a panic caught
/// and its message not printed (see the module docs).
fn quiet_catch<T>(f: impl FnOnce() -> T) -> std::thread::Result<T> {
    static HOOK: Once = Once::new();
    HOOK.call_once(|| {
        let previous = panic::take_hook();
        panic::set_hook(Box::new(move |info| {
            if !CATCHING.with(Cell::get) {
                previous(info);
            }
        }));
    });
    let outer = CATCHING.with(|c| c.replace(true));
    let result = panic::catch_unwind(AssertUnwindSafe(f));
    CATCHING.with(|c| c.set(outer));
    result
}

/// `f`, a call into `rustyhdf5-format` reading `what`: its error or panic
/// as an error naming the file (through `f.bad`).
pub(super) fn guarded<T>(
    bin: &Bin,
    what: &str,
    f: impl FnOnce() -> std::result::Result<T, FormatError>,
) -> Result<T> {
    match quiet_catch(f) {
        Ok(Ok(v)) => Ok(v),
        Ok(Err(e)) => Err(bin.bad(format!("{what}: {e}"))),
        Err(_) => Err(bin.bad(if bin.format == "HDF5" {
            format!("damaged {what} (the HDF5 reader failed on it)")
        } else {
            format!("HDF5: damaged {what} (the HDF5 reader failed on it)")
        })),
    }
}
