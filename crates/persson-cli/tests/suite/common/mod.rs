//! Helpers shared by the tests that run the `persson` binary.
#![allow(dead_code)] // each test binary uses a subset

use std::process::Command;

/// The repository's root, where the tests' relative paths (`tests/…`,
/// `scenes/…`) start.
pub fn root() -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// Run `persson ARGS` in the repository's root with `RUST_BACKTRACE=1` (so a
/// panic would show on stderr): (exit code, stdout, stderr).
pub fn persson(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_persson"))
        .args(args)
        .current_dir(root())
        .env("RUST_BACKTRACE", "1")
        .output()
        .expect("run persson");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// Run `persson ARGS`, require exit code 0, and parse stdout as JSON.
pub fn json(args: &[&str]) -> serde_json::Value {
    let (code, out, err) = persson(args);
    assert_eq!(code, 0, "{args:?}: {err}");
    serde_json::from_str(&out).unwrap_or_else(|e| panic!("{args:?}: {e}\n{out}"))
}
