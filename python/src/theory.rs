//! G(ζ), A/A0 of every theory and κ, vectorised over numpy arrays.

use std::collections::HashMap;

use persson::corrected::{self, Theory};
use persson::kappa::Kappa;
use persson::theory::{contact_fraction, Persson};
use persson_studies::scene::{MaterialSpec, TheoryName, TheorySpec};
use pyo3::prelude::*;

use crate::arrays::{broadcast, floats, output};
use crate::convert::{err, name, value_error};
use crate::spectrum::Spectrum;

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(contact_modulus, m)?)?;
    m.add_function(wrap_pyfunction!(g, m)?)?;
    m.add_function(wrap_pyfunction!(contact_area, m)?)?;
    m.add_function(wrap_pyfunction!(kappa, m)?)?;
    m.add_function(wrap_pyfunction!(low_load_kappa, m)?)?;
    Ok(())
}

/// The contact modulus E* of one elastic body (Young's modulus E, Poisson
/// ratio ν) on a rigid one, or of two bodies:
/// 1/E* = (1 − ν₁²)/E₁ + (1 − ν₂²)/E₂ (Johnson, Contact Mechanics, 1985).
/// Moduli in any one pressure unit; E* comes out in it.
#[pyfunction]
#[pyo3(signature = (young, poisson, young2=None, poisson2=None))]
fn contact_modulus(
    young: f64,
    poisson: f64,
    young2: Option<f64>,
    poisson2: Option<f64>,
) -> PyResult<f64> {
    let m = MaterialSpec {
        contact_modulus: None,
        young: Some(young),
        poisson: Some(poisson),
        young2,
        poisson2,
    };
    Ok(m.build().map_err(err)?.contact_modulus())
}

/// Pressures and magnifications broadcast against each other, flattened,
/// with the shape of the result.
struct Points {
    shape: Vec<usize>,
    pressure: Vec<f64>,
    zeta: Vec<f64>,
}

fn points(
    spectrum: &Spectrum,
    pressure: &Bound<'_, PyAny>,
    zeta: Option<&Bound<'_, PyAny>>,
) -> PyResult<Points> {
    let p = floats("pressure", pressure)?;
    let pv = p.as_array();
    let Some(zeta) = zeta else {
        let z = spectrum.shared.0.q_max() / spectrum.shared.0.q_min();
        return Ok(Points {
            shape: pv.shape().to_vec(),
            pressure: pv.iter().copied().collect(),
            zeta: vec![z; pv.len()],
        });
    };
    let z = floats("zeta", zeta)?;
    let zv = z.as_array();
    let shape = broadcast(("pressure", pv.shape()), ("zeta", zv.shape()))?;
    let dim = numpy::ndarray::IxDyn(&shape);
    let pb = pv
        .broadcast(dim.clone())
        .ok_or_else(|| value_error("pressure: cannot broadcast"))?;
    let zb = zv
        .broadcast(dim)
        .ok_or_else(|| value_error("zeta: cannot broadcast"))?;
    Ok(Points {
        shape,
        pressure: pb.iter().copied().collect(),
        zeta: zb.iter().copied().collect(),
    })
}

/// Indices of the points grouped by ζ, in order of first appearance.
fn by_zeta(zeta: &[f64]) -> Vec<(f64, Vec<usize>)> {
    let mut index: HashMap<u64, usize> = HashMap::new();
    let mut groups: Vec<(f64, Vec<usize>)> = Vec::new();
    for (i, &z) in zeta.iter().enumerate() {
        let k = *index.entry(z.to_bits()).or_insert_with(|| {
            groups.push((z, Vec::new()));
            groups.len() - 1
        });
        groups[k].1.push(i);
    }
    groups
}

/// The value array, or the pair (values, error bounds).
fn result<'py>(
    py: Python<'py>,
    shape: &[usize],
    values: Vec<f64>,
    bounds: Vec<f64>,
    error_bound: bool,
) -> PyResult<Bound<'py, PyAny>> {
    let v = output(py, shape, values)?;
    if error_bound {
        Ok((v, output(py, shape, bounds)?)
            .into_pyobject(py)?
            .into_any())
    } else {
        Ok(v)
    }
}

/// Run `f(i)` for every i in `0..n`, in parallel chunks when n is large;
/// each value depends on its own i alone.
fn map_parallel(
    n: usize,
    f: &(dyn Fn(usize) -> persson::Result<(f64, f64)> + Sync),
) -> persson::Result<(Vec<f64>, Vec<f64>)> {
    let threads = if n < 20_000 {
        1
    } else {
        std::thread::available_parallelism()
            .map_or(1, |t| t.get())
            .min(16)
    };
    let chunk = n.div_ceil(threads).max(1);
    let mut values = vec![0.0; n];
    let mut bounds = vec![0.0; n];
    std::thread::scope(|s| {
        let handles: Vec<_> = values
            .chunks_mut(chunk)
            .zip(bounds.chunks_mut(chunk))
            .enumerate()
            .map(|(k, (v, b))| {
                s.spawn(move || -> persson::Result<()> {
                    for j in 0..v.len() {
                        (v[j], b[j]) = f(k * chunk + j)?;
                    }
                    Ok(())
                })
            })
            .collect();
        handles
            .into_iter()
            .try_for_each(|h| h.join().unwrap_or_else(|p| std::panic::resume_unwind(p)))
    })?;
    Ok((values, bounds))
}

/// G(ζ) = (π/4)(E*/σ0)² ∫_{q_l}^{ζ q_l} q³ C(q) dq (Persson, Bucher &
/// Chiaia, Phys. Rev. B 65, 184106 (2002), Eq. 2) at the nominal pressures
/// σ0 (`pressure`, unit of E*) and magnifications ζ (default q_s/q_l), both
/// numbers or numpy arrays broadcast against each other. With
/// `error_bound=True`: the pair (G, bound on its absolute error).
#[pyfunction]
#[pyo3(signature = (spectrum, contact_modulus, pressure, zeta=None, *, error_bound=false))]
fn g<'py>(
    py: Python<'py>,
    spectrum: &Spectrum,
    contact_modulus: f64,
    pressure: &Bound<'py, PyAny>,
    zeta: Option<&Bound<'py, PyAny>>,
    error_bound: bool,
) -> PyResult<Bound<'py, PyAny>> {
    let pts = points(spectrum, pressure, zeta)?;
    let s = &spectrum.shared;
    let (values, bounds) = py
        .detach(|| -> persson::Result<_> {
            let model = Persson::new(s, contact_modulus)?;
            let mut cache: HashMap<u64, persson::Estimate> = HashMap::new();
            let mut values = Vec::with_capacity(pts.pressure.len());
            let mut bounds = Vec::with_capacity(pts.pressure.len());
            for (&p, &z) in pts.pressure.iter().zip(&pts.zeta) {
                let sv = match cache.get(&z.to_bits()) {
                    Some(v) => *v,
                    None => {
                        let v = model.slope_variance(z)?;
                        cache.insert(z.to_bits(), v);
                        v
                    }
                };
                let g = model.g_from(sv, p)?;
                values.push(g.value);
                bounds.push(g.error);
            }
            Ok((values, bounds))
        })
        .map_err(err)?;
    result(py, &pts.shape, values, bounds, error_bound)
}

/// The real contact area A/A0 at the nominal pressures σ0 (`pressure`, unit
/// of the contact modulus `contact_modulus`) and magnifications ζ (default the full
/// q_s/q_l), numbers or numpy arrays broadcast against each other.
///
/// theory: "original" (Persson, J. Chem. Phys. 115, 3840 (2001):
/// A/A0 = erf(1/(2√G))), "yang-persson" (J. Phys.: Condens. Matter 20,
/// 215214 (2008)), "wang-muser" (Tribol. Lett. 65, 103 (2017)) or "xu"
/// (Tribol. Lett. (2024), doi:10.1007/s11249-024-01838-4); gamma: γ of a
/// corrected theory (default the paper's); tolerance: absolute tolerance on
/// A/A0 of the corrected theories' solvers. With `error_bound=True`: the pair
/// (A/A0, bound on its absolute error). The same numbers as `persson area`.
#[pyfunction]
#[pyo3(signature = (spectrum, contact_modulus, pressure, theory="original", gamma=None, *, zeta=None, tolerance=1e-12, error_bound=false))]
#[allow(clippy::too_many_arguments)]
fn contact_area<'py>(
    py: Python<'py>,
    spectrum: &Spectrum,
    contact_modulus: f64,
    pressure: &Bound<'py, PyAny>,
    theory: &str,
    gamma: Option<f64>,
    zeta: Option<&Bound<'py, PyAny>>,
    tolerance: f64,
    error_bound: bool,
) -> PyResult<Bound<'py, PyAny>> {
    let spec = TheorySpec {
        theory: name::<TheoryName>("theory", theory)?,
        gamma,
    };
    let th: Theory = spec.build().map_err(err)?;
    let pts = points(spectrum, pressure, zeta)?;
    let s = &spectrum.shared;
    let n = pts.pressure.len();
    let (values, bounds) = py
        .detach(|| -> persson::Result<_> {
            let model = Persson::new(s, contact_modulus)?;
            if spec.theory == TheoryName::Original {
                // As Persson::load_curve: ⟨|∇h|²⟩ once per ζ, then
                // G and erf point by point (independent: safe to split).
                let mut cache = HashMap::new();
                for &z in &pts.zeta {
                    if let std::collections::hash_map::Entry::Vacant(e) = cache.entry(z.to_bits()) {
                        e.insert(model.slope_variance(z)?);
                    }
                }
                return map_parallel(n, &|i| {
                    let sv = cache[&pts.zeta[i].to_bits()];
                    let g = model.g_from(sv, pts.pressure[i])?;
                    let a = contact_fraction(g.value, g.error)?;
                    Ok((a.fraction, a.error))
                });
            }
            // Corrected theories: one load curve per ζ, as `persson area`.
            let mut values = vec![0.0; n];
            let mut bounds = vec![0.0; n];
            for (z, idx) in by_zeta(&pts.zeta) {
                let ps: Vec<f64> = idx.iter().map(|&i| pts.pressure[i]).collect();
                let curve = corrected::load_curve(&model, th, z, &ps, tolerance)?;
                for (&i, c) in idx.iter().zip(curve) {
                    values[i] = c.contact_fraction;
                    bounds[i] = c.error_bound;
                }
            }
            Ok((values, bounds))
        })
        .map_err(err)?;
    result(py, &pts.shape, values, bounds, error_bound)
}

/// κ of the low-load law A/A0 = κ σ0/(E* h'_rms): "bush" (Bush, Gibson &
/// Thomas, Wear 35, 87 (1975): √(2π)) or "persson" (Persson, J. Chem. Phys.
/// 115, 3840 (2001): √(8/π)).
#[pyfunction]
#[pyo3(signature = (law="persson"))]
fn kappa(law: &str) -> PyResult<f64> {
    match law {
        "bush" => Ok(Kappa::Bush.value()),
        "persson" => Ok(Kappa::Persson.value()),
        _ => Err(value_error(format!(
            "invalid law = '{law}': expected one of `bush`, `persson`"
        ))),
    }
}

/// κ a theory gives in its low-load limit (closed form), for the theory and
/// γ of `contact_area`.
#[pyfunction]
#[pyo3(signature = (theory="original", gamma=None))]
fn low_load_kappa(theory: &str, gamma: Option<f64>) -> PyResult<f64> {
    let spec = TheorySpec {
        theory: name::<TheoryName>("theory", theory)?,
        gamma,
    };
    Ok(spec.build().map_err(err)?.low_load_kappa())
}
