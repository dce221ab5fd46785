"""`persson.surrogates`: the map against random surfaces of its spectrum,
equal to `persson surrogates --json` on the same map, and on a two-worker
Dask LocalCluster equal to the serial run to the last digit."""

import math

import pytest

import persson
from conftest import run_cli, same

TAU = 2 * math.pi
PRESSURES = [0.002, 0.005, 0.01]
N = 32


def spectrum():
    return persson.Spectrum.self_affine(0.8, TAU, N / 2 * TAU, q_r=4 * TAU, rms_slope=0.1)


def test_serial_matches_cli():
    cli = run_cli("surrogates", "--hurst", 0.8, "--q-l", TAU, "--q-r", 4 * TAU,
                  "--q-s", N / 2 * TAU, "--rms-slope", 0.1, "--contact-modulus", 1,
                  "--pressure", ",".join(map(repr, PRESSURES)), "--grid", N, "--map-seed", 3,
                  "--count", 4)
    heights = persson.synthesize(spectrum(), N, seed=3)
    r = persson.surrogates(heights, 1.0, 1.0, PRESSURES, count=4, spectrum=spectrum())
    same(r, cli, drop=("seconds", "map"))
    assert r["count"] == 4 and len(r["points"]) == 3
    assert all(p["theory_contact_fraction"] > 0 for p in r["points"])


def test_amplitude_adjusted_keeps_the_heights():
    heights = persson.synthesize(spectrum(), N, seed=3)
    cut = sorted(heights.ravel())[int(0.9 * N * N)]
    plateau = heights.clip(max=cut)
    r = persson.surrogates(plateau, 1.0, 1.0, PRESSURES, count=2, kind="amplitude-adjusted")
    assert r["surrogate_heights"]["skewness"] == pytest.approx(r["map_heights"]["skewness"], abs=1e-12)
    assert r["spectrum_mismatch"] < 0.01


def test_two_worker_local_cluster_equals_serial_run():
    distributed = pytest.importorskip("dask.distributed")
    heights = persson.synthesize(spectrum(), N, seed=3)
    serial = persson.surrogates(heights, 1.0, 1.0, PRESSURES, count=4)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster:
        with distributed.Client(cluster) as client:
            r = persson.surrogates(heights, 1.0, 1.0, PRESSURES, count=4, client=client)
    same(r, serial)


def test_bad_input_is_named():
    heights = persson.synthesize(spectrum(), N, seed=3)
    with pytest.raises(ValueError, match="count"):
        persson.surrogates(heights, 1.0, 1.0, PRESSURES, count=1)
    with pytest.raises(ValueError, match="kind"):
        persson.surrogates(heights, 1.0, 1.0, PRESSURES, kind="shuffle")
    with pytest.raises(ValueError, match="heights"):
        persson.surrogates(heights[:, :16], 1.0, 1.0, PRESSURES)
    with pytest.raises(ValueError, match="heights"):
        persson.surrogates(heights * 0.0, 1.0, 1.0, PRESSURES)
