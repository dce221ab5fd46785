//! The README and the user guide (`docs/*.md`) run as written, so they cannot
//! go stale.
//!
//! - ```` ```console ```` blocks are transcripts: every `$ persson …` line
//!   runs (trycmd) and must print what follows it, digit for digit. `[..]`
//!   in a line stands for what legitimately varies (a time, an iteration
//!   count, a residual); `...` on a line of its own for lines left out.
//!   `> ` continues a command on the next line. The commands run in a scratch
//!   directory that holds copies of `scenes/`, `tests/reference/data/`,
//!   `tests/data/` (the instrument files) and `docs/data/` (so they read
//!   what a user at the repository's root reads
//!   and write their plots and tables there, not into the source tree).
//! - ```` ```sh ```` blocks are shown but not run (a toolchain command, or a
//!   reproduction that takes minutes); the line above each says why, as
//!   `<!-- not run: … -->`.
//! - ```` ```rust ```` blocks are doctests of `persson-studies` (its
//!   `guide` module includes every page that has one); ```` ```python ````
//!   blocks run in `python/tests/test_readme.py`.
//!
//! After a change of output, `TRYCMD=overwrite cargo test --release -p
//! persson-cli --test docs` writes the new output into the pages (keep the
//! `[..]` elisions: it preserves them where the line still matches) and the
//! README's figure into `docs/area.svg`; read the diff before committing.
#![cfg(all(feature = "bem", feature = "topography", feature = "plot"))]

use std::path::{Path, PathBuf};

/// The repository's root.
fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .canonicalize()
        .expect("the repository's root")
}

/// README.md and every page of the guide, `docs/*.md`.
fn pages() -> Vec<PathBuf> {
    let root = root();
    let mut pages: Vec<PathBuf> = std::fs::read_dir(root.join("docs"))
        .expect("docs/")
        .map(|e| e.expect("read docs/").path())
        .filter(|p| p.extension().is_some_and(|x| x == "md"))
        .collect();
    pages.sort();
    pages.insert(0, root.join("README.md"));
    pages
}

fn read(path: &Path) -> String {
    std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// A fenced code block: its info string, its first line's number (1-based,
/// the fence's) and its lines.
struct Block {
    info: String,
    line: usize,
    body: Vec<String>,
}

/// The fenced code blocks of a markdown page (``` fences; a longer fence
/// closes only on a fence of at least its length).
fn blocks(text: &str) -> Vec<Block> {
    let mut out = Vec::new();
    let mut open: Option<(usize, Block)> = None;
    for (i, line) in text.lines().enumerate() {
        let ticks = line.chars().take_while(|&c| c == '`').count();
        match &mut open {
            None if ticks >= 3 => {
                let info = line[ticks..].trim().to_string();
                let block = Block {
                    info,
                    line: i + 1,
                    body: Vec::new(),
                };
                open = Some((ticks, block));
            }
            None => {}
            Some((n, _)) if ticks >= *n && line[ticks..].trim().is_empty() => {
                let (_, block) = open.take().expect("open block");
                out.push(block);
            }
            Some((_, block)) => block.body.push(line.to_string()),
        }
    }
    assert!(open.is_none(), "a code block is never closed");
    out
}

/// Copies `from` (a directory) to `to`, recursively.
fn copy_dir(from: &Path, to: &Path) {
    std::fs::create_dir_all(to).expect("create a scratch directory");
    for entry in std::fs::read_dir(from).expect("read a directory to copy") {
        let entry = entry.expect("a directory entry");
        let target = to.join(entry.file_name());
        if entry.file_type().expect("a file type").is_dir() {
            copy_dir(&entry.path(), &target);
        } else {
            std::fs::copy(entry.path(), target).expect("copy a file");
        }
    }
}

/// Every `$ persson …` line of every ```` ```console ```` block runs and
/// prints what the page shows; the README's figure is the one its command
/// draws.
///
/// This is the only test of this binary that depends on the working
/// directory (it sets it to the scratch directory for trycmd, which runs the
/// commands in the process's directory); the others use absolute paths.
/// The scratch directory the commands run in; removed (and the working
/// directory restored) when the test ends, also when it fails.
struct Scratch {
    dir: PathBuf,
    root: PathBuf,
}

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::env::set_current_dir(&self.root);
        let _ = std::fs::remove_dir_all(&self.dir);
    }
}

#[test]
fn commands_print_what_the_pages_show() {
    let root = root();
    let scratch = std::env::temp_dir().join(format!("persson-docs-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&scratch);
    let _guard = Scratch {
        dir: scratch.clone(),
        root: root.clone(),
    };
    copy_dir(&root.join("scenes"), &scratch.join("scenes"));
    copy_dir(
        &root.join("tests/reference/data"),
        &scratch.join("tests/reference/data"),
    );
    copy_dir(&root.join("tests/data"), &scratch.join("tests/data"));
    copy_dir(&root.join("docs/data"), &scratch.join("docs/data"));
    std::env::set_current_dir(&scratch).expect("enter the scratch directory");

    let cases = trycmd::TestCases::new();
    cases
        .register_bin("persson", Path::new(env!("CARGO_BIN_EXE_persson")))
        .env("RUST_BACKTRACE", "0")
        .timeout(std::time::Duration::from_secs(120));
    for page in pages() {
        cases.case(page);
    }
    cases.run();

    // The README's figure: the file its tour command writes (unless a
    // `trycmd=PAGE` filter left the README out).
    let filtered = std::env::args().any(|a| a.starts_with("trycmd="));
    if filtered && !scratch.join(FIGURE).exists() {
        return;
    }
    let drawn = read(&scratch.join(FIGURE));
    let committed = root.join(FIGURE);
    if std::env::var_os("TRYCMD").is_some_and(|v| v == "overwrite") {
        std::fs::write(&committed, &drawn).expect("write the README's figure");
    }
    assert!(
        drawn == std::fs::read_to_string(&committed).unwrap_or_default(),
        "{FIGURE} is not what the README's command draws: regenerate it with \
         TRYCMD=overwrite cargo test --release -p persson-cli --test docs"
    );
}

/// The README's one figure, drawn by its tour (relative to the root).
const FIGURE: &str = "docs/area.svg";

/// The kinds of code block a page may hold (see the module's docs). A block
/// without a kind would be read by trycmd as a transcript.
const KINDS: &[&str] = &[
    "console", "sh", "rust", "python", "text", "json", "toml", "csv",
];

#[test]
fn every_block_is_of_a_known_kind() {
    let mut problems = Vec::new();
    for page in pages() {
        let text = read(&page);
        let lines: Vec<&str> = text.lines().collect();
        let name = page
            .strip_prefix(root())
            .unwrap_or(&page)
            .display()
            .to_string();
        for block in blocks(&text) {
            let kind = block.info.split([',', ' ']).next().unwrap_or_default();
            let at = format!("{name}:{}", block.line);
            if !KINDS.contains(&kind) {
                problems.push(format!("{at}: block of kind `{}`", block.info));
            }
            if kind == "console" {
                if block.info != "console" {
                    problems.push(format!(
                        "{at}: `{}`: a console block always runs",
                        block.info
                    ));
                }
                for cmd in block.body.iter().filter(|l| l.starts_with("$ ")) {
                    if !cmd.starts_with("$ persson ") {
                        problems.push(format!("{at}: `{cmd}`: console blocks run `persson` only"));
                    }
                }
            }
            if kind == "sh" {
                let above = lines.get(block.line.wrapping_sub(2)).copied().unwrap_or("");
                if !(above.starts_with("<!-- not run: ") && above.ends_with("-->")) {
                    problems.push(format!(
                        "{at}: a sh block (shown, not run) needs `<!-- not run: why -->` on the line above"
                    ));
                }
            }
        }
    }
    assert!(problems.is_empty(), "\n{}", problems.join("\n"));
}

/// Every page with a Rust example is a doctest of persson-studies.
#[test]
fn every_rust_block_is_a_doctest() {
    let root = root();
    let guide = read(&root.join("crates/persson-studies/src/guide.rs"));
    for page in pages() {
        if blocks(&read(&page))
            .iter()
            .any(|b| b.info.starts_with("rust"))
        {
            let rel = page.strip_prefix(&root).expect("a page under the root");
            let include = format!("include_str!(\"../../../{}\")", rel.display());
            assert!(
                guide.contains(&include),
                "{}: has Rust blocks, but crates/persson-studies/src/guide.rs lacks `{include}`",
                rel.display()
            );
        }
    }
}

/// Every relative link of a page names a file that exists, and every page of
/// the guide is linked from the README or the guide's index.
#[test]
fn links_resolve_and_every_page_is_linked() {
    let root = root();
    let mut problems = Vec::new();
    let mut linked = std::collections::BTreeSet::new();
    for page in pages() {
        let text = read(&page);
        let dir = page.parent().expect("a page's directory");
        for target in text.split("](").skip(1).filter_map(|s| s.split(')').next()) {
            let path = target.split('#').next().unwrap_or_default();
            if path.is_empty() || path.contains("://") || path.starts_with("mailto:") {
                continue;
            }
            let file = dir.join(path);
            match file.canonicalize() {
                Ok(f) => {
                    linked.insert(f);
                }
                Err(_) => problems.push(format!("{}: broken link `{target}`", page.display())),
            }
        }
    }
    for page in pages().iter().skip(1) {
        let canonical = page.canonicalize().expect("a page");
        if !linked.contains(&canonical) {
            problems.push(format!("{}: linked from no page", page.display()));
        }
    }
    assert!(problems.is_empty(), "\n{}", problems.join("\n"));
    assert!(
        root.join("docs/README.md").exists(),
        "docs/README.md: the guide's index"
    );
}

/// The README stays an entry point (issue 21: at most ~300 lines); what
/// does not fit goes to a page of the guide.
const README_LINES: usize = 300;

#[test]
fn readme_stays_short_with_its_set_up_commands_on_top() {
    let readme = read(&root().join("README.md"));
    let lines = readme.lines().count();
    assert!(
        lines <= README_LINES,
        "README.md has {lines} lines (at most {README_LINES}): move the detail to docs/"
    );
    let head: String = readme.lines().take(25).collect::<Vec<_>>().join("\n");
    for command in [
        "cargo run --release -p persson-cli -- area --example",
        "scripts/test",
    ] {
        assert!(
            head.contains(command),
            "README.md: `{command}` is not at the top"
        );
    }
}

/// A dependency line a page shows (`persson = "0.3"`,
/// `persson = { version = "0.3", … }`) names the workspace's version (0.3's
/// README still said 0.2).
#[test]
fn dependency_lines_name_this_version() {
    let version = env!("CARGO_PKG_VERSION");
    let minor = version.rsplit_once('.').map_or(version, |(m, _)| m);
    let mut problems = Vec::new();
    for page in pages() {
        for line in read(&page).lines() {
            let Some(rest) = line.trim_start().strip_prefix("persson") else {
                continue;
            };
            let Some(value) = rest.trim_start().strip_prefix('=') else {
                continue;
            };
            let shown = value.split('"').nth(1).unwrap_or_default();
            if !shown.is_empty() && shown != minor && shown != version {
                problems.push(format!(
                    "{}: `{}` (the crates are {version})",
                    page.display(),
                    line.trim()
                ));
            }
        }
    }
    assert!(problems.is_empty(), "\n{}", problems.join("\n"));
}
