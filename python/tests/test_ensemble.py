"""`persson.ensemble`: on a two-worker Dask LocalCluster equal to the serial
run to the last digit, equal to `persson compare ensemble --json`, with the
statistics the textbook mean and standard error (statistics module) of the
jobs' numbers, and an unreachable scheduler a clear error naming it."""

import math
import statistics

import pytest

import persson
from conftest import run_cli, same

TAU = 2 * math.pi
PRESSURES = [0.02, 0.005, 0.01]
SETTINGS = dict(grid=32, levels=2, seeds=3, seed=5)
# Relative rounding of a mean or standard error of 3 values summed in
# another order (statistics' exact fractions against a plain two-pass sum).
STATISTICS_ROUNDING = 1e-14


def spectrum():
    return persson.Spectrum.self_affine(0.8, TAU, 8 * TAU, q_r=2 * TAU, rms_slope=0.1)


def test_serial_matches_cli_and_threads():
    cli = run_cli("compare", "ensemble", "--hurst", 0.8, "--q-l", TAU, "--q-r", 2 * TAU,
                  "--q-s", 8 * TAU, "--rms-slope", 0.1, "--contact-modulus", 1,
                  "--pressure", ",".join(map(repr, PRESSURES)), "--grid", 32, "--levels", 2,
                  "--seeds", 3, "--seed", 5, "--threads", 2)
    serial = persson.ensemble(spectrum(), 1.0, PRESSURES, **SETTINGS)
    same(serial, cli)
    same(persson.ensemble(spectrum(), 1.0, PRESSURES, threads=2, **SETTINGS), serial)
    assert [g["grid"] for g in serial["grids"]] == [16, 32]
    assert [(s["grid"], s["seed"]) for s in serial["solves"]] == [
        (16, 5), (16, 6), (16, 7), (32, 5), (32, 6), (32, 7)]


def test_statistics_are_the_sample_mean_and_standard_error():
    r = persson.ensemble(spectrum(), 1.0, PRESSURES, **SETTINGS)
    for g in r["grids"]:
        runs = [s for s in r["solves"] if s["grid"] == g["grid"]]
        for key in ["contact_fraction", "mean_separation"]:
            for k in range(len(PRESSURES)):
                x = [s[key][k] for s in runs]
                mean = statistics.fmean(x)
                se = statistics.stdev(x) / math.sqrt(len(x))
                assert g[key][k] == pytest.approx(mean, rel=STATISTICS_ROUNDING, abs=0)
                assert g[key + "_standard_error"][k] == pytest.approx(
                    se, rel=STATISTICS_ROUNDING, abs=0)
                assert se > 0


def test_two_worker_local_cluster_equals_serial_run():
    distributed = pytest.importorskip("dask.distributed")
    serial = persson.ensemble(spectrum(), 1.0, PRESSURES, **SETTINGS)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster:
        with distributed.Client(cluster) as client:
            r = persson.ensemble(spectrum(), 1.0, PRESSURES, client=client, **SETTINGS)
            # Both workers took jobs: the study ran distributed.
            assert len(client.scheduler_info()["workers"]) == 2
        # The scheduler's address works as well as a Client.
        by_address = persson.ensemble(spectrum(), 1.0, PRESSURES, client=cluster.scheduler_address,
                                      **SETTINGS)
    same(r, serial)
    same(by_address, serial)


def test_unreachable_scheduler_is_a_clear_error():
    pytest.importorskip("dask.distributed")
    address = "tcp://127.0.0.1:9"
    with pytest.raises(ConnectionError, match="tcp://127.0.0.1:9"):
        persson.ensemble(spectrum(), 1.0, PRESSURES, client=address, timeout="1s", **SETTINGS)


def test_bad_input_fails_before_any_scheduler_is_contacted():
    with pytest.raises(ValueError, match="nominal_pressure"):
        persson.ensemble(spectrum(), 1.0, [-1.0], client="tcp://127.0.0.1:9", **SETTINGS)
    with pytest.raises(ValueError, match="seeds"):
        persson.ensemble(spectrum(), 1.0, PRESSURES, grid=32, seeds=0)
    # the last seed, seed + seeds − 1, must fit in 64 bits (as the CLI's --seed)
    with pytest.raises(ValueError, match="seed: at most 18446744073709551614 with 2 seeds"):
        persson.ensemble(spectrum(), 1.0, PRESSURES, grid=32, seeds=2, seed=2**64 - 1)
    with pytest.raises(ValueError, match="client"):
        persson.ensemble(spectrum(), 1.0, PRESSURES, client=42, **SETTINGS)
