//! The flags of `persson compare --leakage / --conductance`: the theories'
//! leak rate and contact conductance against the BEM's on the sweep's
//! surfaces ([`persson_studies::validation::compare_transport`]).

use persson_studies::scene::transport;
use persson_studies::validation::TransportCompareConfig;

use super::bem_args::{ConductanceArgs, SealArgs};
use super::number::number;

/// `compare --leakage / --conductance` (flattened into `compare`'s flags).
#[derive(clap::Args, Debug, Clone)]
pub struct TransportArgs {
    /// Also compare the leak rate of a seal: critical-junction and effective-medium
    /// theories against Reynolds flow on the BEM's gap (needs --viscosity and
    /// --pressure-drop, or a gas's --inlet-pressure and --outlet-pressure).
    #[arg(long)]
    pub leakage: bool,
    #[command(flatten)]
    pub seal: SealArgs,
    /// Percolation threshold a_c of the critical junction, in (0, 1) (with --leakage).
    #[arg(long, default_value = "0.42", allow_hyphen_values = true, value_parser = number)]
    pub percolation_threshold: f64,
    /// Also compare the contact conductance: Barber's identity on the theory's and
    /// the BEM's stiffness (needs --conductivity and/or --resistivity, or a gas
    /// law, each of which asks for the comparison alone, as in `bem rough`).
    #[arg(long)]
    pub conductance: bool,
    #[command(flatten)]
    pub bodies: ConductanceArgs,
}

impl TransportArgs {
    /// The transport comparison the flags ask for (`None`: none), checked
    /// before any solve; `breaks` are the spectrum's kinks.
    pub fn config(&self, breaks: Vec<f64>) -> anyhow::Result<Option<TransportCompareConfig>> {
        if self.seal.given() && !self.leakage {
            anyhow::bail!(
                "--viscosity / --pressure-drop / --inlet-pressure / --outlet-pressure: add --leakage to compare the leak rate"
            );
        }
        let conductance_flags = self.bodies.given();
        if self.conductance && !conductance_flags {
            anyhow::bail!(
                "--conductance: give --conductivity κ1[,κ2] (W/(m K)) and/or --resistivity ρ1[,ρ2] (Ω m), or --gas-conductivity with --mean-free-path"
            );
        }
        if !self.leakage && !conductance_flags {
            return Ok(None);
        }
        let seal = if self.leakage {
            let out = self.seal.output(self.percolation_threshold, 1e-9, false)?;
            Some(transport::seal(&out)?)
        } else {
            None
        };
        let request = self.bodies.request(seal)?;
        let mut config = TransportCompareConfig::new(request);
        config.percolation_threshold = self.percolation_threshold;
        config.breaks = breaks;
        config.validate(None, None)?;
        Ok(Some(config))
    }
}

/// `FILE.ext` → `FILE_<what>.ext`: the transport figures beside `--plot`'s.
fn sibling(path: &std::path::Path, what: &str) -> std::path::PathBuf {
    let stem = path.file_stem().unwrap_or_default().to_string_lossy();
    let name = match path.extension() {
        Some(e) => format!("{stem}_{what}.{}", e.to_string_lossy()),
        None => format!("{stem}_{what}"),
    };
    path.with_file_name(name)
}

/// With `--plot FILE` and `--leakage` / `--conductance`: Q(σ0) into
/// `FILE_leakage.ext` and h(σ0) into `FILE_conductance.ext`, log–log, the
/// theories as lines and the BEM as markers on one figure each.
pub fn plot(
    path: Option<&std::path::Path>,
    r: &persson_studies::validation::Comparison,
    files: &mut persson_studies::output::Files,
) -> anyhow::Result<()> {
    use persson_studies::plot::{Axis, Encode, Figure, Series};
    let (Some(path), Some(t)) = (path, &r.transport) else {
        return Ok(());
    };
    let positive = |pts: Vec<(f64, Option<f64>)>| -> Vec<(f64, f64)> {
        pts.into_iter()
            .filter_map(|(x, y)| y.map(|y| (x, y)))
            .filter(|&(x, y)| x > 0.0 && y > 0.0 && y.is_finite())
            .collect()
    };
    let finest = t.bem.last().map_or(0, |g| g.grid);
    let leak: Vec<_> = t
        .points
        .iter()
        .filter_map(|p| p.leakage.as_ref().map(|l| (p.nominal_pressure, l)))
        .collect();
    if !leak.is_empty() {
        let mut fig = Figure::new(
            "Leak rate against load: theories and Reynolds flow on the BEM's gap",
            Axis::log("nominal pressure σ0 (Pa)"),
            Axis::log("leak rate Q (m³/s)"),
        );
        let series =
            |f: fn(&persson_studies::validation::compare_transport::LeakageCompared) -> f64| {
                positive(leak.iter().map(|(p, l)| (*p, Some(f(l)))).collect())
            };
        let a_c = t.percolation_threshold.unwrap_or_default();
        fig.push(Series::line(
            format!(
                "critical junction, a_c = {}",
                persson_studies::table::number(a_c, 3)
            ),
            series(|l| l.critical_junction_leak_rate),
        ));
        fig.push(Series::dashed(
            "effective medium",
            series(|l| l.effective_medium_leak_rate),
        ));
        fig.push(Series::markers(
            format!("BEM {finest}², Reynolds flow (mean of x and y)"),
            series(|l| l.bem_leak_rate),
        ));
        let p = sibling(path, "leakage");
        files.write(&p, &fig.encode(&p)?)?;
    }
    let cond: Vec<_> = t
        .points
        .iter()
        .filter_map(|p| p.conductance.as_ref().map(|c| (p.nominal_pressure, c)))
        .collect();
    if !cond.is_empty() {
        use persson_studies::validation::compare_transport::ConductanceCompared as C;
        let mut fig = Figure::new(
            "Contact conductance against load: theory and BEM (N → ∞)",
            Axis::log("nominal pressure σ0 (Pa)"),
            Axis::log("conductance h: W/(m² K) (thermal, gap), S/m² (electrical)"),
        );
        type Pick = fn(&C) -> Option<f64>;
        let curves: [(&str, Pick, Pick); 3] = [
            (
                "thermal h_c",
                |c| c.theory_thermal_conductance,
                |c| c.bem_thermal_conductance,
            ),
            (
                "electrical h_e",
                |c| c.theory_electrical_conductance,
                |c| c.bem_electrical_conductance,
            ),
            (
                "gap h_gap",
                |c| c.theory_gap_conductance,
                |c| c.bem_gap_conductance,
            ),
        ];
        for (label, theory, bem) in curves {
            let th = positive(cond.iter().map(|(p, c)| (*p, theory(c))).collect());
            if th.is_empty() {
                continue;
            }
            fig.push(Series::line(format!("{label}, theory"), th));
            fig.push(Series::markers(
                format!("{label}, BEM N → ∞"),
                positive(cond.iter().map(|(p, c)| (*p, bem(c))).collect()),
            ));
        }
        let p = sibling(path, "conductance");
        files.write(&p, &fig.encode(&p)?)?;
    }
    Ok(())
}
