//! Command-line interface: argument parsing and dispatch. Every subcommand
//! lives in its own file and only calls the library.

mod adhesion;
mod anisotropy;
mod area;
mod args;
mod blame;
mod conductance;
mod features;
mod files;
mod friction;
mod kappa;
mod leakage;
mod magnification;
mod measured_args;
mod number;
mod output;
mod plot;
// The BEM's subcommands and what only they use.
cfg_feature! {
    "bem",
    mod bem;
    mod bem_args;
    mod bem_detail;
    mod bem_transport;
    mod compare;
    mod compare_args;
    mod compare_plot;
    mod compare_transport;
    mod surrogates;
    mod progress;
}
mod report;
mod run;
mod separation;
mod spec_args;
mod spectrum;
mod stress;
mod study;

use clap::{Parser, Subcommand};
#[cfg(not(feature = "bem"))]
use features::{bem, bem as compare, bem as surrogates};

/// Contact mechanics of randomly rough surfaces (Persson's theory).
///
/// Exit codes: 0 success, 2 bad input or a computation that could not reach
/// its tolerance (one line on stderr), 2 also for usage errors (clap).
#[derive(Parser, Debug)]
#[command(name = "persson", version, about, long_about = None)]
pub struct Cli {
    #[command(subcommand)]
    cmd: Cmd,
}

#[derive(Subcommand, Debug)]
enum Cmd {
    /// Spectrum summary: rms height, slope and curvature, and C(q).
    Spectrum(spectrum::Args),
    /// G(ζ) and A/A0 against magnification at one nominal pressure.
    #[command(alias = "g")]
    Magnification(magnification::Args),
    /// Real contact area A/A0 against nominal pressure (load curve).
    Area(area::Args),
    /// Anisotropy of a height map: Peklenik number, texture aspect ratio Str, direction Std.
    Anisotropy(anisotropy::Args),
    /// κ of the linear low-load law for Bush and Persson.
    Kappa(kappa::Args),
    /// Compute what a scene file (JSON) asks for, and nothing else.
    Run(run::Args),
    /// Reports: error against run time, and stability at the extremes.
    Report(report::Args),
    /// Stress distribution P(σ) at one G (dimensionless; Persson, Bucher & Chiaia 2002, Figs. 2–4).
    Stress(stress::Args),
    /// Mean interfacial separation ū, stiffness K = −dσ0/dū and elastic energy against load.
    Separation(separation::Args),
    /// Adhesion: stickiness per magnification, A/A0 against load (tension included), pull-off.
    Adhesion(adhesion::Args),
    /// FFT boundary-element cross-check: Hertz validation and rough contact (feature `bem`).
    Bem(bem::Args),
    /// Theories against the BEM at several resolutions, its continuum limit, κ and your data (feature `bem`).
    Compare(compare::Args),
    /// Rubber friction μ(v, T, σ0) and A/A0 from a viscoelastic master curve (Persson 2001, 2006).
    Friction(friction::Args),
    /// Thermal and electrical contact conductance against load (Barber's identity; gap over P(u)).
    Conductance(conductance::Args),
    /// Leak rate of a static seal against load (critical junction, effective medium).
    Leakage(leakage::Args),
    /// The map against random surfaces of its spectrum: the FFT-BEM on a
    /// measured map and on its surrogates (feature `bem`).
    Surrogates(surrogates::Args),
}

/// Run one parsed command line (`matches` as clap parsed it): every file it
/// names is checked before anything is computed, and its outputs are
/// written only once the whole command has succeeded ([`files`]).
pub fn run(cli: Cli, matches: &clap::ArgMatches) -> anyhow::Result<()> {
    use clap::CommandFactory;
    let mut staged =
        stage(cli, matches).map_err(|e| blame::name_flag(&Cli::command(), matches, e))?;
    staged.commit()?;
    Ok(())
}

/// Run one parsed command line up to its outputs: computed, and staged
/// beside their targets, which nothing has touched yet (`persson run`
/// writes its own, to list them).
fn stage(cli: Cli, matches: &clap::ArgMatches) -> anyhow::Result<persson_studies::output::Files> {
    use clap::CommandFactory;
    let mut out = persson_studies::output::Files::new();
    files::plan(&Cli::command(), matches, &mut out)?;
    let o = &mut out;
    match cli.cmd {
        Cmd::Spectrum(a) => spectrum::run(a, o),
        Cmd::Magnification(a) => magnification::run(a, o),
        Cmd::Area(a) => area::run(a, o),
        Cmd::Anisotropy(a) => anisotropy::run(a, o),
        Cmd::Kappa(a) => kappa::run(a),
        Cmd::Run(a) => run::run(a, o),
        Cmd::Report(a) => report::run(a, o),
        Cmd::Stress(a) => stress::run(a, o),
        Cmd::Separation(a) => separation::run(a, o),
        Cmd::Adhesion(a) => adhesion::run(a, o),
        Cmd::Bem(a) => bem::run(a, o),
        Cmd::Compare(a) => compare::run(a, o),
        Cmd::Friction(a) => friction::run(a, o),
        Cmd::Conductance(a) => conductance::run(a, o),
        Cmd::Leakage(a) => leakage::run(a, o),
        Cmd::Surrogates(a) => surrogates::run(a, o),
    }?;
    Ok(out)
}

#[cfg(test)]
mod tests;
