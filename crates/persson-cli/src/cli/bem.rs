//! `persson bem`: the FFT boundary-element cross-check (Hertz validation and
//! rough-surface solves).

use std::path::{Path, PathBuf};

use anyhow::Context;
use persson::bem::rough::{self, Observer, RoughOptions, RoughProgress, SurfaceOrigin};
use persson::bem::surface::synthesize;
use persson::bem::{check_memory, Solution};
use persson::error::check;
use persson::io::npy;
use persson_studies::table::Tabulate;

pub use super::bem_args::Args;
use super::bem_args::{Cmd, HertzArgs, RoughArgs, RoughSettings};
use super::bem_detail::{details, RoughWithDetails};
use super::output::print_narrowed;
use super::progress::Progress;
use persson_studies::bem_detail::Details;
use persson_studies::output::Files;
use persson_studies::scene::{BemAdhesionOutput, BemOutput};

/// Run `persson bem`.
pub fn run(a: Args, files: &mut Files) -> anyhow::Result<()> {
    match a.cmd {
        Cmd::Hertz(h) => hertz(&h, files),
        Cmd::Rough(r) => rough_contact(&r, files),
    }
}

/// `persson bem hertz`: the study `bem_hertz`, with a bar over its solves.
fn hertz(h: &HertzArgs, files: &mut Files) -> anyhow::Result<()> {
    use persson_studies::bem_hertz::BemHertz;
    use persson_studies::study::{Context, Study};
    let spec = h.spec.spec()?;
    let bar = std::rc::Rc::new(std::cell::RefCell::new(None::<Progress>));
    let shown = std::rc::Rc::clone(&bar);
    let report = persson_studies::progress::observe(
        move |p| {
            let mut bar = shown.borrow_mut();
            let bar = bar.get_or_insert_with(|| Progress::solves(p.steps, None));
            bar.step(p, &|| format!("Hertz {}/{}", p.step + 1, p.steps));
        },
        || BemHertz::run(&Context::nothing(), &spec),
    );
    if let Some(b) = bar.borrow().as_ref() {
        b.finish();
    }
    let report = report?;
    BemHertz::write(&spec, &report, &Context::nothing(), Path::new(""), files)?;
    print_narrowed(&report, &BemHertz::warnings(&report), &h.format, h.wide)
}

/// The CLI's view of the solves: progress, and the pressure and gap fields
/// to write (staged as they arrive, written when the whole run succeeded).
struct Solves<'a> {
    bar: Progress,
    fields: Option<&'a Path>,
    gaps: Option<&'a Path>,
    files: &'a mut Files,
    several: bool,
    n: usize,
    details: Details,
}

impl Observer for Solves<'_> {
    fn iteration(&mut self, p: RoughProgress) {
        let what = || format!("σ0 = {:e}", p.nominal_pressure);
        self.bar.update(p.index, &what, p.iteration);
    }
    fn solution(&mut self, k: usize, s: &Solution) -> persson::Result<()> {
        self.details.solution(k, s)?;
        if let Some(path) = self.fields {
            let p = indexed(path, self.several.then_some(k));
            self.files
                .write(&p, &npy::encode(self.n, self.n, &s.pressure)?)?;
        }
        if let Some(path) = self.gaps {
            // The gap the flow is solved on: 0 in contact (p > 0), max(g, 0) elsewhere.
            let gap: Vec<f64> = s
                .gap
                .iter()
                .zip(&s.pressure)
                .map(|(&g, &p)| if p > 0.0 { 0.0 } else { g.max(0.0) })
                .collect();
            let p = indexed(path, self.several.then_some(k));
            self.files.write(&p, &npy::encode(self.n, self.n, &gap)?)?;
        }
        Ok(())
    }
}

fn rough_contact(a: &RoughArgs, files: &mut Files) -> anyhow::Result<()> {
    if let Some(path) = a.adhesion.path()? {
        return adhesive_rough(a, &path, files);
    }
    if a.spectrum.example {
        // Say what the example is (stdout stays the report alone).
        eprintln!("persson: {}", persson_studies::scene::EXAMPLE);
    }
    let pressures = super::args::pressures(&a.pressure, a.spectrum.example)?;
    // Before any computation: the settings, the transport flags.
    let set = a.settings()?;
    let request = super::bem_transport::request(a, &set)?;
    let options = RoughOptions {
        boundary: set.boundary,
        solver: set.options,
        bins: set.spec.histogram.as_ref().map(|_| set.bins),
        ..RoughOptions::default()
    };
    let e_star = a.material.build(a.spectrum.example)?.contact_modulus();
    let (surface, source) = rough_surface(a, &set)?;
    let details = details(
        &set.spec,
        (surface.n, surface.size, set.boundary),
        a.material.poisson,
        &pressures,
    )?;
    if let Some(path) = &a.surface_out {
        files.write(path, &npy::encode(surface.n, surface.n, &surface.heights)?)?;
    }
    let several = pressures.len() > 1;
    let mut solves = Solves {
        bar: Progress::solves(pressures.len(), None),
        fields: a.pressure_field.as_deref(),
        gaps: a.transport.gap_field.as_deref(),
        files,
        several,
        n: surface.n,
        details,
    };
    let mut observer = super::bem_transport::Observed::new(
        &mut solves,
        request,
        (surface.n, surface.size, e_star),
        &pressures,
        set.options.tolerance,
    )?;
    let report = if set.spec.pressure_plot.is_some() {
        rough::rough_contact_mapped(
            &surface,
            source,
            e_star,
            &pressures,
            &options,
            observer.observer(),
        )
    } else {
        rough::rough_contact(
            &surface,
            source,
            e_star,
            &pressures,
            &options,
            observer.observer(),
        )
    };
    let transport = observer.finish();
    solves.bar.finish();
    let (files, details) = (solves.files, solves.details);
    let report = report?;
    super::plot::draw(files, set.spec.pressure_plot.as_deref(), || {
        persson_studies::plot::map::rough_map(&report)
    })?;
    super::plot::draw(files, set.spec.plot.as_deref(), || {
        persson_studies::bem::figures::bem(&report)
    })?;
    if let Some(path) = &set.spec.histogram {
        // The report's own histogram table: every pressure in one CSV.
        if let Some(t) = report
            .tables()
            .into_iter()
            .find(|t| t.name == "bem_histogram")
        {
            files.write(path, t.to_csv().as_bytes())?;
        }
    }
    let mut warnings = a.spectrum.file_warnings();
    warnings.extend(persson_studies::warning::of_rough(&report));
    write_details(
        &set.spec,
        &details,
        (surface.n, surface.size, e_star),
        &pressures,
        files,
    )?;
    let (patches, subsurface) = (details.patches, details.subsurface);
    match transport {
        Some(points) => {
            let report = persson_studies::scene::RoughTransportReport::new(report, points);
            warnings.extend(super::bem_transport::sealed(&report));
            let out = RoughWithDetails {
                rough: &report,
                patches,
                subsurface,
            };
            print_narrowed(&out, &warnings, &a.format, a.wide)
        }
        None => {
            let out = RoughWithDetails {
                rough: &report,
                patches,
                subsurface,
            };
            print_narrowed(&out, &warnings, &a.format, a.wide)
        }
    }
}

/// The figures and files of the detail studies: the patch-area
/// distribution (`--patches-plot`), the depth profiles (`--stress-plot`)
/// and the von Mises map of every plane below every solve (`--stress-field`
/// .npy, `--stress-plot` colour maps, `_k_j` added to each name).
fn write_details(
    b: &BemOutput,
    details: &Details,
    (n, size, e_star): (usize, f64, f64),
    pressures: &[f64],
    files: &mut Files,
) -> anyhow::Result<()> {
    let sub = b.subsurface.as_ref();
    if let Some(path) = sub.and_then(|s| s.stress_field.as_ref()) {
        for m in &details.maps {
            let p = persson_studies::bem_detail::indexed(path, m.index, m.depth_index);
            files.write(&p, &npy::encode(n, n, &m.von_mises_stress)?)?;
        }
    }
    use persson_studies::bem::figures;
    let patches_plot = b.patches.as_ref().and_then(|p| p.plot.as_ref());
    if let (Some(path), Some(p)) = (patches_plot, &details.patches) {
        super::plot::draw(files, Some(path), || figures::patch_areas(p))?;
    }
    let stress_plot = sub.and_then(|s| s.plot.as_ref());
    if let (Some(path), Some(s)) = (stress_plot, &details.subsurface) {
        super::plot::draw(files, Some(path), || figures::subsurface_profiles(s))?;
    }
    if let (Some(path), Some(s)) = (stress_plot, sub) {
        use persson_studies::plot::Encode;
        let unit = if e_star == 1.0 { "E*" } else { "Pa" };
        let planes = persson_studies::bem_detail::planes(
            &details.maps,
            (n, size),
            &s.depth,
            pressures,
            unit,
            path,
        );
        for (p, fig) in planes {
            files.write(&p, &fig.encode(&p)?)?;
        }
    }
    Ok(())
}

/// The rigid surface of `bem rough`: a height map read (through the one
/// reader every command uses, [`persson_studies::scene::HeightMapSpec`]),
/// or a spectrum synthesised.
fn rough_surface(
    a: &RoughArgs,
    set: &RoughSettings,
) -> anyhow::Result<(persson::bem::surface::GridSurface, SurfaceOrigin)> {
    Ok(if let Some(path) = &a.surface {
        let mut map = a.read.spec(path, 0);
        map.size = a.size.map(persson_studies::scene::Sides::One);
        map.detrend = a.detrend;
        (
            map.bem_surface(set.boundary)?,
            SurfaceOrigin::height_map(path),
        )
    } else {
        // The example's surface on 128² nodes unless --grid says otherwise.
        let n = set
            .spec
            .grid
            .or(a.spectrum.example.then_some(128))
            .context("no surface: give --surface FILE, or spectrum flags with --grid N")?;
        check_memory(n, set.boundary)?;
        let spectrum = a.spectrum.build()?;
        let size = check::positive(
            "size",
            a.size.unwrap_or(std::f64::consts::TAU / spectrum.q_min()),
        )?;
        let s = synthesize(spectrum.as_ref(), n, size, set.seed)?;
        (s, SurfaceOrigin::synthesised(spectrum.as_ref(), set.seed)?)
    })
}

/// `bem rough --work-of-adhesion`: the adhesive BEM along the --mean-gap path.
fn adhesive_rough(a: &RoughArgs, path: &BemAdhesionOutput, files: &mut Files) -> anyhow::Result<()> {
    use persson_studies::bem_detail::{adhesive_controlled_path, adhesive_warnings, PathControl};
    let set = a.settings()?;
    refuse_load_curve(a, &set)?;
    let control = PathControl::new(&path.mean_gap, &path.approach, set.boundary)?;
    if a.spectrum.example {
        eprintln!("persson: {}", persson_studies::scene::EXAMPLE);
    }
    let e_star = a.material.build(a.spectrum.example)?.contact_modulus();
    let (surface, _) = rough_surface(a, &set)?;
    if let Some(p) = &a.surface_out {
        files.write(p, &npy::encode(surface.n, surface.n, &surface.heights)?)?;
    }
    let options = persson::bem::adhesive::AdhesiveOptions {
        tolerance: set.options.tolerance,
        max_iterations: set.options.max_iterations,
    };
    let report = adhesive_controlled_path(
        &surface.heights,
        (surface.n, surface.size, e_star),
        set.boundary,
        (
            path.adhesion.unwrap_or_default(),
            path.work_of_adhesion,
            path.adhesion_range,
        ),
        control,
        &options,
        path.adhesive_iteration.unwrap_or_default(),
    )?;
    let mut warnings = a.spectrum.file_warnings();
    warnings.extend(adhesive_warnings(&report));
    print_narrowed(&report, &warnings, &a.format, a.wide)
}

/// The flags of the load curve, refused beside `--work-of-adhesion` (the
/// adhesive path is under mean-gap or approach control, elastic, and reports
/// its own points).
fn refuse_load_curve(a: &RoughArgs, set: &RoughSettings) -> anyhow::Result<()> {
    let b = &set.spec;
    let given = [
        ("--pressure", !a.pressure.is_empty()),
        ("--yield-stress", b.yield_stress.is_some()),
        ("--plot", b.pressure_plot.is_some()),
        ("--area-plot", b.plot.is_some()),
        ("--histogram", b.histogram.is_some()),
        ("--pressure-field", a.pressure_field.is_some()),
        ("--patches", b.patches.is_some()),
        ("--subsurface", b.subsurface.is_some()),
        ("--leakage", a.transport.leakage),
        ("--conductivity / --resistivity / --gas-conductivity", a.transport.conductance.given()),
        ("--gap-field", a.transport.gap_field.is_some()),
    ];
    match given.iter().find(|g| g.1) {
        Some((flag, _)) => anyhow::bail!(
            "{flag}: not with --work-of-adhesion (the adhesive path, under --mean-gap or \
             --approach control, reports its own points)"
        ),
        None => Ok(()),
    }
}

/// `dir/name.ext` → `dir/name_k.ext` when `k` is given.
pub fn indexed(path: &Path, k: Option<usize>) -> PathBuf {
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
