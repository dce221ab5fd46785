"""`persson.compare(..., leakage=True, conductivity=...)` against
`persson compare --leakage --conductance --json`: the same `transport` dict
and the same warnings (issue 23)."""

import pytest

import persson
from conftest import run_cli, same
from test_bem import SPEC, spectrum

PRESSURES = [0.002, 0.01, 0.06]


def test_compare_transport_matches_cli():
    cli = run_cli("compare", *SPEC, "--contact-modulus", 1, "--grid", 64, "--levels", 3,
                  "--pressure", ",".join(map(str, PRESSURES)),
                  "--leakage", "--viscosity", 1e-3, "--pressure-drop", 1,
                  "--conductance", "--conductivity", 50)
    r = persson.compare(spectrum(), 1.0, PRESSURES, grid=64, levels=3, leakage=True,
                        viscosity=1e-3, pressure_drop=1.0, conductivity=50.0)
    same(r, cli)
    assert [w["kind"] for w in r["warnings"]] == [w["kind"] for w in cli["warnings"]]
    t = r["transport"]
    assert "linear solve on the converged contact set" in t["stiffness_method"]
    low, _, sealed = t["points"]
    # h_c = 2 κ_s K/E* with κ_s = 25 (Barber), on the BEM's K∞.
    c = low["conductance"]
    assert c["bem_thermal_conductance"] == pytest.approx(50.0 * c["bem_stiffness"], rel=1e-14)
    assert 0.1 < low["leakage"]["critical_junction_ratio"] < 10.0
    # A/A0 ≈ 0.98: no open path, Q = 0, said so.
    assert sealed["leakage"]["bem_leak_rate"] == 0.0
    assert "no open path" in sealed["leakage"]["note"]
    assert "critical_junction_ratio" not in sealed["leakage"]


def test_compare_without_transport_has_no_key():
    r = persson.compare(spectrum(), 1.0, [0.005], grid=32, levels=2)
    assert "transport" not in r


@pytest.mark.parametrize("kwargs, name", [
    (dict(leakage=True, viscosity=0.0, pressure_drop=1.0), "viscosity"),
    (dict(leakage=True, viscosity=-1e-3, pressure_drop=1.0), "viscosity"),
    (dict(leakage=True, viscosity=1e-3, pressure_drop=-1.0), "pressure_drop"),
    (dict(leakage=True, viscosity=1e-3, pressure_drop=1.0, percolation_threshold=1.5),
     "percolation_threshold"),
    (dict(leakage=True, pressure_drop=1.0), "viscosity"),
    (dict(viscosity=1e-3, pressure_drop=1.0), "leakage"),
    (dict(conductivity=0.0), "conductivity"),
    (dict(resistivity=[1e-7, -1e-7]), "resistivity"),
])
def test_compare_transport_bad_input_names_the_keyword(kwargs, name):
    with pytest.raises(ValueError, match=name):
        persson.compare(spectrum(), 1.0, [0.005], grid=32, levels=2, **kwargs)
