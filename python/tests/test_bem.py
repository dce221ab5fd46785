"""The BEM, synthesis and compare against `persson bem … --json` and
`persson compare --json`; arrays out of the solver checked against the
CLI's .npy files, value for value."""

import threading
import time

import numpy as np
import pytest

import persson
from conftest import run_cli, same

TAU = 2 * np.pi
# A periodic surface of side L = 1: q_l = 2π, roll-off 2·q_l, q_s = 16·q_l.
SPEC = ["--hurst", 0.8, "--q-l", TAU, "--q-r", 2 * TAU, "--q-s", 16 * TAU, "--rms-slope", 0.1]


def spectrum():
    return persson.Spectrum.self_affine(0.8, TAU, 16 * TAU, q_r=2 * TAU, rms_slope=0.1)


def test_synthesize_and_rough_match_cli(tmp_path):
    out = tmp_path / "surface.npy"
    cli = run_cli("bem", "rough", *SPEC, "--contact-modulus", 1, "--grid", 32, "--seed", 3,
                  "--pressure", "0.005,0.02", "--surface-out", out)
    h = persson.synthesize(spectrum(), 32, seed=3)
    assert h.shape == (32, 32) and h.dtype == np.float64 and h.flags["C_CONTIGUOUS"]
    assert np.array_equal(h, np.load(out))
    same(persson.bem_rough(1.0, [0.005, 0.02], spectrum=spectrum(), grid=32, seed=3), cli)


def test_rough_on_heights_with_yield_stress_matches_cli(tmp_path):
    h = persson.synthesize(spectrum(), 32, seed=4)
    path = tmp_path / "h.npy"
    np.save(path, h)
    cli = run_cli("bem", "rough", "--surface", path, "--size", 1, "--contact-modulus", 1,
                  "--pressure", "0.01,0.03", "--yield-stress", 0.2, "--boundary", "free")
    r = persson.bem_rough(1.0, [0.01, 0.03], heights=h, size=1.0, yield_stress=0.2,
                          boundary="free", bins=None)
    same(r, cli, drop=("seconds", "surface"))
    assert r["surface"] == {"file": "(array)"}


def test_solve_pressure_and_gap_match_cli(tmp_path):
    h = persson.synthesize(spectrum(), 32, seed=2)
    path = tmp_path / "h.npy"
    field = tmp_path / "p.npy"
    np.save(path, h)
    cli = run_cli("bem", "rough", "--surface", path, "--size", 1, "--contact-modulus", 1,
                  "--pressure", 0.02, "--pressure-field", field)
    p, gap, summary = persson.bem_solve(h, 1.0, 1.0, pressure=0.02)
    assert p.shape == gap.shape == (32, 32)
    assert np.array_equal(p, np.load(field))
    point = cli["points"][0]
    for key in ["contact_fraction", "mean_separation", "approach", "iterations", "residual"]:
        assert summary[key] == point[key], key
    # The arrays are the solver's own buffers handed over, not copies: numpy
    # does not own their memory, the Rust vector behind `base` does.
    for a in (p, gap):
        assert a.flags["WRITEABLE"] and a.flags["C_CONTIGUOUS"] and a.dtype == np.float64
        assert not a.flags["OWNDATA"] and a.base is not None
    # The mean pressure is the load asked for; the gap is ≥ 0, and 0 in
    # contact to the solver's tolerance (1e-10 relative to the heights).
    assert abs(p.mean() - 0.02) < 1e-12
    assert gap.min() >= 0 and gap[p > 0].max() < 1e-9 * np.ptp(h)
    # Penetration control: the approach of that solve gives back its load.
    p2, _, s2 = persson.bem_solve(h, 1.0, 1.0, approach=summary["approach"])
    assert abs(s2["nominal_pressure"] - 0.02) < 1e-6 * 0.02


def test_hertz_matches_cli():
    cli = run_cli("bem", "hertz", "--grid", 32)
    same(persson.bem_hertz(grid=32), cli)
    cli = run_cli("bem", "hertz", "--grid", 32, "--boundary", "periodic", "--size", 2,
                  "--radius", 3, "--contact-modulus", 5, "--contact-radius", 0.3)
    r = persson.bem_hertz(grid=32, boundary="periodic", size=2.0, radius=3.0,
                          contact_modulus=5.0, contact_radius=0.3)
    same(r, cli)
    # Independent of the CLI: Hertz's closed form for the contact radius
    # a = 0.3 asked for, p0 = 2 E* a / (π R) (Johnson, Contact Mechanics,
    # Eq. 4.24), to rounding.
    assert r["hertz_contact_radius"] == 0.3
    assert r["hertz_peak_pressure"] == pytest.approx(2 * 5.0 * 0.3 / (np.pi * 3.0), rel=1e-14)


def test_compare_matches_cli():
    cli = run_cli("compare", *SPEC, "--contact-modulus", 1, "--grid", 64, "--levels", 3,
                  "--pressure", "0.002,0.005,0.01")
    r = persson.compare(spectrum(), 1.0, [0.002, 0.005, 0.01], grid=64, levels=3)
    same(r, cli)
    # The contact patches per grid and σ0 (issue 27): the largest patch's
    # share of the contact area is a fraction, the counts are whole solves'.
    per_grid = r["patches"]["per_grid"]
    assert [g["grid"] for g in per_grid] == [16, 32, 64]
    for g in per_grid:
        assert set(g) == {"grid", "patch_count", "largest_patch_share", "patch_area_exponent"}
        assert all(0 < s <= 1 for s in g["largest_patch_share"])
        assert all(c >= 1 and c == int(c) for c in g["patch_count"])


@pytest.mark.parametrize("periodic", [True, False])
def test_compare_on_a_map_matches_cli(tmp_path, periodic):
    h = persson.synthesize(spectrum(), 64, seed=6)
    path = tmp_path / "h.npy"
    np.save(path, h)
    flag = ["--periodic"] if periodic else []
    cli = run_cli("compare", "--surface", path, "--size", 1, *flag, "--contact-modulus", 1,
                  "--levels", 3, "--pressure", "0.005,0.01")
    s = persson.Spectrum.from_file(path, size=[1.0], periodic=periodic)
    r = persson.compare(s, 1.0, [0.005, 0.01], heights=h, size=1.0, periodic=periodic, levels=3)
    same(r, cli)
    s = persson.Spectrum.from_height_map(h, 1.0 / 64, periodic=periodic)
    r = persson.compare(s, 1.0, [0.005, 0.01], heights=h, size=1.0, periodic=periodic, levels=3)
    same(r, cli, drop=("seconds", "surface"))


def test_compare_refuses_what_it_would_ignore():
    """As the command line: `grid`/`seed`/`seeds` are for a synthesised
    surface, `periodic` for a height map, `outlet_pressure` for the leakage
    comparison; given where they do nothing, they are refused, named."""
    h = persson.synthesize(spectrum(), 32, seed=6)
    s = persson.Spectrum.from_height_map(h, 1.0 / 32)
    for bad in [dict(grid=64), dict(seed=2), dict(seeds=2)]:
        with pytest.raises(ValueError, match="grid, seed, seeds"):
            persson.compare(s, 1.0, [0.01], heights=h, size=1.0, **bad)
    with pytest.raises(ValueError, match="periodic"):
        persson.compare(spectrum(), 1.0, [0.01], grid=32, levels=2, periodic=True)
    with pytest.raises(ValueError, match="outlet_pressure"):
        persson.compare(spectrum(), 1.0, [0.01], grid=32, levels=2, outlet_pressure=1e5)


def test_adhesive_path_is_checked_before_any_solve():
    """Every mean gap is checked first, named by its index, as the command
    line and the scene do (`PathControl::new`)."""
    with pytest.raises(ValueError, match=r"mean_gap\[1\]"):
        persson.bem_rough(1.0, spectrum=spectrum(), grid=32, work_of_adhesion=2e-4,
                          adhesion_range=0.05, mean_gap=[4e-3, -1e-3])
    with pytest.raises(ValueError, match="mean_gap and approach"):
        persson.bem_rough(1.0, spectrum=spectrum(), grid=32, work_of_adhesion=2e-4,
                          adhesion_range=0.05, mean_gap=[4e-3], approach=[1e-3])


def test_scene_with_bem_matches_cli(tmp_path):
    import pathlib
    path = pathlib.Path(__file__).resolve().parents[2] / "scenes" / "bem_rough.json"
    same(persson.run_scene(path), run_cli("run", path, cwd=tmp_path))


def test_solve_releases_the_interpreter():
    """Another Python thread runs while a solve is under way."""
    h = persson.synthesize(spectrum(), 256, seed=1)
    ticks = []
    done = threading.Event()

    def tick():
        while not done.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.001)

    t = threading.Thread(target=tick)
    t.start()
    start = time.perf_counter()
    _, _, summary = persson.bem_solve(h, 1.0, 1.0, pressure=0.01, tolerance=1e-12)
    end = time.perf_counter()
    done.set()
    t.join()
    inside = [x for x in ticks if start < x < end]
    assert end - start > 0.02, "solve too short to tell"
    assert len(inside) >= 5, (len(inside), end - start)


def test_adhesive_rough_matches_cli():
    """`bem_rough(work_of_adhesion=…)` is `persson bem rough --work-of-adhesion --json`,
    warnings included (the range here is below the grid spacing 1/32)."""
    args = dict(work_of_adhesion=2e-5, adhesion_range=1e-2, adhesion="exponential",
                mean_gap=[4e-3, 2e-3, 8e-3])
    cli = run_cli("bem", "rough", *SPEC, "--contact-modulus", 1, "--grid", 32, "--seed", 3,
                  "--work-of-adhesion", 2e-5, "--adhesion-range", 1e-2, "--adhesion",
                  "exponential", "--mean-gap", "4e-3,2e-3,8e-3")
    with pytest.warns(UserWarning, match="cohesive zone is not resolved"):
        r = persson.bem_rough(1.0, spectrum=spectrum(), grid=32, seed=3, **args)
    same(r, cli)
    assert [w["kind"] for w in r["warnings"]] == ["cohesive_zone_unresolved"]
    assert r["pull_off_stress"] == -min(0.0, *(p["nominal_pressure"] for p in r["points"]))
    with pytest.raises(ValueError, match="mean_gap"):
        persson.bem_rough(1.0, spectrum=spectrum(), grid=32, work_of_adhesion=1e-5,
                          adhesion_range=1e-2)


def test_adhesive_iteration_matches_cli():
    """`bem_rough(adhesive_iteration="preconditioned")` is `--adhesive-iteration
    preconditioned`; another name is refused, naming the argument."""
    cli = run_cli("bem", "rough", *SPEC, "--contact-modulus", 1, "--grid", 32, "--seed", 3,
                  "--work-of-adhesion", 2e-4, "--adhesion-range", 0.05,
                  "--mean-gap", "4e-3,8e-3", "--adhesive-iteration", "preconditioned")
    r = persson.bem_rough(1.0, spectrum=spectrum(), grid=32, seed=3, work_of_adhesion=2e-4,
                          adhesion_range=0.05, mean_gap=[4e-3, 8e-3],
                          adhesive_iteration="preconditioned")
    same(r, cli)
    with pytest.raises(ValueError, match="adhesive_iteration"):
        persson.bem_rough(1.0, spectrum=spectrum(), grid=32, work_of_adhesion=2e-4,
                          adhesion_range=0.05, mean_gap=[4e-3], adhesive_iteration="fast")


def test_adhesive_free_boundary_matches_cli():
    """`bem_rough(boundary="free", approach=[…])` is `bem rough --boundary free --approach`;
    mean_gap on the free boundary is refused, naming it."""
    cli = run_cli("bem", "rough", *SPEC, "--contact-modulus", 1, "--grid", 32, "--seed", 3,
                  "--boundary", "free", "--work-of-adhesion", 2e-4, "--adhesion-range",
                  0.05, "--approach", "1e-2,0,-1e-2")
    r = persson.bem_rough(1.0, spectrum=spectrum(), grid=32, seed=3, boundary="free",
                          work_of_adhesion=2e-4, adhesion_range=0.05,
                          approach=[1e-2, 0.0, -1e-2])
    same(r, cli)
    assert r["boundary"] == "free"
    assert [p["approach"] for p in r["points"]] == [1e-2, 0.0, -1e-2]
    with pytest.raises(ValueError, match="mean_gap"):
        persson.bem_rough(1.0, spectrum=spectrum(), grid=32, boundary="free",
                          work_of_adhesion=2e-4, adhesion_range=0.05, mean_gap=[1e-2])


def test_adhesive_sphere_matches_cli():
    """`bem_hertz(work_of_adhesion=…)` is `persson bem hertz --work-of-adhesion --json`."""
    cli = run_cli("bem", "hertz", "--grid", "16,32", "--boundary", "periodic",
                  "--work-of-adhesion", 1e-4, "--adhesion-range", 0.05)
    r = persson.bem_hertz(grids=[16, 32], boundary="periodic", work_of_adhesion=1e-4,
                          adhesion_range=0.05)
    same(r, cli)
    assert 1.5 < r["per_grid"][-1]["reduced_pull_off_force"] < 2.0
