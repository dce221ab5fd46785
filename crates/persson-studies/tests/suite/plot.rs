//! The plotting layer (feature `plot`): every standard figure renders to SVG
//! and PNG with its labels, log axes work at any magnitude, and failures are
//! clean (typed error, no partial file, existing file untouched).
#![cfg(feature = "plot")]

use persson::Error;
use persson_studies::plot::{
    self, render, render_svg_string, Axis, Figure, LegendPosition, LinearLaw, PowerLaw, Rgb,
    Series, Style, DEFAULT_SIZE, PALETTE,
};

// The one oracle of the workspace's tests (the root crate's tests/common).
use crate::oracle;
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

    /// The names of the files in the directory, sorted.
    fn files(&self) -> Vec<String> {
        let mut v: Vec<String> = std::fs::read_dir(&self.0)
            .expect("list temp dir")
            .map(|e| {
                e.expect("dir entry")
                    .file_name()
                    .to_string_lossy()
                    .into_owned()
            })
            .collect();
        v.sort();
        v
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

/// The decoded RGB pixels of a PNG (8-bit RGB, as written by `render`).
fn png_pixels(path: &Path) -> Vec<[u8; 3]> {
    let decoder = png::Decoder::new(std::fs::File::open(path).expect("open png"));
    let mut reader = decoder.read_info().expect("png header");
    let mut buf = vec![0; reader.output_buffer_size()];
    let info = reader.next_frame(&mut buf).expect("png data");
    assert_eq!(info.color_type, png::ColorType::Rgb);
    buf[..info.buffer_size()]
        .chunks_exact(3)
        .map(|c| [c[0], c[1], c[2]])
        .collect()
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

fn geomspace(a: f64, b: f64, n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| a * (b / a).powf(i as f64 / (n - 1) as f64))
        .collect()
}

/// Every standard figure, with the texts its SVG must contain.
fn standard_figures() -> Vec<(&'static str, Figure, Vec<&'static str>)> {
    let sigma: Vec<f64> = (0..=60).map(|i| 3.0 * i as f64 / 60.0).collect();
    let p1: Vec<f64> = sigma.iter().map(|s| s * (-s * s).exp()).collect();
    let p2: Vec<f64> = sigma
        .iter()
        .map(|s| 0.5 * s * (-s * s / 4.0).exp())
        .collect();
    let zeta = geomspace(1.0, 1e4, 40);
    let g: Vec<f64> = zeta.iter().map(|z| 0.01 * (z * z - 1.0) + 1e-3).collect();
    let area: Vec<f64> = g
        .iter()
        .map(|g| oracle::erf(1.0 / (2.0 * g.sqrt())))
        .collect();
    let pressure = geomspace(1e3, 1e7, 30);
    let load_area: Vec<f64> = pressure.iter().map(|p| (1.6 * p / 1e7).min(1.0)).collect();
    let q = geomspace(1e4, 1e9, 60);
    let c: Vec<f64> = q.iter().map(|q| 1e-22 * (q / 1e4).powf(-3.6)).collect();
    let timing = [(1e-6, 1e-3), (1e-5, 1e-8), (1e-4, 1e-14)];
    vec![
        (
            "stress_family",
            plot::stress_family(&sigma, &[("G = 0.6", &p1), ("G = 2", &p2)]).unwrap(),
            vec!["normal stress σ/σH", "P(σ, ζ) (1/σH)", "G = 0.6", "G = 2"],
        ),
        (
            "area_vs_zeta",
            plot::area_vs_zeta(&zeta, &[("σ0 = 1 MPa", &area)]).unwrap(),
            vec![
                "magnification ζ = q/qL",
                "contact fraction A/A0",
                "σ0 = 1 MPa",
            ],
        ),
        (
            "g_vs_zeta",
            plot::g_vs_zeta(&zeta, &[("σ0 = 1 MPa", &g)]).unwrap(),
            vec!["G(ζ) (dimensionless)", "σ0 = 1 MPa"],
        ),
        (
            "area_vs_load",
            plot::area_vs_load(
                &pressure,
                &[("theory", &load_area)],
                "Pa",
                Some(LinearLaw {
                    contact_modulus: 1e7,
                    rms_slope: 1.0,
                }),
            )
            .unwrap(),
            vec![
                "nominal pressure σ0 (Pa)",
                "contact fraction A/A0",
                "theory",
                "Bush et al.: κ = √(2π)",
                "Persson: κ = √(8/π)",
            ],
        ),
        (
            "spectrum",
            plot::spectrum(
                &q,
                &c,
                Some(PowerLaw {
                    prefactor: 1e-22 * 1e4f64.powf(3.6),
                    exponent: -3.6,
                    q_range: None,
                }),
            )
            .unwrap(),
            vec![
                "wavevector q (1/m)",
                "C(q) (m⁴)",
                "C(q)",
                "power-law fit C ∝ q^−3.60",
            ],
        ),
        (
            "error_vs_time",
            plot::error_vs_time(&[("method A", &timing)]),
            vec!["wall-clock time (s)", "relative error", "method A"],
        ),
    ]
}

#[test]
fn every_standard_figure_renders_to_svg_and_png() {
    let dir = TempDir::new("standard");
    for (name, fig, texts) in standard_figures() {
        let svg_path = dir.join(&format!("{name}.svg"));
        let png_path = dir.join(&format!("{name}.png"));
        render(&fig, &svg_path).unwrap_or_else(|e| panic!("{name}.svg: {e}"));
        render(&fig, &png_path).unwrap_or_else(|e| panic!("{name}.png: {e}"));

        let svg = std::fs::read_to_string(&svg_path).unwrap();
        assert!(svg.starts_with("<svg"), "{name}.svg is not an SVG document");
        let found = svg_texts(&svg);
        for t in texts.iter().chain([&fig.title.as_str()]) {
            assert!(
                found.iter().any(|f| f == t),
                "{name}.svg lacks the text {t:?}: {found:?}"
            );
        }
        assert_eq!(png_size(&png_path), DEFAULT_SIZE, "{name}.png");
    }
    // Nothing but the twelve figures: no temporary files left behind.
    assert_eq!(dir.files().len(), 12, "{:?}", dir.files());
}

#[test]
fn tiny_magnitudes_get_decade_tick_labels() {
    // C(q) in m⁴ around 1e-40: below f64::EPSILON, where plotters' own log
    // scale draws no ticks at all.
    let q = geomspace(1e6, 1e9, 30);
    let c: Vec<f64> = q.iter().map(|q| 1e-40 * (q / 1e6).powf(-3.0)).collect();
    let fig = plot::spectrum(&q, &c, None).unwrap();
    let texts = svg_texts(&render_svg_string(&fig).unwrap());
    for label in ["10⁻⁴⁰", "10⁻⁴⁴", "10⁻⁴⁸", "10⁶", "10⁹"] {
        assert!(
            texts.iter().any(|t| t == label),
            "no tick {label:?} in {texts:?}"
        );
    }
    // Tiny values on a linear axis too (pressures of 1e-12): scientific labels.
    let fig = Figure::new("tiny", Axis::linear("x (Pa)"), Axis::linear("y (Pa)"))
        .with_series(Series::line("s", vec![(0.0, 0.0), (3e-12, 2e-12)]));
    let texts = svg_texts(&render_svg_string(&fig).unwrap());
    for label in ["0", "1.0×10⁻¹²", "3.0×10⁻¹²"] {
        assert!(
            texts.iter().any(|t| t == label),
            "no tick {label:?} in {texts:?}"
        );
    }
}

#[test]
fn huge_spans_get_few_labels() {
    // 1e-300 … 1e300 on a log axis: every 100th decade, at most 10 labels.
    let fig = Figure::new("wide", Axis::log("x"), Axis::log("y"))
        .with_series(Series::line("s", vec![(1.0, 1e-300), (10.0, 1e300)]));
    let texts = svg_texts(&render_svg_string(&fig).unwrap());
    for label in ["10⁻³⁰⁰", "10⁻²⁰⁰", "10⁰", "10³⁰⁰"] {
        assert!(
            texts.iter().any(|t| t == label),
            "no tick {label:?} in {texts:?}"
        );
    }
    let hundreds = texts.iter().filter(|t| t.ends_with("⁰⁰")).count();
    assert_eq!(hundreds, 6, "{texts:?}");
}

#[test]
fn non_positive_values_on_log_axes_are_dropped() {
    let fig = Figure::new("mixed", Axis::log("x (m)"), Axis::log("y (m)"))
        .with_series(Series::line(
            "partly drawable",
            vec![
                (1.0, 1.0),
                (2.0, 0.0),
                (3.0, -1.0),
                (4.0, f64::NAN),
                (5.0, 10.0),
                (6.0, 100.0),
            ],
        ))
        .with_series(Series::line(
            "nothing drawable",
            vec![(-1.0, 1.0), (0.0, 2.0)],
        ));
    let dir = TempDir::new("nonpositive");
    render(&fig, &dir.join("mixed.png")).unwrap();
    let texts = svg_texts(&render_svg_string(&fig).unwrap());
    // The empty series keeps its legend entry.
    assert!(texts.iter().any(|t| t == "nothing drawable"), "{texts:?}");
}

#[test]
fn a_figure_without_drawable_data_is_an_error() {
    let fig = Figure::new("empty", Axis::log("x"), Axis::log("y"))
        .with_series(Series::line("zeros", vec![(0.0, 0.0), (-1.0, 1.0)]))
        .with_series(Series::markers("nan", vec![(f64::NAN, 1.0)]));
    match render_svg_string(&fig) {
        Err(Error::Inconsistent { name, .. }) => assert!(name.contains("empty"), "{name}"),
        other => panic!("expected Inconsistent, got {other:?}"),
    }
    let no_series = Figure::new("none", Axis::linear("x"), Axis::linear("y"));
    assert!(matches!(
        render_svg_string(&no_series),
        Err(Error::Inconsistent { .. })
    ));
}

#[test]
fn bad_extension_is_an_error_naming_path_and_formats() {
    let dir = TempDir::new("badext");
    let (_, fig, _) = standard_figures().remove(0);
    for name in ["figure.jpg", "figure", "figure.svg.txt"] {
        let path = dir.join(name);
        let err = render(&fig, &path).unwrap_err();
        let msg = err.to_string();
        assert!(
            matches!(&err, Error::Io { source, .. } if source.kind() == std::io::ErrorKind::InvalidInput),
            "{name}: {err:?}"
        );
        assert!(
            msg.contains(name) && msg.contains(".svg") && msg.contains(".png"),
            "{msg}"
        );
    }
    assert!(dir.files().is_empty(), "{:?}", dir.files());
    // Upper-case extensions are accepted.
    render(&fig, &dir.join("FIGURE.SVG")).unwrap();
}

#[test]
fn unwritable_directory_is_an_io_error_naming_the_path() {
    let dir = TempDir::new("unwritable");
    let (_, fig, _) = standard_figures().remove(0);
    // A directory that does not exist, and a "directory" that is a file (the
    // tests may run as root, for whom permission bits do not apply).
    std::fs::write(dir.join("plain-file"), b"x").unwrap();
    for path in [
        dir.join("missing").join("out.png"),
        dir.join("plain-file").join("out.svg"),
    ] {
        match render(&fig, &path) {
            Err(e @ Error::Io { .. }) => {
                assert!(e.to_string().contains(&*path.to_string_lossy()), "{e}")
            }
            other => panic!("{}: expected Io, got {other:?}", path.display()),
        }
    }
}

#[test]
fn failed_render_leaves_an_existing_file_untouched() {
    let dir = TempDir::new("untouched");
    let precious = b"the user's earlier figure";
    let bad = Figure::new("no data", Axis::log("x"), Axis::log("y"))
        .with_series(Series::line("zeros", vec![(0.0, 0.0)]));
    let bad_range = {
        let (_, mut fig, _) = standard_figures().remove(0);
        fig.y = fig.y.with_range(1.0, 1.0);
        fig
    };
    for name in ["keep.svg", "keep.png"] {
        let path = dir.join(name);
        std::fs::write(&path, precious).unwrap();
        assert!(render(&bad, &path).is_err());
        assert!(matches!(
            render(&bad_range, &path),
            Err(Error::InvalidParameter { .. })
        ));
        assert_eq!(
            std::fs::read(&path).unwrap(),
            precious,
            "{name} was modified"
        );
    }
    assert_eq!(dir.files(), ["keep.png", "keep.svg"]);
    // A failure after the temporary file was written (the rename onto a
    // non-empty directory fails) removes the temporary file.
    let busy = dir.join("busy.png");
    std::fs::create_dir(&busy).unwrap();
    std::fs::write(busy.join("inside"), b"x").unwrap();
    let (_, good, _) = standard_figures().remove(0);
    match render(&good, &busy) {
        Err(e @ Error::Io { .. }) => assert!(e.to_string().contains("busy.png"), "{e}"),
        other => panic!("expected Io, got {other:?}"),
    }
    assert_eq!(dir.files(), ["busy.png", "keep.png", "keep.svg"]);
    std::fs::remove_dir_all(&busy).unwrap();
    // A successful render replaces it.
    let (_, good, _) = standard_figures().remove(0);
    render(&good, &dir.join("keep.png")).unwrap();
    assert_eq!(png_size(&dir.join("keep.png")), DEFAULT_SIZE);
    assert_eq!(dir.files(), ["keep.png", "keep.svg"]);
}

#[test]
fn fixed_ranges_are_checked() {
    let base = || {
        Figure::new("r", Axis::log("x"), Axis::linear("y"))
            .with_series(Series::line("s", vec![(1.0, 1.0), (10.0, 2.0)]))
    };
    let cases: Vec<(Figure, &str)> = vec![
        (
            {
                let mut f = base();
                f.x = f.x.with_range(0.0, 10.0);
                f
            },
            "x range lower bound",
        ),
        (
            {
                let mut f = base();
                f.x = f.x.with_range(-1.0, 10.0);
                f
            },
            "x range lower bound",
        ),
        (
            {
                let mut f = base();
                f.y = f.y.with_range(2.0, 1.0);
                f
            },
            "y range upper bound",
        ),
        (
            {
                let mut f = base();
                f.y = f.y.with_range(0.0, f64::INFINITY);
                f
            },
            "y range upper bound",
        ),
        (
            {
                let mut f = base();
                f.y = f.y.with_range(f64::NAN, 1.0);
                f
            },
            "y range lower bound",
        ),
        (
            {
                let mut f = base();
                f.size = (100, 560);
                f
            },
            "figure width",
        ),
        (
            {
                let mut f = base();
                f.size = (800, 9000);
                f
            },
            "figure height",
        ),
    ];
    for (fig, expected) in cases {
        match render_svg_string(&fig) {
            Err(Error::InvalidParameter { name, .. }) => assert_eq!(name, expected),
            other => panic!("{expected}: expected InvalidParameter, got {other:?}"),
        }
    }
    // A valid fixed range clips the data instead of failing.
    let mut f = base();
    f.x = f.x.with_range(2.0, 5.0);
    f.y = f.y.with_range(1.2, 1.5);
    render_svg_string(&f).unwrap();
}

#[test]
fn png_has_the_requested_size_and_the_series_colour() {
    let dir = TempDir::new("pixels");
    let mut fig = Figure::new("", Axis::linear("x (m)"), Axis::linear("y (m)"))
        .with_series(Series::line("flat", vec![(0.0, 1.0), (1.0, 1.0)]))
        .with_series(Series::line("", vec![(0.0, 0.0), (1.0, 2.0)]).with_color(Rgb(255, 0, 255)));
    fig.size = (1000, 700);
    fig.legend = LegendPosition::Hidden;
    let path = dir.join("pixels.png");
    render(&fig, &path).unwrap();
    assert_eq!(png_size(&path), (1000, 700));
    let pixels = png_pixels(&path);
    assert_eq!(pixels.len(), 1000 * 700);
    let count = |c: [u8; 3]| pixels.iter().filter(|&&p| p == c).count();
    let first = PALETTE[0];
    // A horizontal line ~2.5 px wide across ~850 px of plot: at least one
    // full row of exactly the palette colour after the anti-aliasing.
    const MIN_LINE_PIXELS: usize = 700;
    assert!(count([first.0, first.1, first.2]) >= MIN_LINE_PIXELS);
    assert!(count([255, 0, 255]) >= MIN_LINE_PIXELS);
    assert!(
        count([255, 255, 255]) > pixels.len() / 2,
        "background is white"
    );
}

#[test]
fn legend_can_be_hidden_and_unlabelled_series_are_left_out() {
    let fig = |legend| {
        let mut f = Figure::new("legend", Axis::linear("x"), Axis::linear("y"))
            .with_series(Series::line("labelled", vec![(0.0, 0.0), (1.0, 1.0)]))
            .with_series(Series::dashed("", vec![(0.0, 1.0), (1.0, 0.0)]));
        f.legend = legend;
        f
    };
    let shown = svg_texts(&render_svg_string(&fig(LegendPosition::Auto)).unwrap());
    assert_eq!(shown.iter().filter(|t| *t == "labelled").count(), 1);
    let hidden = svg_texts(&render_svg_string(&fig(LegendPosition::Hidden)).unwrap());
    assert!(!hidden.iter().any(|t| t == "labelled"), "{hidden:?}");
}

#[test]
fn every_style_renders() {
    let styles = [
        Style::Line,
        Style::Dashed,
        Style::Dotted,
        Style::Markers,
        Style::LineMarkers,
    ];
    let mut fig = Figure::new("styles", Axis::linear("x"), Axis::log("y"));
    for (i, style) in styles.iter().enumerate() {
        for shape in 0..4 {
            let pts = (0..10)
                .map(|k| {
                    (
                        k as f64,
                        (1.0 + i as f64 + shape as f64 * 5.0) * 1.5f64.powi(k),
                    )
                })
                .collect();
            fig.push(Series::new(format!("{style:?} {shape}"), pts, *style));
        }
    }
    let dir = TempDir::new("styles");
    render(&fig, &dir.join("styles.png")).unwrap();
    let texts = svg_texts(&render_svg_string(&fig).unwrap());
    assert!(texts.iter().any(|t| t == "LineMarkers 3"), "{texts:?}");
}

#[test]
fn builders_check_their_input() {
    let x = [1.0, 2.0, 3.0];
    let short = [1.0, 2.0];
    assert!(matches!(
        plot::stress_family(&x, &[("a", &short)]),
        Err(Error::Inconsistent { .. })
    ));
    assert!(matches!(
        plot::area_vs_zeta(&x, &[("a", &short)]),
        Err(Error::Inconsistent { .. })
    ));
    assert!(matches!(
        plot::g_vs_zeta(&x, &[("a", &short)]),
        Err(Error::Inconsistent { .. })
    ));
    assert!(matches!(
        plot::area_vs_load(&x, &[("a", &short)], "Pa", None),
        Err(Error::Inconsistent { .. })
    ));
    assert!(matches!(
        plot::spectrum(&x, &short, None),
        Err(Error::Inconsistent { .. })
    ));
    assert!(matches!(
        plot::area_vs_load(
            &x,
            &[("a", &x)],
            "Pa",
            Some(LinearLaw {
                contact_modulus: 0.0,
                rms_slope: 1.0
            })
        ),
        Err(Error::InvalidParameter { .. })
    ));
    for (prefactor, exponent) in [(0.0, -3.6), (-1.0, -3.6), (1.0, f64::NAN)] {
        let fit = PowerLaw {
            prefactor,
            exponent,
            q_range: None,
        };
        assert!(matches!(
            plot::spectrum(&x, &x, Some(fit)),
            Err(Error::InvalidParameter { .. })
        ));
    }
}

#[test]
fn linear_laws_stop_at_full_contact() {
    // κ σ0/(E* slope) = 1 at σ0 = E* slope/κ: the Bush line ends there.
    let p = geomspace(1e3, 1e8, 20);
    let a: Vec<f64> = p.iter().map(|p| (p / 1e8).min(1.0)).collect();
    let law = LinearLaw {
        contact_modulus: 1e7,
        rms_slope: 1.0,
    };
    let fig = plot::area_vs_load(&p, &[("theory", &a)], "Pa", Some(law)).unwrap();
    let bush = fig
        .series
        .iter()
        .find(|s| s.label.starts_with("Bush"))
        .unwrap();
    let &(p_end, a_end) = bush.points.last().unwrap();
    let expected_end = 1e7 / (2.0 * std::f64::consts::PI).sqrt();
    // Two-point line evaluated in f64: a few ulps.
    const TOL: f64 = 1e-14;
    assert!((p_end / expected_end - 1.0).abs() < TOL, "{p_end}");
    assert!((a_end - 1.0).abs() < TOL, "{a_end}");
    assert_eq!(bush.points[0].0, 1e3);
}
