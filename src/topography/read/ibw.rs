//! Igor binary wave `.ibw`, version 5 (Asylum Research / Oxford
//! Instruments AFMs).
//!
//! A 64-byte binary header, a 320-byte wave header, the wave's values, then
//! sections whose sizes the binary header gives (formula, note, extended
//! units, dimension labels). Either byte order: the version (i16 at 0) is 5
//! in the file's order. Read (byte offsets):
//!
//! ```text
//! binary header:   0 version (i16)   4 wfmSize (i32)   8 formulaSize   12 noteSize
//!                 16 dataEUnitsSize  20 dimEUnitsSize[4]  36 dimLabelsSize[4] (i32)
//! wave header:    76 npnts (i32)   80 type (i16)   132 nDim[4] (i32)
//!                148 sfA[4] (f64: the step per index)   212 dataUnits (4 chars)
//!                216 dimUnits[4][4] (chars)
//! values:        384 npnts values of the type, first index fastest
//! ```
//!
//! An AFM image is a wave of `nx × ny × channels` (Igor's first index is x);
//! each channel's name is a 32-byte dimension label of the third dimension
//! (after the dimension's own label): `HeightTrace`, `HeightRetrace`,
//! `AmplitudeTrace`, `PhaseTrace`, `ZSensorTrace`, …; channels without a
//! label are `no name (1)`, `no name (2)`, … as SurfaceTopography names
//! them. [`ReadOptions::channel`] chooses one by name or index (from 0, as
//! SurfaceTopography's). By default the channel read is the first whose
//! name contains `Height` or `ZSensor`; a wave without names reads its
//! first channel; named channels none of which is a height are an error
//! naming them. Asylum Research writes one data unit (`m`) for all the
//! channels of a wave: a chosen channel is read in it only if its quantity
//! is a length, by its `<name>Unit` in the wave's note, else by its name
//! as SurfaceTopography 1.27 decides (`Height`, `ZSensor`, `Deflection`,
//! `Amplitude`: lengths; `Phase`: deg, `Potential`: V, …); another is an
//! error naming its unit. With SurfaceTopography's orientation (Igor's y
//! runs upwards, the map's rows downwards):
//!
//! ```text
//! h[iy, ix] = value[ix + nx·(ny − 1 − iy) + nx·ny·channel]   (dataUnits)
//! Lx = nx·sfA[0],   Ly = ny·sfA[1]   (dimUnits)
//! ```
//!
//! Units are the extended units where the file has them, else the 4-char
//! fields. A wave without a height unit needs `ReadOptions::height_unit`;
//! without a unit of x it stores no size (give `ReadOptions::size`): Igor's
//! default step is 1 of no unit.
//!
//! # References
//! WaveMetrics, Igor Pro Technical Note PTN003 "Igor Binary Wave Format"
//! (`IgorBin.h`: `BinHeader5`, `WaveHeader5`); the layout as
//! SurfaceTopography's `IO/IBW.py` (through igor2) reads it.

use std::borrow::Cow;
use std::path::Path;

use super::bin::{product, Bin};
use super::channel;
use super::units::{not_a_length, LengthUnit, Unit};
use super::{Raw, ReadOptions, Stored};
use crate::error::Result;

/// The binary header's size; the wave header follows.
const BIN_HEADER: usize = 64;
/// The wave header's size; the values follow.
const WAVE_HEADER: usize = 320;
/// A dimension label: 31 characters and a NUL.
const LABEL: usize = 32;
/// Relative precision of a float64 step.
const F64_RESOLUTION: f64 = 2.3e-16;

/// Fields in the file's byte order.
struct Fields<'b> {
    f: Bin<'b>,
    big: bool,
}

impl Fields<'_> {
    fn raw<const N: usize>(&self, offset: usize, what: &str) -> Result<[u8; N]> {
        let mut a = [0u8; N];
        a.copy_from_slice(self.f.slice(offset, N, what)?);
        if self.big {
            a.reverse();
        }
        Ok(a)
    }

    fn i16(&self, offset: usize, what: &str) -> Result<i16> {
        self.raw(offset, what).map(i16::from_le_bytes)
    }

    fn i32(&self, offset: usize, what: &str) -> Result<i32> {
        self.raw(offset, what).map(i32::from_le_bytes)
    }

    /// A size or count: an i32 that must not be negative.
    fn size(&self, offset: usize, what: &str) -> Result<usize> {
        let v = self.i32(offset, what)?;
        usize::try_from(v).map_err(|_| self.f.bad(format!("{what} = {v}: negative")))
    }

    fn f64(&self, offset: usize, what: &str) -> Result<f64> {
        self.raw(offset, what).map(f64::from_le_bytes)
    }
}

/// Whether the file is big-endian, from its version field (version 5 only).
fn big_endian(f: &Bin) -> Result<bool> {
    let v = f.slice(0, 2, "the version")?;
    match (v[0], v[1]) {
        (0, 5) => Ok(true),
        (5, 0) => Ok(false),
        (0, n) | (n, 0) if (1..=3).contains(&n) => Err(f.bad(format!(
            "version {n}: only version 5 is read (save it from Igor Pro 3 or later)"
        ))),
        _ => Err(f.bad("the file does not start with an Igor binary wave version")),
    }
}

/// The size in bytes and the kind of one value, from the wave header's type.
fn wave_type(w: &Fields) -> Result<(usize, Kind)> {
    Ok(match w.i16(BIN_HEADER + 16, "type")? {
        2 => (4, Kind::F32),
        4 => (8, Kind::F64),
        8 => (1, Kind::I8),
        0x10 => (2, Kind::I16),
        0x20 => (4, Kind::I32),
        0x48 => (1, Kind::U8),
        0x50 => (2, Kind::U16),
        0x60 => (4, Kind::U32),
        t => {
            return Err(w.f.bad(format!(
                "wave type {t:#x}: real numbers (float32/64, 8/16/32-bit integers) are read, \
                 not complex or text waves"
            )))
        }
    })
}

pub(crate) fn parse(path: &Path, b: &[u8], options: &ReadOptions) -> Result<Raw> {
    let f = Bin::new(b, path, "Igor binary wave .ibw");
    let big = big_endian(&f)?;
    let w = Fields { f, big };
    let f = &w.f;
    f.slice(0, BIN_HEADER + WAVE_HEADER, "the headers")?;
    let h = BIN_HEADER;
    let npnts = w.size(h + 12, "npnts")?;
    let (item, kind) = wave_type(&w)?;
    let mut dims = [0usize; 4];
    for (d, n) in dims.iter_mut().enumerate() {
        *n = w.size(h + 68 + 4 * d, "nDim")?;
    }
    let [nx, ny, channels, layers] = dims;
    if nx < 1 || ny < 1 || layers > 1 {
        return Err(f.bad(format!(
            "the wave has dimensions {dims:?}: an image (nx × ny, or nx × ny × channels) is read"
        )));
    }
    // Before anything per channel: a map needs 2 × 2 points.
    if nx < 2 || ny < 2 {
        return Err(f.bad(format!(
            "the map has {ny} row(s) and {nx} column(s): need at least 2 of each"
        )));
    }
    let channels = channels.max(1);
    let points = product(nx, ny, channels).filter(|&p| p == npnts);
    let Some(points) = points else {
        return Err(f.bad(format!(
            "npnts = {npnts}, the dimensions {nx} × {ny} × {channels} disagree"
        )));
    };
    let values = f.slice(
        BIN_HEADER + WAVE_HEADER,
        product(points, item, 1).unwrap_or(usize::MAX),
        "the values",
    )?;
    // The sections after the wave: formula, note, extended units, labels.
    let mut at = BIN_HEADER.saturating_add(w.size(4, "wfmSize")?);
    at = at.saturating_add(w.size(8, "formulaSize")?);
    let note = section(&w, &mut at, 12, "the note")?;
    let data_units = section(&w, &mut at, 16, "the extended data units")?;
    let mut dim_units = Vec::new();
    for d in 0..4 {
        dim_units.push(section(
            &w,
            &mut at,
            20 + 4 * d,
            "the extended dimension units",
        )?);
    }
    let mut labels = Vec::new();
    for d in 0..4 {
        labels.push(section(&w, &mut at, 36 + 4 * d, "the dimension labels")?);
    }
    let labelled = labels_of(labels[2], channels);
    let unnamed = labelled.iter().all(|n| n.is_empty());
    let channel = channel::choose_among(
        channels,
        |k| name(&labelled, k),
        |k| holds_heights(&labelled, unnamed, k),
        options.channel.as_deref(),
    )
    .map_err(|m| f.bad(m))?;
    if options.channel.is_some() {
        asylum_length(f, note, labels[2], channel, &name(&labelled, channel))?;
    }
    let start = channel * nx * ny;
    let value = |k: usize| kind.decode(&values[(start + k) * item..(start + k + 1) * item], big);
    let mut heights = Vec::with_capacity(nx * ny);
    for iy in 0..ny {
        let row = nx * (ny - 1 - iy);
        heights.extend((0..nx).map(|ix| value(row + ix)));
    }
    let unit = |extended: &[u8], short: usize, what: &str| -> Result<Unit> {
        let s = if extended.is_empty() {
            text(f.slice(short, 4, what)?)
        } else {
            text(extended)
        };
        Unit::declared(what, &s).map_err(|m| f.bad(m))
    };
    let height_unit = unit(data_units, h + 148, "the heights")?;
    let ux = unit(dim_units[0], h + 152, "x")?;
    let uy = unit(dim_units[1], h + 156, "y")?;
    if ux != uy {
        return Err(f.bad(format!("the units of x ({ux:?}) and y ({uy:?}) differ")));
    }
    let size = match ux {
        Unit::Unstated => None,
        unit => Some(Stored {
            lx: nx as f64 * w.f64(h + 84, "sfA")?.abs(),
            ly: ny as f64 * w.f64(h + 92, "sfA")?.abs(),
            unit,
            resolution: F64_RESOLUTION,
        }),
    };
    Ok(Raw {
        size,
        height_unit,
        require_units: true,
        ..Raw::map(nx, ny, heights)
    })
}

/// The value types of a real wave.
#[derive(Clone, Copy)]
enum Kind {
    F32,
    F64,
    I8,
    I16,
    I32,
    U8,
    U16,
    U32,
}

impl Kind {
    /// One value from its `bytes` (as many as the kind's size), in the
    /// file's byte order.
    fn decode(self, bytes: &[u8], big: bool) -> f64 {
        let item = bytes.len();
        let mut a = [0u8; 8];
        a[..item].copy_from_slice(bytes);
        if big {
            a[..item].reverse();
        }
        let [b0, b1, b2, b3, ..] = a;
        match self {
            Kind::F32 => f64::from(f32::from_le_bytes([b0, b1, b2, b3])),
            Kind::F64 => f64::from_le_bytes(a),
            Kind::I8 => f64::from(b0 as i8),
            Kind::I16 => f64::from(i16::from_le_bytes([b0, b1])),
            Kind::I32 => f64::from(i32::from_le_bytes([b0, b1, b2, b3])),
            Kind::U8 => f64::from(b0),
            Kind::U16 => f64::from(u16::from_le_bytes([b0, b1])),
            Kind::U32 => f64::from(u32::from_le_bytes([b0, b1, b2, b3])),
        }
    }
}

/// The next section after the wave, of the size at `offset` of the binary
/// header; `at` moves past it.
fn section<'b>(w: &Fields<'b>, at: &mut usize, offset: usize, what: &str) -> Result<&'b [u8]> {
    let n = w.size(offset, what)?;
    let s = w.f.slice(*at, n, what)?;
    *at += n;
    Ok(s)
}

/// NUL-terminated Latin-1 text.
fn text(b: &[u8]) -> String {
    b.iter()
        .take_while(|&&c| c != 0)
        .map(|&c| char::from(c))
        .collect::<String>()
        .trim()
        .to_string()
}

/// The channels' labels: those of the third dimension after its own (31
/// characters each). SurfaceTopography names the channels without a label
/// `no name (k)` ([`name`]); a channel holds heights if its name contains
/// `Height` or `ZSensor`, or no channel has a label ([`holds_heights`]).
fn labels_of(labels: &[u8], channels: usize) -> Vec<String> {
    labels
        .chunks(LABEL)
        .skip(1)
        .take(channels)
        .map(text)
        .collect()
}

/// The name of channel `k`, made on demand: a wave of many channels
/// without labels costs no list of names.
fn name(labelled: &[String], k: usize) -> Cow<'_, str> {
    match labelled.get(k) {
        Some(n) => Cow::Borrowed(n.as_str()),
        None => Cow::Owned(format!("no name ({})", k - labelled.len() + 1)),
    }
}

/// Whether channel `k` holds heights (see [`labels_of`]); `unnamed`: no
/// channel has a label.
fn holds_heights(labelled: &[String], unnamed: bool, k: usize) -> bool {
    if unnamed {
        return true;
    }
    let l = name(labelled, k).to_ascii_lowercase();
    l.contains("height") || l.contains("zsensor")
}

/// The unit of an Asylum Research channel by the prefix of its name (after
/// `Nap` or `DAC`, before `Trace`/`Retrace`), as SurfaceTopography 1.27
/// reads it: the wave's data unit is that of the height channels, written
/// for all its channels alike.
const ASYLUM_UNITS: [(&str, Option<&str>); 11] = [
    ("Height", Some("m")),
    ("ZSensor", Some("m")),
    ("Deflection", Some("m")),
    ("Amplitude", Some("m")),
    ("Phase", Some("deg")),
    ("Current", Some("A")),
    ("Frequency", Some("Hz")),
    ("Capacitance", Some("F")),
    ("Potential", Some("V")),
    ("Count", None),
    ("QFactor", None),
];

/// A channel the caller chose in a wave with a note (Asylum Research) is
/// read only if its quantity is a length: its `<name>Unit` in the note,
/// else by the prefix of its name (`ASYLUM_UNITS`, others are volts).
fn asylum_length(f: &Bin, note: &[u8], labels: &[u8], k: usize, name: &str) -> Result<()> {
    let note: String = note.iter().map(|&c| char::from(c)).collect();
    let labelled = labels.chunks(LABEL).skip(1).nth(k).is_some();
    if !labelled || !note.contains(':') {
        return Ok(());
    }
    let mut base = name.trim_end_matches(|c: char| c.is_ascii_digit());
    base = base.strip_suffix("Mod").unwrap_or(base);
    for suffix in ["Trace", "Retrace"] {
        if let Some(b) = base.strip_suffix(suffix) {
            base = b;
            break;
        }
    }
    let key = format!("{base}Unit");
    // Igor ends the note's lines with CR.
    let noted = note.split(['\r', '\n']).find_map(|l| {
        let (k, v) = l.split_once(':')?;
        (k.trim() == key).then(|| v.trim().to_string())
    });
    let unit = match noted {
        Some(u) => Some(u),
        None => {
            let b = ["DAC", "Nap"]
                .iter()
                .find_map(|p| base.strip_prefix(p))
                .unwrap_or(base);
            ASYLUM_UNITS
                .iter()
                .find(|(p, _)| b.starts_with(p))
                .map_or(Some("V"), |(_, u)| *u)
                .map(str::to_string)
        }
    };
    let unit = unit.unwrap_or_default();
    // Igor writes SI symbols: `A` is the ampere, never the ångström.
    if unit != "A" && LengthUnit::parse(&unit).is_some() {
        return Ok(());
    }
    Err(f.bad(not_a_length(
        &format!("the values of channel \"{name}\""),
        &unit,
    )))
}
