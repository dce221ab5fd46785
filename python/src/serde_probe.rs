//! A value of every serde shape, for the tests of [`crate::to_python`]:
//! `python/tests/test_to_python.py` compares the Python object the
//! serializer builds with `json.loads` of serde_json's text of the same value.

use pyo3::prelude::*;

use crate::to_python::to_python;

/// A value of every serde shape (for the tests): the Python object this
/// module builds and serde_json's text of the same value, which
/// `python/tests/test_to_python.py` compares with `json.loads`.
#[pyfunction]
pub fn _serde_probe(py: Python<'_>) -> PyResult<(Bound<'_, PyAny>, String)> {
    let probe = probe::Probe::new();
    let text = serde_json::to_string(&probe)
        .map_err(|e| pyo3::exceptions::PyValueError::new_err(e.to_string()))?;
    Ok((to_python(py, &probe)?, text))
}

mod probe {
    use std::collections::BTreeMap;

    use serde::Serialize;

    #[derive(Serialize)]
    pub enum Shape {
        Unit,
        Newtype(f64),
        Tuple(i32, f64),
        Struct { a: u8, b: Option<f64> },
    }

    #[derive(Serialize)]
    #[serde(tag = "kind", rename_all = "snake_case")]
    pub enum Tagged {
        HighPressure { nominal_pressure: f64 },
    }

    #[derive(Serialize)]
    pub struct UnitStruct;

    #[derive(Serialize)]
    pub struct Newtype(u64);

    /// Bytes through `serialize_bytes` (a `&[u8]` field would go through
    /// `serialize_seq`).
    pub struct Bytes(&'static [u8]);

    impl Serialize for Bytes {
        fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
            s.serialize_bytes(self.0)
        }
    }

    #[derive(Serialize)]
    pub struct Probe {
        third: f64,
        tiny: f64,
        big: f64,
        negative_zero: f64,
        nan: f64,
        infinity: f64,
        single: f32,
        single_nan: f32,
        u64_max: u64,
        i64_min: i64,
        i128_big: i128,
        text: String,
        letter: char,
        bytes: Bytes,
        none: Option<f64>,
        some: Option<f64>,
        unit: (),
        unit_struct: UnitStruct,
        newtype: Newtype,
        tuple: (f64, usize, bool),
        shapes: Vec<Shape>,
        tagged: Tagged,
        integer_keys: BTreeMap<i32, f64>,
        bool_keys: BTreeMap<bool, u8>,
        #[serde(skip_serializing_if = "Option::is_none")]
        skipped: Option<f64>,
        #[serde(flatten)]
        flattened: BTreeMap<String, f64>,
    }

    impl Probe {
        pub fn new() -> Self {
            Probe {
                third: 1.0 / 3.0,
                tiny: 5e-324,
                big: f64::MAX,
                negative_zero: -0.0,
                nan: f64::NAN,
                infinity: f64::NEG_INFINITY,
                single: 0.1,
                single_nan: f32::NAN,
                u64_max: u64::MAX,
                i64_min: i64::MIN,
                i128_big: i128::from(u64::MAX) * 4,
                text: "σ0 ≤ 0.1 E*".into(),
                letter: 'ζ',
                bytes: Bytes(&[0, 7, 255]),
                none: None,
                some: Some(2.5),
                unit: (),
                unit_struct: UnitStruct,
                newtype: Newtype(42),
                tuple: (0.5, 3, true),
                shapes: vec![
                    Shape::Unit,
                    Shape::Newtype(1e-300),
                    Shape::Tuple(-4, 0.25),
                    Shape::Struct { a: 9, b: None },
                ],
                tagged: Tagged::HighPressure {
                    nominal_pressure: 3e6,
                },
                integer_keys: BTreeMap::from([(-1, 0.5), (128, 1e22)]),
                bool_keys: BTreeMap::from([(false, 0), (true, 1)]),
                skipped: None,
                flattened: BTreeMap::from([("extra".to_string(), 7.0)]),
            }
        }
    }
}
