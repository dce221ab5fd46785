//! The error-against-time report: each method's knob, its rows and the table.

use persson::clock::Instant;

use serde::Serialize;

use crate::table::{Cell, Table, Tabulate};

/// The accuracy knob of a method.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
#[non_exhaustive]
pub enum Knob {
    /// A requested tolerance ε.
    Tolerance,
    /// The grid side N of the BEM.
    Grid,
    /// The number of terms of a series.
    Terms,
    /// A phase fraction (the blocked fraction a of a two-phase medium).
    Fraction,
    /// A number of samples (surrogates K).
    Count,
}

impl Knob {
    /// Its key (CSV header) and its heading for people.
    fn column(self) -> (&'static str, &'static str) {
        match self {
            Knob::Tolerance => ("tolerance", "ε"),
            Knob::Grid => ("grid", "N"),
            Knob::Terms => ("terms", "terms"),
            Knob::Fraction => ("fraction", "a"),
            Knob::Count => ("count", "K"),
        }
    }
}

/// One measured point: a method at one setting of its knob.
#[derive(Debug, Clone, Serialize)]
#[non_exhaustive]
pub struct AccuracyRow {
    /// The knob's setting (a tolerance, or a grid side or term count).
    pub setting: f64,
    /// Achieved error against the reference (its measure is the method's
    /// [`MethodAccuracy::reference`]).
    pub error: f64,
    /// The method's own bound on that error, where it gives one.
    pub error_bound: Option<f64>,
    /// The solver's final residual ε, for an iterative solver (the BEM).
    pub residual: Option<f64>,
    /// Wall time of one evaluation, s (what one evaluation is: see
    /// [`MethodAccuracy::reference`]).
    pub seconds: f64,
}

/// One numerical method of the accuracy report, at every setting of its knob.
#[derive(Debug, Clone, Serialize)]
#[non_exhaustive]
pub struct MethodAccuracy {
    /// Short name (kebab-case), e.g. `g-quadrature`.
    pub method: &'static str,
    /// What the method computes and how, for people.
    pub title: String,
    /// Its accuracy knob.
    pub knob: Knob,
    /// The reference the error is measured against, the error's measure and
    /// what `seconds` times.
    pub reference: String,
    /// One row per setting, loosest first.
    pub rows: Vec<AccuracyRow>,
}

/// Error against run time of every numerical method of this build.
#[derive(Debug, Clone, Serialize)]
#[non_exhaustive]
pub struct AccuracyReport {
    /// The methods, in the order of the crate's layers (core, stress, BEM).
    pub methods: Vec<MethodAccuracy>,
}

impl Tabulate for AccuracyReport {
    fn tables(&self) -> Vec<Table> {
        self.methods
            .iter()
            .map(|m| {
                let (key, heading) = m.knob.column();
                let has =
                    |f: fn(&AccuracyRow) -> Option<f64>| m.rows.iter().any(|r| f(r).is_some());
                let (bound, residual) = (has(|r| r.error_bound), has(|r| r.residual));
                let mut t = Table::new(
                    format!("accuracy_{}", m.method.replace('-', "_")),
                    m.title.clone(),
                )
                .scalar("reference", "reference", m.reference.as_str())
                .column_digits(key, heading, 1)
                // errors and times to two digits: run-to-run noise of the
                // times is a few per cent, and an error needs no more
                .column_digits("error", "error", 2);
                if bound {
                    t = t.column_digits("error_bound", "error bound", 2);
                }
                if residual {
                    t = t.column_digits("residual", "residual", 2);
                }
                t = t.column_digits("seconds", "time (s)", 2);
                for r in &m.rows {
                    let setting = match m.knob {
                        Knob::Tolerance | Knob::Fraction => Cell::Num(r.setting),
                        Knob::Grid | Knob::Terms | Knob::Count => Cell::Int(r.setting as i64),
                    };
                    let mut row = vec![setting, Cell::Num(r.error)];
                    if bound {
                        row.push(r.error_bound.into());
                    }
                    if residual {
                        row.push(r.residual.into());
                    }
                    row.push(Cell::Num(r.seconds));
                    t.push(row);
                }
                t
            })
            .collect()
    }
}

/// How far the accuracy report goes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Extent {
    /// The default: under two minutes on two cores.
    Default,
    /// Further: finer tolerances and larger grids.
    Full,
}

/// Median wall time of `f` over enough repetitions to last ~`budget` seconds.
pub(crate) fn time_it<T>(budget: f64, mut f: impl FnMut() -> T) -> (T, f64) {
    let t0 = Instant::now();
    let mut out = f();
    let first = t0.elapsed().as_secs_f64();
    let reps = ((budget / first.max(1e-9)) as usize).clamp(1, 10_000);
    if reps == 1 {
        return (out, first);
    }
    let mut times = Vec::with_capacity(reps);
    for _ in 0..reps {
        let t = Instant::now();
        out = f();
        times.push(t.elapsed().as_secs_f64());
    }
    times.sort_by(f64::total_cmp);
    (out, times[reps / 2])
}
