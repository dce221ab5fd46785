//! The saturated loop's convergence measure (see the module docs of
//! [`super`]).

/// The convergence measure of a state (see the module docs).
#[derive(Debug, Clone, Copy)]
pub(super) struct Measure {
    /// ε.
    pub eps: f64,
    /// The level ḡ of the free set.
    pub g_bar: f64,
    /// Lowest gap − ḡ off the contact.
    pub off_min: f64,
    /// Nodes with 0 < p < σY.
    pub nf: usize,
    /// Σp.
    pub sum_p: f64,
}

/// ε, ḡ and the largest overlap off the contact of the pressure `p` with
/// the gap `g` (ḡ: the free set's mean gap under load control, else 0).
pub(super) fn measure(p: &[f64], g: &[f64], y: f64, load_control: bool, sigma_h: f64) -> Measure {
    let (mut nf, mut sum_gf, mut g_max_pl) = (0usize, 0.0, f64::NEG_INFINITY);
    for (&pk, &gk) in p.iter().zip(g) {
        if pk > 0.0 && pk < y {
            nf += 1;
            sum_gf += gk;
        } else if pk >= y {
            g_max_pl = g_max_pl.max(gk);
        }
    }
    let g_bar = match load_control {
        true if nf > 0 => sum_gf / nf as f64,
        true if g_max_pl.is_finite() => g_max_pl,
        _ => 0.0,
    };
    let (mut sum_p, mut num, mut off_min) = (0.0, 0.0, f64::INFINITY);
    for (&pk, &gk) in p.iter().zip(g) {
        let dg = gk - g_bar;
        sum_p += pk;
        if pk <= 0.0 {
            off_min = off_min.min(dg);
        } else if pk < y {
            num += pk * dg.abs();
        } else {
            num += y * dg.max(0.0);
        }
    }
    let eps = if sum_p > 0.0 {
        num / (sum_p * sigma_h)
    } else {
        0.0
    };
    Measure {
        eps,
        g_bar,
        off_min,
        nf,
        sum_p,
    }
}
