//! `persson anisotropy --surface FILE`: the Peklenik number and the ISO
//! 25178-2 texture parameters of a height map
//! ([`persson::topography::anisotropy`]).

use super::measured_args::MeasuredArgs;
use super::output::Format;

/// Arguments of `persson anisotropy`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    measured: MeasuredArgs,
    #[command(flatten)]
    format: Format,
}

/// Run `persson anisotropy`.
#[cfg(feature = "topography")]
pub fn run(a: Args) -> anyhow::Result<()> {
    use super::output::print;
    use persson::topography::{anisotropy, Conditioning};
    let Some(map) = a.measured.spec(None)? else {
        anyhow::bail!("persson anisotropy needs a height map: --surface FILE");
    };
    let t = map.read()?;
    let defaults = Conditioning::for_topography(&t);
    let conditioning = Conditioning {
        detrend: map.detrend.map_or(defaults.detrend, Into::into),
        window: map.window.map_or(defaults.window, Into::into),
    };
    let report =
        anisotropy(&t, conditioning).map_err(|e| anyhow::anyhow!("{}: {e}", map.file.display()))?;
    print(&report, &a.format)
}

/// Without the feature `topography`, an error.
#[cfg(not(feature = "topography"))]
pub fn run(_: Args) -> anyhow::Result<()> {
    anyhow::bail!("this persson was built without the `topography` feature")
}
