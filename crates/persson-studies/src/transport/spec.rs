//! What passes through the interface: the scene outputs `conductance` and
//! `leakage`, and the BEM solve a scene may set beside the theory.

use std::path::PathBuf;

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

/// Contact conductance against the scene's nominal pressures: through the
/// contact spots from the stiffness (Barber's identity) and through the gap
/// from P(u).
#[derive(Debug, Clone, Default, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ConductanceOutput {
    /// Thermal conductivities κ1[, κ2] of the two bodies, W/(m K) (one value:
    /// both bodies): adds the thermal conductance.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub conductivity: Vec<f64>,
    /// Electrical resistivities ρ1[, ρ2] of the two bodies, Ω m (one value:
    /// both bodies): adds the electrical conductance.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub resistivity: Vec<f64>,
    /// Gas conductivity κ_gas of the gap law α(u) = κ_gas/(u + 2ℓ), W/(m K):
    /// adds the gap conductance (with `mean_free_path`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub gas_conductivity: Option<f64>,
    /// Temperature-jump length ℓ of the gas law, m (> 0).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mean_free_path: Option<f64>,
    /// A table of the gap's heat-transfer coefficient instead of the gas law:
    /// `[[u, α], …]`, u ascending in m, α in W/(m² K) (linear in between,
    /// held at the ends).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub gap_table: Option<Vec<(f64, f64)>>,
    /// Relative tolerance of the wavevector integrals (default 1e-9).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tolerance: Option<f64>,
    /// Solve the FFT-BEM at the same pressures and report its conductances
    /// beside the theory's (feature `flow`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub bem: Option<TransportBem>,
    /// Draw h(σ0) on log axes, theory and BEM (.svg or .png).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub plot: Option<PathBuf>,
}

/// Leak rate of a static seal against the scene's nominal pressures: the
/// critical junction and the effective medium.
#[derive(Debug, Clone, Default, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct LeakageOutput {
    /// Dynamic viscosity η of the fluid, Pa s.
    pub viscosity: f64,
    /// Pressure drop ΔP across the seal, Pa (a liquid; or give
    /// `inlet_pressure` and `outlet_pressure` for a gas).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pressure_drop: Option<f64>,
    /// Inlet pressure P_a of a gas, Pa (absolute).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub inlet_pressure: Option<f64>,
    /// Outlet pressure P_b of a gas, Pa (absolute, below P_a).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub outlet_pressure: Option<f64>,
    /// Seal width L_x along the flow, m (default 1e-3).
    #[serde(default = "one_millimetre")]
    pub seal_width: f64,
    /// Seal length L_y across the flow (an O-ring's circumference), m (default 1e-3).
    #[serde(default = "one_millimetre")]
    pub seal_length: f64,
    /// Percolation threshold a_c of the critical junction in (0, 1) (default 0.42).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub percolation_threshold: Option<f64>,
    /// Relative tolerance of the wavevector integrals (default 1e-9).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tolerance: Option<f64>,
    /// Solve the FFT-BEM at the same pressures and Reynolds' equation on its
    /// gap, beside the theories (feature `flow`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub bem: Option<TransportBem>,
    /// Draw Q(σ0) on log axes, both theories and the BEM (.svg or .png).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub plot: Option<PathBuf>,
}

/// The FFT-BEM beside a transport theory, solved at the scene's pressures on
/// the scene's height map (periodic) or, with a spectrum, on a surface
/// synthesised from it (side 2π/q_l, periodic).
#[derive(Debug, Clone, Copy, Default, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct TransportBem {
    /// Grid side N of the synthesised surface (q_s should be resolved: N ≥ 8
    /// q_s/q_l or so); required with a spectrum, refused with a height map
    /// (its file sets the grid).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub grid: Option<usize>,
    /// Seed of the synthesised surface (default 1; refused with a height map).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub seed: Option<u64>,
    /// Solver tolerance ε of the contact and of the stiffness's CG (default 1e-10).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tolerance: Option<f64>,
}

/// A seal's side where none is given: 1 mm (the command line's and Python's
/// default too).
fn one_millimetre() -> f64 {
    1e-3
}

impl LeakageOutput {
    /// The built-in example's seal: water (η = 1 mPa s at 20 °C) under a
    /// pressure drop of 1 bar across a 1 mm × 1 mm seal.
    pub fn example() -> Self {
        LeakageOutput {
            viscosity: 1e-3,
            pressure_drop: Some(1e5),
            inlet_pressure: None,
            outlet_pressure: None,
            seal_width: 1e-3,
            seal_length: 1e-3,
            percolation_threshold: None,
            tolerance: None,
            bem: None,
            plot: None,
        }
    }
}

impl ConductanceOutput {
    /// The built-in example's heat path: bodies of κ = 50 W/(m K) (a steel)
    /// with an air gap (κ_gas = 0.026 W/(m K), temperature-jump length
    /// ℓ = 70 nm at 1 atm), so that both the spots' and the gap's
    /// conductance are reported.
    pub fn example() -> Self {
        ConductanceOutput {
            conductivity: vec![50.0],
            gas_conductivity: Some(0.026),
            mean_free_path: Some(7e-8),
            ..Default::default()
        }
    }
}
