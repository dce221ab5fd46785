//! `persson bem`: the FFT boundary-element cross-check (Hertz validation and
//! rough-surface solves).

use std::path::{Path, PathBuf};

use anyhow::Context;
use persson::bem::surface::{read_height_map, synthesize, write_npy};
use persson::bem::{
    check_memory, hertz, pressure_histogram, Boundary, Control, Iteration, Operator, Options,
    Solver, Surface,
};
use persson::error::check;
use serde_json::json;

use super::args::{MaterialArgs, SpectrumArgs};
use super::output::{Format, Report};

/// Arguments of `persson bem`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(subcommand)]
    cmd: Cmd,
}

#[derive(clap::Subcommand, Debug)]
enum Cmd {
    /// Hertz validation: energy-norm error η, fitted contact radius and peak pressure.
    Hertz(HertzArgs),
    /// Rough contact: contact fraction at each nominal pressure.
    Rough(Box<RoughArgs>),
}

/// Boundary condition flag.
#[derive(clap::ValueEnum, Debug, Clone, Copy, PartialEq, Eq)]
enum BoundaryArg {
    /// The grid is one period of a periodic system.
    Periodic,
    /// Isolated contact: zero-padded to 2N, no periodic images.
    Free,
}

impl From<BoundaryArg> for Boundary {
    fn from(b: BoundaryArg) -> Self {
        match b {
            BoundaryArg::Periodic => Boundary::Periodic,
            BoundaryArg::Free => Boundary::Free,
        }
    }
}

/// Solver knobs shared by both subcommands.
#[derive(clap::Args, Debug, Clone)]
struct SolverArgs {
    /// Relative tolerance ε of the Polonsky–Keer solver (p-weighted gap over σ_h).
    #[arg(long, default_value_t = 1e-10, allow_negative_numbers = true)]
    tol: f64,
    /// Maximum number of iterations per solve.
    #[arg(long, default_value_t = 10_000)]
    max_iter: usize,
}

#[derive(clap::Args, Debug)]
struct HertzArgs {
    /// Grid side N (nodes per side), at least 8.
    #[arg(long, default_value_t = 256)]
    grid: usize,
    /// Boundary condition of the elastic half-space.
    #[arg(long, value_enum, default_value_t = BoundaryArg::Free)]
    boundary: BoundaryArg,
    /// Side L of the square domain.
    #[arg(long, default_value_t = 1.0, allow_negative_numbers = true)]
    size: f64,
    /// Sphere radius R (unit of L).
    #[arg(long, default_value_t = 1.0, allow_negative_numbers = true)]
    radius: f64,
    /// Contact modulus E*.
    #[arg(long, default_value_t = 1.0, allow_negative_numbers = true)]
    modulus: f64,
    /// Hertz contact radius a that sets the load (default 0.1 L).
    #[arg(long, allow_negative_numbers = true)]
    contact_radius: Option<f64>,
    #[command(flatten)]
    solver: SolverArgs,
    #[command(flatten)]
    format: Format,
}

#[derive(clap::Args, Debug)]
struct RoughArgs {
    /// Height map of the rigid surface: .npy (float64/float32, 2-D square) or a text matrix.
    #[arg(long, requires = "size")]
    surface: Option<PathBuf>,
    /// Physical side L of the surface (default with a spectrum: 2π/q_l).
    #[arg(long, allow_negative_numbers = true)]
    size: Option<f64>,
    /// Grid side N for a synthesised surface.
    #[arg(long, conflicts_with = "surface")]
    grid: Option<usize>,
    /// Seed of the synthesised surface (Pcg64Mcg, value-stable).
    #[arg(long, default_value_t = 1, conflicts_with = "surface")]
    seed: u64,
    #[command(flatten)]
    spectrum: SpectrumArgs,
    #[command(flatten)]
    material: MaterialArgs,
    /// Nominal (mean) pressure, same unit as the modulus; repeatable or comma-separated.
    #[arg(
        long,
        value_delimiter = ',',
        allow_negative_numbers = true,
        required_unless_present = "example"
    )]
    pressure: Vec<f64>,
    /// Boundary condition of the elastic half-space.
    #[arg(long, value_enum, default_value_t = BoundaryArg::Periodic)]
    boundary: BoundaryArg,
    /// Write each pressure field as .npy (N×N float64); `_k` is added before
    /// the extension when several pressures are given.
    #[arg(long)]
    pressure_field: Option<PathBuf>,
    /// Write the histogram P(σ) of each solve as CSV (pressure_low,
    /// pressure_high, density; the bins integrate to A/A0).
    #[arg(long)]
    histogram: Option<PathBuf>,
    /// Number of histogram bins.
    #[arg(long, default_value_t = 50)]
    bins: usize,
    /// Write the (synthesised or read) surface heights as .npy.
    #[arg(long)]
    surface_out: Option<PathBuf>,
    #[command(flatten)]
    solver: SolverArgs,
    #[command(flatten)]
    format: Format,
}

/// Run `persson bem`.
pub fn run(a: Args) -> anyhow::Result<()> {
    match a.cmd {
        Cmd::Hertz(h) => {
            let f = h.format.clone();
            hertz_report(&h)?.print(&f)
        }
        Cmd::Rough(r) => {
            let f = r.format.clone();
            rough_report(&r)?.print(&f)
        }
    }
}

fn options(s: &SolverArgs) -> anyhow::Result<Options> {
    check::tolerance("tol", s.tol)?;
    Ok(Options {
        tol: s.tol,
        max_iter: s.max_iter,
        warm_start: true,
    })
}

fn hertz_report(a: &HertzArgs) -> anyhow::Result<Report> {
    let boundary = Boundary::from(a.boundary);
    check_memory(a.grid, boundary)?;
    let case = hertz::HertzCase {
        grid: a.grid,
        boundary,
        size: a.size,
        radius: a.radius,
        e_star: a.modulus,
        contact_radius: a.contact_radius.unwrap_or(0.1 * a.size),
    };
    let opts = options(&a.solver)?;
    let spinner = Progress::spinner(&format!("Hertz {}² {:?}", a.grid, boundary));
    let r = hertz::validate_observed(&case, &opts, &mut |it| spinner.tick(it))?;
    spinner.finish();
    let mut scalars = vec![
        ("grid".into(), a.grid as f64),
        ("energy_error".into(), r.energy_error),
        ("contact_radius".into(), r.contact_radius),
        ("contact_radius_error".into(), r.contact_radius_error),
        ("peak_pressure".into(), r.peak_pressure),
        ("peak_pressure_error".into(), r.peak_pressure_error),
        ("contact_fraction".into(), r.contact_fraction),
        ("iterations".into(), r.iterations as f64),
        ("residual".into(), r.residual),
        ("seconds".into(), r.seconds),
    ];
    if let Some(l) = r.energy_error_lecture {
        scalars.insert(2, ("energy_error_lecture".into(), l));
    }
    Ok(Report {
        title: format!(
            "Hertz validation, {0}x{0} grid, {1} boundary, a = {2:e}, R = {3:e}, E* = {4:e}, tol = {5:e}",
            a.grid,
            format!("{boundary:?}").to_lowercase(),
            case.contact_radius,
            a.radius,
            a.modulus,
            opts.tol
        ),
        scalars,
        columns: Vec::new(),
        rows: Vec::new(),
        json: json!({
            "grid": a.grid,
            "boundary": boundary,
            "size": a.size,
            "radius": a.radius,
            "contact_modulus": a.modulus,
            "tol": opts.tol,
            "hertz_contact_radius": case.contact_radius,
            "hertz_peak_pressure": case.peak_pressure(),
            "mean_pressure": case.mean_pressure(),
            "energy_error": r.energy_error,
            "energy_error_lecture": r.energy_error_lecture,
            "contact_radius": r.contact_radius,
            "contact_radius_error": r.contact_radius_error,
            "peak_pressure": r.peak_pressure,
            "peak_pressure_error": r.peak_pressure_error,
            "contact_fraction": r.contact_fraction,
            "iterations": r.iterations,
            "residual": r.residual,
            "seconds": r.seconds,
        }),
    })
}

/// The rigid surface from a file or from the spectrum flags.
fn surface(a: &RoughArgs, boundary: Boundary) -> anyhow::Result<(Surface, serde_json::Value)> {
    if let Some(path) = &a.surface {
        let size = check::positive("size", a.size.context("--surface needs --size L")?)?;
        let len = std::fs::metadata(path)
            .map_err(|source| persson::Error::Io {
                path: path.clone(),
                source,
            })?
            .len();
        // A float32 file of this length holds at most len/4 values.
        let n_max = ((len / 4) as f64).sqrt() as usize;
        if n_max > persson::bem::MIN_GRID {
            check_memory(n_max.min(persson::bem::MAX_GRID), boundary)?;
        }
        let s = read_height_map(path, size)?;
        let src = json!({ "file": path.display().to_string() });
        return Ok((s, src));
    }
    let n = a
        .grid
        .context("no surface: give --surface FILE --size L, or spectrum flags with --grid N")?;
    check_memory(n, boundary)?;
    let spectrum = a.spectrum.build()?;
    let size = match a.size {
        Some(l) => check::positive("size", l)?,
        None => std::f64::consts::TAU / spectrum.q_min(),
    };
    let s = synthesize(spectrum.as_ref(), n, size, a.seed)?;
    let (q_l, q_s) = (spectrum.q_min(), spectrum.q_max());
    let src = json!({
        "seed": a.seed,
        "spectrum_q_l": q_l,
        "spectrum_q_s": q_s,
        "spectrum_rms_height": spectrum.rms_height(q_l, q_s)?.value,
        "spectrum_rms_slope": spectrum.rms_slope(q_l, q_s)?.value,
    });
    Ok((s, src))
}

fn rough_report(a: &RoughArgs) -> anyhow::Result<Report> {
    let boundary = Boundary::from(a.boundary);
    if let Some(n) = a.grid {
        persson::bem::check_grid(n)?;
    }
    let pressures = super::args::pressures(&a.pressure, a.spectrum.example)?;
    for &p in &pressures {
        check::positive("pressure", p)?;
    }
    let opts = options(&a.solver)?;
    let e_star = a.material.build(a.spectrum.example)?.contact_modulus();
    let (surf, source) = surface(a, boundary)?;
    check_memory(surf.n, boundary)?;
    let n = surf.n;
    if let Some(path) = &a.surface_out {
        write_npy(path, n, n, &surf.heights)?;
    }
    let mut solver = Solver::new(Operator::new(boundary, n, surf.size, e_star)?);
    let rms_height = surf.rms_height();
    let rms_slope = surf.rms_slope()?;
    let mut rows = Vec::new();
    let mut points = Vec::new();
    let bar = Progress::bar(pressures.len());
    for (k, &p) in pressures.iter().enumerate() {
        bar.message(&format!("pressure {p:e}"));
        let sol =
            solver.solve_observed(&surf.heights, Control::MeanPressure(p), &opts, &mut |it| {
                bar.tick(it)
            })?;
        bar.inc();
        let suffix = (pressures.len() > 1).then_some(k);
        if let Some(path) = &a.pressure_field {
            write_npy(&indexed(path, suffix), n, n, &sol.pressure)?;
        }
        if let Some(path) = &a.histogram {
            write_histogram(&indexed(path, suffix), &sol.pressure, a.bins)?;
        }
        rows.push(vec![
            p,
            sol.contact_fraction,
            sol.iterations as f64,
            sol.residual,
            sol.approach,
            sol.seconds,
        ]);
        points.push(json!({
            "pressure": p,
            "contact_fraction": sol.contact_fraction,
            "iterations": sol.iterations,
            "residual": sol.residual,
            "approach": sol.approach,
            "seconds": sol.seconds,
        }));
    }
    bar.finish();
    Ok(Report {
        title: format!(
            "Rough contact (FFT-BEM, Polonsky–Keer), {n}x{n} grid, L = {:e}, {} boundary, E* = {e_star:e}, tol = {:e}",
            surf.size,
            format!("{boundary:?}").to_lowercase(),
            opts.tol
        ),
        scalars: vec![
            ("grid".into(), n as f64),
            ("size".into(), surf.size),
            ("rms_height".into(), rms_height),
            ("rms_slope".into(), rms_slope),
        ],
        columns: ["pressure", "contact_fraction", "iterations", "residual", "approach", "seconds"]
            .map(String::from)
            .to_vec(),
        rows,
        json: json!({
            "grid": n,
            "size": surf.size,
            "boundary": boundary,
            "contact_modulus": e_star,
            "tol": opts.tol,
            "rms_height": rms_height,
            "rms_slope": rms_slope,
            "surface": source,
            "points": points,
        }),
    })
}

/// `dir/name.ext` → `dir/name_k.ext` when `k` is given.
fn indexed(path: &Path, k: Option<usize>) -> PathBuf {
    let Some(k) = k else {
        return path.to_path_buf();
    };
    let stem = path
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    let name = match path.extension() {
        Some(e) => format!("{stem}_{k}.{}", e.to_string_lossy()),
        None => format!("{stem}_{k}"),
    };
    path.with_file_name(name)
}

fn write_histogram(path: &Path, pressure: &[f64], bins: usize) -> anyhow::Result<()> {
    let h = pressure_histogram(pressure, bins)?;
    let mut s = String::from("pressure_low,pressure_high,density\n");
    for b in h {
        s.push_str(&format!(
            "{:e},{:e},{:e}\n",
            b.pressure_low, b.pressure_high, b.density
        ));
    }
    std::fs::write(path, s).map_err(|source| persson::Error::Io {
        path: path.to_path_buf(),
        source,
    })?;
    Ok(())
}

/// Progress display on stderr, shown only on a terminal (feature `progress`).
struct Progress {
    #[cfg(feature = "progress")]
    bar: indicatif::ProgressBar,
}

impl Progress {
    #[cfg(feature = "progress")]
    fn spinner(msg: &str) -> Self {
        let bar = indicatif::ProgressBar::new_spinner();
        bar.set_message(msg.to_string());
        Progress { bar }
    }

    #[cfg(not(feature = "progress"))]
    fn spinner(_msg: &str) -> Self {
        Progress {}
    }

    #[cfg(feature = "progress")]
    fn bar(len: usize) -> Self {
        let bar = indicatif::ProgressBar::new(len as u64);
        if let Ok(style) =
            indicatif::ProgressStyle::with_template("{bar:30} {pos}/{len} solves {msg} [{elapsed}]")
        {
            bar.set_style(style);
        }
        Progress { bar }
    }

    #[cfg(not(feature = "progress"))]
    fn bar(_len: usize) -> Self {
        Progress {}
    }

    #[allow(unused_variables)]
    fn message(&self, msg: &str) {
        #[cfg(feature = "progress")]
        self.bar.set_message(msg.to_string());
    }

    #[allow(unused_variables)]
    fn tick(&self, it: Iteration) {
        #[cfg(feature = "progress")]
        if it.iteration.is_multiple_of(10) {
            self.bar.set_message(format!(
                "iteration {} residual {:.2e} contact {:.4}",
                it.iteration, it.residual, it.contact_fraction
            ));
        }
    }

    fn inc(&self) {
        #[cfg(feature = "progress")]
        self.bar.inc(1);
    }

    fn finish(&self) {
        #[cfg(feature = "progress")]
        self.bar.finish_and_clear();
    }
}
