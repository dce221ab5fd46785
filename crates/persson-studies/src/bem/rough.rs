//! The study `bem` (feature `bem`): the solves, their details and files.

use std::path::Path;

use persson::bem::rough::RoughReport;
use persson::error::Result;
use serde::Serialize;

use super::spec::BemOutput;
use crate::bem_detail::{PatchReport, StressMap, SubsurfaceStudy};
use crate::output::Files;
use crate::study::Context;
use crate::table::{Table, Tabulate};

/// What `bem` computed: the solves and, when asked, their contact patches
/// and the stress below them (reported under `bem`, `bem_patches` and
/// `bem_subsurface`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Report {
    /// The solves.
    pub rough: RoughReport,
    /// Contact-patch statistics of the solves.
    pub patches: Option<PatchReport>,
    /// Stress below the solves.
    pub subsurface: Option<SubsurfaceStudy>,
    /// The von Mises maps of `subsurface` to write (`stress_field`).
    #[serde(skip)]
    pub stress_maps: Vec<StressMap>,
}

impl Tabulate for Report {
    fn tables(&self) -> Vec<Table> {
        let mut out = self.rough.tables();
        if let Some(p) = &self.patches {
            out.extend(p.tables());
        }
        if let Some(s) = &self.subsurface {
            out.extend(s.tables());
        }
        out
    }
}

/// Solve.
///
/// # Errors
/// Missing or invalid inputs; a solve that fails.
pub fn run(ctx: &Context<'_>, b: &BemOutput) -> Result<Report> {
    let (rough, details) = super::solve::bem_rough(ctx, b)?;
    Ok(Report {
        rough,
        patches: details.patches,
        subsurface: details.subsurface,
        stress_maps: details.maps,
    })
}

/// The solves' warnings.
pub fn warnings(r: &Report) -> Vec<crate::warning::Warning> {
    crate::warning::of_rough(&r.rough)
}

/// `bem`, `bem_patches` and `bem_subsurface`.
///
/// # Errors
/// As the serializer's.
pub fn entries<M: serde::ser::SerializeMap>(r: &Report, map: &mut M) -> Result<(), M::Error> {
    map.serialize_entry("bem", &r.rough)?;
    if let Some(p) = &r.patches {
        map.serialize_entry("bem_patches", p)?;
    }
    if let Some(s) = &r.subsurface {
        map.serialize_entry("bem_subsurface", s)?;
    }
    Ok(())
}

/// Stage the plots (feature `plot`), the histogram and the von Mises maps.
///
/// # Errors
/// A figure that cannot be drawn; a file that cannot be staged.
pub fn write(
    b: &BemOutput,
    r: &Report,
    ctx: &Context<'_>,
    dir: &Path,
    out: &mut Files,
) -> Result<()> {
    plots(b, r, ctx, dir, out)?;
    if let Some(file) = &b.histogram {
        if let Some(t) = r
            .rough
            .tables()
            .into_iter()
            .find(|t| t.name == "bem_histogram")
        {
            out.write(&dir.join(file), t.to_csv().as_bytes())?;
        }
    }
    let field = b.subsurface.as_ref().and_then(|s| s.stress_field.as_ref());
    if let Some(file) = field {
        for m in &r.stress_maps {
            let p = crate::bem_detail::indexed(&dir.join(file), m.index, m.depth_index);
            out.write(
                &p,
                &persson::io::npy::encode(r.rough.grid, r.rough.grid, &m.von_mises_stress)?,
            )?;
        }
    }
    Ok(())
}

/// The plots of the solves, the patches and the stress below them, each
/// plane's von Mises map beside the depth plot (`_k_j` added).
fn plots(b: &BemOutput, r: &Report, ctx: &Context<'_>, dir: &Path, out: &mut Files) -> Result<()> {
    use super::figures as plot;
    use crate::plot::Encode;
    use crate::study::draw;
    draw(out, dir, b.plot.as_ref(), || {
        plot::bem(&r.rough).map(Box::new)
    })?;
    draw(out, dir, b.pressure_plot.as_ref(), || {
        crate::plot::map::rough_map(&r.rough).map(Box::new)
    })?;
    if let (Some(p), Some(pr)) = (&b.patches, &r.patches) {
        draw(out, dir, p.plot.as_ref(), || {
            plot::patch_areas(pr).map(Box::new)
        })?;
    }
    let Some(s) = &b.subsurface else {
        return Ok(());
    };
    if let Some(sr) = &r.subsurface {
        draw(out, dir, s.plot.as_ref(), || {
            plot::subsurface_profiles(sr).map(Box::new)
        })?;
    }
    if let Some(p) = &s.plot {
        let planes = crate::bem_detail::planes(
            &r.stress_maps,
            (r.rough.grid, r.rough.size),
            &s.depth,
            ctx.nominal_pressure(),
            if r.rough.contact_modulus == 1.0 {
                "E*"
            } else {
                "Pa"
            },
            &dir.join(p),
        );
        for (p, fig) in planes {
            out.write(&p, &fig.encode(&p)?)?;
        }
    }
    Ok(())
}
