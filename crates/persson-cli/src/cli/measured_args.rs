//! The flags of a measured surface (`--surface FILE` and its conditioning),
//! flattened into every subcommand that takes a spectrum but `bem rough`
//! (which has its own `--surface` and `--size`). They build the scene file's
//! `height_map` spectrum, [`HeightMapSpec`].

use anyhow::bail;

use super::files::{in_file, InFile};
use persson::names::{Detrend, Window};
use persson_studies::scene::{by_name, HeightMapSpec, LengthUnitName, Sides, SpectrumSpec};

/// A measured surface as the spectrum (`--surface FILE` and its conditioning),
/// flattened next to [`SpectrumArgs`]; the scene's `height_map` spectrum.
#[derive(clap::Args, Debug, Clone, Default)]
pub struct MeasuredArgs {
    /// Measured surface whose isotropic spectrum is used (q_l and q_s from the map):
    /// .npy, text matrix, .xyz, Gwyddion .gsf, ISO 25178-72 .x3p, or two-column line scans.
    /// Repeat it for measurements of one surface at different scales: their spectra
    /// are combined (mode-weighted mean over the overlaps of their reliable bands).
    #[arg(long, conflicts_with_all = ["hurst", "q_l", "q_r", "amplitude", "psd", "example"], value_parser = in_file)]
    pub surface: Vec<InFile>,
    /// Tip radius R of the scanning probe that measured the --surface, m: the band
    /// ends where the measured curvature is sharper than the tip (safety factor 1/2);
    /// with several --surface, one value for all or one per surface.
    #[arg(long, requires = "surface", value_delimiter = ',', allow_hyphen_values = true, value_parser = super::number::number)]
    pub tip_radius: Vec<f64>,
    /// Physical size LX[,LY] of the --surface map, m (files that store it need none; a
    /// given one is checked against the file's). A row of a .npy or text matrix runs
    /// along x: LX is along a row, the array of shape (ny, nx) has nx points along x.
    /// With several --surface, one LX per surface (square pixels).
    #[arg(
        long,
        requires = "surface",
        value_delimiter = ',',
        allow_hyphen_values = true,
        value_parser = super::number::number,
    )]
    pub size: Vec<f64>,
    /// Least-squares detrending of the --surface (default: plane, none if --periodic).
    #[arg(long, requires = "surface", value_parser = by_name::<Detrend>())]
    pub detrend: Option<Detrend>,
    /// Window before the spectrum (default: hann, none if --periodic).
    #[arg(long, requires = "surface", value_parser = by_name::<Window>())]
    pub window: Option<Window>,
    /// The --surface map is periodic (no detrending or window by default).
    #[arg(long, requires = "surface")]
    pub periodic: bool,
    #[command(flatten)]
    pub read: MapReadArgs,
}

/// How a `--surface` file is read: the flags every command that takes a
/// measured surface shares (the BEM's `bem rough --surface` too), so that
/// one file is read the same way everywhere.
#[derive(clap::Args, Debug, Clone, Default)]
pub struct MapReadArgs {
    /// Pixel size Δ of the --surface map (square pixels), m; with several
    /// --surface, one value for all or one per surface (comma-separated or repeated).
    #[arg(
        long,
        requires = "surface",
        conflicts_with = "size",
        value_delimiter = ',',
        allow_hyphen_values = true,
        value_parser = super::number::number,
    )]
    pub pixel_size: Vec<f64>,
    /// Fill undefined points (NaN, missing data) by harmonic interpolation.
    #[arg(long, requires = "surface")]
    pub fill_undefined: bool,
    /// Unit of the --surface heights when the file states none (default m).
    #[arg(long, value_enum, requires = "surface")]
    pub height_unit: Option<LengthUnitName>,
    /// Unit of the x (and y) columns of a --surface line scan or XYZ file that states none (default m).
    #[arg(long, value_enum, requires = "surface")]
    pub lateral_unit: Option<LengthUnitName>,
    /// Swap the axes of the --surface map after reading (a row of the file becomes a
    /// column; for arrays saved from SurfaceTopography's heights(), indexed [ix, iy]).
    #[arg(long, requires = "surface")]
    pub transpose: bool,
    /// The channel of a multi-channel --surface file (a data set of an HDF5 file), by name
    /// or index from 0 (default: the first height channel).
    #[arg(long, requires = "surface", value_name = "NAME|INDEX")]
    pub channel: Option<String>,
}

impl MapReadArgs {
    /// The height-map entry of `file` read as these flags say (`i`: which of
    /// several surfaces, for a per-surface --pixel-size).
    pub fn spec(&self, file: &InFile, i: usize) -> HeightMapSpec {
        let pixel_size = match self.pixel_size[..] {
            [] => None,
            [d] => Some(d),
            _ => self.pixel_size.get(i).copied(),
        };
        HeightMapSpec {
            pixel_size,
            fill_undefined: self.fill_undefined,
            height_unit: self.height_unit,
            lateral_unit: self.lateral_unit,
            transpose: self.transpose,
            channel: self.channel.clone(),
            ..HeightMapSpec::new(file.to_path_buf())
        }
    }
}

impl MeasuredArgs {
    /// The scene's `height_map` entry for these flags (`q_max`: the band's
    /// upper end, `--q-s` or `spectrum --q-max`), if `--surface` is given.
    pub fn spec(&self, q_max: Option<f64>) -> anyhow::Result<Option<HeightMapSpec>> {
        match self.surface.len() {
            0 => Ok(None),
            1 => self.one(0, q_max).map(Some),
            n => bail!("{n} --surface files: this command takes one"),
        }
    }

    /// The spectrum entry: one `height_map`, or `multi_scale` for several
    /// --surface; `None` without --surface.
    pub fn spectrum_spec(&self, q_max: Option<f64>) -> anyhow::Result<Option<SpectrumSpec>> {
        if self.surface.len() < 2 {
            return Ok(self.spec(q_max)?.map(SpectrumSpec::HeightMap));
        }
        let n = self.surface.len();
        for (flag, given) in [
            ("--pixel-size", self.read.pixel_size.len()),
            ("--tip-radius", self.tip_radius.len()),
            ("--size", self.size.len()),
        ] {
            if given > 1 && given != n || (flag == "--size" && given == 1) {
                bail!(
                    "{flag}: {given} values for {n} --surface files: give one per surface{}",
                    if flag == "--size" {
                        " (LX each)"
                    } else {
                        " or one for all"
                    }
                );
            }
        }
        let measurements = (0..n)
            .map(|i| self.one(i, q_max))
            .collect::<anyhow::Result<Vec<_>>>()?;
        Ok(Some(SpectrumSpec::MultiScale { measurements }))
    }

    /// The `i`-th surface's entry.
    fn one(&self, i: usize, q_max: Option<f64>) -> anyhow::Result<HeightMapSpec> {
        let pick = |v: &[f64]| match v.len() {
            0 => None,
            1 => Some(v[0]),
            _ => v.get(i).copied(),
        };
        let several = self.surface.len() > 1;
        let size = match self.size[..] {
            [] => None,
            _ if several => self.size.get(i).map(|&lx| Sides::One(lx)),
            [lx] => Some(Sides::One(lx)),
            [lx, ly] => Some(Sides::Two([lx, ly])),
            _ => bail!(
                "--size takes LX or LX,LY (m), got {} values",
                self.size.len()
            ),
        };
        Ok(HeightMapSpec {
            size,
            tip_radius: pick(&self.tip_radius),
            periodic: self.periodic,
            detrend: self.detrend,
            window: self.window,
            q_max,
            ..self.read.spec(&self.surface[i], i)
        })
    }
}
