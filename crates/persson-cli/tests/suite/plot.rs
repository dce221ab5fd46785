//! The plotting layer (feature `plot`): every standard figure renders to SVG
//! and PNG with its labels, log axes work at any magnitude, and failures are
//! clean (typed error, no partial file, existing file untouched).
#![cfg(feature = "plot")]

use persson_studies::plot::DEFAULT_SIZE;

use std::path::{Path, PathBuf};

/// The eight bytes every PNG file starts with (PNG spec §5.2).
const PNG_SIGNATURE: [u8; 8] = [137, 80, 78, 71, 13, 10, 26, 10];

/// A fresh, empty directory under the system temp dir, removed on drop.
struct TempDir(PathBuf);

impl TempDir {
    fn new(name: &str) -> Self {
        let dir =
            std::env::temp_dir().join(format!("persson-plot-test-{}-{name}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).expect("create temp dir");
        TempDir(dir)
    }

    fn join(&self, file: &str) -> PathBuf {
        self.0.join(file)
    }
}

/// Width and height from a PNG's IHDR chunk, after checking the signature.
fn png_size(path: &Path) -> (u32, u32) {
    let bytes = std::fs::read(path).expect("read png");
    assert!(bytes.len() > 24, "{} too short", path.display());
    assert_eq!(bytes[..8], PNG_SIGNATURE, "{} is not a PNG", path.display());
    assert_eq!(&bytes[12..16], b"IHDR", "first chunk of {}", path.display());
    let be = |b: &[u8]| u32::from_be_bytes([b[0], b[1], b[2], b[3]]);
    (be(&bytes[16..20]), be(&bytes[20..24]))
}

/// The text contents of an SVG document's `<text>` elements.
fn svg_texts(svg: &str) -> Vec<String> {
    svg.split("<text")
        .skip(1)
        .filter_map(|t| {
            let start = t.find('>')? + 1;
            let end = t.find("</text>")?;
            Some(t[start..end].trim().to_string())
        })
        .collect()
}

/// `persson area --plot FILE`: the CLI pattern for every subcommand.
#[test]
fn cli_area_writes_the_load_curve_plot() {
    let dir = TempDir::new("cli");
    let run = |file: &Path| {
        std::process::Command::new(env!("CARGO_BIN_EXE_persson"))
            .current_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."))
            .args(["area", "--example", "--json", "--plot"])
            .arg(file)
            .env("RUST_BACKTRACE", "0")
            .output()
            .expect("run persson")
    };
    let png = dir.join("area.png");
    let out = run(&png);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert_eq!(png_size(&png), DEFAULT_SIZE);
    // The table output is unchanged by --plot.
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).expect("json on stdout");
    assert!(json["points"].is_array());

    let svg = dir.join("area.svg");
    assert!(run(&svg).status.success());
    let texts = svg_texts(&std::fs::read_to_string(&svg).unwrap());
    for t in [
        "Bush et al.: κ = √(2π)",
        "Persson: κ = √(8/π)",
        "contact fraction A/A0",
    ] {
        assert!(texts.iter().any(|x| x == t), "no {t:?} in {texts:?}");
    }

    let out = run(&dir.join("area.jpg"));
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("area.jpg") && err.contains(".svg or .png"),
        "{err}"
    );
    assert!(out.stdout.is_empty(), "nothing printed after a failed plot");
}
