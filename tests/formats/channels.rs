//! `ReadOptions::channel` on the readers of multi-channel files that
//! predate it (`.ibw`, Nanoscope `.di`, `.gwy`) and on single-channel
//! formats: the default is unchanged, another channel is read by name
//! (case-insensitive) or index against SurfaceTopography 1.27.1
//! (`st.open_topography(f).topography(channel_index=i)`: its grid, sizes
//! and heights `h[ix, iy]`), a channel that is not a height map or does
//! not exist is an error naming the file, the format and the channels.

use persson::topography::read::{as_read, AsRead, LengthUnit, ReadOptions};

use super::support::{data, error_of, temp};

/// One height: the same integer or float times the same factors in
/// another order, a few roundings.
const SAME_NUMBERS: f64 = 1e-14;

fn channel(name: &str) -> ReadOptions {
    ReadOptions {
        channel: Some(name.into()),
        ..Default::default()
    }
}

fn read(path: &std::path::Path, o: &ReadOptions) -> AsRead {
    as_read(path, o).unwrap_or_else(|e| panic!("{e}"))
}

/// The same grid, sizes and heights, bit for bit (NaN where undefined).
fn same(a: &AsRead, b: &AsRead) -> bool {
    (a.nx, a.ny, a.lx, a.ly) == (b.nx, b.ny, b.lx, b.ly)
        && a.heights.len() == b.heights.len()
        && a.heights
            .iter()
            .zip(&b.heights)
            .all(|(x, y)| x.to_bits() == y.to_bits())
}

/// `r` against SurfaceTopography: `nb_grid_pts`, `physical_sizes` and
/// `h[ix, iy]`, in its unit (`unit` metres).
fn agrees(
    r: &AsRead,
    unit: f64,
    (nx, ny): (usize, usize),
    (lx, ly): (f64, f64),
    at: &[((usize, usize), f64)],
) {
    let rel = |a: f64, b: f64| if a == b { 0.0 } else { (a / b - 1.0).abs() };
    assert_eq!((r.nx, r.ny), (nx, ny));
    assert!(
        rel(r.lx, lx * unit) <= SAME_NUMBERS,
        "Lx {} vs {}",
        r.lx,
        lx * unit
    );
    assert!(
        rel(r.ly, ly * unit) <= SAME_NUMBERS,
        "Ly {} vs {}",
        r.ly,
        ly * unit
    );
    for &((ix, iy), h) in at {
        let ours = r.heights[iy * r.nx + ix];
        assert!(
            rel(ours, h * unit) <= SAME_NUMBERS,
            "h[{ix}, {iy}] {ours:e} vs {:e}",
            h * unit
        );
    }
}

#[test]
fn ibw_channels_by_name_and_index() {
    let f = data("spot_1-1000nm.ibw");
    let default = read(&f, &ReadOptions::default());
    assert!(same(&read(&f, &channel("HeightTrace")), &default));
    assert!(same(&read(&f, &channel("0")), &default));
    let retrace = read(&f, &channel("heightretrace"));
    assert!(same(&read(&f, &channel("1")), &retrace));
    assert!(!same(&retrace, &default));
    let l = 2.007843137254902e-05;
    agrees(
        &retrace,
        1.0,
        (256, 256),
        (l, l),
        &[
            ((0, 0), -3.0985046350906487e-07),
            ((5, 7), -3.173833249547897e-07),
            ((255, 254), -6.617800636377069e-07),
        ],
    );
    // The amplitude is a length (m), as SurfaceTopography reads it.
    agrees(
        &read(&f, &channel("2")),
        1.0,
        (256, 256),
        (l, l),
        &[
            ((0, 0), 6.785420936239461e-08),
            ((5, 7), 6.861798595991786e-08),
            ((255, 254), 6.82253116224274e-08),
        ],
    );
    // The wave's unit (m) is not the phase's (deg) nor the potential's (V).
    for (name, unit) in [("PhaseTrace", "\"deg\""), ("7", "\"V\"")] {
        let e = error_of(&f, &channel(name), "not a unit of length");
        assert!(
            e.contains("Igor binary wave .ibw") && e.contains(unit),
            "{e}"
        );
    }
    for wrong in ["Topography", "8"] {
        let e = error_of(&f, &channel(wrong), &format!("no channel \"{wrong}\""));
        assert!(
            e.contains("0: \"HeightTrace\"") && e.contains("7: \"NapPotentialRetrace\""),
            "{e}"
        );
    }
}

#[test]
fn unnamed_ibw_channel_is_no_name_1() {
    let f = data("10x10-one_channel_without_name.ibw");
    let o = |c: Option<&str>| ReadOptions {
        height_unit: Some(LengthUnit::Metre),
        size: Some(persson::topography::read::SizeSpec::PixelSize(1.0)),
        channel: c.map(Into::into),
        ..Default::default()
    };
    let default = read(&f, &o(None));
    assert!(same(&read(&f, &o(Some("no name (1)"))), &default));
    assert!(same(&read(&f, &o(Some("0"))), &default));
    error_of(&f, &o(Some("1")), "the file has 0: \"no name (1)\"");
}

#[test]
fn nanoscope_channels_by_name_and_index() {
    let f = data("di-3.di");
    let default = read(&f, &ReadOptions::default());
    assert!(same(&read(&f, &channel("zsensor")), &default));
    let height = read(&f, &channel("Height"));
    assert!(same(&read(&f, &channel("3")), &height));
    assert!(!same(&height, &default));
    agrees(
        &height,
        1e-9,
        (256, 256),
        (10000.0, 10000.0),
        &[
            ((0, 0), 366.45366030130924),
            ((5, 7), 345.0510960956772),
            ((255, 254), -1013.9247286684372),
        ],
    );
    agrees(
        &default,
        1e-9,
        (256, 256),
        (10000.0, 10000.0),
        &[((0, 0), 564.01630244078), ((255, 254), -620.3290178710208)],
    );
    for name in ["Phase", "1"] {
        let e = error_of(&f, &channel(name), "is not in a length per volt");
        assert!(e.contains("Nanoscope .spm/.di"), "{e}");
    }
    let e = error_of(&f, &channel("Deflection"), "no channel \"Deflection\"");
    assert!(
        e.contains(r#"0: "ZSensor", 1: "AmplitudeError", 2: "Phase", 3: "Height""#),
        "{e}"
    );
}

#[test]
fn gwy_channels_by_title_and_index() {
    // gwyfile-mask.gwy: /0/data "Phase" (deg), /1/data "Height" (µm, masked).
    let f = data("gwyfile-mask.gwy");
    let default = read(&f, &ReadOptions::default());
    assert!(same(&read(&f, &channel("height")), &default));
    assert!(same(&read(&f, &channel("1")), &default));
    agrees(
        &default,
        1.0,
        (75, 305),
        (2.773965e-05, 0.00011280791),
        &[
            ((5, 7), -1.4983293073699998e-07),
            ((74, 303), 2.02965693087e-07),
        ],
    );
    for name in ["Phase", "0"] {
        let e = error_of(&f, &channel(name), "not a unit of length");
        assert!(
            e.contains("Gwyddion .gwy") && e.contains("\"Phase\" (/0/data)"),
            "{e}"
        );
    }
    let e = error_of(&f, &channel("Topography"), "no channel \"Topography\"");
    assert!(e.contains(r#"0: "Phase", 1: "Height""#), "{e}");
    // The phase in µm (the same 3 bytes as deg): the first height channel
    // is now /0/data, the default; "Height" still reads /1/data.
    let mut b = std::fs::read(&f).unwrap();
    let at = b.windows(4).position(|w| w == b"deg\0").unwrap();
    b[at..at + 3].copy_from_slice("µm".as_bytes());
    let g = temp("two-heights.gwy", &b);
    let phase = read(&g, &ReadOptions::default());
    assert!(same(&read(&g, &channel("Phase")), &phase));
    assert!(!same(&phase, &default));
    assert!(same(&read(&g, &channel("Height")), &default));
    // gwyfile-test.gwy: one untitled-unit channel "Test".
    let f = data("gwyfile-test.gwy");
    let o = |c: Option<&str>| ReadOptions {
        height_unit: Some(LengthUnit::Nanometre),
        lateral_unit: Some(LengthUnit::Micrometre),
        channel: c.map(Into::into),
        ..Default::default()
    };
    let default = read(&f, &o(None));
    assert!(same(&read(&f, &o(Some("test"))), &default));
    assert!(same(&read(&f, &o(Some("0"))), &default));
    error_of(&f, &o(Some("Height")), "the file has 0: \"Test\"");
}

#[test]
fn single_channel_formats_take_none_or_0() {
    for (file, format) in [
        ("sur-2.sur", "Digital Surf .sur"),
        ("top-1.top", "WSxM"),
        ("nms-1-crop.nms", "NanoFocus .nms"),
        ("sdf-1.sdf", "ISO 25178-71 .sdf"),
        ("xyz-1.txt", "Text"),
        ("ISO5436-sample4.x3p", "ISO 25178-72 .x3p"),
    ] {
        let f = data(file);
        let default = read(&f, &ReadOptions::default());
        assert!(same(&read(&f, &channel(" 0 ")), &default), "{file}");
        for wrong in ["Height", "1"] {
            let e = error_of(
                &f,
                &channel(wrong),
                &format!(
                    "{format} files hold one channel: channel \"{wrong}\" does not exist \
                     (give none, or 0)"
                ),
            );
            eprintln!("{e}");
        }
    }
}

/// A wave of one point per channel is refused before its channels are
/// named; a wave of many unnamed channels names them on demand and lists
/// at most 20 in an error.
#[test]
fn ibw_many_channels() {
    let bytes = std::fs::read(data("10x10-one_channel_without_name.ibw")).unwrap();
    let dims = |d: [i32; 3]| {
        let mut b = bytes.clone();
        for (k, n) in d.iter().enumerate() {
            b[132 + 4 * k..136 + 4 * k].copy_from_slice(&n.to_le_bytes());
        }
        b
    };
    let p = temp("points.ibw", &dims([1, 1, 100]));
    let e = error_of(&p, &ReadOptions::default(), "need at least 2 of each");
    assert!(e.contains("Igor binary wave .ibw"), "{e}");
    let p = temp("channels.ibw", &dims([2, 2, 25]));
    let o = ReadOptions {
        height_unit: Some(LengthUnit::Metre),
        size: Some(persson::topography::read::SizeSpec::PixelSize(1.0)),
        channel: Some("no name (25)".into()),
        ..Default::default()
    };
    let r = read(&p, &o);
    assert_eq!((r.nx, r.ny), (2, 2));
    let e = error_of(
        &p,
        &ReadOptions {
            channel: Some("no name (26)".into()),
            ..o
        },
        "19: \"no name (20)\" … and 5 more",
    );
    assert!(e.contains("Igor binary wave .ibw"), "{e}");
}

/// An Asylum Research channel's unit is its `<base>Unit` in the note, the
/// base without the trailing digits, `Mod` and `Trace`/`Retrace`
/// (`LateralMod2` → `LateralUnit`), not the prefix table's volts.
#[test]
fn ibw_asylum_unit_of_a_numbered_channel() {
    let bytes = std::fs::read(data("spot_1-1000nm.ibw")).unwrap();
    let at = |b: &[u8], s: &[u8]| b.windows(s.len()).rposition(|w| w == s).unwrap();
    let mut b = bytes.clone();
    let k = at(&b, b"LateralUnit: V");
    b[k..k + 14].copy_from_slice(b"LateralUnit: m");
    let k = at(&b, b"PhaseTrace\0");
    b[k..k + 11].copy_from_slice(b"LateralMod2");
    let p = temp("lateral.ibw", &b);
    let r = read(&p, &channel("LateralMod2"));
    assert!(same(&r, &read(&p, &channel("4"))));
    // Without the note's unit: volts, by the name.
    let k = at(&b, b"LateralUnit: m");
    b[k..k + 14].copy_from_slice(b"LateralUnit: V");
    let p = temp("lateral-v.ibw", &b);
    let e = error_of(&p, &channel("LateralMod2"), "not a unit of length");
    assert!(e.contains("\"V\"") && e.contains("LateralMod2"), "{e}");
}
