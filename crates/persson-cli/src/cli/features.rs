//! A command or flag whose feature this build leaves out: refused, naming
//! the feature and the build that has it.

/// The arguments of a command whose feature this build leaves out: taken
/// as they come, and refused naming the feature.
#[derive(clap::Args, Debug)]
pub struct LeftOut {
    #[arg(trailing_var_arg = true, allow_hyphen_values = true, hide = true)]
    args: Vec<String>,
}

/// The error of a command that needs `feature` (unused in a build with all).
#[cfg_attr(
    all(feature = "bem", feature = "flow", feature = "topography"),
    allow(dead_code)
)]
pub fn left_out(feature: &str) -> anyhow::Error {
    anyhow::anyhow!(
        "this command needs the feature `{feature}`, which this build of persson leaves out: \
         build with `cargo run --release -p persson-cli --features full -- …` or install with \
         `cargo install --path crates/persson-cli --features full`"
    )
}

/// `bem` and `compare` in a build without the feature `bem`: taken, and
/// refused naming it.
#[cfg(not(feature = "bem"))]
pub mod bem {
    /// Whatever follows the command.
    pub type Args = super::LeftOut;

    /// The error naming the feature.
    pub fn run(_: Args, _: &mut persson_studies::output::Files) -> anyhow::Result<()> {
        Err(super::left_out("bem"))
    }
}
