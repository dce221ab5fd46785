//! What the BEM computes besides the contact, built from a transport output.

use persson::conductance::{Conductivity, GapLaw, Resistivity};
use persson::leakage::Seal;

/// What the BEM computes besides the contact: the conductances and the flow.
#[derive(Debug, Clone, PartialEq, Default)]
#[non_exhaustive]
pub struct TransportRequest {
    /// κ1, κ2: the thermal conductance.
    pub conductivity: Option<Conductivity>,
    /// ρ1, ρ2: the electrical conductance.
    pub resistivity: Option<Resistivity>,
    /// α(u): the gap conductance.
    pub gap_law: Option<GapLaw>,
    /// The seal: Reynolds flow and the leak rate.
    pub seal: Option<Seal>,
}

impl TransportRequest {
    /// A request from its parts.
    pub fn new(
        conductivity: Option<Conductivity>,
        resistivity: Option<Resistivity>,
        gap_law: Option<GapLaw>,
        seal: Option<Seal>,
    ) -> Self {
        TransportRequest {
            conductivity,
            resistivity,
            gap_law,
            seal,
        }
    }
}
