//! Length units: the ones files state (`ZUnits = m`, `# Width: 10 µm`,
//! `Lateral um`, `[mm]`) and the ones a caller gives for files that state
//! none.

use std::str::FromStr;

/// A unit of length, for heights and coordinates in files that state none.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum LengthUnit {
    /// m.
    Metre,
    /// cm = 1e-2 m.
    Centimetre,
    /// mm = 1e-3 m.
    Millimetre,
    /// µm = 1e-6 m.
    Micrometre,
    /// nm = 1e-9 m.
    Nanometre,
    /// pm = 1e-12 m.
    Picometre,
    /// Å = 1e-10 m.
    Angstrom,
}

impl LengthUnit {
    /// Every unit, largest first.
    pub const ALL: [LengthUnit; 7] = [
        LengthUnit::Metre,
        LengthUnit::Centimetre,
        LengthUnit::Millimetre,
        LengthUnit::Micrometre,
        LengthUnit::Nanometre,
        LengthUnit::Angstrom,
        LengthUnit::Picometre,
    ];

    /// The unit in metres.
    pub fn metres(self) -> f64 {
        match self {
            LengthUnit::Metre => 1.0,
            LengthUnit::Centimetre => 1e-2,
            LengthUnit::Millimetre => 1e-3,
            LengthUnit::Micrometre => 1e-6,
            LengthUnit::Nanometre => 1e-9,
            LengthUnit::Picometre => 1e-12,
            LengthUnit::Angstrom => 1e-10,
        }
    }

    /// The SI symbol (`µm` with the micro sign).
    pub fn symbol(self) -> &'static str {
        match self {
            LengthUnit::Metre => "m",
            LengthUnit::Centimetre => "cm",
            LengthUnit::Millimetre => "mm",
            LengthUnit::Micrometre => "µm",
            LengthUnit::Nanometre => "nm",
            LengthUnit::Picometre => "pm",
            LengthUnit::Angstrom => "Å",
        }
    }

    /// The unit a file writes as `s`: the SI symbols (`µm` with the micro
    /// sign or the Greek mu, also `um`), `Å`, and the names instruments write
    /// (`micron`, `Micrometer`, `nanometers`, `Angstrom`, …). `A` is not
    /// taken for Å (it is the ampere in Gwyddion's files).
    pub fn parse(s: &str) -> Option<Self> {
        let s = s.trim();
        let u = match s {
            "m" => LengthUnit::Metre,
            "cm" => LengthUnit::Centimetre,
            "mm" => LengthUnit::Millimetre,
            "\u{b5}m" | "\u{3bc}m" | "um" => LengthUnit::Micrometre,
            "nm" => LengthUnit::Nanometre,
            "pm" => LengthUnit::Picometre,
            "\u{c5}" | "\u{212b}" => LengthUnit::Angstrom,
            _ => {
                let l = s.to_ascii_lowercase();
                let l = l.trim_end_matches('s');
                match l {
                    "meter" | "metre" => LengthUnit::Metre,
                    "centimeter" | "centimetre" => LengthUnit::Centimetre,
                    "millimeter" | "millimetre" => LengthUnit::Millimetre,
                    "micron" | "micrometer" | "micrometre" => LengthUnit::Micrometre,
                    "nanometer" | "nanometre" => LengthUnit::Nanometre,
                    "picometer" | "picometre" => LengthUnit::Picometre,
                    "angstrom" | "ångström" | "angstroem" => LengthUnit::Angstrom,
                    _ => return None,
                }
            }
        };
        Some(u)
    }
}

impl FromStr for LengthUnit {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        LengthUnit::parse(s)
            .ok_or_else(|| format!("{s:?} is not a unit of length (m, mm, µm, nm, pm, Å)"))
    }
}

impl std::fmt::Display for LengthUnit {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.symbol())
    }
}

/// What a file says about the unit of some numbers.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Unit {
    /// The file names the unit (its text as written) and it is a length.
    Stated(String, LengthUnit),
    /// The file names no unit.
    Unstated,
}

impl Unit {
    /// `u`, stated by its symbol: the unit a format fixes (`.sdf` in
    /// metres, `.tmd` in millimetres).
    pub(crate) fn of(u: LengthUnit) -> Unit {
        Unit::Stated(u.symbol().to_string(), u)
    }

    /// The unit of a declared unit field (`ZUnits`, `Value units`, `data
    /// unit`): empty is unstated, a length is stated, anything else (a phase
    /// in `deg`, a signal in `V`) is an error message naming it.
    pub(crate) fn declared(what: &str, text: &str) -> Result<Unit, String> {
        let t = text.trim();
        if t.is_empty() {
            return Ok(Unit::Unstated);
        }
        match LengthUnit::parse(t) {
            Some(u) => Ok(Unit::Stated(t.to_string(), u)),
            None => Err(not_a_length(what, t)),
        }
    }

    /// The length unit found among the words of a column heading
    /// (`Lateral um`, `[mm]`, `x in µm`, `X_(microns)`); a heading naming a
    /// unit that is not a length (`Phase [deg]`) is an error message.
    pub(crate) fn in_heading(what: &str, heading: &str) -> Result<Unit, String> {
        let words = heading
            .split(|c: char| c.is_whitespace() || "_()[]{}/:=,;".contains(c))
            .filter(|w| !w.is_empty());
        let mut found = Unit::Unstated;
        for w in words {
            if let Some(u) = LengthUnit::parse(w) {
                found = Unit::Stated(w.to_string(), u);
            } else if NON_LENGTH.contains(&w) {
                return Err(not_a_length(what, w));
            }
        }
        Ok(found)
    }
}

/// Units instruments write for channels that are not heights.
const NON_LENGTH: &[&str] = &[
    "deg", "°", "rad", "V", "mV", "µV", "Hz", "kHz", "N", "nN", "pN", "%", "a.u.", "counts",
];

pub(crate) fn not_a_length(what: &str, unit: &str) -> String {
    format!(
        "{what} are in {unit:?}, not a unit of length: this channel is not a height map \
         (export the height channel, in m, mm, µm, nm, pm or Å)"
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn units_as_instruments_write_them() {
        for (s, u) in [
            ("m", LengthUnit::Metre),
            ("µm", LengthUnit::Micrometre),
            ("\u{3bc}m", LengthUnit::Micrometre),
            ("um", LengthUnit::Micrometre),
            ("Micrometer", LengthUnit::Micrometre),
            ("microns", LengthUnit::Micrometre),
            ("Å", LengthUnit::Angstrom),
            ("nanometers", LengthUnit::Nanometre),
        ] {
            assert_eq!(LengthUnit::parse(s), Some(u), "{s}");
        }
        assert_eq!(LengthUnit::parse("A"), None);
        assert_eq!(LengthUnit::parse("deg"), None);
        assert_eq!(
            Unit::in_heading("x", "Lateral um").unwrap(),
            Unit::Stated("um".into(), LengthUnit::Micrometre)
        );
        assert_eq!(
            Unit::in_heading("x", "X_(microns)").unwrap(),
            Unit::Stated("microns".into(), LengthUnit::Micrometre)
        );
        assert_eq!(Unit::in_heading("x", "index").unwrap(), Unit::Unstated);
        assert!(Unit::in_heading("heights", "Phase [deg]").is_err());
        assert!(Unit::declared("heights", "deg")
            .unwrap_err()
            .contains("\"deg\""));
    }
}
