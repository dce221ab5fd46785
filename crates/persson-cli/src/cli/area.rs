//! `persson area`: A/A0 against nominal pressure (the scene output `area`).

use persson_studies::area::Area;
use persson_studies::scene::{AreaOutput, TheoryName};
use persson_studies::study::Context;

use super::args::{measured_contact, pressures, MaterialArgs, MeasuredArgs, SpectrumArgs};
use super::output::Format;

/// Arguments of `persson area`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    spectrum: SpectrumArgs,
    #[command(flatten)]
    measured: MeasuredArgs,
    #[command(flatten)]
    material: MaterialArgs,
    /// Nominal (mean) pressure σ0, same unit as E*; repeatable or comma-separated.
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true, value_parser = super::number::number)]
    pressure: Vec<f64>,
    /// Magnification ζ (default q_s/q_l, full magnification).
    #[arg(long, allow_hyphen_values = true, value_parser = super::number::number)]
    zeta: Option<f64>,
    #[command(flatten)]
    theory: TheoryArgs,
    /// Hardness σY of the overlap theory's load law σ0 = σY A/A0 (same unit
    /// as the pressures; required by --theory overlap, refused by the others).
    #[arg(long, allow_hyphen_values = true, value_parser = super::number::number)]
    yield_stress: Option<f64>,
    #[command(flatten)]
    format: Format,
    #[command(flatten)]
    plot: super::plot::PlotArg,
}

/// Choice of contact-area theory (`--theory`, `--gamma`, `--tolerance`).
#[derive(clap::Args, Debug, Clone)]
pub struct TheoryArgs {
    /// Contact-area theory: original (Persson 2001), yang-persson (Yang & Persson
    /// 2008, γ = 0.45), wang-muser (Wang & Müser 2017, γ = 5/9), xu (Xu et al. 2024, γ = 0.42);
    /// the asperity theories overlap (bearing area, needs --yield-stress),
    /// greenwood-williamson (1966) and bush (Bush, Gibson & Thomas 1975), from the moments m0, m2, m4.
    #[arg(long, value_enum, default_value_t = TheoryName::Original)]
    pub theory: TheoryName,
    /// γ of the corrected theory (yang-persson and xu: [0.001, 1]; wang-muser: [0.02, 11/9]).
    #[arg(long, allow_hyphen_values = true, value_parser = super::number::number)]
    pub gamma: Option<f64>,
    /// Absolute tolerance on A/A0 of the corrected theories' solver (for bush:
    /// the relative tolerance of its integrals).
    #[arg(
        long,
        alias = "theory-tolerance",
        default_value = "1e-12",
        allow_hyphen_values = true,
        value_parser = super::number::number,
    )]
    pub tolerance: f64,
}

/// Run `persson area`.
pub fn run(a: Args, files: &mut persson_studies::output::Files) -> anyhow::Result<()> {
    let surface = measured_contact(&a.spectrum, &a.measured, &a.material)?;
    let pressures = pressures(&a.pressure, a.spectrum.example)?;
    let out = AreaOutput {
        zeta: a.zeta,
        theory: a.theory.theory,
        gamma: a.theory.gamma,
        tolerance: Some(a.theory.tolerance),
        yield_stress: a.yield_stress,
        plot: a.plot.path(),
    };
    let ctx = Context::with_contact(surface, &pressures);
    super::study::run::<Area>(&ctx, &out, files, &a.format)
}
