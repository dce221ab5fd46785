//! `persson stress`: the stress distribution P(σ) (Persson, Bucher & Chiaia,
//! Phys. Rev. B 65, 184106 (2002)), dimensionless at one G (`--g`, Figs. 2–4)
//! or in Pa for a ball, a cylinder or a flat punch on a rough surface at the
//! magnifications `--zeta` (the scene output `stress` in either mode).

use persson::stress::{Start, TabulatedStart};
use persson::Error;
use persson_studies::scene::{run, BallSpec, CylinderSpec, StressOutput};

use super::args::{measured_contact, MaterialArgs, MeasuredArgs, SpectrumArgs};
use super::output::{print_warned, Format};
use super::spec_args::{SpecArgs, SpecFlags};

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

/// The flags of a contact that sets its own start (a ball, a cylinder, a
/// flat punch): not with `--start`, `--g` or `--yield-ratio`.
const OWN_START: [&str; 3] = ["start", "g", "yield_ratio"];

/// Arguments of `persson stress`: the spec's ([`StressOutput`]) derived
/// from it, and the command's own: a tabulated start, the contact bodies as
/// flags, σ/σH where to evaluate.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    spec: SpecArgs<StressOutput>,
    /// A tabulated start instead of --start: a file of two columns σ/σH, σH P0
    /// (comma or blank separated, `#` comments), piecewise linear, σH = the last σ.
    #[arg(long, conflicts_with_all = PHYSICAL, conflicts_with = "start", value_parser = super::files::in_file)]
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
    /// Physical mode: a Hertz ball of radius R (m), with --load F (N).
    #[arg(long, requires = "load", allow_hyphen_values = true, value_parser = super::number::number,
          conflicts_with_all = ["cylinder_radius", "flat", "peak_pressure"], conflicts_with_all = OWN_START)]
    ball_radius: Option<f64>,
    /// Load F on the ball, N (a cylinder takes --load-per-length, N/m).
    #[arg(long, requires = "ball_radius", allow_hyphen_values = true, value_parser = super::number::number,
          conflicts_with_all = ["cylinder_radius", "flat", "peak_pressure"])]
    load: Option<f64>,
    /// Physical mode: a Hertz cylinder of radius R (m), with --load-per-length F' (N/m).
    #[arg(long, requires = "load_per_length", allow_hyphen_values = true, value_parser = super::number::number,
          conflicts_with_all = ["flat", "peak_pressure"], conflicts_with_all = OWN_START)]
    cylinder_radius: Option<f64>,
    /// Load per unit length F' on the cylinder, N/m (a ball takes --load, N).
    #[arg(long, requires = "cylinder_radius", allow_hyphen_values = true, value_parser = super::number::number,
          conflicts_with_all = ["ball_radius", "flat", "peak_pressure"])]
    load_per_length: Option<f64>,
    /// Physical mode: a flat punch (uniform start) at the nominal pressure --pressure σ0 (Pa).
    #[arg(long, requires = "pressure", conflicts_with = "peak_pressure", conflicts_with_all = OWN_START)]
    flat: bool,
    /// Nominal pressure σ0 of the --flat punch, Pa.
    #[arg(long, requires = "flat", allow_hyphen_values = true, value_parser = super::number::number)]
    pressure: Option<f64>,
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
    #[command(flatten)]
    format: Format,
}

/// A ball and a cylinder are flags here (objects in a scene).
impl SpecFlags for StressOutput {
    const OWN: &'static [&'static str] = &["ball", "cylinder"];
    const ALIASES: &'static [(&'static str, &'static str)] = &[("tolerance", "tol")];
}

/// Run `persson stress`.
pub fn run(mut a: Args, files: &mut persson_studies::output::Files) -> anyhow::Result<()> {
    // The example: a flat punch at σ0 = 1 MPa on the example surface, its
    // P(σ, ζ) at four magnifications.
    let contact = a.ball_radius.is_some() || a.cylinder_radius.is_some() || a.flat;
    let given = |a: &Args, f: &str| a.spec.has(f);
    let chosen = ["start", "g", "peak_pressure"].iter().any(|f| given(&a, f));
    if a.spectrum.example && !contact && !chosen && a.table.is_none() {
        a.flat = true;
        a.pressure = Some(super::args::example::PRESSURES[2]);
        a.spec.or("zeta", vec![10.0, 100.0, 1e3, 1e4]);
    }
    if a.ball_radius.is_some()
        || a.cylinder_radius.is_some()
        || a.flat
        || given(&a, "peak_pressure")
    {
        return physical(a, files);
    }
    if a.spectrum.is_given() || !a.measured.surface.is_empty() || given(&a, "zeta") {
        anyhow::bail!(
            "a spectrum, --surface or --zeta needs a physical contact: --ball-radius R --load F, \
             --cylinder-radius R --load-per-length F, --flat --pressure P, or --start S \
             --peak-pressure P (without them, --g G gives the dimensionless distribution)"
        );
    }
    if !given(&a, "g") {
        anyhow::bail!(
            "no G: give --g G (dimensionless), or a physical contact: --ball-radius R --load F, \
             --cylinder-radius R --load-per-length F, --flat --pressure P, or --start S \
             --peak-pressure P"
        );
    }
    let table = match &a.table {
        Some(path) => {
            let (s, p) = read_table(path)?;
            let t = TabulatedStart::new(&s, &p, a.table_normalisation)
                .map_err(|e| anyhow::anyhow!("--table {}: {e}", path.display()))?;
            // The table stands for the start the spec requires.
            a.spec.or("start", "flat");
            Some(Start::Tabulated(t))
        }
        None if given(&a, "start") => None,
        None => anyhow::bail!("give --start or --table"),
    };
    let spec = a.spec.spec()?;
    // The physical mode's fields (`--yield-stress`) are refused here as in
    // a scene.
    spec.check_mode()?;
    let start = table.unwrap_or_else(|| Start::from(spec.start));
    let report = run::stress_dimensionless(
        &start,
        &spec.g,
        spec.yield_ratio,
        spec.tolerance,
        &a.sigma_ratio,
        spec.points,
    )?;
    super::plot::draw(files, spec.plot.as_deref(), || {
        persson_studies::scene::plot::stress(&report)
    })?;
    print_warned(&report, &report.warnings, &a.format)
}

/// The physical mode: the scene's `stress` output with `zeta`, on the surface
/// of the spectrum (or `--surface`) and material flags.
fn physical(mut a: Args, files: &mut persson_studies::output::Files) -> anyhow::Result<()> {
    let surface = measured_contact(&a.spectrum, &a.measured, &a.material)?;
    let (ball, cylinder) = match (a.ball_radius, a.cylinder_radius) {
        (Some(radius), _) => {
            a.spec.or("start", "hertz");
            (a.load.map(|load| BallSpec { radius, load }), None)
        }
        (_, Some(radius)) => {
            a.spec.or("start", "cylinder");
            let c = a.load_per_length.map(|load_per_length| CylinderSpec {
                radius,
                load_per_length,
            });
            (None, c)
        }
        _ if a.flat => {
            a.spec.or("start", "flat");
            if let Some(p) = a.pressure {
                a.spec.or("peak_pressure", p);
            }
            (None, None)
        }
        _ => (None, None),
    };
    a.spec.or(
        "zeta",
        vec![surface.spectrum.q_max() / surface.spectrum.q_min()],
    );
    let out = StressOutput {
        ball,
        cylinder,
        ..a.spec.spec()?
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
