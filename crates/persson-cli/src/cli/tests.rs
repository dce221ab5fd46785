//! Nothing the user gave is lost: for every output flag of every command,
//! an output onto an input is refused before anything is computed, and a
//! run that fails leaves an existing output byte for byte as it was.

use std::path::{Path, PathBuf};

use clap::{CommandFactory, FromArgMatches};

use super::files::{InFile, OutDir, OutFile};
use super::{stage, Cli};

/// One command line of each command that writes files, small enough to
/// run in a test: its arguments (`{d}` the fixtures' folder), the input
/// an output is aimed at in the overwrite test (`None`: the command reads
/// no file), and its output flags with an extension each flag accepts and
/// the flags it needs beside it.
struct Case {
    args: &'static str,
    input: Option<&'static str>,
    outputs: &'static [(&'static str, &'static str, &'static str)],
}

const PSD: &str = "--psd {d}/spec.csv --contact-modulus 1e9 --pressure 1e6";

fn cases() -> Vec<Case> {
    vec![
        Case {
            args: "area {psd}",
            input: Some("spec.csv"),
            outputs: &[("--plot", "svg", "")],
        },
        Case {
            args: "magnification {psd}",
            input: Some("spec.csv"),
            outputs: &[("--plot", "svg", ""), ("--plot-g", "png", "")],
        },
        Case {
            args: "separation {psd}",
            input: Some("spec.csv"),
            outputs: &[("--plot", "svg", ""), ("--plot-area", "svg", "")],
        },
        Case {
            args: "spectrum --surface {d}/surf.npy --size 1e-3",
            input: Some("surf.npy"),
            outputs: &[("--plot", "svg", ""), ("--psd-out", "csv", "")],
        },
        Case {
            args: "anisotropy --surface {d}/surf.npy --size 1e-3",
            input: Some("surf.npy"),
            outputs: &[("--plot", "png", ""), ("--spectrum-2d", "npy", "")],
        },
        Case {
            args: "stress {psd} --flat",
            input: Some("spec.csv"),
            outputs: &[("--plot", "svg", "")],
        },
        Case {
            args: "conductance {psd} --conductivity 50",
            input: Some("spec.csv"),
            outputs: &[("--plot", "svg", "")],
        },
        Case {
            args: "leakage --psd {d}/spec.csv --contact-modulus 1e9 --pressure 1e3 \
                   --viscosity 1e-3 --pressure-drop 1e5",
            input: Some("spec.csv"),
            outputs: &[("--plot", "svg", "")],
        },
        Case {
            args:
                "friction --psd {d}/spec.csv --master-curve {d}/curve.csv --frequency-unit rad/s \
                   --pressure 1e5 --velocity 1e-2",
            input: Some("curve.csv"),
            outputs: &[("--plot", "svg", "")],
        },
        Case {
            args: "surrogates --surface {d}/surf.npy --size 1e-3 --contact-modulus 1e9 \
                   --pressure 1e6 --count 2",
            input: Some("surf.npy"),
            outputs: &[
                ("--surfaces", "npy", ""),
                ("--plot", "svg", ""),
                ("--plot-distribution", "png", ""),
            ],
        },
        Case {
            args:
                "bem rough --surface {d}/surf.npy --size 1e-3 --contact-modulus 1e9 --pressure 1e6",
            input: Some("surf.npy"),
            outputs: &[
                ("--pressure-field", "npy", ""),
                ("--histogram", "csv", ""),
                ("--surface-out", "npy", ""),
                ("--plot", "svg", ""),
                ("--area-plot", "svg", ""),
                ("--gap-field", "npy", "--conductivity 50"),
                ("--stress-field", "npy", "--subsurface --depth 1e-5"),
                ("--stress-plot", "svg", "--subsurface --depth 1e-5"),
                ("--patches-plot", "svg", "--patches"),
            ],
        },
        Case {
            args: "bem hertz --grid 32 --subsurface",
            input: None,
            outputs: &[("--stress-plot", "svg", "")],
        },
        Case {
            args: "compare --surface {d}/surf.npy --size 1e-3 --periodic --contact-modulus 1e9 \
                   --pressure 1e6 --levels 2",
            input: Some("surf.npy"),
            outputs: &[
                ("--plot", "svg", ""),
                ("--plot-histogram", "svg", ""),
                ("--plot-histogram-log", "png", ""),
            ],
        },
        Case {
            args: "compare kappa --hurst 0.8 --grid 32 --levels 2 --pressure 1e-3",
            input: None,
            outputs: &[("--plot", "svg", "")],
        },
        Case {
            args: "report accuracy",
            input: None,
            outputs: &[("--plot", "svg", "")],
        },
        Case {
            args: "run {d}/scene.json",
            input: Some("scene.json"),
            outputs: &[("--out", "", "")],
        },
    ]
}

/// A fresh folder with the fixtures: a 32² surface, its spectrum, a master
/// curve and a scene.
fn fixtures(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("persson-files-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    let q = std::f64::consts::TAU / 1e-3;
    let spectrum = persson::spectrum::SelfAffine::new(
        q,
        2.0 * q,
        8.0 * q,
        0.8,
        persson::spectrum::Amplitude::RmsHeight(1e-6),
    )
    .unwrap();
    let s = persson::bem::surface::synthesize(&spectrum, 32, 1e-3, 1).unwrap();
    persson::io::npy::write(&d.join("surf.npy"), 32, 32, &s.heights).unwrap();
    let mut csv = String::from("q,c\n");
    for k in 0..40 {
        let q = 1e3 * 10f64.powf(k as f64 / 8.0);
        csv.push_str(&format!("{q},{}\n", 1e-22 * (q / 1e3).powf(-3.6)));
    }
    std::fs::write(d.join("spec.csv"), csv).unwrap();
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    std::fs::copy(
        root.join("tests/reference/data/rubber_master_curve.csv"),
        d.join("curve.csv"),
    )
    .unwrap();
    std::fs::write(
        d.join("scene.json"),
        r#"{"schema": 1, "spectrum": {"kind": "tabulated", "file": "spec.csv"},
            "material": {"contact_modulus": 1e9}, "nominal_pressure": [1e6],
            "outputs": {"area": {"plot": "area.svg"}}}"#,
    )
    .unwrap();
    d
}

/// `args` with `{psd}` and `{d}` filled in, split into words.
fn words(args: &str, d: &Path, extra: &[&str]) -> Vec<String> {
    let line = args
        .replace("{psd}", PSD)
        .replace("{d}", &d.display().to_string());
    std::iter::once("persson".to_string())
        .chain(line.split_whitespace().map(String::from))
        .chain(extra.iter().map(|s| s.to_string()))
        .collect()
}

/// Parse and stage `words` (computed, outputs staged, nothing committed).
fn staged(words: &[String]) -> anyhow::Result<persson_studies::output::Files> {
    let m = Cli::command()
        .try_get_matches_from(words)
        .map_err(|e| anyhow::anyhow!("clap: {e}"))?;
    let cli = Cli::from_arg_matches(&m).map_err(|e| anyhow::anyhow!("clap: {e}"))?;
    stage(cli, &m)
}

/// Every output flag of the command tree: (subcommand path, flag).
fn output_flags() -> Vec<(String, String)> {
    fn walk(cmd: &clap::Command, path: &str, out: &mut Vec<(String, String)>) {
        for a in cmd.get_arguments() {
            let id = a.get_value_parser().type_id();
            if id == std::any::TypeId::of::<OutFile>() || id == std::any::TypeId::of::<OutDir>() {
                out.push((path.trim().to_string(), super::files::flag(a)));
            }
        }
        for s in cmd.get_subcommands() {
            walk(s, &format!("{path} {}", s.get_name()), out);
        }
    }
    let mut out = Vec::new();
    walk(&Cli::command(), "", &mut out);
    out
}

/// The subcommand words of a case (`bem rough`).
fn command_of(args: &str) -> String {
    args.split_whitespace()
        .take_while(|w| !w.starts_with('-') && !w.starts_with('{'))
        .collect::<Vec<_>>()
        .join(" ")
}

#[test]
fn every_output_flag_has_a_case() {
    let covered: Vec<(String, String)> = cases()
        .iter()
        .flat_map(|c| {
            c.outputs
                .iter()
                .map(|(flag, ..)| (command_of(c.args), flag.to_string()))
        })
        .collect();
    for f in output_flags() {
        assert!(covered.contains(&f), "no case for {f:?}");
    }
    // and the input flags are typed too: a path flag of neither type would be missed
    fn untyped(cmd: &clap::Command, out: &mut Vec<String>) {
        for a in cmd.get_arguments() {
            let id = a.get_value_parser().type_id();
            let path = id == std::any::TypeId::of::<PathBuf>();
            if path {
                out.push(super::files::flag(a));
            }
        }
        cmd.get_subcommands().for_each(|s| untyped(s, out));
    }
    let mut bare = Vec::new();
    untyped(&Cli::command(), &mut bare);
    assert!(
        bare.is_empty(),
        "path flags without InFile/OutFile: {bare:?}"
    );
    let _ = InFile::clone;
}

#[test]
fn an_output_onto_an_input_is_refused_before_computing() {
    let d = fixtures("onto");
    for c in cases() {
        let Some(input) = c.input else { continue };
        for (flag, _, needs) in c.outputs {
            let target = d.join(input);
            let before = std::fs::read(&target).unwrap();
            let mut extra: Vec<String> = needs.split_whitespace().map(String::from).collect();
            extra.push(flag.to_string());
            extra.push(target.display().to_string());
            let extra: Vec<&str> = extra.iter().map(String::as_str).collect();
            let w = words(c.args, &d, &extra);
            let e = match staged(&w) {
                Ok(_) => panic!("{w:?}: accepted"),
                Err(e) => format!("{e:#}"),
            };
            assert!(
                e.contains(&format!("{flag} would overwrite the input file"))
                    || e.contains(&format!("{flag} is the input file")),
                "{w:?}: {e}"
            );
            assert_eq!(std::fs::read(&target).unwrap(), before, "{w:?}");
        }
    }
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn a_run_that_fails_after_computing_leaves_every_output_as_it_was() {
    let d = fixtures("failed");
    for c in cases() {
        for (flag, ext, needs) in c.outputs {
            if *flag == "--out" {
                continue; // `persson run` lists what it wrote: tests/scene.rs
            }
            let out = d.join(format!("old.{ext}"));
            std::fs::write(&out, b"the user's earlier result").unwrap();
            let mut extra: Vec<String> = needs.split_whitespace().map(String::from).collect();
            extra.push(flag.to_string());
            extra.push(out.display().to_string());
            let extra: Vec<&str> = extra.iter().map(String::as_str).collect();
            let w = words(c.args, &d, &extra);
            // Computed and staged: a failure from here on must leave `out` alone.
            let files = staged(&w).unwrap_or_else(|e| panic!("{w:?}: {e:#}"));
            assert_eq!(
                std::fs::read(&out).unwrap(),
                b"the user's earlier result",
                "{w:?}"
            );
            drop(files); // the run fails
            assert_eq!(
                std::fs::read(&out).unwrap(),
                b"the user's earlier result",
                "{w:?}"
            );
            let left: Vec<_> = std::fs::read_dir(&d)
                .unwrap()
                .filter_map(|e| e.ok())
                .map(|e| e.file_name().to_string_lossy().into_owned())
                .filter(|n| n.contains(".tmp"))
                .collect();
            assert!(left.is_empty(), "{w:?}: {left:?}");
            // The same run that succeeds does replace it (so the check above can fail).
            let mut files = staged(&w).unwrap();
            files.commit().unwrap();
            let written = files_named(&d, "old");
            assert!(
                written
                    .iter()
                    .any(|p| std::fs::read(p).unwrap() != b"the user's earlier result"),
                "{w:?}: nothing written"
            );
            for p in written {
                std::fs::remove_file(p).ok();
            }
        }
    }
    std::fs::remove_dir_all(&d).ok();
}

/// The files of `d` whose name starts with `stem` (`old.npy`, `old_0_0.npy`).
fn files_named(d: &Path, stem: &str) -> Vec<PathBuf> {
    std::fs::read_dir(d)
        .unwrap()
        .filter_map(|e| e.ok())
        .map(|e| e.path())
        .filter(|p| {
            p.file_name()
                .is_some_and(|n| n.to_string_lossy().starts_with(stem))
        })
        .collect()
}

/// A command whose feature a build leaves out names the feature and the
/// build that has it (the default build is the theory's).
#[test]
fn a_left_out_feature_is_named_with_the_build_that_has_it() {
    let e = super::features::left_out("bem").to_string();
    assert!(e.contains("the feature `bem`"), "{e}");
    assert!(e.contains("--features full"), "{e}");
}

/// clap's own consistency checks on the whole command line, with the flags
/// the studies' specs derive: no flag declared twice (a spec's field named
/// as a shared flag), every default among its values.
#[test]
fn the_command_line_is_consistent() {
    Cli::command().debug_assert();
}
