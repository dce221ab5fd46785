//! `persson.Spectrum`: a roughness power spectrum C(q) in Persson's
//! normalisation, built as the CLI and scenes build it.

use std::path::{Path, PathBuf};
use std::sync::Arc;

use numpy::ndarray::Zip;
use persson::spectrum::{Spectrum as _, Tabulated};
use persson::topography::Note;
use persson::{Estimate, Result};
use persson_studies::scene::{ConventionName, HeightMapSpec, Sides, SpectrumSpec, EXAMPLE};
use pyo3::prelude::*;

use crate::arrays::{floats, output};
use crate::convert::{err, name, to_dict_warned, value_error};
use crate::height_map::{analysis, heights_topography, sides_from_pixel};
use crate::state::{estimate, note_of_state, note_state, recipe_state, NoteState, Recipe};

/// A spectrum shared between Python objects and the library's reports.
#[derive(Clone)]
pub struct Shared(pub Arc<dyn persson::Spectrum>);

impl persson::Spectrum for Shared {
    fn c(&self, q: f64) -> f64 {
        self.0.c(q)
    }
    fn q_min(&self) -> f64 {
        self.0.q_min()
    }
    fn q_max(&self) -> f64 {
        self.0.q_max()
    }
    fn moment(&self, k: i32, a: f64, b: f64) -> Result<Estimate> {
        self.0.moment(k, a, b)
    }
    fn rms_height(&self, a: f64, b: f64) -> Result<Estimate> {
        self.0.rms_height(a, b)
    }
    fn rms_slope(&self, a: f64, b: f64) -> Result<Estimate> {
        self.0.rms_slope(a, b)
    }
    fn rms_curvature(&self, a: f64, b: f64) -> Result<Estimate> {
        self.0.rms_curvature(a, b)
    }
    /// The plane of an anisotropic spectrum, so that `synthesize` and the
    /// BEM on a stretched spectrum see it (not only its angular average).
    fn as_2d(&self) -> Option<&dyn persson::spectrum::Spectrum2d> {
        self.0.as_2d()
    }
}

/// An isotropic roughness power spectrum C(q) in Persson's normalisation
/// (m⁴, q the angular wavevector in 1/m), zero outside [q_l, q_s].
///
/// Build it with one of the static methods: `self_affine`, `tabulated`,
/// `from_csv`, `from_height_map`, `from_file`, `from_topography`, `example`.
#[pyclass(frozen, module = "persson")]
pub struct Spectrum {
    pub shared: Shared,
    /// Kinks of C(q) inside the band (the roll-off), for the separation integrals.
    pub breaks: Vec<f64>,
    /// What the spectrum is, in words (the example, a measured surface).
    pub description: Option<String>,
    /// How to build it again (pickling, for multiprocessing and Dask).
    pub recipe: Recipe,
    /// Remarks on the spectrum (a file's convention, a slope above 1, what
    /// the analysis of a measured map could not do), as the CLI's for the
    /// same spectrum; passed on to every report.
    pub warnings: Vec<persson_studies::Warning>,
    /// The notes of a measured map's analysis and the input they name (its
    /// file, or `(array)`, `(topography)`): kept so that a pickled copy
    /// words the same warnings.
    pub measured: Option<Measured>,
}

/// What the analysis of a measured height map noted, and the input it read.
#[derive(Clone)]
pub struct Measured {
    pub file: PathBuf,
    pub notes: Vec<Note>,
}

impl Measured {
    pub(crate) fn warnings(&self) -> Vec<persson_studies::Warning> {
        persson_studies::warning::of_notes(&self.file, &self.notes)
    }
}

impl Spectrum {
    /// The library's surface: this spectrum on a body of contact modulus E*.
    pub fn contact(
        &self,
        contact_modulus: f64,
    ) -> PyResult<persson_studies::scene::run::RoughContact> {
        persson::error::check::positive("contact_modulus", contact_modulus).map_err(err)?;
        Ok(persson_studies::scene::run::RoughContact {
            spectrum: Box::new(self.shared.clone()),
            contact_modulus,
            breaks: self.breaks.clone(),
            description: self.description.clone(),
            warnings: self.warnings.clone(),
            // Asperity theories take their moments from the spectrum here.
            height_map: None,
        })
    }

    fn band(&self, q_min: Option<f64>, q_max: Option<f64>) -> (f64, f64) {
        (
            q_min.unwrap_or(self.shared.q_min()),
            q_max.unwrap_or(self.shared.q_max()),
        )
    }
}

#[pymethods]
impl Spectrum {
    /// Self-affine spectrum with roll-off (Persson, Bucher & Chiaia 2002,
    /// Eq. 5): C = C(q_r) for q_l ≤ q < q_r, C(q_r)(q/q_r)^(−2(H+1)) up to q_s.
    ///
    /// hurst: H in (0, 1). q_l, q_s, q_r: cut-offs and roll-off, 1/m
    /// (q_r defaults to q_l: no roll-off). Exactly one amplitude:
    /// rms_height (m) or rms_slope over [q_l, q_s], or c_r = C(q_r) (m⁴).
    #[staticmethod]
    #[pyo3(signature = (hurst, q_l, q_s, *, q_r=None, rms_height=None, rms_slope=None, c_r=None))]
    #[allow(clippy::too_many_arguments)]
    fn self_affine(
        hurst: f64,
        q_l: f64,
        q_s: f64,
        q_r: Option<f64>,
        rms_height: Option<f64>,
        rms_slope: Option<f64>,
        c_r: Option<f64>,
    ) -> PyResult<Self> {
        Self::from_spec(&SpectrumSpec::SelfAffine {
            hurst,
            q_l,
            q_r,
            q_s,
            rms_height,
            rms_slope,
            c_r,
        })
    }

    /// The CLI's built-in example (`--example`): H = 0.8, q_l = 1e4,
    /// q_r = 1e5, q_s = 1e8 1/m, rms height 1 µm (use it with E* = 1e9 Pa).
    #[staticmethod]
    fn example() -> PyResult<Self> {
        let mut s = Self::from_spec(&SpectrumSpec::example())?;
        s.description = Some(EXAMPLE.to_string());
        Ok(s)
    }

    /// A tabulated spectrum from arrays q (1/m) and C, piecewise power law
    /// between the points; `convention` says C's normalisation: "persson"
    /// (m⁴), "surface-topography" (C/(2π)²), "profile1d" (a 1D profile
    /// spectrum, m³) or "grid" (q in units of 2π/L and a dimensionless φ,
    /// with `size` = L in m).
    #[staticmethod]
    #[pyo3(signature = (q, c, convention="persson", size=None))]
    fn tabulated(
        q: &Bound<'_, PyAny>,
        c: &Bound<'_, PyAny>,
        convention: &str,
        size: Option<f64>,
    ) -> PyResult<Self> {
        let conv: ConventionName = name("convention", convention)?;
        let q = crate::arrays::float_list("q", q)?;
        let c = crate::arrays::float_list("c", c)?;
        if q.len() != c.len() {
            return Err(value_error(format!(
                "q and c: {} and {} values, expected the same number",
                q.len(),
                c.len()
            )));
        }
        let pts: Vec<(f64, f64)> = q.into_iter().zip(c).collect();
        let pts = conv
            .with(size)
            .map_err(err)?
            .to_persson(&pts)
            .map_err(err)?;
        let s = Tabulated::new(&pts).map_err(err)?;
        Ok(Self::tabulated_spectrum(s, None, None))
    }

    /// A tabulated spectrum from a CSV file of two columns q, C (as the
    /// CLI's `--psd FILE --psd-convention … --psd-size …`).
    #[staticmethod]
    #[pyo3(signature = (path, convention="persson", size=None))]
    fn from_csv(path: PathBuf, convention: &str, size: Option<f64>) -> PyResult<Self> {
        Self::from_spec(&SpectrumSpec::Tabulated {
            file: path,
            convention: name("convention", convention)?,
            size,
        })
    }

    /// The binned isotropic spectrum of a measured height map in a file
    /// (every format of docs/surfaces.md; a contact.engineering dataset is
    /// the combined spectrum of its measurements, `channel` reads one), as the
    /// CLI's `--surface FILE` with `--size`/`--pixel-size`, `--periodic`,
    /// `--detrend`, `--window`, `--fill-undefined`, `--q-max`, `--channel`.
    #[staticmethod]
    #[pyo3(signature = (path, *, size=None, pixel_size=None, periodic=false, detrend=None, window=None, fill_undefined=false, q_max=None, channel=None))]
    #[allow(clippy::too_many_arguments)]
    fn from_file(
        path: PathBuf,
        size: Option<Vec<f64>>,
        pixel_size: Option<f64>,
        periodic: bool,
        detrend: Option<&str>,
        window: Option<&str>,
        fill_undefined: bool,
        q_max: Option<f64>,
        channel: Option<String>,
    ) -> PyResult<Self> {
        let size = match size.as_deref() {
            None => None,
            Some([l]) => Some(Sides::One(*l)),
            Some([lx, ly]) => Some(Sides::Two([*lx, *ly])),
            Some(v) => {
                return Err(value_error(format!(
                    "size: {} values, expected L or (Lx, Ly)",
                    v.len()
                )))
            }
        };
        let mut spec = HeightMapSpec::new(path);
        spec.size = size;
        spec.pixel_size = pixel_size;
        spec.periodic = periodic;
        spec.detrend = detrend.map(|d| name("detrend", d)).transpose()?;
        spec.window = window.map(|w| name("window", w)).transpose()?;
        spec.fill_undefined = fill_undefined;
        spec.q_max = q_max;
        spec.channel = channel;
        Self::from_spec(&SpectrumSpec::HeightMap(spec))
    }

    /// The roughness of two (or more) rough bodies pressed together: the sum
    /// of their spectra, C = C1 + C2 (each zero outside its band; the CLI's
    /// --psd2/--surface2). Use it with the E* of both bodies.
    #[staticmethod]
    fn sum(spectra: Vec<PyRef<'_, Spectrum>>) -> PyResult<Self> {
        let parts: Vec<Spectrum> = spectra
            .iter()
            .map(|s| Spectrum {
                shared: s.shared.clone(),
                breaks: s.breaks.clone(),
                description: s.description.clone(),
                recipe: s.recipe.clone(),
                warnings: s.warnings.clone(),
                measured: s.measured.clone(),
            })
            .collect();
        Self::sum_of(&parts)
    }

    /// One spectrum from several measurements of one surface in files (the
    /// CLI's repeated --surface): each contributes its reliable band (from
    /// 8 modes of its size, where a window's main lobe no longer biases C,
    /// to Nyquist, `q_max`, the tip-radius cut-off or its noise floor), and
    /// C is the mode-weighted mean over the overlaps. `sizes`, `pixel_sizes`,
    /// `tip_radii`: one value per file (None where the file says).
    #[staticmethod]
    #[pyo3(signature = (paths, *, sizes=None, pixel_sizes=None, tip_radii=None, periodic=false, detrend=None, window=None, q_max=None))]
    #[allow(clippy::too_many_arguments)]
    fn combine(
        paths: Vec<PathBuf>,
        sizes: Option<Vec<Option<f64>>>,
        pixel_sizes: Option<Vec<Option<f64>>>,
        tip_radii: Option<Vec<Option<f64>>>,
        periodic: bool,
        detrend: Option<&str>,
        window: Option<&str>,
        q_max: Option<f64>,
    ) -> PyResult<Self> {
        let n = paths.len();
        let each = |arg: &str, v: Option<Vec<Option<f64>>>| -> PyResult<Vec<Option<f64>>> {
            match v {
                None => Ok(vec![None; n]),
                Some(v) if v.len() == n => Ok(v),
                Some(v) => Err(value_error(format!(
                    "{arg}: {} values for {n} paths, expected one per path",
                    v.len()
                ))),
            }
        };
        let (sizes, pixels, tips) = (
            each("sizes", sizes)?,
            each("pixel_sizes", pixel_sizes)?,
            each("tip_radii", tip_radii)?,
        );
        let detrend: Option<persson::names::Detrend> =
            detrend.map(|d| name("detrend", d)).transpose()?;
        let window: Option<persson::names::Window> =
            window.map(|w| name("window", w)).transpose()?;
        let measurements = paths
            .into_iter()
            .enumerate()
            .map(|(i, path)| {
                let mut m = HeightMapSpec::new(path);
                m.size = sizes[i].map(Sides::One);
                m.pixel_size = pixels[i];
                m.tip_radius = tips[i];
                m.periodic = periodic;
                m.detrend = detrend;
                m.window = window;
                m.q_max = q_max;
                m
            })
            .collect();
        Self::from_spec(&SpectrumSpec::MultiScale { measurements })
    }

    /// The binned isotropic spectrum of a height map given as a numpy array
    /// (rows along y, columns along x; a 1-D array is one line scan) with
    /// its pixel size Δ or (Δx, Δy) in m. Non-periodic maps are detrended
    /// (plane) and windowed (Hann) unless `detrend`/`window` say otherwise
    /// ("none", "mean", "plane", "curvature"; "none", "hann", "blackman");
    /// the band ends at the Nyquist wavevector π/Δ or `q_max`.
    #[staticmethod]
    #[pyo3(signature = (heights, pixel_size, *, periodic=false, detrend=None, window=None, q_max=None))]
    fn from_height_map(
        py: Python<'_>,
        heights: &Bound<'_, PyAny>,
        pixel_size: &Bound<'_, PyAny>,
        periodic: bool,
        detrend: Option<&str>,
        window: Option<&str>,
        q_max: Option<f64>,
    ) -> PyResult<Self> {
        let t = heights_topography(heights, sides_from_pixel(pixel_size)?, periodic)?;
        let a = py.detach(|| analysis(&t, detrend, window, q_max))?;
        Self::from_analysis(a, Path::new("(array)"))
    }

    /// The spectrum of a SurfaceTopography `Topography` (or anything with
    /// `.heights()` indexed [x, y] and `.physical_sizes`), duck-typed: no
    /// import of SurfaceTopography. `periodic` defaults to the object's
    /// `is_periodic` when it has one.
    #[staticmethod]
    #[pyo3(signature = (topography, *, periodic=None, detrend=None, window=None, q_max=None))]
    fn from_topography(
        py: Python<'_>,
        topography: &Bound<'_, PyAny>,
        periodic: Option<bool>,
        detrend: Option<&str>,
        window: Option<&str>,
        q_max: Option<f64>,
    ) -> PyResult<Self> {
        let heights = topography.call_method0("heights").map_err(|e| {
            value_error(format!(
                "topography: no .heights() ({e}); pass a SurfaceTopography Topography"
            ))
        })?;
        // SurfaceTopography indexes heights [x, y]; persson's maps are rows along y.
        let heights = heights.getattr("T")?;
        let sizes = crate::arrays::float_list(
            "topography.physical_sizes",
            &topography
                .getattr("physical_sizes")
                .map_err(|e| value_error(format!("topography: no .physical_sizes ({e})")))?,
        )?;
        let periodic = match periodic {
            Some(p) => p,
            None => topography
                .getattr("is_periodic")
                .and_then(|p| p.extract::<bool>())
                .unwrap_or(false),
        };
        let contiguous = py
            .import("numpy")?
            .call_method1("ascontiguousarray", (heights,))?;
        let t = heights_topography(
            &contiguous,
            |_| match sizes[..] {
                [lx] => Ok((lx, lx)),
                [lx, ly] => Ok((lx, ly)),
                _ => Err(value_error(
                    "topography.physical_sizes: expected (Lx,) or (Lx, Ly)",
                )),
            },
            periodic,
        )?;
        let a = py.detach(|| analysis(&t, detrend, window, q_max))?;
        Self::from_analysis(a, Path::new("(topography)"))
    }

    /// C(q) in m⁴ at the wavevectors q (1/m; a number or an array), 0
    /// outside the band.
    fn c<'py>(&self, py: Python<'py>, q: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        let q = floats("q", q)?;
        let v = q.as_array();
        let mut out = vec![0.0; v.len()];
        let s = &self.shared;
        Zip::from(
            numpy::ndarray::ArrayViewMut::from_shape(v.raw_dim(), &mut out[..])
                .map_err(|e| value_error(e.to_string()))?,
        )
        .and(&v)
        .for_each(|o, &q| *o = persson::Spectrum::c(s, q));
        output(py, v.shape(), out)
    }

    /// Lower end q_l of the band, 1/m.
    #[getter]
    fn q_l(&self) -> f64 {
        self.shared.q_min()
    }

    /// Upper end q_s of the band, 1/m.
    #[getter]
    fn q_s(&self) -> f64 {
        self.shared.q_max()
    }

    /// What the spectrum is in words (the example, a measured map), or None.
    #[getter]
    fn description(&self) -> Option<String> {
        self.description.clone()
    }

    /// rms height √(2π ∫ q C dq) over [q_min, q_max] (default the band), m;
    /// with `error_bound=True` the pair (value, bound on its absolute error).
    #[pyo3(signature = (q_min=None, q_max=None, *, error_bound=false))]
    fn rms_height<'py>(
        &self,
        py: Python<'py>,
        q_min: Option<f64>,
        q_max: Option<f64>,
        error_bound: bool,
    ) -> PyResult<Bound<'py, PyAny>> {
        let (a, b) = self.band(q_min, q_max);
        estimate(py, self.shared.rms_height(a, b).map_err(err)?, error_bound)
    }

    /// rms slope √(2π ∫ q³ C dq) over [q_min, q_max] (default the band).
    #[pyo3(signature = (q_min=None, q_max=None, *, error_bound=false))]
    fn rms_slope<'py>(
        &self,
        py: Python<'py>,
        q_min: Option<f64>,
        q_max: Option<f64>,
        error_bound: bool,
    ) -> PyResult<Bound<'py, PyAny>> {
        let (a, b) = self.band(q_min, q_max);
        estimate(py, self.shared.rms_slope(a, b).map_err(err)?, error_bound)
    }

    /// rms curvature √(2π ∫ q⁵ C dq) over [q_min, q_max] (default the band), 1/m.
    #[pyo3(signature = (q_min=None, q_max=None, *, error_bound=false))]
    fn rms_curvature<'py>(
        &self,
        py: Python<'py>,
        q_min: Option<f64>,
        q_max: Option<f64>,
        error_bound: bool,
    ) -> PyResult<Bound<'py, PyAny>> {
        let (a, b) = self.band(q_min, q_max);
        estimate(
            py,
            self.shared.rms_curvature(a, b).map_err(err)?,
            error_bound,
        )
    }

    /// `persson spectrum --json` as a dict: rms height, slope and curvature
    /// over [q_min, q_max] with error bounds, a power-law fit over the upper
    /// half of the band, C(q) at `points` log-spaced q and a 201-point curve.
    #[pyo3(signature = (q_min=None, q_max=None, points=11))]
    fn report<'py>(
        &self,
        py: Python<'py>,
        q_min: Option<f64>,
        q_max: Option<f64>,
        points: usize,
    ) -> PyResult<Bound<'py, PyAny>> {
        let r = persson_studies::scene::run::spectrum(
            &self.shared,
            self.description.clone(),
            q_min,
            q_max,
            points,
        )
        .map_err(err)?;
        let mut warnings = r.warnings.clone();
        for w in &self.warnings {
            if !warnings.contains(w) {
                warnings.push(w.clone());
            }
        }
        to_dict_warned(py, &r, &warnings)
    }

    /// Pickling (multiprocessing, Dask): the spectrum is rebuilt from its
    /// self-affine parameters or its tabulated points, so the copy gives
    /// the same numbers.
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyAny>> {
        let py = slf.py();
        let s = slf.get();
        let restore = py.get_type::<Spectrum>().getattr("_restore")?;
        let state = recipe_state(py, &s.recipe)?;
        let measured = s.measured.as_ref().map(|m| {
            (
                m.file.clone(),
                m.notes.iter().map(note_state).collect::<Vec<_>>(),
            )
        });
        (restore, (state.0, state.1, s.description.clone(), measured))
            .into_pyobject(py)
            .map(|t| t.into_any())
    }

    /// Rebuild a pickled spectrum (see `__reduce__`).
    #[staticmethod]
    #[pyo3(signature = (kind, payload, description, measured=None))]
    fn _restore(
        kind: &str,
        payload: &Bound<'_, PyAny>,
        description: Option<String>,
        measured: Option<(PathBuf, Vec<NoteState>)>,
    ) -> PyResult<Self> {
        let mut s = match kind {
            "self_affine" => {
                let spec: SpectrumSpec = serde_json::from_str(&payload.extract::<String>()?)
                    .map_err(|e| value_error(e.to_string()))?;
                Self::from_spec(&spec)?
            }
            "points" => {
                let points: Vec<(f64, f64)> = payload.extract()?;
                let measured = measured
                    .map(|(file, notes)| -> PyResult<Measured> {
                        let notes = notes
                            .into_iter()
                            .map(note_of_state)
                            .collect::<PyResult<_>>()?;
                        Ok(Measured { file, notes })
                    })
                    .transpose()?;
                Self::tabulated_spectrum(Tabulated::new(&points).map_err(err)?, None, measured)
            }
            "sum" => {
                let parts: Vec<(String, Bound<'_, PyAny>)> = payload.extract()?;
                let parts: Vec<Spectrum> = parts
                    .iter()
                    .map(|(k, p)| Self::_restore(k, p, None, None))
                    .collect::<PyResult<_>>()?;
                Self::sum_of(&parts)?
            }
            _ => return Err(value_error(format!("invalid kind = '{kind}'"))),
        };
        s.description = description;
        Ok(s)
    }

    fn __repr__(&self) -> String {
        format!(
            "persson.Spectrum(q_l={:e}, q_s={:e}{})",
            self.shared.q_min(),
            self.shared.q_max(),
            self.description
                .as_deref()
                .map(|d| format!(", description={d:?}"))
                .unwrap_or_default()
        )
    }
}
