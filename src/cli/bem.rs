//! `persson bem`: the FFT boundary-element cross-check (Hertz validation and
//! rough-surface solves).

use std::path::{Path, PathBuf};

use anyhow::Context;
use persson::bem::rough::{self, Observer, RoughOptions, RoughProgress, SurfaceSource};
use persson::bem::surface::{synthesize, write_npy};
use persson::bem::{check_memory, hertz::HertzCase, Boundary, Options, Solution};
use persson::error::check;
use persson::table::csv_number;

use super::args::{MaterialArgs, SpectrumArgs};
use super::output::{print, Format};
use super::progress::Progress;

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
    /// Rough contact: contact fraction and mean separation at each nominal pressure.
    Rough(Box<RoughArgs>),
}

/// Solver knobs shared by both subcommands (and `persson compare`).
#[derive(clap::Args, Debug, Clone)]
pub struct SolverArgs {
    /// Relative tolerance ε of the Polonsky–Keer solver (pressure-weighted gap over the rms height).
    #[arg(long, default_value = "1e-10", allow_negative_numbers = true)]
    tolerance: f64,
    /// Maximum number of iterations per solve.
    #[arg(long, default_value = "10000")]
    max_iterations: usize,
}

impl SolverArgs {
    /// The solver options, warm-started along a list of pressures.
    pub fn options(&self) -> anyhow::Result<Options> {
        check::tolerance("tolerance", self.tolerance)?;
        Ok(Options {
            tol: self.tolerance,
            max_iter: self.max_iterations,
            warm_start: true,
        })
    }
}

#[derive(clap::Args, Debug)]
struct HertzArgs {
    /// Grid side N (nodes per side), at least 8.
    #[arg(long, default_value = "256")]
    grid: usize,
    /// Boundary condition of the elastic half-space: free (an isolated contact, zero-padded to 2N) or periodic.
    #[arg(long, default_value = "free")]
    boundary: Boundary,
    /// Side L of the square domain.
    #[arg(long, default_value = "1", allow_negative_numbers = true)]
    size: f64,
    /// Ball radius R (unit of L).
    #[arg(long, default_value = "1", allow_negative_numbers = true)]
    radius: f64,
    /// Contact modulus E*.
    #[arg(
        long,
        alias = "modulus",
        default_value = "1",
        allow_negative_numbers = true
    )]
    contact_modulus: f64,
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
    #[arg(long, default_value = "1", conflicts_with = "surface")]
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
    /// Boundary condition of the elastic half-space: periodic (the grid is one period) or free.
    #[arg(long, default_value = "periodic")]
    boundary: Boundary,
    /// Write each pressure field as .npy (N×N float64); `_k` is added before
    /// the extension when several pressures are given.
    #[arg(long)]
    pressure_field: Option<PathBuf>,
    /// Write the histogram P(σ) of each solve as CSV (sigma_low, sigma_high,
    /// density; the bins integrate to A/A0).
    #[arg(long)]
    histogram: Option<PathBuf>,
    /// Number of histogram bins.
    #[arg(long, default_value = "50")]
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
            let case = HertzCase {
                grid: h.grid,
                boundary: h.boundary,
                size: h.size,
                radius: h.radius,
                e_star: h.contact_modulus,
                contact_radius: h.contact_radius.unwrap_or(0.1 * h.size),
            };
            let mut bar = Progress::spinner(&format!("Hertz {}²", h.grid));
            let r = persson::validation::hertz(&case, &h.solver.options()?, &mut |it| {
                bar.update(0, &|| "Hertz".into(), it)
            });
            bar.finish();
            print(&r?, &h.format)
        }
        Cmd::Rough(r) => rough_contact(&r),
    }
}

/// The CLI's view of the solves: progress, and the pressure fields to write.
struct Solves<'a> {
    bar: Progress,
    fields: Option<&'a Path>,
    several: bool,
    n: usize,
}

impl Observer for Solves<'_> {
    fn iteration(&mut self, p: RoughProgress) {
        let what = || format!("σ0 = {:e}", p.nominal_pressure);
        self.bar.update(p.index, &what, p.iteration);
    }
    fn solution(&mut self, k: usize, s: &Solution) -> persson::Result<()> {
        match self.fields {
            Some(path) => write_npy(
                &indexed(path, self.several.then_some(k)),
                self.n,
                self.n,
                &s.pressure,
            ),
            None => Ok(()),
        }
    }
}

fn rough_contact(a: &RoughArgs) -> anyhow::Result<()> {
    let pressures = super::args::pressures(&a.pressure, a.spectrum.example)?;
    let options = RoughOptions {
        boundary: a.boundary,
        solver: a.solver.options()?,
        bins: a.histogram.as_ref().map(|_| a.bins),
    };
    let e_star = a.material.build(a.spectrum.example)?.contact_modulus();
    let (surface, source) = if let Some(path) = &a.surface {
        let size = a.size.context("--surface needs --size L")?;
        (
            rough::read_surface(path, size, a.boundary)?,
            SurfaceSource::height_map(path),
        )
    } else {
        let n = a
            .grid
            .context("no surface: give --surface FILE --size L, or spectrum flags with --grid N")?;
        check_memory(n, a.boundary)?;
        let spectrum = a.spectrum.build()?;
        let size = check::positive(
            "size",
            a.size.unwrap_or(std::f64::consts::TAU / spectrum.q_min()),
        )?;
        let s = synthesize(spectrum.as_ref(), n, size, a.seed)?;
        (s, SurfaceSource::synthesised(spectrum.as_ref(), a.seed)?)
    };
    if let Some(path) = &a.surface_out {
        write_npy(path, surface.n, surface.n, &surface.heights)?;
    }
    let several = pressures.len() > 1;
    let mut solves = Solves {
        bar: Progress::solves(pressures.len(), None),
        fields: a.pressure_field.as_deref(),
        several,
        n: surface.n,
    };
    let report = rough::rough_contact(&surface, source, e_star, &pressures, &options, &mut solves);
    solves.bar.finish();
    let report = report?;
    if let Some(path) = &a.histogram {
        for (k, p) in report.points.iter().enumerate() {
            let mut s = String::from("sigma_low,sigma_high,density\n");
            for b in p.histogram.iter().flatten() {
                let cells = [b.sigma_low, b.sigma_high, b.density].map(csv_number);
                s.push_str(&format!("{}\n", cells.join(",")));
            }
            let file = indexed(path, several.then_some(k));
            std::fs::write(&file, s).map_err(|source| persson::Error::Io { path: file, source })?;
        }
    }
    print(&report, &a.format)
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
