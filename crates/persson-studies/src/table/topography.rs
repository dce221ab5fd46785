//! The table of a measured surface's analysis ([`persson::topography`]): its
//! statistics as scalars, then the binned spectrum.

use persson::topography::{Analysis, Layout};

use super::{number, Cell, Table, Tabulate};

impl Tabulate for Analysis {
    /// One table `psd`: the statistics as scalars under the title, then the
    /// binned spectrum (q, C, modes per bin).
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
            Cell::Measured {
                value: self.hurst,
                error: self.hurst_error,
            },
        )
        .scalar("q_min", "q_min = 2π/L (1/m)", self.q_min)
        .scalar("q_max", "q_max (1/m)", self.q_max)
        .column("q", "q (1/m)")
        .column("c", "C (m⁴)")
        .column("count", "modes");
        for ((q, c), n) in self.psd.q.iter().zip(&self.psd.c).zip(&self.psd.count) {
            t.push(vec![Cell::Num(*q), Cell::Num(*c), Cell::from(*n)]);
        }
        vec![t]
    }
}
