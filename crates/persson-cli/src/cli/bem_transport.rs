//! `persson bem rough --conductivity/--resistivity/--gas-conductivity/--leakage`:
//! the conductance and leak rate of each solve (feature `flow`), computed by
//! the studies' observer beside the CLI's own (progress, fields to write).

use anyhow::bail;
use persson::bem::rough::Observer;
use persson::bem::Boundary;
use persson_studies::scene::transport::{self, TransportRequest};
use persson_studies::scene::transport_bem::TransportObserver;
use persson_studies::scene::{BemTransportPoint, RoughTransportReport};
use persson_studies::Warning;

use super::bem_args::{RoughArgs, RoughSettings};

/// The transport values the flags ask for (`None`: none).
pub fn request(a: &RoughArgs, set: &RoughSettings) -> anyhow::Result<Option<TransportRequest>> {
    let t = &a.transport;
    if t.seal.given() && !t.leakage {
        bail!(
            "--viscosity / --pressure-drop / --inlet-pressure / --outlet-pressure: add --leakage to compute the flow"
        );
    }
    let seal = if t.leakage {
        let out = t
            .seal
            .output(persson::leakage::DEFAULT_PERCOLATION_THRESHOLD, 1e-9, false)?;
        Some(transport::seal(&out)?)
    } else {
        None
    };
    let request = t.conductance.request(seal)?;
    if request == TransportRequest::default() {
        if t.gap_field.is_some() {
            bail!(
                "--gap-field: add --leakage (the gap the flow is solved on) or a conductance flag"
            );
        }
        return Ok(None);
    }
    if set.boundary != Boundary::Periodic {
        bail!("--leakage / --conductivity / --resistivity / --gas-conductivity: need --boundary periodic (the stiffness and the flow of the periodic cell)");
    }
    if set.options.yield_stress.is_some() {
        bail!("--leakage / --conductivity / --resistivity / --gas-conductivity: not with --yield-stress (Barber's identity and the stiffness solve are elastic)");
    }
    if cfg!(not(feature = "flow")) {
        bail!("--leakage / --conductivity / --resistivity / --gas-conductivity: this persson was built without the `flow` feature");
    }
    Ok(Some(request))
}

/// The CLI's observer, wrapped in the studies' transport observer when asked.
pub enum Observed<'a> {
    /// Only the CLI's.
    Plain(&'a mut dyn Observer),
    /// With the conductance and flow of each solve (feature `flow`).
    Transport(Box<TransportObserver<'a>>),
}

impl<'a> Observed<'a> {
    /// Wrap `inner` when `request` is given; `grid` is (N, L, E*).
    pub fn new(
        inner: &'a mut dyn Observer,
        request: Option<TransportRequest>,
        grid: (usize, f64, f64),
        pressures: &[f64],
        tolerance: f64,
    ) -> anyhow::Result<Self> {
        Ok(match request {
            None => Observed::Plain(inner),
            Some(r) => Observed::Transport(Box::new(TransportObserver::new(
                inner, grid.0, grid.1, grid.2, pressures, tolerance, r,
            )?)),
        })
    }

    /// The observer to pass to the solves.
    pub fn observer(&mut self) -> &mut dyn Observer {
        match self {
            Observed::Plain(o) => *o,
            Observed::Transport(t) => t.as_mut(),
        }
    }

    /// The transport points, when asked for.
    pub fn finish(self) -> Option<Vec<BemTransportPoint>> {
        match self {
            Observed::Plain(_) => None,
            Observed::Transport(t) => Some(t.into_points()),
        }
    }
}

/// The warning of the loads whose gap does not percolate.
pub fn sealed(r: &RoughTransportReport) -> Option<Warning> {
    transport::sealed_bem(&r.transport)
}
