//! The FFT-BEM's rough contact with its transport values (feature `bem`).

use serde::Serialize;

use super::{transport_table, BemTransportPoint};
use crate::table::{Table, Tabulate};

/// An FFT-BEM rough contact with its conductance and leak rate per load
/// (`persson bem rough --conductivity/--resistivity/--leakage`): the rough
/// report's keys, and `transport` with one point per load.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct RoughTransportReport {
    /// The contact.
    #[serde(flatten)]
    pub rough: persson::bem::rough::RoughReport,
    /// The transport values of each solve, in the order of `points`.
    pub transport: Vec<BemTransportPoint>,
}

impl RoughTransportReport {
    /// The report of a contact and its transport values.
    pub fn new(rough: persson::bem::rough::RoughReport, transport: Vec<BemTransportPoint>) -> Self {
        RoughTransportReport { rough, transport }
    }
}

impl Tabulate for RoughTransportReport {
    fn tables(&self) -> Vec<Table> {
        let mut out = self.rough.tables();
        out.push(transport_table(&self.transport));
        out
    }
}
