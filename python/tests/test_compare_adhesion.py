"""`persson.compare(..., work_of_adhesion=...)` against
`persson compare --work-of-adhesion --json`: the same `adhesion` dict (issue 24)."""

import pytest

import persson
from conftest import run_cli, same
from test_bem import SPEC, spectrum


def test_compare_adhesion_matches_cli():
    cli = run_cli("compare", *SPEC, "--contact-modulus", 1, "--grid", 32, "--levels", 2,
                  "--pressure", "0.002,0.01", "--work-of-adhesion", "1e-4,3e-4",
                  "--adhesion", "exponential")
    r = persson.compare(spectrum(), 1.0, [0.002, 0.01], grid=32, levels=2,
                        work_of_adhesion=[1e-4, 3e-4], adhesion="exponential")
    same(r, cli)
    a = r["adhesion"]
    assert a["adhesion"] == "exponential"
    assert [w["work_of_adhesion"] for w in a["per_work"]] == [1e-4, 3e-4]
    for w in a["per_work"]:
        assert w["bem_pull_off_stress"] > 0.0


def test_compare_adhesion_bad_input_names_the_keyword():
    with pytest.raises(ValueError, match="work_of_adhesion"):
        persson.compare(spectrum(), 1.0, [0.002], grid=32, levels=2, work_of_adhesion=-1e-4)
    with pytest.raises(ValueError, match="adhesion_range"):
        persson.compare(spectrum(), 1.0, [0.002], grid=32, levels=2, adhesion_range=1e-3)
