//! The module's exports: byte buffers in linear memory, JSON across.
//!
//! The page calls, in order:
//! 1. [`persson_alloc`]`(n)` for each buffer it writes (a file's bytes, a
//!    file name, the scene), and copies the bytes to the pointer returned;
//! 2. [`persson_mount`]`(name, name_len, bytes, len)` once per input file
//!    (the module takes both buffers), [`persson_unmount_all`] to forget them;
//! 3. [`persson_run`]`(scene, len)`, which returns the length of the result
//!    (the JSON of [`crate::run::Outcome`]) and takes the scene's buffer; the
//!    result lies at [`persson_output`]`()` until the next call.
//!
//! A panic (a bug: every input error is an `Outcome::Error`) aborts the call
//! with a trap; [`persson_panic`] then puts its message at
//! [`persson_output`] and the page starts a new instance.

use std::cell::RefCell;
use std::sync::{Mutex, PoisonError};

thread_local! {
    static OUTPUT: RefCell<Vec<u8>> = const { RefCell::new(Vec::new()) };
}

static PANIC: Mutex<String> = Mutex::new(String::new());

/// A buffer of `len` bytes for the page to fill; it passes it back to
/// [`persson_mount`] or [`persson_run`], which take it, or to
/// [`persson_free`].
#[no_mangle]
pub extern "C" fn persson_alloc(len: usize) -> *mut u8 {
    let mut v = Vec::<u8>::with_capacity(len);
    let p = v.as_mut_ptr();
    std::mem::forget(v);
    p
}

/// Give back a buffer of [`persson_alloc`].
///
/// # Safety
/// `ptr` and `len` as [`persson_alloc`] returned and took them, not yet
/// passed to another call.
#[no_mangle]
pub unsafe extern "C" fn persson_free(ptr: *mut u8, len: usize) {
    // SAFETY: the caller's contract.
    drop(unsafe { Vec::from_raw_parts(ptr, 0, len) });
}

/// The `len` bytes at `ptr`, taken back as the `Vec` [`persson_alloc`] made.
///
/// # Safety
/// As [`persson_free`], with all `len` bytes written.
unsafe fn take(ptr: *mut u8, len: usize) -> Vec<u8> {
    // SAFETY: the caller's contract.
    unsafe { Vec::from_raw_parts(ptr, len, len) }
}

/// Hold `bytes` as the input file `name` (UTF-8) for the scenes that follow.
/// Returns 0, or 1 if the name is not UTF-8 (nothing is held).
///
/// # Safety
/// Both buffers from [`persson_alloc`], filled; the module takes them.
#[no_mangle]
pub unsafe extern "C" fn persson_mount(
    name: *mut u8,
    name_len: usize,
    bytes: *mut u8,
    len: usize,
) -> u32 {
    // SAFETY: the caller's contract.
    let (name, bytes) = unsafe { (take(name, name_len), take(bytes, len)) };
    match String::from_utf8(name) {
        Ok(name) => {
            persson::io::mount(name, bytes);
            0
        }
        Err(_) => 1,
    }
}

/// Forget every file [`persson_mount`] holds.
#[no_mangle]
pub extern "C" fn persson_unmount_all() {
    persson::io::unmount_all();
}

/// Run the scene (UTF-8 JSON) and return the length of the result at
/// [`persson_output`].
///
/// # Safety
/// The buffer from [`persson_alloc`], filled; the module takes it.
#[no_mangle]
pub unsafe extern "C" fn persson_run(scene: *mut u8, len: usize) -> usize {
    install();
    // SAFETY: the caller's contract.
    let scene = unsafe { take(scene, len) };
    let outcome = match std::str::from_utf8(&scene) {
        Ok(text) => crate::run::run(text),
        Err(e) => crate::run::Outcome::Error {
            error: format!("{}: not UTF-8 text ({e})", crate::run::SCENE),
        },
    };
    let json = serde_json::to_vec(&outcome).unwrap_or_else(|e| {
        format!(r#"{{"status":"error","error":"the result is not JSON: {e}"}}"#).into_bytes()
    });
    set_output(json)
}

/// The result of the last [`persson_run`] or [`persson_panic`].
#[no_mangle]
pub extern "C" fn persson_output() -> *const u8 {
    OUTPUT.with(|o| o.borrow().as_ptr())
}

/// After a trap: the panic's message at [`persson_output`]; returns its length.
#[no_mangle]
pub extern "C" fn persson_panic() -> usize {
    let message = PANIC.lock().unwrap_or_else(PoisonError::into_inner).clone();
    set_output(message.into_bytes())
}

fn set_output(bytes: Vec<u8>) -> usize {
    let len = bytes.len();
    OUTPUT.with(|o| *o.borrow_mut() = bytes);
    len
}

/// The page's clock, and a panic hook that keeps the message.
fn install() {
    static ONCE: std::sync::Once = std::sync::Once::new();
    ONCE.call_once(|| {
        crate::host::install_clock();
        std::panic::set_hook(Box::new(|info| {
            *PANIC.lock().unwrap_or_else(PoisonError::into_inner) = info.to_string();
        }));
    });
}
