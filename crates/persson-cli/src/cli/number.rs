//! The value parsers of the numeric flags: plain SI numbers (a number typed
//! with a unit is refused with the SI number it stands for) and counts. Both
//! take values that start with `-` (the flags set `allow_hyphen_values`), so
//! that `--yield-stress -inf` or `--points -3` reach a range message instead
//! of clap's "unexpected argument".

/// Units a number may have been typed with, and their factor to SI.
const UNITS: [(&str, f64, &str); 14] = [
    ("GPa", 1e9, "Pa"),
    ("MPa", 1e6, "Pa"),
    ("kPa", 1e3, "Pa"),
    ("Pa", 1.0, "Pa"),
    ("nm", 1e-9, "m"),
    ("µm", 1e-6, "m"),
    ("um", 1e-6, "m"),
    ("mm", 1e-3, "m"),
    ("cm", 1e-2, "m"),
    ("m", 1.0, "m"),
    ("kN", 1e3, "N"),
    ("mN", 1e-3, "N"),
    ("N", 1.0, "N"),
    ("%", 1e-2, "(a fraction)"),
];

/// A number flag's value parser: a plain number (SI units: Pa, m, N, 1/m);
/// a number with a unit is refused with the plain SI number it stands for.
pub fn number(s: &str) -> Result<f64, String> {
    let t = s.trim();
    if let Ok(v) = t.parse::<f64>() {
        return Ok(v);
    }
    for (unit, factor, si) in UNITS {
        if let Some(n) = t.strip_suffix(unit).map(str::trim) {
            if n.parse::<f64>().is_ok() {
                // The number as typed, times the unit's power of ten.
                let exp = factor.log10().round() as i32;
                let (m, e0) = match n.split_once(['e', 'E']) {
                    Some((m, e)) => (m, e.parse::<i32>().unwrap_or(0)),
                    None => (n, 0),
                };
                let plain = match exp + e0 {
                    0 => m.to_string(),
                    e => format!("{m}e{e}"),
                };
                return Err(format!(
                    "`{s}` is not a plain number: give SI numbers without units \
                     ({plain} for {s}, in {si})"
                ));
            }
        }
    }
    if t.contains(',') {
        return Err(format!("`{s}` is a list: this flag takes one number"));
    }
    Err(format!(
        "`{s}` is not a number: give a plain SI number (Pa, m, N, 1/m), e.g. 1e6, 2.5e-7"
    ))
}

/// A count flag's value parser (`--points`, `--bins`, `--grid`, …): a whole
/// number ≥ 0; a negative or fractional one is refused with that range (the
/// library's checks then name the range of each count, e.g. `points` ≥ 2).
pub fn count(s: &str) -> Result<usize, String> {
    let t = s.trim();
    if let Ok(v) = t.parse::<usize>() {
        return Ok(v);
    }
    match t.parse::<f64>() {
        Ok(v) => Err(format!("must be an integer >= 0 (a count), got {v}")),
        Err(_) => Err(format!("`{s}` is not a count: give an integer >= 0")),
    }
}

/// As [`count`], for a seed (an integer from 0 to 2⁶⁴ − 1).
pub fn seed(s: &str) -> Result<u64, String> {
    let t = s.trim();
    if let Ok(v) = t.parse::<u64>() {
        return Ok(v);
    }
    match t.parse::<f64>() {
        Ok(v) => Err(format!(
            "must be an integer from 0 to 18446744073709551615 (a seed), got {v}"
        )),
        Err(_) => Err(format!("`{s}` is not a seed: give an integer >= 0")),
    }
}
