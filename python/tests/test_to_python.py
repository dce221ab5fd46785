"""Reports reach Python through our serde Serializer (python/src/to_python.rs),
not a JSON string: the objects it builds equal `json.loads` of serde_json's
text of the same value for every serde shape (floats bit for bit, NaN and
±∞ as None, f32 as its shortest digits, integer and bool map keys as text),
and a report is built without the `json` module."""

import json
import math
import struct

import persson
from persson import _persson


def bits(x):
    return struct.pack("<d", x)


def test_every_serde_shape_is_serde_jsons():
    obj, text = _persson._serde_probe()
    expected = json.loads(text)
    assert obj == expected
    # Independent values, not only agreement with serde_json: the exact
    # doubles of the fields, and their bits (−0.0 == 0.0 compares equal).
    assert bits(obj["third"]) == bits(1.0 / 3.0)
    assert bits(obj["tiny"]) == bits(5e-324)
    assert obj["big"] == 1.7976931348623157e308
    assert bits(obj["negative_zero"]) == bits(-0.0)
    assert obj["nan"] is None and obj["infinity"] is None and obj["single_nan"] is None
    assert obj["single"] == 0.1  # the f32's shortest digits, not 0.10000000149011612
    assert obj["u64_max"] == 2**64 - 1 and obj["i64_min"] == -(2**63)
    assert obj["i128_big"] == (2**64 - 1) * 4
    assert obj["text"] == "σ0 ≤ 0.1 E*" and obj["letter"] == "ζ"
    assert obj["bytes"] == [0, 7, 255]
    assert obj["unit"] is None and obj["unit_struct"] is None and obj["none"] is None
    assert obj["tuple"] == [0.5, 3, True]
    assert obj["shapes"] == ["Unit", {"Newtype": 1e-300}, {"Tuple": [-4, 0.25]},
                             {"Struct": {"a": 9, "b": None}}]
    assert obj["tagged"] == {"kind": "high_pressure", "nominal_pressure": 3e6}
    assert obj["integer_keys"] == {"-1": 0.5, "128": 1e22}
    assert obj["bool_keys"] == {"false": 0, "true": 1}
    assert "skipped" not in obj and obj["extra"] == 7.0


def test_reports_are_built_without_json(monkeypatch):
    import sys
    # A report must not go through json.loads any more.
    real = json.loads

    def refuse(*a, **k):  # pragma: no cover - only called on a regression
        raise AssertionError("json.loads called while building a report")

    monkeypatch.setattr(sys.modules["json"], "loads", refuse)
    r = persson.area(persson.Spectrum.example(), 1e9, [1e6])
    monkeypatch.setattr(sys.modules["json"], "loads", real)
    assert isinstance(r, dict) and isinstance(r["points"][0]["contact_fraction"], float)
    assert math.isfinite(r["points"][0]["contact_fraction"])
