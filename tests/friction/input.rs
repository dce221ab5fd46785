//! Readers, bad input, the out-of-table report, sweeps and JSON keys.

use super::*;

/// A table used far outside its range says where and how much.
#[test]
fn table_excursion_is_reported() {
    let s = spectrum();
    let table = MasterCurve::new(&[(1e2, 3e6, 1e6), (1e3, 5e6, 2e6), (1e4, 9e6, 3e6)]).unwrap();
    let rubber = Rubber::new(table, TemperatureShift::none(T_REF).unwrap());
    let f = Friction::new(&s, &rubber, &options(1e-8)).unwrap();
    let p = f.point(1e-2, T_REF, 1e5).unwrap();
    let x = p.isothermal.table_excursion.unwrap();
    // Principal reduced frequencies q v from 1 to 1e5 rad/s against the table's 1e2..1e4.
    assert!(
        (x.decades_below - 2.0).abs() < IDENTITY_TOL
            && (x.decades_above - 1.0).abs() < IDENTITY_TOL,
        "{x:?}"
    );
    assert!(x.friction_fraction > 0.0 && x.friction_fraction < 1.0);
    assert!(x.g_fraction > 0.0 && x.g_fraction < 1.0);
    // Inside the table for q v in [1e2, 1e4]: v = 1, q in [1e2, 1e4] would need q1 = 1e4.
    let opts = FrictionOptions {
        cutoff: CutOff::Wavevector(1e4),
        ..options(1e-8)
    };
    let x = Friction::new(&s, &rubber, &opts)
        .unwrap()
        .point(1.0, T_REF, 1e5)
        .unwrap()
        .isothermal
        .table_excursion
        .unwrap();
    assert_eq!((x.decades_below, x.decades_above), (0.0, 0.0));
}

#[test]
fn master_curve_files_with_bad_rows_name_the_line() {
    let cases: [(&str, &str); 7] = [
        ("1 1e6 1e5\n10 1e6 1e5\n5 1e6 1e5\n", "x.txt:3"), // non-monotone
        ("1 1e6 1e5\n10 1e6 1e5\n10 2e6 1e5\n", "x.txt:3"), // repeated frequency
        ("# c\n1 1e6 1e5\n10 -1e6 1e5\n100 1e6 1e5\n", "x.txt:3"), // negative E′
        ("1 1e6 1e5\n10 1e6 NaN\n100 1e6 1e5\n", "x.txt:2"), // NaN E″
        ("1 1e6 1e5\n10 1e6 0\n100 1e6 1e5\n", "x.txt:2"), // E″ = 0
        ("1 1e6 1e5\n10 1e6 1e5\n", "fewer than 3"),       // too few
        ("1 1e6 1e5\n10 1e6\n100 1e6 1e5\n", "x.txt:2"),   // missing column
    ];
    for (text, want) in cases {
        let e = MasterCurve::from_bytes(
            Path::new("x.txt"),
            text.as_bytes(),
            FrequencyUnit::RadPerSecond,
        )
        .unwrap_err()
        .to_string();
        let want = if want == "fewer than 3" {
            "needs at least 3"
        } else {
            want
        };
        assert!(e.contains(want), "{text:?}: {e}");
        assert!(matches!(
            MasterCurve::from_bytes(Path::new("x.txt"), text.as_bytes(), FrequencyUnit::Hertz),
            Err(Error::Parse { .. })
        ));
    }
    let e =
        MasterCurve::from_file(Path::new("/no/such/file.txt"), FrequencyUnit::Hertz).unwrap_err();
    assert!(matches!(e, Error::Io { .. }));
}

#[test]
fn bad_input_names_the_field_and_never_gives_nan() {
    let s = spectrum();
    let rubber = Rubber::new(sls(), TemperatureShift::wlf(T_REF, 8.86, 101.6).unwrap());
    let f = Friction::new(&s, &rubber, &options(1e-8)).unwrap();
    let name_of = |e: Error| match e {
        Error::InvalidParameter { name, .. } => name,
        e => panic!("{e}"),
    };
    for (v, t, p, name) in [
        (0.0, T_REF, 1e5, "velocity"),
        (-1.0, T_REF, 1e5, "velocity"),
        (f64::NAN, T_REF, 1e5, "velocity"),
        (1.0, T_REF - 101.6, 1e5, "temperature"),
        (1.0, T_REF - 200.0, 1e5, "temperature"),
        (1.0, f64::NAN, 1e5, "temperature"),
        (1.0, T_REF, 0.0, "nominal_pressure"),
        (1.0, T_REF, f64::INFINITY, "nominal_pressure"),
    ] {
        assert_eq!(
            name_of(f.point(v, t, p).unwrap_err()),
            name,
            "({v}, {t}, {p})"
        );
    }
    let bad = |o: FrictionOptions| name_of(Friction::new(&s, &rubber, &o).err().expect("error"));
    assert_eq!(
        bad(FrictionOptions {
            gamma: 1.5,
            ..options(1e-8)
        }),
        "gamma"
    );
    assert_eq!(
        bad(FrictionOptions {
            tolerance: 0.0,
            ..options(1e-8)
        }),
        "tolerance"
    );
    assert_eq!(
        bad(FrictionOptions {
            points_per_decade: 0,
            ..options(1e-8)
        }),
        "points_per_decade"
    );
    assert_eq!(
        bad(FrictionOptions {
            breaks: vec![-1.0],
            ..options(1e-8)
        }),
        "break"
    );
    assert!(rubber.clone().with_poisson(0.7).is_err());
    assert_eq!(
        name_of(
            Prony::new(
                1e6,
                &[PronyTerm {
                    modulus: -1.0,
                    relaxation_time: 1.0
                }]
            )
            .unwrap_err()
        ),
        "prony_modulus[0]"
    );
    assert_eq!(
        name_of(TemperatureShift::wlf(T_REF, 8.86, -1.0).unwrap_err()),
        "wlf_c2"
    );
    assert_eq!(
        name_of(Thermal::new(0.2, 1e3, f64::NAN).unwrap_err()),
        "heat_capacity"
    );
    assert!(log_velocities(1.0, 0.1, 10).is_err() && log_velocities(0.0, 1.0, 10).is_err());
    // A shift table: temperatures outside it are errors.
    let table =
        ShiftTable::new(&[(280.0, 10.0, None), (300.0, 1.0, None), (320.0, 0.1, None)]).unwrap();
    let r2 = Rubber::new(sls(), TemperatureShift::table(300.0, table).unwrap());
    let f2 = Friction::new(&s, &r2, &options(1e-8)).unwrap();
    assert_eq!(
        name_of(f2.point(1.0, 330.0, 1e5).unwrap_err()),
        "temperature"
    );
    // Extreme but valid inputs: finite results.
    for (v, p) in [(1e-30, 1e5), (1e30, 1e5), (1.0, 1e-30), (1.0, 1e30)] {
        let r = f.point(v, T_REF, p).unwrap().isothermal;
        assert!(
            r.friction_coefficient.is_finite() && r.contact_fraction.is_finite() && r.g.is_finite(),
            "({v}, {p}): {r:?}"
        );
    }
}

#[test]
fn velocity_sweep_and_json_keys() {
    let s = spectrum();
    let rubber = Rubber::new(sls(), TemperatureShift::wlf(T_REF, 8.86, 101.6).unwrap())
        .with_thermal(Thermal::new(0.25, 1200.0, 1500.0).unwrap());
    let f = Friction::new(&s, &rubber, &options(1e-8)).unwrap();
    let vs = log_velocities(1e-4, 1.0, 5).unwrap();
    assert_eq!(vs.len(), 5);
    assert!((vs[2] - 1e-2).abs() < 1e-17);
    let pts = f.sweep(&vs, &[T_REF, T_REF + 20.0], &[1e5, 2e5]).unwrap();
    assert_eq!(pts.len(), 20);
    assert_eq!(
        (pts[5].temperature, pts[5].nominal_pressure, pts[5].velocity),
        (T_REF, 2e5, 1e-4)
    );
    let json = serde_json::to_value(&pts[0]).unwrap();
    for key in [
        "velocity",
        "temperature",
        "nominal_pressure",
        "friction_coefficient",
        "friction_coefficient_error_bound",
        "contact_fraction",
        "contact_fraction_error_bound",
        "decades",
        "profile",
        "flash",
    ] {
        assert!(json.get(key).is_some(), "missing {key}");
    }
    assert!(json["flash"]["flash_temperature"].as_f64().unwrap() >= 0.0);
}
