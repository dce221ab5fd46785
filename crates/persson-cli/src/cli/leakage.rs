//! `persson leakage`: the leak rate of a static seal against load, from the
//! critical-junction and the effective-medium theories; the scene output
//! `leakage`.

use persson_studies::scene::LeakageOutput;

use super::args::{measured_contact, pressures, MaterialArgs, MeasuredArgs, SpectrumArgs};
use super::number::number;
use super::output::Format;
use super::spec_args::{SpecArgs, SpecFlags};

/// Arguments of `persson leakage`: the shared ones, and the spec's
/// ([`LeakageOutput`]) derived from it.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    spectrum: SpectrumArgs,
    #[command(flatten)]
    measured: MeasuredArgs,
    #[command(flatten)]
    material: MaterialArgs,
    /// Nominal (mean) pressure σ0 on the seal, Pa; repeatable or comma-separated.
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true, value_parser = number)]
    pressure: Vec<f64>,
    #[command(flatten)]
    spec: SpecArgs<LeakageOutput>,
    #[command(flatten)]
    format: Format,
}

/// The BEM beside the theories is `persson bem rough --leakage`.
impl SpecFlags for LeakageOutput {
    const OWN: &'static [&'static str] = &["bem"];
}

/// The seal and its fluid (shared with `bem rough --leakage`).
#[derive(clap::Args, Debug, Clone)]
pub struct SealArgs {
    /// Dynamic viscosity η of the fluid, Pa s.
    #[arg(long, allow_hyphen_values = true, value_parser = number)]
    pub viscosity: Option<f64>,
    /// Pressure drop ΔP across the seal, Pa (a liquid).
    #[arg(long, allow_hyphen_values = true, value_parser = number, conflicts_with_all = ["inlet_pressure", "outlet_pressure"])]
    pub pressure_drop: Option<f64>,
    /// Inlet pressure P_a of a gas (isothermal, ideal), Pa absolute.
    #[arg(long, requires = "outlet_pressure", allow_hyphen_values = true, value_parser = number)]
    pub inlet_pressure: Option<f64>,
    /// Outlet pressure P_b of a gas, Pa absolute (below P_a); Q is the flow at P_b.
    #[arg(long, requires = "inlet_pressure", allow_hyphen_values = true, value_parser = number)]
    pub outlet_pressure: Option<f64>,
    /// Seal width L_x along the flow, m.
    #[arg(long, default_value = "1e-3", allow_hyphen_values = true, value_parser = number)]
    pub seal_width: f64,
    /// Seal length L_y across the flow (e.g. an O-ring's circumference), m.
    #[arg(long, default_value = "1e-3", allow_hyphen_values = true, value_parser = number)]
    pub seal_length: f64,
}

impl SealArgs {
    /// The scene's `leakage` output for these flags; with `example`, the example's water seal
    /// ([`LeakageOutput::example`]) where the fluid or its drive is not given.
    pub fn output(
        &self,
        percolation_threshold: f64,
        tolerance: f64,
        example: bool,
    ) -> anyhow::Result<LeakageOutput> {
        // The example's water seal stands in for what is not given.
        let water = example.then(LeakageOutput::example);
        let Some(viscosity) = self.viscosity.or(water.as_ref().map(|w| w.viscosity)) else {
            anyhow::bail!("no --viscosity: give the fluid's dynamic viscosity η in Pa s");
        };
        let pressure_drop = match (&water, self.inlet_pressure) {
            (Some(w), None) => self.pressure_drop.or(w.pressure_drop),
            _ => self.pressure_drop,
        };
        if pressure_drop.is_none() && self.inlet_pressure.is_none() {
            anyhow::bail!(
                "no --pressure-drop: give ΔP in Pa (a liquid), or --inlet-pressure and --outlet-pressure (a gas)"
            );
        }
        Ok(LeakageOutput {
            viscosity,
            pressure_drop,
            inlet_pressure: self.inlet_pressure,
            outlet_pressure: self.outlet_pressure,
            seal_width: self.seal_width,
            seal_length: self.seal_length,
            percolation_threshold: Some(percolation_threshold),
            tolerance: Some(tolerance),
            bem: None,
            plot: None,
        })
    }
}

/// Run `persson leakage`.
pub fn run(mut a: Args, files: &mut persson_studies::output::Files) -> anyhow::Result<()> {
    if a.spectrum.example {
        // The example's water seal where the fluid or its drive is not given.
        let water = LeakageOutput::example();
        a.spec.or_number("viscosity", water.viscosity);
        if !a.spec.has("inlet_pressure") {
            a.spec
                .or_number("pressure_drop", water.pressure_drop.unwrap_or_default());
        }
    }
    let out = a.spec.spec()?;
    let surface = measured_contact(&a.spectrum, &a.measured, &a.material)?;
    let pressures = pressures(&a.pressure, a.spectrum.example)?;
    let ctx = persson_studies::study::Context::with_contact(surface, &pressures);
    super::study::run::<persson_studies::transport::Leakage>(&ctx, &out, files, &a.format)
}
