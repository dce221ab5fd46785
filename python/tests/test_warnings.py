"""Warnings (issue 15) from Python: the dict carries the CLI's top-level
`warnings` list (each a dict with its `kind`, its fields and its `message`,
which names the input, never a command-line flag), and each message is raised
as a `UserWarning`; the numbers are those of the CLI's --json either way."""

import numpy as np
import pytest

import persson
from conftest import run_cli, same

TAU = 2 * np.pi


def test_pressure_near_the_modulus_warns_as_the_cli():
    # E* = 1e7 Pa and σ0 = 3e6 Pa: σ0 = 0.3 E*, as with E typed in MPa.
    cli = run_cli("area", "--hurst", 0.8, "--q-l", 1e4, "--q-s", 1e8, "--rms-height", 1e-6,
                  "--contact-modulus", 1e7, "--pressure", 3e6)
    assert len(cli["warnings"]) == 1 and "0.1 E*" in cli["warnings"][0]["message"]
    assert cli["warnings"][0]["kind"] == "high_pressure"
    assert cli["warnings"][0]["nominal_pressure"] == 3e6
    s = persson.Spectrum.self_affine(0.8, 1e4, 1e8, rms_height=1e-6)
    with pytest.warns(UserWarning) as caught:
        r = persson.area(s, 1e7, [3e6])
    assert [str(w.message) for w in caught] == [w["message"] for w in cli["warnings"]]
    assert r["warnings"] == cli["warnings"]
    same(r, cli)


def test_steep_slope_and_file_convention_warn_as_the_cli(tmp_path):
    q = np.geomspace(1e3, 1e6, 30)
    path = tmp_path / "psd.csv"
    # C(q) ∝ q^-3.6 with an rms slope far above 1.
    np.savetxt(path, np.column_stack([q, 1e-11 * (q / 1e3) ** -3.6]), delimiter=",")
    cli = run_cli("area", "--psd", path, "--psd-convention", "surface-topography",
                  "--contact-modulus", 1e9, "--pressure", 1e6)
    assert any(w["kind"] == "psd_convention" and w["convention"] == "surface-topography"
               for w in cli["warnings"])
    assert any("rms slope" in w["message"] for w in cli["warnings"])
    # Independent of the CLI: the warned slope is the closed form of the
    # power law the file samples, h'² = 2π ∫ q³ C dq with Persson's
    # C = 1e-11/(2π)² (q/1e3)^-3.6 (SurfaceTopography's C is (2π)² times his).
    c0 = 1e-11 / (2 * np.pi) ** 2
    slope2 = 2 * np.pi * c0 * 1e3 ** 3.6 * (1e6 ** 0.4 - 1e3 ** 0.4) / 0.4
    steep = [w for w in cli["warnings"] if w["kind"] == "steep_slope"]
    assert steep[0]["rms_slope"] == pytest.approx(np.sqrt(slope2), rel=1e-10)
    assert not any("--" in w["message"] for w in cli["warnings"])
    s = persson.Spectrum.from_csv(path, "surface-topography")
    with pytest.warns(UserWarning):
        r = persson.area(s, 1e9, [1e6])
    assert r["warnings"] == cli["warnings"]
    same(r, cli)


def test_no_warning_gives_an_empty_list():
    s = persson.Spectrum.self_affine(0.8, TAU, 16 * TAU, q_r=2 * TAU, rms_slope=0.1)
    r = persson.area(s, 1.0, [0.01])
    assert r["warnings"] == []


def test_band_limited_bem_surface_warns_as_the_cli():
    cli = run_cli("bem", "rough", "--example", "--grid", 32)
    assert any(w["kind"] == "band_limited" and w["grid"] == 32 and "rms slope" in w["message"]
               for w in cli["warnings"])
    s = persson.Spectrum.example()
    p = [x["nominal_pressure"] for x in cli["points"]]
    with pytest.warns(UserWarning):
        r = persson.bem_rough(cli["contact_modulus"], p, spectrum=s, grid=32, seed=cli["surface"]["seed"])
    assert r["warnings"] == cli["warnings"]
    same(r, cli)


def test_yield_stress_compare_and_plastic_disc_match_cli():
    spec = ["--hurst", 0.8, "--q-l", TAU, "--q-r", 2 * TAU, "--q-s", 16 * TAU,
            "--rms-slope", 0.1]
    s = persson.Spectrum.self_affine(0.8, TAU, 16 * TAU, q_r=2 * TAU, rms_slope=0.1)
    cli = run_cli("compare", *spec, "--contact-modulus", 1, "--grid", 32, "--levels", 2,
                  "--pressure", "0.002,0.005", "--yield-stress", 0.05)
    r = persson.compare(s, 1.0, [0.002, 0.005], grid=32, levels=2, yield_stress=0.05)
    same(r, cli)
    assert r["yield_stress"] == 0.05
    cli = run_cli("bem", "hertz", "--grid", "16,32", "--yield-stress", 0.05)
    same(persson.bem_hertz(grids=[16, 32], yield_stress=0.05), cli)
    # Several grids without a yield stress: η per grid, as the CLI and a
    # scene's bem_hertz give it; grid and grids together are refused.
    cli = run_cli("bem", "hertz", "--grid", "16,32")
    r = persson.bem_hertz(grids=[16, 32])
    same(r, cli)
    assert [row["grid"] for row in r["rows"]] == [16, 32]
    with pytest.raises(ValueError, match="grids"):
        persson.bem_hertz(grid=16, grids=[16, 32])
