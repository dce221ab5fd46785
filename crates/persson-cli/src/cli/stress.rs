//! `persson stress`: the stress distribution P(σ) (Persson, Bucher & Chiaia,
//! Phys. Rev. B 65, 184106 (2002)), dimensionless at one G (`--g`, Figs. 2–4)
//! or in Pa for a ball, a cylinder or a flat punch on a rough surface at the
//! magnifications `--zeta` (the scene output `stress` in either mode).

use persson::stress::{Start, TabulatedStart};
use persson::Error;
use persson_studies::scene::{run, BallSpec, CylinderSpec, StartName, StressOutput};

use super::args::{measured_contact, MaterialArgs, MeasuredArgs, SpectrumArgs};
use super::output::{print_warned, Format};

/// The flags of the physical mode; `--g`, `--table`, `--yield-ratio` and
/// `--sigma-ratio` belong to the dimensionless one.
const PHYSICAL: [&str; 9] = [
    "ball_radius",
    "cylinder_radius",
    "flat",
    "peak_pressure",
    "load",
    "load_per_length",
    "pressure",
    "zeta",
    "yield_stress",
];

/// Arguments of `persson stress`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Start condition P(σ, ζ = 1).
    #[arg(
        long,
        value_enum,
        required_unless_present_any = ["table", "ball_radius", "cylinder_radius", "flat", "example"],
        conflicts_with_all = ["table", "ball_radius", "cylinder_radius", "flat"]
    )]
    start: Option<StartName>,
    /// A tabulated start instead: a file of two columns σ/σH, σH P0 (comma or
    /// blank separated, `#` comments), piecewise linear, σH = the last σ.
    #[arg(long, conflicts_with_all = PHYSICAL, value_parser = super::files::in_file)]
    table: Option<super::files::InFile>,
    /// How far ∫ P0 dσ of a --table may be from 1.
    #[arg(
        long,
        alias = "table-tol",
        default_value = "1e-6",
        allow_hyphen_values = true,
        value_parser = super::number::number,
    )]
    table_normalisation: f64,
    /// Dimensionless mode: G(ζ) (Persson, Bucher & Chiaia 2002, Eq. 2, with σ0 the
    /// nominal mean pressure).
    #[arg(
        long,
        allow_hyphen_values = true,
        value_parser = super::number::number,
        conflicts_with_all = PHYSICAL
    )]
    g: Option<f64>,
    /// Dimensionless mode: σY/σH, the yield stress in units of the peak pressure
    /// (absent: elastic).
    #[arg(
        long,
        allow_hyphen_values = true,
        value_parser = super::number::number,
        conflicts_with_all = PHYSICAL
    )]
    yield_ratio: Option<f64>,
    /// Physical mode: a Hertz ball of radius R (m), with --load F (N).
    #[arg(long, requires = "load", allow_hyphen_values = true, value_parser = super::number::number,
          conflicts_with_all = ["cylinder_radius", "flat", "peak_pressure"])]
    ball_radius: Option<f64>,
    /// Load F on the ball, N (a cylinder takes --load-per-length, N/m).
    #[arg(long, requires = "ball_radius", allow_hyphen_values = true, value_parser = super::number::number,
          conflicts_with_all = ["cylinder_radius", "flat", "peak_pressure"])]
    load: Option<f64>,
    /// Physical mode: a Hertz cylinder of radius R (m), with --load-per-length F' (N/m).
    #[arg(long, requires = "load_per_length", allow_hyphen_values = true, value_parser = super::number::number,
          conflicts_with_all = ["flat", "peak_pressure"])]
    cylinder_radius: Option<f64>,
    /// Load per unit length F' on the cylinder, N/m (a ball takes --load, N).
    #[arg(long, requires = "cylinder_radius", allow_hyphen_values = true, value_parser = super::number::number,
          conflicts_with_all = ["ball_radius", "flat", "peak_pressure"])]
    load_per_length: Option<f64>,
    /// Physical mode: a flat punch (uniform start) at the nominal pressure --pressure σ0 (Pa).
    #[arg(long, requires = "pressure", conflicts_with = "peak_pressure")]
    flat: bool,
    /// Nominal pressure σ0 of the --flat punch, Pa.
    #[arg(long, requires = "flat", allow_hyphen_values = true, value_parser = super::number::number)]
    pressure: Option<f64>,
    /// Physical mode: the --start's peak pressure σH (Pa), instead of a ball, a
    /// cylinder or a flat punch (Persson, Bucher & Chiaia's rail–wheel: --start
    /// cylinder --peak-pressure 542e6).
    #[arg(long, requires = "start", allow_hyphen_values = true, value_parser = super::number::number)]
    peak_pressure: Option<f64>,
    /// Physical mode: magnifications ζ ≥ 1, comma-separated (default q_s/q_l, full
    /// magnification).
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true, value_parser = super::number::number)]
    zeta: Vec<f64>,
    /// Physical mode: yield stress σY (Pa) above the peak pressure (absent: elastic).
    #[arg(long, allow_hyphen_values = true, value_parser = super::number::number)]
    yield_stress: Option<f64>,
    #[command(flatten)]
    spectrum: SpectrumArgs,
    #[command(flatten)]
    measured: MeasuredArgs,
    #[command(flatten)]
    material: MaterialArgs,
    /// Dimensionless mode: σ/σH where to evaluate P; comma-separated (default:
    /// --points values from 0 to the end of the distribution).
    #[arg(
        conflicts_with_all = PHYSICAL,
        long,
        alias = "sigma",
        value_delimiter = ',',
        allow_hyphen_values = true,
        value_parser = super::number::number,
    )]
    sigma_ratio: Vec<f64>,
    /// Number of evenly spaced σ (at least 2): when --sigma-ratio is not given; in
    /// the physical mode from 0 to σY, or (elastic) to σH plus four standard
    /// deviations of the widest curve.
    #[arg(long, default_value_t = 201, allow_hyphen_values = true, value_parser = super::number::count)]
    points: usize,
    /// Absolute tolerance of σH P and of the fractions.
    #[arg(
        long,
        alias = "tol",
        default_value = "1e-12",
        allow_hyphen_values = true,
        value_parser = super::number::number,
    )]
    tolerance: f64,
    #[command(flatten)]
    format: Format,
    #[command(flatten)]
    plot: super::plot::PlotArg,
}

/// Run `persson stress`.
pub fn run(mut a: Args, files: &mut persson_studies::output::Files) -> anyhow::Result<()> {
    // The example: a flat punch at σ0 = 1 MPa on the example surface, its
    // P(σ, ζ) at four magnifications.
    let contact = a.ball_radius.is_some() || a.cylinder_radius.is_some() || a.flat;
    if a.spectrum.example && !contact && a.start.is_none() && a.table.is_none() && a.g.is_none() {
        a.flat = true;
        a.pressure = Some(super::args::example::PRESSURES[2]);
        if a.zeta.is_empty() {
            a.zeta = vec![10.0, 100.0, 1e3, 1e4];
        }
    }
    if a.ball_radius.is_some() || a.cylinder_radius.is_some() || a.flat || a.peak_pressure.is_some()
    {
        return physical(&a, files);
    }
    if a.spectrum.is_given() || !a.measured.surface.is_empty() || !a.zeta.is_empty() {
        anyhow::bail!(
            "a spectrum, --surface or --zeta needs a physical contact: --ball-radius R --load F, \
             --cylinder-radius R --load-per-length F, --flat --pressure P, or --start S \
             --peak-pressure P (without them, --g G gives the dimensionless distribution)"
        );
    }
    let Some(g) = a.g else {
        anyhow::bail!(
            "no G: give --g G (dimensionless), or a physical contact: --ball-radius R --load F, \
             --cylinder-radius R --load-per-length F, --flat --pressure P, or --start S \
             --peak-pressure P"
        );
    };
    let start = match (a.start, &a.table) {
        (Some(s), _) => Start::from(s),
        (None, Some(path)) => {
            let (s, p) = read_table(path)?;
            Start::Tabulated(
                TabulatedStart::new(&s, &p, a.table_normalisation)
                    .map_err(|e| anyhow::anyhow!("--table {}: {e}", path.display()))?,
            )
        }
        (None, None) => anyhow::bail!("give --start or --table"),
    };
    let report = run::stress_dimensionless(
        &start,
        &[g],
        a.yield_ratio,
        a.tolerance,
        &a.sigma_ratio,
        a.points,
    )?;
    a.plot
        .draw(files, || persson_studies::scene::plot::stress(&report))?;
    print_warned(&report, &report.warnings, &a.format)
}

/// The physical mode: the scene's `stress` output with `zeta`, on the surface
/// of the spectrum (or `--surface`) and material flags.
fn physical(a: &Args, files: &mut persson_studies::output::Files) -> anyhow::Result<()> {
    let surface = measured_contact(&a.spectrum, &a.measured, &a.material)?;
    let (start, ball, cylinder, peak_pressure) =
        match (a.ball_radius, a.cylinder_radius, a.peak_pressure, a.start) {
            (Some(radius), ..) => (
                StartName::Hertz,
                a.load.map(|load| BallSpec { radius, load }),
                None,
                None,
            ),
            (_, Some(radius), ..) => (
                StartName::Cylinder,
                None,
                a.load_per_length.map(|load_per_length| CylinderSpec {
                    radius,
                    load_per_length,
                }),
                None,
            ),
            (_, _, Some(p), Some(start)) => (start, None, None, Some(p)),
            _ => (StartName::Flat, None, None, a.pressure),
        };
    let zeta = if a.zeta.is_empty() {
        vec![surface.spectrum.q_max() / surface.spectrum.q_min()]
    } else {
        a.zeta.clone()
    };
    let out = StressOutput {
        start,
        g: vec![],
        yield_ratio: None,
        zeta,
        peak_pressure,
        ball,
        cylinder,
        yield_stress: a.yield_stress,
        points: a.points,
        tolerance: a.tolerance,
        plot: a.plot.path(),
    };
    let ctx = persson_studies::study::Context::with_contact(surface, &[]);
    super::study::run::<persson_studies::stress::Stress>(&ctx, &out, files, &a.format)
}

/// Two columns of numbers; `#` starts a comment.
fn read_table(path: &std::path::Path) -> Result<(Vec<f64>, Vec<f64>), Error> {
    let text = std::fs::read_to_string(path).map_err(|e| Error::Io {
        path: path.to_path_buf(),
        source: e,
    })?;
    let (mut s, mut p) = (Vec::new(), Vec::new());
    for (i, line) in text.lines().enumerate() {
        let line = line.split('#').next().unwrap_or("").trim();
        if line.is_empty() {
            continue;
        }
        let cols: Vec<&str> = line
            .split(|c: char| c == ',' || c.is_whitespace())
            .filter(|c| !c.is_empty())
            .collect();
        if cols.len() != 2 {
            return Err(Error::parse(
                path,
                i + 1,
                1,
                format!("expected two columns σ, P0, found {}", cols.len()),
            ));
        }
        let mut v = [0.0; 2];
        for (k, c) in cols.iter().enumerate() {
            v[k] = c
                .parse()
                .map_err(|_| Error::parse(path, i + 1, k + 1, format!("`{c}` is not a number")))?;
        }
        s.push(v[0]);
        p.push(v[1]);
    }
    Ok((s, p))
}
