"""One declaration per study: the Python keywords against the study's spec.

A study's spec (its section of the scene file) is the one declaration its
front-ends follow: the scene schema is generated from it, the command line
derives its flags from it, and here every field of the spec must be a keyword
of the study's Python function with the spec's default. The schema file is the
one `persson run` validates scenes against (regenerated from the specs by the
Rust tests).
"""

import inspect
import json
import math
import pathlib
import re

import pytest

import persson

SCHEMA = (
    pathlib.Path(__file__).resolve().parents[2]
    / "crates"
    / "persson-studies"
    / "schema"
    / "scene.schema.json"
)

# (function, spec, keywords named otherwise, fields that are not keywords and why)
STUDIES = [
    ("area", "AreaOutput", {}, {"plot": "a figure: Python plots itself"}),
    (
        "magnification",
        "MagnificationOutput",
        {"nominal_pressure": "pressure"},
        {"plot": "a figure", "plot_g": "a figure"},
    ),
    ("adhesion", "AdhesionOutput", {}, {}),
    (
        "conductance",
        "ConductanceOutput",
        {},
        {"plot": "a figure", "bem": "compare(..., conductivity=...) is the BEM beside it"},
    ),
    (
        "leakage",
        "LeakageOutput",
        {},
        {"plot": "a figure", "bem": "compare(..., leakage=True) is the BEM beside it"},
    ),
    (
        "separation",
        "SeparationOutput",
        {},
        {"plot": "a figure", "plot_area": "a figure", "plot_points": "a figure's points"},
    ),
    ("separation_density", "SeparationDensityOutput", {}, {}),
    (
        "friction",
        "FrictionOutput",
        {},
        {"plot": "a figure", "velocity_range": "velocity takes any array"},
    ),
    ("theories", "TheoriesOutput", {}, {"plot": "a figure"}),
    ("compare", "SweepSpec", {}, {"fit_alpha": "alpha=None fits α"}),
    ("compare", "CompareSpec", {}, {}),
    ("ensemble", "EnsembleSpec", {}, {}),
    (
        "bem_rough",
        "BemOutput",
        {},
        {
            "histogram": "Python returns the histogram: bins switches it on",
            "plot": "a figure",
            "pressure_plot": "a figure",
            "patches": "contact_patches() on the returned pressure",
            "subsurface": "subsurface_stress() on the returned pressure",
        },
    ),
    (
        "bem_hertz",
        "BemHertzOutput",
        {},
        {"stress_plot": "a figure: Python plots itself"},
    ),
    (
        "stress",
        "StressOutput",
        {},
        {
            "zeta": "the physical mode is stress_physical()",
            "peak_pressure": "the physical mode is stress_physical()",
            "ball": "the physical mode is stress_physical()",
            "cylinder": "the physical mode is stress_physical()",
            "yield_stress": "the physical mode is stress_physical()",
            "plot": "a figure",
        },
    ),
    (
        "stress_physical",
        "StressOutput",
        {},
        {
            "g": "the dimensionless mode is stress()",
            "yield_ratio": "the dimensionless mode is stress()",
            "plot": "a figure",
        },
    ),
    (
        "surrogates",
        "SurrogatesOutput",
        {},
        {
            "grid": "Python passes the heights",
            "map_seed": "Python passes the heights",
            "surfaces": "Python returns the surrogates",
            "plot": "a figure",
            "plot_distribution": "a figure",
        },
    ),
]


# Specs that are not a section of a scene, each in its own generated file.
OTHER_SPECS = {
    "SweepSpec": SCHEMA.parent / "sweep.schema.json",
    "CompareSpec": SCHEMA.parent / "compare.schema.json",
    "EnsembleSpec": SCHEMA.parent / "ensemble.schema.json",
}


def spec(name):
    if name in OTHER_SPECS:
        with open(OTHER_SPECS[name], encoding="utf-8") as f:
            return json.load(f)
    with open(SCHEMA, encoding="utf-8") as f:
        return json.load(f)["$defs"][name]


def stated_default(field):
    """The default a field's schema gives, or its description states."""
    if "default" in field:
        return field["default"]
    m = re.search(r"\(default ([-+0-9.e]+)\)", field.get("description", ""))
    return float(m.group(1)) if m else None


@pytest.mark.parametrize("function, name, renamed, not_keywords", STUDIES)
def test_every_field_of_the_spec_is_a_keyword_with_its_default(
    function, name, renamed, not_keywords
):
    params = inspect.signature(getattr(persson, function)).parameters
    fields = spec(name)["properties"]
    for field, schema in fields.items():
        if field in not_keywords:
            assert field not in params
            continue
        keyword = renamed.get(field, field)
        assert keyword in params, f"{function}() has no keyword for {name}.{field}"
        want = stated_default(schema)
        got = params[keyword].default
        if want is None or got is inspect.Parameter.empty or got is None:
            continue
        if isinstance(want, float):
            assert math.isclose(got, want, rel_tol=1e-12), (function, field, got, want)
        else:
            assert got == want, (function, field, got, want)
