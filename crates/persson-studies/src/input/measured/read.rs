//! Reading, conditioning and analysing a measured surface (feature
//! `topography`).

use persson::error::{Error, Result};
use persson::spectrum::Tabulated;

use super::in_file;
use crate::input::{Described, HeightMapSpec, LengthUnitName, Sides};

use persson::topography::{self as topo, Analysis, AnalysisOptions, Topography};

impl From<LengthUnitName> for topo::LengthUnit {
    fn from(u: LengthUnitName) -> Self {
        match u {
            LengthUnitName::M => topo::LengthUnit::Metre,
            LengthUnitName::Mm => topo::LengthUnit::Millimetre,
            LengthUnitName::Um => topo::LengthUnit::Micrometre,
            LengthUnitName::Nm => topo::LengthUnit::Nanometre,
            LengthUnitName::Pm => topo::LengthUnit::Picometre,
            LengthUnitName::Angstrom => topo::LengthUnit::Angstrom,
        }
    }
}

impl HeightMapSpec {
    /// The size as the reader takes it.
    ///
    /// # Errors
    /// Both `size` and `pixel_size` given.
    fn size_spec(&self) -> Result<Option<topo::SizeSpec>> {
        Ok(match (self.size, self.pixel_size) {
            (Some(_), Some(_)) => {
                return Err(Error::Inconsistent {
                    name: "size / pixel_size".into(),
                    requirement: "give one of them, not both".into(),
                })
            }
            (Some(Sides::One(lx)), None) => Some(topo::SizeSpec::Size(lx, None)),
            (Some(Sides::Two([lx, ly])), None) => Some(topo::SizeSpec::Size(lx, Some(ly))),
            (None, Some(d)) => Some(topo::SizeSpec::PixelSize(d)),
            (None, None) => None,
        })
    }

    /// Read the file (the formats of [`persson::topography::read()`]).
    ///
    /// # Errors
    /// As [`persson::topography::read()`].
    pub fn read(&self) -> Result<Topography> {
        let options = topo::ReadOptions {
            size: self.size_spec()?,
            periodic: self.periodic,
            fill_undefined: self.fill_undefined,
            format: None,
            height_unit: self.height_unit.map(Into::into),
            lateral_unit: self.lateral_unit.map(Into::into),
            transpose: self.transpose,
            channel: self.channel.clone(),
        };
        topo::read(&self.file, &options)
    }

    /// A contact.engineering dataset named without a channel: its
    /// measurements, each as this entry with the channel naming it and the
    /// dataset's detrending (unless this entry gives one); `None` for any
    /// other file.
    ///
    /// # Errors
    /// As [`persson::topography::read::dataset`].
    pub fn dataset_measurements(&self) -> Result<Option<Vec<HeightMapSpec>>> {
        if self.channel.is_some() {
            return Ok(None);
        }
        let Some(d) = topo::read::dataset(&self.file)? else {
            return Ok(None);
        };
        Ok(Some(
            d.measurements
                .iter()
                .map(|m| HeightMapSpec {
                    channel: Some(m.name.clone()),
                    detrend: self.detrend.or(Some(m.detrend)),
                    ..self.clone()
                })
                .collect(),
        ))
    }

    /// Read and analyse the map: spectrum, statistics, Hurst fit.
    ///
    /// # Errors
    /// As [`HeightMapSpec::read`] and [`persson::topography::analyse`].
    pub fn analyse(&self) -> Result<Analysis> {
        let t = self.read()?;
        let tip = match self.tip_radius {
            Some(r) => topo::tip_radius_cutoff(&t, r, topo::TIP_SAFETY_FACTOR)
                .map_err(|e| in_file(&self.file, e))?,
            None => None,
        };
        let tip_q = tip.map(|l| std::f64::consts::TAU / l);
        let q_max = match (self.q_max, tip_q) {
            (Some(a), Some(b)) => Some(a.min(b)),
            (a, b) => a.or(b),
        };
        let options = AnalysisOptions {
            detrend: self.detrend,
            window: self.window,
            q_max,
            bins: None,
        };
        topo::analyse(&t, &options).map_err(|e| in_file(&self.file, e))
    }

    /// The map's spectrum, tabulated, with what was assumed in words.
    ///
    /// # Errors
    /// As [`HeightMapSpec::analyse`] and [`persson::topography::Psd::to_tabulated`].
    pub fn spectrum_described(&self) -> Result<Described<Tabulated>> {
        if let Some(measurements) = self.dataset_measurements()? {
            return crate::input::multiscale::described(&measurements);
        }
        let a = self.analyse()?;
        let s = a.psd.to_tabulated().map_err(|e| in_file(&self.file, e))?;
        Ok(Described {
            value: s,
            description: Some(describe(&self.file, &a)),
            warnings: crate::warning::of_measured(&self.file, &a),
        })
    }
}

/// What the spectrum of a measured surface assumed, for report titles.
pub fn describe(file: &std::path::Path, a: &Analysis) -> String {
    use crate::table::number;
    let pixel: Vec<String> = a.pixel_size.iter().map(|d| number(*d, 6)).collect();
    format!(
        "measured surface {} ({} × {} points, pixel {} m, {}; detrend {}, window {}; band q = {} … {} 1/m)",
        file.display(),
        a.shape[0],
        a.shape[1],
        pixel.join(" × "),
        if a.periodic { "periodic" } else { "not periodic" },
        a.detrend.name(),
        a.window.name(),
        number(a.q_min, 6),
        number(a.q_max, 6),
    )
}

#[cfg(feature = "bem")]
impl HeightMapSpec {
    /// The map as the BEM's rigid surface, read by [`HeightMapSpec::read`]
    /// like every other command's surface (the file's own size and units),
    /// heights as in the file, with the trend `detrend` removed only when it
    /// is given (the spectrum's default detrending is for the spectrum; the
    /// window, `q_max` and `tip_radius` shape the spectrum only). The BEM solves on square N × N grids only: a
    /// non-square map is an error (cropping it would change its spectrum,
    /// padding it would add a flat strip).
    ///
    /// # Errors
    /// As [`HeightMapSpec::read`]; a non-square map, line scans, `Lx ≠ Ly`;
    /// a grid whose solve would not fit in memory.
    pub fn bem_surface(
        &self,
        boundary: persson::bem::Boundary,
    ) -> Result<persson::bem::surface::GridSurface> {
        self.grid_surface(boundary, self.detrend)
    }

    /// As [`HeightMapSpec::bem_surface`], detrended as the spectrum is: the
    /// given `detrend`, else the default of the map
    /// ([`persson::topography::Conditioning::for_topography`]: the plane of a
    /// map not measured periodic). For a comparison with surfaces of the
    /// map's spectrum (`surrogates`), whose spectrum is of the conditioned map.
    ///
    /// # Errors
    /// As [`HeightMapSpec::bem_surface`].
    pub fn conditioned_surface(
        &self,
        boundary: persson::bem::Boundary,
    ) -> Result<persson::bem::surface::GridSurface> {
        let t = self.read()?;
        let detrend = self
            .detrend
            .unwrap_or_else(|| topo::Conditioning::for_topography(&t).detrend);
        self.grid_surface(boundary, Some(detrend))
    }

    fn grid_surface(
        &self,
        boundary: persson::bem::Boundary,
        detrend: Option<topo::Detrend>,
    ) -> Result<persson::bem::surface::GridSurface> {
        let t = self.read()?;
        let [ny, nx] = t.shape();
        let bad = |what: String| {
            Error::parse(
                &self.file,
                0,
                0,
                format!("{what}: the BEM solves on square N × N maps of equal sides (crop or resample it yourself)"),
            )
        };
        if t.layout() != topo::Layout::Map {
            return Err(bad("line scans, not a height map".into()));
        }
        if nx != ny {
            return Err(bad(format!("{ny} × {nx} points")));
        }
        if (t.lx() - t.ly()).abs() > 1e-12 * t.lx() {
            return Err(bad(format!("sides {} × {} m", t.lx(), t.ly())));
        }
        persson::bem::check_memory(nx, boundary)?;
        let heights = match detrend {
            Some(d) => t.detrended(d),
            None => t.heights().to_vec(),
        };
        persson::bem::surface::GridSurface::new(nx, t.lx(), heights)
            .map_err(|e| Error::parse(&self.file, 0, 0, e.to_string()))
    }
}
