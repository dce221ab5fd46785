//! The map against its surrogates (feature `bem`): a plan whose jobs (the
//! map, then each surrogate) are independent solves, run here one after the
//! other or shipped to other processes, and gathered into the report by
//! the same code.
//!
//! Like with like: every surface is solved on the map's grid, with the same
//! boundary, tolerance and loads. With the periodic boundary (the default)
//! the BEM sees the map repeated, and its periodic spectrum, the one every
//! surrogate keeps exactly (phase) or nearly (IAAFT), is then the spectrum
//! of the surface the BEM solves: the comparison is of two surfaces of one
//! spectrum, even for a map that was not measured periodic (its edge step
//! is in that spectrum, and in the surrogates as power on the axes).

use persson::clock::Instant;

use serde::{Deserialize, Serialize};

use persson::bem::patches::{patch_statistics, pressure_tail, PatchOptions, TailShape};
use persson::bem::rough::{solve, Observer, RoughOptions};
use persson::bem::surface::GridSurface;
use persson::bem::surrogate::{
    amplitude_adjusted, check_map, height_moments, phase_randomised, student_t_975,
    DEFAULT_IAAFT_ITERATIONS,
};
use persson::bem::{Options, Solution};
use persson::error::{check, Error, Result};
use persson::spectrum::BandLimited;
use persson::theory::Persson;

use super::report::{HeightMoments, SurrogatePoint, SurrogatesReport, Tail};
use super::spec::SurrogatesOutput;
use crate::input::SurrogateKindName;
use crate::naming::prefix;
use persson::names::Boundary;

/// Surrogates when `count` is not given.
pub const DEFAULT_COUNT: usize = 8;

/// Solver tolerance when `tolerance` is not given.
pub const DEFAULT_TOLERANCE: f64 = 1e-8;

/// Bins of P(p) per nominal pressure σ0 (width σ0/10, pooled exactly over
/// the surrogates).
const BINS_PER_SIGMA0: f64 = 10.0;

/// What every job needs: the map, the surrogates' recipe and the solves'.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct Plan {
    /// Where the map came from (for the report).
    pub map_name: String,
    /// Grid side N.
    pub grid: usize,
    /// Side L.
    pub size: f64,
    /// The map's heights, row-major N × N (not in the serde form: a
    /// process boundary carries them as floats, exactly, not as decimals).
    #[serde(skip)]
    pub heights: Vec<f64>,
    /// Kind of surrogate.
    pub kind: SurrogateKindName,
    /// K.
    pub count: usize,
    /// Seed of surrogate 1.
    pub seed: u64,
    /// Most IAAFT iterations.
    pub iterations: usize,
    /// E*.
    pub contact_modulus: f64,
    /// σ0 of the solves, in the scene's order.
    pub pressures: Vec<f64>,
    /// Boundary of every solve.
    pub boundary: Boundary,
    /// Tolerance of every solve.
    pub tolerance: f64,
}

/// One job's numbers: surface `index` (0 the map, k the k-th surrogate).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Solved {
    /// 0 for the map, k for surrogate k.
    pub index: usize,
    /// Skewness and kurtosis of its heights.
    pub moments: (f64, f64),
    /// IAAFT: the radial-spectrum mismatch and the iterations.
    pub adjusted: Option<(f64, usize)>,
    /// Per pressure: A/A0, patches, tail (exponential?, advantage), P(p) counts.
    pub points: Vec<SolvedPoint>,
}

/// One solve of a job.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SolvedPoint {
    /// A/A0.
    pub contact_fraction: f64,
    /// Contact patches.
    pub patches: usize,
    /// The tail: exponential better, and the log-likelihood advantage.
    pub tail: Option<(bool, f64)>,
    /// Contact pressures counted in bins of σ0/10 from 0.
    pub counts: Vec<u64>,
}

impl Plan {
    /// The plan of `spec` on `map` at `pressures` (E* = `contact_modulus`).
    ///
    /// # Errors
    /// K < 2, no pressure or a pressure not positive, a tolerance out of
    /// range, `iterations` = 0, a constant map (each named).
    pub fn new(
        spec: &SurrogatesOutput,
        map: (&str, &GridSurface),
        contact_modulus: f64,
        pressures: &[f64],
    ) -> Result<Self> {
        let count = spec.count.unwrap_or(DEFAULT_COUNT);
        if count < 2 {
            return Err(Error::invalid(
                "count",
                count as f64,
                ">= 2 (a spread needs two surrogates)",
            ));
        }
        let iterations = spec.iterations.unwrap_or(DEFAULT_IAAFT_ITERATIONS);
        if iterations == 0 {
            return Err(Error::invalid("iterations", 0.0, ">= 1"));
        }
        let tolerance = check::tolerance("tolerance", spec.tolerance.unwrap_or(DEFAULT_TOLERANCE))?;
        if pressures.is_empty() {
            return Err(crate::naming::required("nominal_pressure"));
        }
        for &p in pressures {
            check::positive("nominal_pressure", p)?;
        }
        let (name, surface) = map;
        let plan = Plan {
            map_name: name.to_string(),
            grid: surface.n,
            size: surface.size,
            heights: surface.heights.clone(),
            kind: spec.kind.unwrap_or_default(),
            count,
            seed: spec.seed.unwrap_or(1),
            iterations,
            contact_modulus,
            pressures: pressures.to_vec(),
            boundary: spec.boundary.unwrap_or(Boundary::Periodic),
            tolerance,
        };
        check_map(surface)?;
        Ok(plan)
    }

    /// The jobs: 0 (the map), 1 … K (the surrogates).
    pub fn jobs(&self) -> Vec<usize> {
        (0..=self.count).collect()
    }

    /// The map.
    ///
    /// # Errors
    /// Heights that are not an N × N map.
    pub fn map(&self) -> Result<GridSurface> {
        GridSurface::new(self.grid, self.size, self.heights.clone())
    }

    /// Surface `index` with its IAAFT figures: the map (0) or surrogate k.
    ///
    /// # Errors
    /// A constant map.
    pub fn surface(&self, index: usize) -> Result<(GridSurface, Option<(f64, usize)>)> {
        let map = self.map()?;
        if index == 0 {
            return Ok((map, None));
        }
        let seed = self.seed.wrapping_add(index as u64 - 1);
        Ok(match self.kind {
            SurrogateKindName::Phase => (phase_randomised(&map, seed)?, None),
            SurrogateKindName::AmplitudeAdjusted => {
                let a = amplitude_adjusted(&map, seed, self.iterations)?;
                let figures = (a.spectrum_mismatch, a.iterations);
                (a.surface, Some(figures))
            }
        })
    }

    /// Job `index`: make the surface and solve it at every pressure.
    ///
    /// # Errors
    /// As [`Plan::surface`] and [`solve`].
    pub fn solve(&self, index: usize) -> Result<Solved> {
        let (surface, adjusted) = self.surface(index)?;
        let boundary = self.boundary;
        let options = RoughOptions {
            boundary,
            solver: Options {
                tolerance: self.tolerance,
                warm_start: true,
                ..Options::default()
            },
            ..RoughOptions::default()
        };
        let mut each = Each {
            plan: self,
            patches: PatchOptions {
                boundary,
                ..PatchOptions::default()
            },
            points: Vec::new(),
        };
        let points = solve(
            &surface,
            self.contact_modulus,
            &self.pressures,
            &options,
            &mut each,
        )?;
        let mut solved = each.points;
        for (s, p) in solved.iter_mut().zip(&points) {
            s.contact_fraction = p.contact_fraction;
        }
        Ok(Solved {
            index,
            moments: height_moments(&surface.heights),
            adjusted,
            points: solved,
        })
    }

    /// The report from every job's numbers (in any order) and the theory's
    /// A/A0 at each pressure.
    ///
    /// # Errors
    /// A job missing or given twice.
    pub fn gather(
        &self,
        mut solved: Vec<Solved>,
        theory: &[f64],
        seconds: f64,
    ) -> Result<SurrogatesReport> {
        solved.sort_by_key(|s| s.index);
        if solved.iter().map(|s| s.index).ne(self.jobs()) {
            return Err(Error::Inconsistent {
                name: "solves".into(),
                requirement: format!("one per surface 0 … {}", self.count),
            });
        }
        let (map, surrogates) = solved.split_at(1);
        let map = &map[0];
        let k = surrogates.len() as f64;
        let mean = |f: &dyn Fn(&Solved) -> f64| surrogates.iter().map(f).sum::<f64>() / k;
        let points = (0..self.pressures.len())
            .map(|i| self.point(i, map, surrogates, theory.get(i).copied()))
            .collect();
        let adjusted: Vec<(f64, usize)> = surrogates.iter().filter_map(|s| s.adjusted).collect();
        Ok(SurrogatesReport {
            map: self.map_name.clone(),
            kind: self.kind,
            count: self.count,
            threshold: student_t_975(self.count - 1),
            seed: self.seed,
            grid: self.grid,
            size: self.size,
            boundary: self.boundary,
            tolerance: self.tolerance,
            contact_modulus: self.contact_modulus,
            map_heights: HeightMoments {
                skewness: map.moments.0,
                kurtosis: map.moments.1,
            },
            surrogate_heights: HeightMoments {
                skewness: mean(&|s| s.moments.0),
                kurtosis: mean(&|s| s.moments.1),
            },
            spectrum_mismatch: (!adjusted.is_empty())
                .then(|| adjusted.iter().fold(0.0, |m: f64, a| m.max(a.0))),
            iterations: adjusted.iter().map(|a| a.1).max(),
            points,
            seconds,
            surfaces: Vec::new(),
        })
    }

    /// The row of pressure `i`.
    fn point(
        &self,
        i: usize,
        map: &Solved,
        surrogates: &[Solved],
        theory: Option<f64>,
    ) -> SurrogatePoint {
        let k = surrogates.len() as f64;
        let a: Vec<f64> = surrogates
            .iter()
            .map(|s| s.points[i].contact_fraction)
            .collect();
        let mean = a.iter().sum::<f64>() / k;
        let sd = (a.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (k - 1.0)).sqrt();
        let se = sd / k.sqrt();
        let own = map.points[i].contact_fraction;
        let z = (own - mean) / (sd * (1.0 + 1.0 / k).sqrt());
        let tails: Vec<(bool, f64)> = surrogates.iter().filter_map(|s| s.points[i].tail).collect();
        let surrogate_tail = (tails.len() >= 2).then(|| {
            let m = tails.len() as f64;
            let mean = tails.iter().map(|t| t.1).sum::<f64>() / m;
            let sd = (tails.iter().map(|t| (t.1 - mean).powi(2)).sum::<f64>() / (m - 1.0)).sqrt();
            Tail {
                exponential_share: tails.iter().filter(|t| t.0).count() as f64 / m,
                log_likelihood_advantage: mean,
                standard_deviation: Some(sd),
            }
        });
        let map_tail = map.points[i].tail.map(|(exp, adv)| Tail {
            exponential_share: if exp { 1.0 } else { 0.0 },
            log_likelihood_advantage: adv,
            standard_deviation: None,
        });
        let tail_z = match (&map_tail, &surrogate_tail) {
            (Some(m), Some(s)) => s.standard_deviation.map(|sd| {
                let z = (m.log_likelihood_advantage - s.log_likelihood_advantage)
                    / (sd * (1.0 + 1.0 / tails.len() as f64).sqrt());
                if z.is_finite() {
                    z
                } else {
                    0.0
                }
            }),
            _ => None,
        };
        let sigma0 = self.pressures[i];
        let pooled = pool(surrogates.iter().map(|s| s.points[i].counts.as_slice()));
        SurrogatePoint {
            nominal_pressure: sigma0,
            map_contact_fraction: own,
            surrogate_contact_fraction: mean,
            surrogate_standard_deviation: sd,
            surrogate_standard_error: se,
            ratio: own / mean,
            ratio_error: own / mean * se / mean,
            z: if z.is_finite() { z } else { 0.0 },
            significant: z.abs() > student_t_975(surrogates.len() - 1),
            theory_contact_fraction: theory.unwrap_or(f64::NAN),
            map_patches: map.points[i].patches,
            surrogate_patches: surrogates
                .iter()
                .map(|s| s.points[i].patches as f64)
                .sum::<f64>()
                / k,
            map_tail,
            surrogate_tail,
            tail_z,
            map_distribution: density(&map.points[i].counts, 1, self.grid, sigma0),
            surrogate_distribution: density(&pooled, surrogates.len(), self.grid, sigma0),
        }
    }
}

/// The counts of several surfaces added bin by bin.
fn pool<'a>(counts: impl Iterator<Item = &'a [u64]>) -> Vec<u64> {
    let mut out: Vec<u64> = Vec::new();
    for c in counts {
        if c.len() > out.len() {
            out.resize(c.len(), 0);
        }
        for (o, v) in out.iter_mut().zip(c) {
            *o += v;
        }
    }
    out
}

/// P(p) bins `(low, high, density)` of counts over `surfaces` N × N maps:
/// `density = count/(nodes Δp)`, integrating to the mean A/A0.
fn density(counts: &[u64], surfaces: usize, n: usize, sigma0: f64) -> Vec<(f64, f64, f64)> {
    let width = sigma0 / BINS_PER_SIGMA0;
    let nodes = (surfaces * n * n) as f64;
    counts
        .iter()
        .enumerate()
        .map(|(k, &c)| {
            (
                k as f64 * width,
                (k + 1) as f64 * width,
                c as f64 / (nodes * width),
            )
        })
        .collect()
}

/// The per-solve figures of one surface, taken from each solution.
struct Each<'a> {
    plan: &'a Plan,
    patches: PatchOptions,
    points: Vec<SolvedPoint>,
}

impl Observer for Each<'_> {
    fn solution(&mut self, index: usize, s: &Solution) -> Result<()> {
        let sigma0 = self.plan.pressures[index];
        let contact: Vec<bool> = s.pressure.iter().map(|&p| p > 0.0).collect();
        let patches = patch_statistics(&contact, self.plan.grid, self.plan.size, &self.patches)?;
        let tail = pressure_tail(&s.pressure, None).ok().map(|t| {
            (
                t.better == TailShape::Exponential,
                t.exponential_log_likelihood - t.gaussian_log_likelihood,
            )
        });
        let width = sigma0 / BINS_PER_SIGMA0;
        let mut counts: Vec<u64> = Vec::new();
        for &p in s.pressure.iter().filter(|p| **p > 0.0 && p.is_finite()) {
            let k = (p / width) as usize;
            if k >= counts.len() {
                counts.resize(k + 1, 0);
            }
            counts[k] += 1;
        }
        self.points.push(SolvedPoint {
            contact_fraction: f64::NAN,
            patches: patches.patch_count,
            tail,
            counts,
        });
        Ok(())
    }
}

/// `outputs.surrogates`: the map (the scene's height map, or a surface
/// synthesised from its spectrum), its surrogates, every solve, and the
/// theory's A/A0 on the scene's spectrum up to the grid's Nyquist
/// wavevector πN/L (what the solves resolve of it).
///
/// # Errors
/// Missing or invalid inputs (named `outputs.surrogates.…`); a solve that fails.
pub fn surrogates(
    ctx: &crate::study::Context<'_>,
    spec: &SurrogatesOutput,
) -> Result<SurrogatesReport> {
    let start = Instant::now();
    let named = |e: Error| prefix("outputs.surrogates.", e);
    let boundary = spec.boundary.unwrap_or(Boundary::Periodic);
    // A measured map conditioned as its spectrum is (the plane of a map not
    // measured periodic removed): its tilt would otherwise be a ridge at
    // the periodic BEM's edge, and power on the surrogates' axes.
    let map = match ctx.inputs.spectrum {
        Some(crate::input::SpectrumSpec::HeightMap(m)) => {
            if spec.grid.is_some() || spec.map_seed.is_some() {
                return Err(named(Error::Inconsistent {
                    name: "grid / map_seed".into(),
                    requirement: "only for a map synthesised from a spectrum (a height map \
                                  has its own grid)"
                        .into(),
                }));
            }
            m.conditioned_surface(boundary)?
        }
        _ => crate::bem::solve::bem_surface(
            ctx,
            ("outputs.surrogates.", spec.grid, spec.map_seed),
            boundary,
        )?,
    };
    let name = match ctx.inputs.spectrum {
        Some(crate::input::SpectrumSpec::HeightMap(m)) => m.file.display().to_string(),
        _ => format!(
            "a Gaussian map synthesised from the scene's spectrum (seed {})",
            spec.map_seed.unwrap_or(1)
        ),
    };
    let contact = ctx.contact()?;
    let pressures = ctx.nominal_pressure();
    let plan = Plan::new(spec, (&name, &map), contact.contact_modulus, pressures).map_err(named)?;
    // The theory on what the grid resolves of the spectrum (q ≤ πN/L).
    let band = BandLimited::new(
        contact.spectrum.as_ref(),
        std::f64::consts::PI * map.n as f64 / map.size,
    )
    .map_err(named)?;
    let model = Persson::new(&band, contact.contact_modulus)?;
    let theory: Vec<f64> = model
        .load_curve(pressures, model.zeta_max())?
        .iter()
        .map(|p| p.contact_fraction)
        .collect();
    let solved = plan
        .jobs()
        .into_iter()
        .map(|j| plan.solve(j))
        .collect::<Result<Vec<_>>>()
        .map_err(named)?;
    let mut report = plan.gather(solved, &theory, start.elapsed().as_secs_f64())?;
    if spec.surfaces.is_some() {
        report.surfaces = (1..=plan.count)
            .map(|k| Ok(plan.surface(k)?.0.heights))
            .collect::<Result<_>>()?;
    }
    Ok(report)
}
