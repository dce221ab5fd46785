//! The stability sweep's cases, families and summary table.

use serde::Serialize;

use crate::table::{self, Cell, Table, Tabulate};

/// A family of cases of the stability sweep.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
#[non_exhaustive]
pub enum Family {
    /// A/A0 = erf(1/(2√G)) for G from 1e-12 to 1e30.
    ContactFraction,
    /// Persson's A/A0 of self-affine spectra at extreme H, ζ and σ0.
    SelfAffine,
    /// Stress distributions from the flat start.
    StressFlat,
    /// Stress distributions from the Hertz start.
    StressHertz,
    /// Stress distributions from the cylinder start.
    StressCylinder,
    /// Stress distributions from a tabulated start (Hertz's P0 as a table).
    StressTabulated,
}

impl Family {
    /// Every family, in the order of the report.
    pub const ALL: [Family; 6] = [
        Family::ContactFraction,
        Family::SelfAffine,
        Family::StressFlat,
        Family::StressHertz,
        Family::StressCylinder,
        Family::StressTabulated,
    ];

    /// Its name in JSON and CSV (kebab-case).
    pub fn key(self) -> &'static str {
        match self {
            Family::ContactFraction => "contact-fraction",
            Family::SelfAffine => "self-affine",
            Family::StressFlat => "stress-flat",
            Family::StressHertz => "stress-hertz",
            Family::StressCylinder => "stress-cylinder",
            Family::StressTabulated => "stress-tabulated",
        }
    }

    /// The inputs the family covers, for people.
    pub fn description(self) -> &'static str {
        match self {
            Family::ContactFraction => "A/A0 from G = 1e-12 … 1e30",
            Family::SelfAffine => "Persson's A/A0: H 0.01 … 0.99, ζ to 1e10, σ0 1e-12 … 10 E*",
            Family::StressFlat => "A_el/A0, flat start: G 0 … 1e30, σY/σH 1 + 1e-6 … 1e6",
            Family::StressHertz => "A_el/A0, Hertz start: G 0 … 1e30, σY/σH 1 + 1e-6 … 1e6",
            Family::StressCylinder => "A_el/A0, cylinder start: G 0 … 1e30, σY/σH 1 + 1e-6 … 1e6",
            Family::StressTabulated => {
                "A_el/A0, Hertz's P0 as a table: G 0 … 1e30, σY/σH 1 + 1e-6 … 1e6"
            }
        }
    }
}

/// The error allowed for a reference itself: high-precision values rounded
/// to f64, half an ulp of the value.
const REFERENCE_ROUNDING: f64 = 0.5 * f64::EPSILON;

/// One extreme case of the stability sweep.
#[derive(Debug, Clone, Serialize)]
#[non_exhaustive]
pub struct StabilityCase {
    /// The family of the case.
    pub family: Family,
    /// What was computed, with its inputs.
    pub case: String,
    /// The value (a contact fraction).
    pub value: f64,
    /// Its error bound.
    pub error_bound: f64,
    /// An independent reference value, where one exists.
    pub reference: Option<f64>,
    /// |value − reference|.
    pub error: Option<f64>,
    /// Whether the error is within the bound (plus half an ulp of the
    /// reference for its own rounding).
    pub bound_held: Option<bool>,
    /// Whether every output of the case was finite.
    pub finite: bool,
}

/// One family of the stability sweep, summed up.
#[derive(Debug, Clone, Serialize)]
#[non_exhaustive]
pub struct FamilySummary {
    /// The family.
    pub family: Family,
    /// Cases tried.
    pub cases: usize,
    /// Cases with a reference value.
    pub cases_with_reference: usize,
    /// The largest absolute error against a reference (`None`: no reference).
    pub error: Option<f64>,
    /// Whether every error bound held against its reference.
    pub bounds_held: bool,
    /// Cases with a non-finite output.
    pub non_finite: usize,
}

/// The stability sweep: a summary per family and every case.
#[derive(Debug, Clone, Serialize)]
#[non_exhaustive]
pub struct StabilityReport {
    /// One summary per family.
    pub families: Vec<FamilySummary>,
    /// Every case.
    pub cases: Vec<StabilityCase>,
}

impl StabilityReport {
    pub(crate) fn new(cases: Vec<StabilityCase>) -> Self {
        let families = Family::ALL
            .iter()
            .map(|&family| {
                let of: Vec<&StabilityCase> = cases.iter().filter(|c| c.family == family).collect();
                let errors: Vec<f64> = of.iter().filter_map(|c| c.error).collect();
                FamilySummary {
                    family,
                    cases: of.len(),
                    cases_with_reference: errors.len(),
                    error: errors.iter().copied().reduce(f64::max),
                    bounds_held: of.iter().all(|c| c.bound_held != Some(false)),
                    non_finite: of.iter().filter(|c| !c.finite).count(),
                }
            })
            .filter(|s| s.cases > 0)
            .collect();
        StabilityReport { families, cases }
    }

    /// Cases with a non-finite output, over every family.
    pub fn non_finite(&self) -> usize {
        self.families.iter().map(|f| f.non_finite).sum()
    }

    /// Whether every error bound held against its reference.
    pub fn bounds_held(&self) -> bool {
        self.families.iter().all(|f| f.bounds_held)
    }
}

impl Tabulate for StabilityReport {
    fn tables(&self) -> Vec<Table> {
        let mut t = Table::new(
            "stability",
            "Stability: extreme and stiff inputs, per family (every case with --json)",
        )
        .scalar("cases", "cases", self.cases.len())
        .column("family", "family")
        .column("inputs", "inputs")
        .column("cases", "cases")
        .column("cases_with_reference", "with reference")
        .column_digits("error", "worst error", 2)
        .column("bounds_held", "bounds held")
        .column("non_finite", "non-finite");
        for f in &self.families {
            t.push(vec![
                f.family.key().into(),
                f.family.description().into(),
                f.cases.into(),
                f.cases_with_reference.into(),
                f.error.into(),
                if f.cases_with_reference == 0 {
                    Cell::Empty
                } else if f.bounds_held {
                    "yes".into()
                } else {
                    "no".into()
                },
                f.non_finite.into(),
            ]);
        }
        vec![t]
    }
}

/// A case of `family` with its value, bound, other outputs (checked for
/// finiteness) and reference value, if any.
pub(crate) fn case(
    family: Family,
    case: String,
    (value, error_bound): (f64, f64),
    others: &[f64],
    reference: Option<f64>,
) -> StabilityCase {
    let finite =
        value.is_finite() && error_bound.is_finite() && others.iter().all(|v| v.is_finite());
    let error = reference.map(|r| (value - r).abs());
    let bound_held = reference
        .zip(error)
        .map(|(r, e)| e <= error_bound + REFERENCE_ROUNDING * r.abs());
    StabilityCase {
        family,
        case,
        value,
        error_bound,
        reference,
        error,
        bound_held,
        finite,
    }
}

/// A number for a case description: `1e-12`, `0.5`, `1.000001`.
pub(crate) fn num(v: f64) -> String {
    table::number(v, 7)
}
