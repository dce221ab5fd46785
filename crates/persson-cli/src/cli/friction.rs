//! `persson friction`: Persson's rubber friction μ(v, T, σ0) and A/A0 from a
//! measured master curve (the scene output `friction`; Persson, J. Chem.
//! Phys. 115, 3840 (2001); J. Phys.: Condens. Matter 18, 7789 (2006)).

use anyhow::bail;
use persson::friction::{FrequencyUnit, VerticalShift};
use persson_studies::friction::Friction;
use persson_studies::scene::{
    by_name, friction, FrictionOutput, RubberSpec, StandardLinearSolidSpec, VelocityRange, WlfSpec,
};
use persson_studies::study::{Context, Inputs, Reads, Study};

use super::args::{spectrum_spec, MeasuredArgs, SpectrumArgs};
use super::files::{in_file, InFile};
use super::number::number;
use super::output::{print_warned, Format};
use super::spec_args::{SpecArgs, SpecFlags};

/// The rubber: its modulus, temperature shift, Poisson ratio and thermal data.
#[derive(clap::Args, Debug)]
pub struct RubberArgs {
    /// Viscoelastic master curve at T_ref: columns ω (or f), E′, E″ in Pa; `#` comments.
    #[arg(long, value_name = "FILE", group = "modulus", value_parser = in_file)]
    master_curve: Option<InFile>,
    /// Unit of the --master-curve frequency column.
    #[arg(long, requires = "master_curve", value_parser = by_name::<FrequencyUnit>())]
    frequency_unit: Option<FrequencyUnit>,
    /// Prony series (generalised Maxwell): rows E_k (Pa), τ_k (s); a row with τ = inf is E∞.
    #[arg(long, value_name = "FILE", group = "modulus", value_parser = in_file)]
    prony: Option<InFile>,
    /// Standard linear solid E0,Einf,tau: instantaneous and relaxed modulus (Pa), τ (s).
    #[arg(long, value_name = "E0,EINF,TAU", group = "modulus", value_delimiter = ',',
          allow_hyphen_values = true, value_parser = number)]
    standard_linear_solid: Vec<f64>,
    /// WLF shift C1,C2,Tref: log10 a_T = −C1 (T − Tref)/(C2 + T − Tref), C2 and Tref in K.
    #[arg(long, value_name = "C1,C2,TREF", value_delimiter = ',', conflicts_with = "shift_table",
          allow_hyphen_values = true, value_parser = number)]
    wlf: Vec<f64>,
    /// Shift table: rows T (K), a_T[, b_T]; `#` comments.
    #[arg(long, value_name = "FILE", value_parser = in_file)]
    shift_table: Option<InFile>,
    /// T_ref of a --shift-table (default: where its a_T = 1) or of an unshifted rubber, K.
    #[arg(long, allow_hyphen_values = true, value_parser = number)]
    reference_temperature: Option<f64>,
    /// Vertical shift b_T.
    #[arg(long, value_parser = by_name::<VerticalShift>())]
    vertical_shift: Option<VerticalShift>,
    /// Poisson ratio ν of the rubber.
    #[arg(long, default_value = "0.5", allow_hyphen_values = true, value_parser = number)]
    poisson: f64,
    /// Thermal conductivity of the rubber, W/(m K) (for --flash-temperature).
    #[arg(long, allow_hyphen_values = true, value_parser = number)]
    thermal_conductivity: Option<f64>,
    /// Density of the rubber, kg/m³ (for --flash-temperature).
    #[arg(long, allow_hyphen_values = true, value_parser = number)]
    density: Option<f64>,
    /// Specific heat capacity of the rubber, J/(kg K) (for --flash-temperature).
    #[arg(long, allow_hyphen_values = true, value_parser = number)]
    heat_capacity: Option<f64>,
}

/// Arguments of `persson friction`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    spectrum: SpectrumArgs,
    #[command(flatten)]
    measured: MeasuredArgs,
    #[command(flatten)]
    rubber: RubberArgs,
    /// Nominal (mean) pressure σ0, Pa; repeatable or comma-separated.
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true, value_parser = number)]
    pressure: Vec<f64>,
    /// Log-spaced velocities VMIN,VMAX,N (m/s).
    #[arg(long, value_name = "VMIN,VMAX,N", value_delimiter = ',', allow_hyphen_values = true,
          value_parser = number)]
    velocity_range: Vec<f64>,
    #[command(flatten)]
    spec: SpecArgs<FrictionOutput>,
    #[command(flatten)]
    format: Format,
}

/// The velocity range is three numbers here (an object in a scene).
impl SpecFlags for FrictionOutput {
    const OWN: &'static [&'static str] = &["velocity_range"];
}

impl RubberArgs {
    /// The scene file's `rubber` entry.
    /// The rubber of the flags; with `example` and no modulus given, the
    /// example's modulus ([`RubberSpec::example`]) with the other flags.
    fn spec(&self, example: bool) -> anyhow::Result<RubberSpec> {
        let sls = match self.standard_linear_solid.as_slice() {
            [] => None,
            &[e0, e_inf, tau] => Some(StandardLinearSolidSpec {
                instantaneous_modulus: e0,
                relaxed_modulus: e_inf,
                relaxation_time: tau,
            }),
            v => bail!(
                "--standard-linear-solid: three values E0,Einf,tau, got {}",
                v.len()
            ),
        };
        let wlf = match self.wlf.as_slice() {
            [] => None,
            &[c1, c2, t_ref] => Some(WlfSpec {
                wlf_c1: c1,
                wlf_c2: c2,
                reference_temperature: t_ref,
            }),
            v => bail!("--wlf: three values C1,C2,Tref, got {}", v.len()),
        };
        let given = self.master_curve.is_some() || self.prony.is_some() || sls.is_some();
        let sls = match (given, example) {
            (false, true) => RubberSpec::example().standard_linear_solid,
            _ => sls,
        };
        if self.master_curve.is_none() && self.prony.is_none() && sls.is_none() {
            bail!("no rubber: give --master-curve FILE --frequency-unit rad/s|Hz, --prony FILE or --standard-linear-solid E0,Einf,tau");
        }
        if self.master_curve.is_some() && self.frequency_unit.is_none() {
            bail!("--master-curve needs --frequency-unit rad/s or Hz");
        }
        Ok(RubberSpec {
            master_curve: self.master_curve.clone().map(Into::into),
            frequency_unit: self.frequency_unit,
            prony: self.prony.clone().map(Into::into),
            standard_linear_solid: sls,
            wlf,
            shift_table: self.shift_table.clone().map(Into::into),
            reference_temperature: self.reference_temperature,
            vertical_shift: self.vertical_shift,
            poisson: Some(self.poisson),
            thermal_conductivity: self.thermal_conductivity,
            density: self.density,
            heat_capacity: self.heat_capacity,
        })
    }
}

/// Run `persson friction`.
pub fn run(a: Args, files: &mut persson_studies::output::Files) -> anyhow::Result<()> {
    let given = a.spec.spec()?;
    let thermal = [
        a.rubber.thermal_conductivity,
        a.rubber.density,
        a.rubber.heat_capacity,
    ];
    if given.flash_temperature && thermal.iter().any(Option::is_none) {
        bail!("--flash-temperature needs --thermal-conductivity, --density and --heat-capacity");
    }
    let spectrum = spectrum_spec(&a.spectrum, &a.measured)?;
    let example = a.spectrum.example;
    let rubber = a.rubber.spec(example)?;
    let pressure = match (a.pressure.as_slice(), example) {
        ([], true) => vec![persson_studies::friction::EXAMPLE_PRESSURE],
        ([], false) => {
            bail!("no nominal pressure: give --pressure P (Pa; repeatable or comma-separated)")
        }
        (p, _) => p.to_vec(),
    };
    let velocity_range = velocity_range(&a.velocity_range)?.or_else(|| {
        (example && given.velocity.is_empty())
            .then_some(persson_studies::friction::EXAMPLE_VELOCITY_RANGE)
    });
    match (given.velocity.is_empty(), velocity_range.is_none()) {
        (true, true) => bail!("no velocity: give --velocity V (m/s; repeatable or comma-separated) or --velocity-range VMIN,VMAX,N"),
        (false, false) => bail!("--velocity and --velocity-range: give one of them"),
        _ => {}
    }
    let out = FrictionOutput {
        velocity_range,
        ..given
    };
    let report =
        friction(&spectrum, &rubber, &pressure, &out).map_err(|e| a.spectrum.psd_hint(e))?;
    let inputs = Inputs {
        spectrum: Some(&spectrum),
        material: None,
        rubber: Some(&rubber),
        nominal_pressure: &pressure,
    };
    let ctx = Context::new(inputs, Reads::NOTHING)?;
    Friction::write(&out, &report, &ctx, std::path::Path::new(""), files)?;
    print_warned(&report, &Friction::warnings(&report), &a.format)
}

/// `--velocity-range VMIN,VMAX,N` as the scene's object.
fn velocity_range(v: &[f64]) -> anyhow::Result<Option<VelocityRange>> {
    match *v {
        [] => Ok(None),
        [lo, hi, n] => {
            let max = persson_studies::scene::MAX_VELOCITIES;
            if !(n.fract() == 0.0 && n >= 1.0 && n <= max as f64) {
                bail!("--velocity-range: N = {n} must be a whole number in 1..={max}");
            }
            Ok(Some(VelocityRange {
                velocity_min: lo,
                velocity_max: hi,
                points: n as usize,
            }))
        }
        _ => bail!(
            "--velocity-range: three values VMIN,VMAX,N, got {}",
            v.len()
        ),
    }
}
