//! The one output layer: every file a run writes goes through an
//! [`Files`], so that nothing the user gave is lost.
//!
//! A run declares its inputs and its outputs before it computes anything;
//! [`Files::reserve`] checks each output there and then:
//! - its path, made absolute (symbolic links resolved), is not an input's
//!   and not another output's;
//! - its extension is one the output can write, where the extension picks
//!   the format (`.svg` or `.png` for a plot, `.csv` or `.npy` for a table);
//! - its folder exists and accepts a new file, and the path is not a folder.
//!
//! While the run computes, [`Files::write`] stages each file as a
//! temporary file in the target's folder ([`persson::io::TempFile`]); only
//! [`Files::commit`], called once the whole run has succeeded, renames
//! them over their targets. A run that fails drops its `Files`: the
//! temporary files are removed, and every existing file is left byte for
//! byte as it was (a folder [`Files::folder`] created is removed again if
//! it is still empty).
//!
//! The layer knows paths and the names the front-end gave them (`--plot`,
//! `outputs.area.plot`), never a format's contents: callers encode the bytes.

use std::path::{Path, PathBuf};

use persson::io::TempFile;

use crate::{Error, Result};

/// A path a run reads or writes, with the name the user gave it by.
#[derive(Debug, Clone)]
struct Named {
    /// The flag, scene field or keyword (`--surface`, `outputs.bem.histogram`).
    name: String,
    /// The path as given.
    given: PathBuf,
    /// Absolute, with symbolic links resolved as far as they exist.
    resolved: PathBuf,
}

/// A run's inputs and outputs (module docs).
#[derive(Default)]
pub struct Files {
    inputs: Vec<Named>,
    outputs: Vec<Named>,
    staged: Vec<TempFile>,
    /// Folders this run created, outermost first.
    created: Vec<PathBuf>,
    committed: bool,
}

impl std::fmt::Debug for Files {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Files")
            .field("inputs", &self.inputs)
            .field("outputs", &self.outputs)
            .field("staged", &self.staged.len())
            .finish()
    }
}

impl Files {
    /// No inputs, no outputs.
    pub fn new() -> Self {
        Self::default()
    }

    /// Declare a file the run reads, by the name the user gave it.
    ///
    /// # Errors
    /// An output already reserved at the same path.
    pub fn input(&mut self, name: &str, path: &Path) -> Result<()> {
        let n = named(name, path);
        if let Some(o) = self.outputs.iter().find(|o| same(o, &n)) {
            return Err(refused(o, format!("would overwrite the input file {name}")));
        }
        self.inputs.push(n);
        Ok(())
    }

    /// Reserve a file the run will write (module docs): `formats` lists the
    /// extensions that pick its format (any case), empty when the content
    /// does not depend on the extension.
    ///
    /// # Errors
    /// [`Error::Io`] naming the path and `name` when the path is an input's
    /// or another output's, has another extension, is a folder, or its
    /// folder does not exist or does not accept a new file.
    pub fn reserve(&mut self, name: &str, path: &Path, formats: &[&str]) -> Result<()> {
        let n = named(name, path);
        if let Some(i) = self.inputs.iter().find(|i| same(i, &n)) {
            return Err(refused(
                &n,
                format!("would overwrite the input file {}", i.name),
            ));
        }
        if let Some(o) = self.outputs.iter().find(|o| same(o, &n)) {
            if o.name == n.name {
                return Ok(());
            }
            return Err(refused(
                &n,
                format!(
                    "{} writes this file too: give each output its own file",
                    o.name
                ),
            ));
        }
        check_format(&n, formats)?;
        if n.resolved.is_dir() {
            return Err(refused(&n, "is a folder: give a file name".into()));
        }
        persson::io::check_writable(path).map_err(|e| match e {
            Error::Io { source, .. } => refused(&n, format!("cannot be written ({source})")),
            e => e,
        })?;
        self.outputs.push(n);
        Ok(())
    }

    /// Reserve an output folder, creating it if missing.
    ///
    /// # Errors
    /// [`Error::Io`] naming the folder when it is an input, an existing
    /// file, or cannot be created.
    pub fn folder(&mut self, name: &str, dir: &Path) -> Result<()> {
        let n = named(name, dir);
        if let Some(i) = self.inputs.iter().find(|i| same(i, &n)) {
            return Err(refused(&n, format!("is the input file {}", i.name)));
        }
        if n.resolved.exists() && !n.resolved.is_dir() {
            return Err(refused(&n, "is a file, not a folder".into()));
        }
        let mut missing = Vec::new();
        let mut d = n.resolved.as_path();
        while !d.exists() {
            missing.push(d.to_path_buf());
            match d.parent() {
                Some(p) => d = p,
                None => break,
            }
        }
        std::fs::create_dir_all(&n.resolved)
            .map_err(|e| refused(&n, format!("cannot be created ({e})")))?;
        self.created.extend(missing.into_iter().rev());
        Ok(())
    }

    /// Stage `bytes` for `path`: written now to a temporary file beside it,
    /// renamed over it by [`Files::commit`]. A path not reserved (a file
    /// named after a reserved one, `field_3.npy`) is reserved here, under
    /// the name of the output it derives from when given.
    ///
    /// # Errors
    /// As [`Files::reserve`]; [`Error::Io`] when the temporary file
    /// cannot be written.
    pub fn write(&mut self, path: &Path, bytes: &[u8]) -> Result<()> {
        let n = named("", path);
        if !self.outputs.iter().any(|o| same(o, &n)) {
            let name = self.deriving_name(path);
            self.reserve(&name, path, &[])?;
        }
        let tmp = TempFile::create(path)?;
        std::fs::write(tmp.path(), bytes).map_err(|source| Error::Io {
            path: path.to_path_buf(),
            source,
        })?;
        self.staged.push(tmp);
        Ok(())
    }

    /// The name of the reserved output whose stem starts `path`'s, for
    /// files named after it (`field.npy` → `field_0.npy`).
    fn deriving_name(&self, path: &Path) -> String {
        let stem = |p: &Path| {
            p.file_stem()
                .map(|s| s.to_string_lossy().into_owned())
                .unwrap_or_default()
        };
        let s = stem(path);
        self.outputs
            .iter()
            .filter(|o| o.given.parent() == path.parent())
            .find(|o| s.starts_with(&format!("{}_", stem(&o.given))))
            .map_or_else(|| "output".to_string(), |o| o.name.clone())
    }

    /// Whether an output is reserved at `path`.
    pub fn is_reserved(&self, path: &Path) -> bool {
        let n = named("", path);
        self.outputs.iter().any(|o| same(o, &n))
    }

    /// Rename every staged file over its target, in the order written, and
    /// return their paths. Call it once the run has succeeded.
    ///
    /// # Errors
    /// [`Error::Io`] when a rename fails.
    pub fn commit(&mut self) -> Result<Vec<PathBuf>> {
        let mut written = Vec::with_capacity(self.staged.len());
        for tmp in self.staged.drain(..) {
            let target = tmp.target().to_path_buf();
            tmp.persist()?;
            written.push(target);
        }
        self.committed = true;
        Ok(written)
    }
}

impl Drop for Files {
    fn drop(&mut self) {
        // The staged temporary files remove themselves; the folders this
        // run created go too if a failed run left them empty.
        if !self.committed || !self.staged.is_empty() {
            for d in self.created.iter().rev() {
                let _ = std::fs::remove_dir(d);
            }
        }
    }
}

/// `path` named `name`, resolved (module docs).
fn named(name: &str, path: &Path) -> Named {
    Named {
        name: name.to_string(),
        given: path.to_path_buf(),
        resolved: resolve(path),
    }
}

/// `path` made absolute, with symbolic links resolved as far as the path
/// exists: the whole path for an existing file, else its folder joined
/// with its name, else lexically (`.` and `..` removed).
pub fn resolve(path: &Path) -> PathBuf {
    if let Ok(p) = path.canonicalize() {
        return p;
    }
    let absolute = std::path::absolute(path).unwrap_or_else(|_| path.to_path_buf());
    let lexical = lexical(&absolute);
    match (lexical.parent(), lexical.file_name()) {
        (Some(dir), Some(name)) => dir
            .canonicalize()
            .map(|d| d.join(name))
            .unwrap_or(lexical.clone()),
        _ => lexical,
    }
}

/// `.` and `..` removed without touching the file system.
fn lexical(p: &Path) -> PathBuf {
    use std::path::Component;
    let mut out = PathBuf::new();
    for c in p.components() {
        match c {
            Component::CurDir => {}
            Component::ParentDir => {
                out.pop();
            }
            c => out.push(c.as_os_str()),
        }
    }
    out
}

/// Whether two named paths are one file: the same resolved path, or (for
/// files that exist) the same file by identity (hard links).
fn same(a: &Named, b: &Named) -> bool {
    if a.resolved == b.resolved {
        return true;
    }
    same_identity(&a.resolved, &b.resolved)
}

#[cfg(unix)]
fn same_identity(a: &Path, b: &Path) -> bool {
    use std::os::unix::fs::MetadataExt;
    match (std::fs::metadata(a), std::fs::metadata(b)) {
        (Ok(x), Ok(y)) => x.dev() == y.dev() && x.ino() == y.ino(),
        _ => false,
    }
}

#[cfg(not(unix))]
fn same_identity(_: &Path, _: &Path) -> bool {
    false
}

/// The extension of `n` is one of `formats` (any case), if any are listed.
fn check_format(n: &Named, formats: &[&str]) -> Result<()> {
    if formats.is_empty() {
        return Ok(());
    }
    let ext = n
        .given
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    if ext.as_deref().is_some_and(|e| formats.contains(&e)) {
        return Ok(());
    }
    let list: Vec<String> = formats.iter().map(|f| format!(".{f}")).collect();
    Err(refused(
        n,
        format!(
            "unsupported format: the file name must end in {}",
            list.join(" or ")
        ),
    ))
}

/// An [`Error::Io`] of kind `InvalidInput`: `path: <name> <what>`.
fn refused(n: &Named, what: String) -> Error {
    let message = if n.name.is_empty() {
        what
    } else {
        format!("{} {what}", n.name)
    };
    Error::Io {
        path: n.given.clone(),
        source: std::io::Error::new(std::io::ErrorKind::InvalidInput, message),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn dir(name: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("persson-output-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap();
        d
    }

    #[test]
    fn an_output_onto_an_input_is_refused_by_every_spelling() {
        let d = dir("spelling");
        let input = d.join("in.npy");
        std::fs::write(&input, b"heights").unwrap();
        let mut o = Files::new();
        o.input("--surface", &input).unwrap();
        for spelled in [
            input.clone(),
            d.join(".").join("in.npy"),
            d.join("sub").join("..").join("in.npy"),
        ] {
            let e = o.reserve("--plot", &spelled, &[]).unwrap_err().to_string();
            assert!(
                e.contains("--plot would overwrite the input file --surface"),
                "{e}"
            );
        }
        #[cfg(unix)]
        {
            let link = d.join("link.npy");
            std::os::unix::fs::symlink(&input, &link).unwrap();
            assert!(o.reserve("--plot", &link, &[]).is_err(), "a symbolic link");
            let hard = d.join("hard.npy");
            std::fs::hard_link(&input, &hard).unwrap();
            assert!(o.reserve("--plot", &hard, &[]).is_err(), "a hard link");
        }
        assert_eq!(std::fs::read(&input).unwrap(), b"heights");
    }

    #[test]
    fn two_outputs_to_one_file_and_bad_formats_are_refused() {
        let d = dir("two");
        let mut o = Files::new();
        o.reserve("--plot", &d.join("a.svg"), &["svg", "png"])
            .unwrap();
        let e = o.reserve("--histogram", &d.join("a.svg"), &[]).unwrap_err();
        assert!(e.to_string().contains("--plot writes this file too"), "{e}");
        let e = o
            .reserve("--stress-plot", &d.join("vm.pdf"), &["svg", "png"])
            .unwrap_err();
        assert!(
            e.to_string().contains(
                "--stress-plot unsupported format: the file name must end in .svg or .png"
            ),
            "{e}"
        );
        assert!(o.reserve("--x", &d.join("UP.PNG"), &["svg", "png"]).is_ok());
        let e = o
            .reserve("--x", &d.join("no/such/dir/f.csv"), &[])
            .unwrap_err();
        assert!(e.to_string().contains("cannot be written"), "{e}");
        let e = o.reserve("--y", &d, &[]).unwrap_err();
        assert!(e.to_string().contains("is a folder"), "{e}");
    }

    #[test]
    fn nothing_is_replaced_before_commit_and_a_failed_run_leaves_no_trace() {
        let d = dir("commit");
        let old = d.join("old.csv");
        std::fs::write(&old, b"old").unwrap();
        {
            let mut o = Files::new();
            o.reserve("--histogram", &old, &[]).unwrap();
            o.write(&old, b"new").unwrap();
            assert_eq!(std::fs::read(&old).unwrap(), b"old", "staged only");
            // dropped without commit: a failed run
        }
        assert_eq!(std::fs::read(&old).unwrap(), b"old");
        let names: Vec<_> = std::fs::read_dir(&d).unwrap().collect();
        assert_eq!(names.len(), 1, "no temporary file left");
        let mut o = Files::new();
        o.reserve("--histogram", &old, &[]).unwrap();
        o.write(&old, b"new").unwrap();
        o.write(&d.join("old_1.csv"), b"one").unwrap();
        assert_eq!(o.commit().unwrap().len(), 2);
        assert_eq!(std::fs::read(&old).unwrap(), b"new");
        assert_eq!(std::fs::read(d.join("old_1.csv")).unwrap(), b"one");
    }

    #[test]
    fn a_derived_file_is_checked_against_the_inputs_too() {
        let d = dir("derived");
        let input = d.join("field_0.npy");
        std::fs::write(&input, b"in").unwrap();
        let mut o = Files::new();
        o.input("--surface", &input).unwrap();
        o.reserve("--pressure-field", &d.join("field.npy"), &[])
            .unwrap();
        let e = o.write(&input, b"out").unwrap_err().to_string();
        assert!(
            e.contains("--pressure-field would overwrite the input file --surface"),
            "{e}"
        );
        assert_eq!(std::fs::read(&input).unwrap(), b"in");
    }

    #[test]
    fn a_created_folder_goes_again_when_the_run_fails() {
        let d = dir("folder");
        let out = d.join("new").join("deeper");
        {
            let mut o = Files::new();
            o.folder("--out", &out).unwrap();
            assert!(out.is_dir());
        }
        assert!(!d.join("new").exists());
        let mut o = Files::new();
        o.folder("--out", &out).unwrap();
        o.write(&out.join("report.json"), b"{}").unwrap();
        o.commit().unwrap();
        drop(o);
        assert!(out.join("report.json").is_file());
    }
}
