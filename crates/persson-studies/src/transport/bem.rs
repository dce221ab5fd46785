//! The FFT-BEM's conductance and leak rate at each load (feature `flow`):
//! the exact stiffness of the solved contact (a linear solve on its contact
//! set, [`persson::bem::stiffness`]), Barber's identity on it, the gap
//! conductance of its gap field, and Reynolds flow on that gap along x and
//! along y ([`persson::bem::reynolds`]).

use persson::bem::reynolds::{flow, FlowDirection, GapField};
use persson::bem::rough::{solve, Observer, RoughOptions, RoughProgress};
use persson::bem::stiffness::{contact_stiffness, StiffnessOptions};
use persson::bem::surface::{synthesize, GridSurface};
use persson::bem::{check_memory, Boundary, Operator, Options, Solution};
use persson::conductance::{electrical_conductance, gap_conductance_of_field, thermal_conductance};
use persson::error::{check, Error, Result};
use persson::Estimate;

use super::report::{BemFlow, BemTransportPoint, BemTransportReport};
use super::request::TransportRequest;
use super::spec::TransportBem;
use crate::contact::RoughContact;
use crate::naming::required;

/// Default solver tolerance of the contact and of the stiffness's CG.
pub const DEFAULT_TOLERANCE: f64 = 1e-10;

/// Computes the transport values of each converged solution and passes
/// everything on to an inner observer (progress, fields to write).
pub struct TransportObserver<'a> {
    inner: &'a mut dyn Observer,
    op: Operator,
    request: TransportRequest,
    stiffness: StiffnessOptions,
    pressures: Vec<f64>,
    points: Vec<BemTransportPoint>,
}

impl<'a> TransportObserver<'a> {
    /// An observer for solves of an `n × n` periodic grid of side `size` and
    /// E* = `contact_modulus`, at `pressures` (in the order solved).
    ///
    /// # Errors
    /// As [`Operator::new`]; a tolerance out of range.
    pub fn new(
        inner: &'a mut dyn Observer,
        n: usize,
        size: f64,
        contact_modulus: f64,
        pressures: &[f64],
        tolerance: f64,
        request: TransportRequest,
    ) -> Result<Self> {
        Ok(TransportObserver {
            inner,
            op: Operator::new(Boundary::Periodic, n, size, contact_modulus)?,
            request,
            stiffness: StiffnessOptions {
                tolerance: check::tolerance("tolerance", tolerance)?,
                ..StiffnessOptions::default()
            },
            pressures: pressures.to_vec(),
            points: Vec::new(),
        })
    }

    /// The points computed so far, one per solution.
    pub fn into_points(self) -> Vec<BemTransportPoint> {
        self.points
    }

    fn point(&mut self, index: usize, s: &Solution) -> Result<BemTransportPoint> {
        let n = self.op.n();
        let e_star = self.op.e_star();
        let k = contact_stiffness(&mut self.op, &s.pressure, &self.stiffness)?;
        let ke = Estimate {
            value: k.stiffness,
            error: k.stiffness_error_bound,
        };
        let split = |e: Option<Estimate>| (e.map(|e| e.value), e.map(|e| e.error));
        let (th, th_e) = split(
            self.request
                .conductivity
                .map(|c| thermal_conductance(ke, e_star, &c))
                .transpose()?,
        );
        let (el, el_e) = split(
            self.request
                .resistivity
                .map(|r| electrical_conductance(ke, e_star, &r))
                .transpose()?,
        );
        let gap = self
            .request
            .gap_law
            .as_ref()
            .map(|law| gap_conductance_of_field(&s.gap, &s.pressure, law))
            .transpose()?;
        let mut p = BemTransportPoint {
            nominal_pressure: self
                .pressures
                .get(index)
                .copied()
                .unwrap_or(s.mean_pressure),
            contact_fraction: s.contact_fraction,
            mean_separation: s.gap.iter().sum::<f64>() / s.gap.len() as f64,
            stiffness: k.stiffness,
            stiffness_error_bound: k.stiffness_error_bound,
            thermal_conductance: th,
            thermal_conductance_error_bound: th_e,
            electrical_conductance: el,
            electrical_conductance_error_bound: el_e,
            gap_conductance: gap,
            percolates: None,
            effective_flow_conductivity: None,
            effective_flow_conductivity_error_bound: None,
            leak_rate: None,
            leak_rate_error_bound: None,
            flows: Vec::new(),
        };
        if let Some(seal) = self.request.seal {
            let field = GapField::from_solution(s, n, self.op.size())?;
            for direction in [FlowDirection::X, FlowDirection::Y] {
                let f = flow(&field, seal.viscosity, direction)?;
                p.flows.push(BemFlow {
                    direction,
                    percolates: f.percolates,
                    effective_flow_conductivity: f.effective_flow_conductivity,
                    effective_flow_conductivity_error_bound: f
                        .effective_flow_conductivity_error_bound,
                });
            }
            let mean = |g: &dyn Fn(&BemFlow) -> f64| p.flows.iter().map(g).sum::<f64>() / 2.0;
            let sigma = mean(&|f| f.effective_flow_conductivity);
            let sigma_err = mean(&|f| f.effective_flow_conductivity_error_bound);
            p.percolates = Some(p.flows.iter().any(|f| f.percolates));
            p.effective_flow_conductivity = Some(sigma);
            p.effective_flow_conductivity_error_bound = Some(sigma_err);
            let q = seal.leak_rate(sigma)?;
            p.leak_rate = Some(q);
            p.leak_rate_error_bound = Some(seal.leak_rate(sigma_err)? + 8.0 * f64::EPSILON * q);
        }
        Ok(p)
    }
}

impl Observer for TransportObserver<'_> {
    fn iteration(&mut self, progress: RoughProgress) {
        self.inner.iteration(progress);
    }

    fn solution(&mut self, index: usize, solution: &Solution) -> Result<()> {
        self.inner.solution(index, solution)?;
        let p = self.point(index, solution)?;
        self.points.push(p);
        Ok(())
    }
}

/// Solve `surface` (periodic) at each pressure, warm-started along the list,
/// and compute the transport values of each solution.
///
/// # Errors
/// As [`solve`], [`contact_stiffness`] (every node in contact) and [`flow`].
pub fn transport(
    surface: &GridSurface,
    seed: Option<u64>,
    contact_modulus: f64,
    pressures: &[f64],
    tolerance: f64,
    request: &TransportRequest,
) -> Result<BemTransportReport> {
    let tolerance = check::tolerance("tolerance", tolerance)?;
    let mut nothing = ();
    let mut obs = TransportObserver::new(
        &mut nothing,
        surface.n,
        surface.size,
        contact_modulus,
        pressures,
        tolerance,
        request.clone(),
    )?;
    // Needless before main's RoughOptions gains its `method` field, needed after.
    #[allow(clippy::needless_update)]
    let options = RoughOptions {
        boundary: Boundary::Periodic,
        solver: Options {
            tolerance,
            warm_start: true,
            ..Options::default()
        },
        bins: None,
        // main's RoughOptions gains fields (a solver `method`): their defaults.
        ..RoughOptions::default()
    };
    solve(surface, contact_modulus, pressures, &options, &mut obs)?;
    Ok(BemTransportReport {
        grid: surface.n,
        size: surface.size,
        seed,
        tolerance,
        surface_rms_height: surface.rms_height(),
        surface_rms_slope: surface.rms_slope()?,
        points: obs.into_points(),
    })
}

/// [`transport`] on the scene's rigid surface: its height map (periodic),
/// else a surface synthesised from its spectrum (side 2π/q_l) on `b.grid`
/// nodes with `b.seed`, as `outputs.bem` solves (`bem rough --surface` and
/// `bem rough --grid` on the command line).
///
/// # Errors
/// A grid or seed beside a height map, no grid beside a spectrum; a map that
/// is not square; a grid too large for memory; as [`transport`].
pub fn on_contact(
    contact: &RoughContact,
    pressures: &[f64],
    b: &TransportBem,
    request: &TransportRequest,
) -> Result<BemTransportReport> {
    let tolerance = b.tolerance.unwrap_or(DEFAULT_TOLERANCE);
    let e_star = contact.contact_modulus;
    let (surface, seed) = match &contact.height_map {
        Some(m) => {
            let given = [("grid", b.grid.is_some()), ("seed", b.seed.is_some())];
            if let Some((name, _)) = given.iter().find(|g| g.1) {
                return Err(Error::Inconsistent {
                    name: (*name).into(),
                    requirement: "not used with a height map (its file sets the grid)".into(),
                });
            }
            (m.bem_surface(Boundary::Periodic)?, None)
        }
        None => {
            let n = b
                .grid
                .ok_or_else(|| required("grid (for a surface synthesised from the spectrum)"))?;
            check_memory(n, Boundary::Periodic)?;
            let seed = b.seed.unwrap_or(1);
            let spectrum = contact.spectrum.as_ref();
            let size = std::f64::consts::TAU / spectrum.q_min();
            (synthesize(spectrum, n, size, seed)?, Some(seed))
        }
    };
    transport(&surface, seed, e_star, pressures, tolerance, request)
}
