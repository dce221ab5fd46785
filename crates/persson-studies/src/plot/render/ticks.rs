//! Tick positions and labels for linear and (log10-transformed) log axes.
//!
//! Every chooser walks candidate spacings from dense to sparse and returns the
//! first whose labels fit (the caller measures them in pixels), so that tick
//! labels never overlap whatever the magnitude of the data.

/// At most this many labelled ticks per axis, however much room there is.
pub(crate) const MAX_TICKS: usize = 10;

/// One labelled tick: position in plot coordinates (log10 on a log axis).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Tick {
    pub pos: f64,
    pub label: String,
}

/// Labelled ticks plus unlabelled minor grid positions.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Ticks {
    pub major: Vec<Tick>,
    pub minor: Vec<f64>,
}

/// A predicate telling whether a set of labelled ticks fits on the axis.
pub(crate) type Fits<'a> = &'a dyn Fn(&[Tick]) -> bool;

/// Ticks on a linear axis spanning `[lo, hi]` (`lo < hi`, both finite).
pub(crate) fn linear(lo: f64, hi: f64, fits: Fits) -> Ticks {
    linear_mapped(lo, hi, &|v| v, fits)
}

/// Ticks on a log axis spanning `[lo, hi]` decades (plot coordinates are
/// log10 of the data).
///
/// Decades `10ᵏ` (every s-th decade, s = 1, 2, 3, 5, 10, …) when at least
/// three fit; else 1, 2, 5 × 10ᵏ if at least three; else two decades; else
/// evenly spaced values mapped to log10 (ranges of about a decade or less).
pub(crate) fn log(lo: f64, hi: f64, fits: Fits) -> Ticks {
    let span = hi - lo;
    // Candidate decade labellings, dense to sparse, each with ≥ 2 ticks.
    let mut candidates = Vec::new();
    for s in decade_steps(span) {
        let major: Vec<Tick> = decades(lo, hi)
            .filter(|k| k.rem_euclid(s) == 0)
            .map(|k| Tick {
                pos: k as f64,
                label: power_of_ten(k),
            })
            .collect();
        if major.len() < 2 {
            break;
        }
        candidates.push((s, major));
    }
    let decade_ticks = |(s, major): (i64, Vec<Tick>)| {
        let minor = if s == 1 && span <= 12.0 {
            mantissa_positions(lo, hi, &[2, 3, 4, 5, 6, 7, 8, 9])
                .map(|(m, k)| (m as f64).log10() + k as f64)
                .collect()
        } else {
            decades(lo, hi)
                .filter(|k| k.rem_euclid(s) != 0)
                .map(|k| k as f64)
                .collect()
        };
        Ticks { major, minor }
    };
    let fitting = |n: usize| {
        candidates
            .iter()
            .position(|(_, m)| m.len() >= n && m.len() <= MAX_TICKS && fits(m))
    };
    if let Some(i) = fitting(3) {
        return decade_ticks(candidates.swap_remove(i));
    }
    let picks: Vec<(u32, i64)> = mantissa_positions(lo, hi, &[1, 2, 5]).collect();
    if picks.len() >= 3 && picks.len() <= MAX_TICKS {
        let plain = picks.iter().all(|&(_, k)| (-3..=3).contains(&k));
        let major: Vec<Tick> = picks
            .iter()
            .map(|&(m, k)| Tick {
                pos: (m as f64).log10() + k as f64,
                label: mantissa_label(m, k, plain),
            })
            .collect();
        if fits(&major) {
            let minor = mantissa_positions(lo, hi, &[3, 4, 6, 7, 8, 9])
                .map(|(m, k)| (m as f64).log10() + k as f64)
                .collect();
            return Ticks { major, minor };
        }
    }
    if let Some(i) = fitting(2) {
        return decade_ticks(candidates.swap_remove(i));
    }
    match candidates.pop() {
        // Nothing fits: the sparsest decade labelling is the least bad.
        Some(sparsest) => decade_ticks(sparsest),
        None => linear_mapped(10f64.powf(lo), 10f64.powf(hi), &f64::log10, fits),
    }
}

/// Linear ticks over `[lo, hi]` in value space, placed at `to_pos(value)`.
fn linear_mapped(lo: f64, hi: f64, to_pos: &dyn Fn(f64) -> f64, fits: Fits) -> Ticks {
    let max_abs = lo.abs().max(hi.abs());
    let mut sparsest: Option<Ticks> = None;
    for (step, sub) in nice_steps(hi - lo) {
        let major: Vec<Tick> = multiples(lo, hi, step)
            .map(|v| Tick {
                pos: to_pos(v),
                label: linear_label(v, step, max_abs),
            })
            .collect();
        if major.len() < 2 {
            break;
        }
        if major.len() > MAX_TICKS {
            continue;
        }
        let minor = multiples(lo, hi, step / sub as f64)
            .map(&to_pos)
            .filter(|p| {
                !major
                    .iter()
                    .any(|t| (t.pos - p).abs() < 1e-9 * (1.0 + p.abs()))
            })
            .collect();
        let ticks = Ticks { major, minor };
        if fits(&ticks.major) {
            return ticks;
        }
        sparsest = Some(ticks);
    }
    sparsest.unwrap_or_else(|| Ticks {
        major: [lo, hi]
            .iter()
            .map(|&v| Tick {
                pos: to_pos(v),
                label: linear_label(v, (hi - lo).max(f64::MIN_POSITIVE), max_abs),
            })
            .collect(),
        minor: Vec::new(),
    })
}

/// Candidate steps 1, 2, 5 × 10ᵉ from dense to sparse, each with the number
/// of minor subdivisions (2: one unlabelled grid line between labels).
fn nice_steps(span: f64) -> Vec<(f64, u32)> {
    let e0 = span.log10().floor() as i32;
    let mut steps = Vec::new();
    for e in (e0 - 2)..=(e0 + 1) {
        for (m, sub) in [(1.0, 2), (2.0, 2), (5.0, 2)] {
            steps.push((m * 10f64.powi(e), sub));
        }
    }
    steps
}

/// The multiples `k·step` inside `[lo, hi]` (with a relative slack of 1e-9).
fn multiples(lo: f64, hi: f64, step: f64) -> impl Iterator<Item = f64> {
    let slack = 1e-9;
    let k0 = (lo / step - slack).ceil() as i64;
    let k1 = (hi / step + slack).floor() as i64;
    (k0..=k1).map(move |k| k as f64 * step)
}

/// The integer decades inside `[lo, hi]`.
fn decades(lo: f64, hi: f64) -> impl Iterator<Item = i64> {
    let slack = 1e-9;
    ((lo - slack).ceil() as i64)..=((hi + slack).floor() as i64)
}

/// Decade steps 1, 2, 3, 5, 10, 20, 25, 50, … up to the span.
fn decade_steps(span: f64) -> Vec<i64> {
    let mut steps = vec![1, 2, 3, 5];
    let mut p = 10;
    while (p as f64) <= span.max(10.0) * 10.0 && p < 1_000_000 {
        steps.extend([p, 2 * p, 5 * p / 2, 5 * p]);
        p *= 10;
    }
    steps
}

/// `(m, k)` for every `m·10ᵏ` inside `[lo, hi]` decades with `m` in `mantissas`.
fn mantissa_positions(
    lo: f64,
    hi: f64,
    mantissas: &'static [u32],
) -> impl Iterator<Item = (u32, i64)> {
    let slack = 1e-9;
    ((lo.floor() as i64)..=(hi.ceil() as i64)).flat_map(move |k| {
        mantissas.iter().filter_map(move |&m| {
            let p = (m as f64).log10() + k as f64;
            (p >= lo - slack && p <= hi + slack).then_some((m, k))
        })
    })
}

/// `10ᵏ` with a superscript exponent, e.g. `10⁻⁴⁰`.
pub(crate) fn power_of_ten(k: i64) -> String {
    format!("10{}", superscript(k))
}

/// `m·10ᵏ` as a plain decimal (`plain`) or as `m×10ᵏ` (`10ᵏ` when m = 1).
fn mantissa_label(m: u32, k: i64, plain: bool) -> String {
    if plain {
        let decimals = (-k).max(0) as usize;
        format!("{:.*}", decimals, m as f64 * 10f64.powi(k as i32))
    } else if m == 1 {
        power_of_ten(k)
    } else {
        format!("{m}×{}", power_of_ten(k))
    }
}

/// A tick label for `v` on a linear axis with tick spacing `step`: plain
/// decimals with as many digits as the step needs, or `a×10ᴱ` when the values
/// are large (≥ 10⁵) or small (< 10⁻³).
fn linear_label(v: f64, step: f64, max_abs: f64) -> String {
    // Snap round-off (and −0) to an exact zero.
    let v = if v.abs() < step * 1e-6 { 0.0 } else { v };
    let e_step = (step.log10() + 1e-9).floor() as i64;
    if !(1e-3..1e5).contains(&max_abs) {
        let e = (max_abs.log10() + 1e-9).floor() as i64;
        let decimals = (e - e_step).max(0) as usize;
        if v == 0.0 {
            return "0".into();
        }
        let mantissa = v / 10f64.powi(e as i32);
        minus(format!("{mantissa:.decimals$}×{}", power_of_ten(e)))
    } else {
        let decimals = (-e_step).max(0) as usize;
        minus(format!("{v:.decimals$}"))
    }
}

/// The typographic minus sign (U+2212) instead of a leading hyphen.
fn minus(s: String) -> String {
    match s.strip_prefix('-') {
        Some(rest) => format!("−{rest}"),
        None => s,
    }
}

/// An integer in Unicode superscript digits.
fn superscript(k: i64) -> String {
    k.to_string()
        .chars()
        .map(|c| match c {
            '-' => '⁻',
            '0' => '⁰',
            '1' => '¹',
            '2' => '²',
            '3' => '³',
            '4' => '⁴',
            '5' => '⁵',
            '6' => '⁶',
            '7' => '⁷',
            '8' => '⁸',
            _ => '⁹',
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn labels(t: &Ticks) -> Vec<&str> {
        t.major.iter().map(|t| t.label.as_str()).collect()
    }

    fn at_most(n: usize) -> impl Fn(&[Tick]) -> bool {
        move |t: &[Tick]| t.len() <= n
    }

    #[test]
    fn superscripts() {
        assert_eq!(power_of_ten(-40), "10⁻⁴⁰");
        assert_eq!(power_of_ten(0), "10⁰");
        assert_eq!(power_of_ten(123_456_789), "10¹²³⁴⁵⁶⁷⁸⁹");
    }

    #[test]
    fn linear_unit_interval() {
        let t = linear(-0.04, 1.04, &at_most(6));
        assert_eq!(labels(&t), ["0.0", "0.2", "0.4", "0.6", "0.8", "1.0"]);
        // Minor lines every 0.1 from 0 to 1 (11), less the 6 major ones.
        assert_eq!(t.minor.len(), 5);
    }

    #[test]
    fn linear_negative_and_no_minus_zero() {
        let t = linear(-3.1, 2.9, &at_most(7));
        assert_eq!(labels(&t), ["−3", "−2", "−1", "0", "1", "2"]);
    }

    #[test]
    fn linear_large_values_use_powers_of_ten() {
        let t = linear(0.0, 3.0e6, &at_most(4));
        assert_eq!(labels(&t), ["0", "1×10⁶", "2×10⁶", "3×10⁶"]);
    }

    #[test]
    fn log_decades_of_tiny_values() {
        // C(q) in m⁴: 1e-40 .. 1e-20, at most 6 labels → every 5th decade.
        let t = log(-40.3, -19.8, &at_most(6));
        assert_eq!(labels(&t), ["10⁻⁴⁰", "10⁻³⁵", "10⁻³⁰", "10⁻²⁵", "10⁻²⁰"]);
        assert!(t.minor.contains(&-39.0));
    }

    #[test]
    fn log_every_decade_with_mantissa_minor_lines() {
        let t = log(-3.02, 0.1, &at_most(10));
        assert_eq!(labels(&t), ["10⁻³", "10⁻²", "10⁻¹", "10⁰"]);
        assert_eq!(t.minor.len(), 3 * 8);
    }

    #[test]
    fn log_under_two_decades_uses_mantissas() {
        let t = log(-1.4, 0.02, &at_most(10));
        assert_eq!(labels(&t), ["0.05", "0.1", "0.2", "0.5", "1"]);
        let t = log(-20.4, -19.1, &at_most(10));
        assert_eq!(labels(&t), ["5×10⁻²¹", "10⁻²⁰", "2×10⁻²⁰", "5×10⁻²⁰"]);
    }

    #[test]
    fn log_with_two_mantissa_ticks_falls_back_to_linear_values() {
        // 1 … 4: only 1 and 2 of 1, 2, 5 × 10ᵏ, so evenly spaced values.
        let t = log(0.0, 0.6, &at_most(10));
        assert_eq!(labels(&t), ["1.0", "1.5", "2.0", "2.5", "3.0", "3.5"]);
    }

    #[test]
    fn log_narrow_range_falls_back_to_linear_values() {
        let t = log(0.5f64.log10(), 0.8f64.log10(), &at_most(10));
        assert_eq!(
            labels(&t),
            ["0.50", "0.55", "0.60", "0.65", "0.70", "0.75", "0.80"]
        );
        assert!((t.major[0].pos - 0.5f64.log10()).abs() < 1e-12);
    }

    #[test]
    fn nothing_fits_gives_the_sparsest() {
        let t = linear(0.0, 1.0, &|_: &[Tick]| false);
        assert_eq!(labels(&t), ["0", "1"]);
    }
}
