//! The tables of a measured surface's analysis ([`persson::topography`]): its
//! statistics as scalars, then the binned spectrum; for line scans the 1D
//! spectrum too.

use persson::topography::{Analysis, Layout, ProfileSpectrum};

use super::{number, Cell, Table, Tabulate};

impl Tabulate for Analysis {
    /// One table `psd`: the statistics as scalars under the title, then the
    /// binned spectrum (q, C, modes per bin); for line scans a second table
    /// `psd_profile`, the 1D spectrum (q, C_1D, modes per bin).
    fn tables(&self) -> Vec<Table> {
        let shape = format!("{} × {}", self.shape[0], self.shape[1]);
        let pixel = self
            .pixel_size
            .iter()
            .map(|d| number(*d, 6))
            .collect::<Vec<_>>()
            .join(" × ");
        let what = match self.layout {
            Layout::Map => "height map",
            Layout::LineScans => "line scans",
        };
        let mut t = Table::new(
            "psd",
            format!("Isotropic power spectrum C(q) of the {what} (Persson's normalisation)"),
        )
        .scalar("shape", "points (rows × columns)", shape)
        .scalar("pixel_size", "pixel size (m)", pixel)
        .scalar(
            "periodic",
            "periodic",
            if self.periodic { "yes" } else { "no" },
        )
        .scalar("detrend", "detrending", self.detrend.name())
        .scalar("window", "window", self.window.name())
        .scalar("rms_height", "h_rms (m)", self.rms_height)
        .scalar("rms_slope", "h'_rms (forward differences)", self.rms_slope)
        .scalar(
            "rms_curvature",
            "h''_rms (1/m, 5-point Laplacian)",
            self.rms_curvature,
        )
        .scalar(
            "mean_curvature_rms",
            "rms mean curvature ∇²h/2 (1/m)",
            self.mean_curvature_rms,
        )
        .scalar(
            "rms_height_from_spectrum",
            "h_rms from C(q) (m)",
            self.rms_height_from_spectrum,
        )
        .scalar(
            "rms_slope_from_spectrum",
            "h'_rms from C(q)",
            self.rms_slope_from_spectrum,
        )
        .scalar(
            "rms_curvature_from_spectrum",
            "h''_rms from C(q) (1/m)",
            self.rms_curvature_from_spectrum,
        )
        .scalar(
            "hurst",
            "H (fit over the band)",
            match (self.hurst, self.hurst_error) {
                (Some(value), Some(error)) => Cell::Measured { value, error },
                _ => Cell::Empty,
            },
        )
        .scalar("q_min", "q_min = 2π/L (1/m)", self.q_min)
        .scalar("q_max", "q_max (1/m)", self.q_max);
        if let (Some(s), Some(c)) = (self.rms_slope_profile, self.rms_curvature_profile) {
            t = t
                .scalar("rms_slope_profile", "h'_x rms along the profiles", s)
                .scalar(
                    "rms_curvature_profile",
                    "h''_x rms along the profiles (1/m)",
                    c,
                );
        }
        let mut t = t
            .column("q", "q (1/m)")
            .column("c", "C (m⁴)")
            .column("count", "modes");
        for ((q, c), n) in self.psd.q.iter().zip(&self.psd.c).zip(&self.psd.count) {
            t.push(vec![Cell::Num(*q), Cell::Num(*c), Cell::from(*n)]);
        }
        let mut tables = vec![t];
        tables.extend(self.psd_profile.as_ref().map(profile_table));
        tables
    }
}

/// The table `psd_profile` of line scans: q, C_1D, modes per bin.
fn profile_table(p: &ProfileSpectrum) -> Table {
    let mut t = Table::new(
        "psd_profile",
        "1D power spectrum C_1D(q) along the profiles (Persson's 1D normalisation)",
    )
    .column("q", "q (1/m)")
    .column("c_1d", "C_1D (m³)")
    .column("count", "modes");
    for ((q, c), n) in p.q.iter().zip(&p.c_1d).zip(&p.count) {
        t.push(vec![Cell::Num(*q), Cell::Num(*c), Cell::from(*n)]);
    }
    t
}

impl Tabulate for persson::topography::Anisotropy {
    /// One table `anisotropy`: the Peklenik number and the ISO 25178-2
    /// texture parameters as scalars, then the slope variance along the two
    /// principal directions.
    fn tables(&self) -> Vec<Table> {
        vec![Table::new(
            "anisotropy",
            "Anisotropy of the height map (Peklenik: slope tensor; Str, Sal: autocorrelation at s = 0.2; Std: the lay)",
        )
        .scalar("peklenik_number", "Peklenik number γ", self.peklenik_number)
        .scalar(
            "principal_direction",
            "principal direction, long axis (deg from x)",
            self.principal_direction,
        )
        .scalar("texture_aspect_ratio", "Str", self.texture_aspect_ratio)
        .scalar(
            "autocorrelation_length",
            "Sal (m)",
            self.autocorrelation_length,
        )
        .scalar(
            "texture_direction",
            "Std, the lay (deg from x)",
            self.texture_direction,
        )]
    }
}
