"""Two rough bodies (Spectrum.sum) and one spectrum from several
measurements (Spectrum.combine), checked against independent values."""

import math
import pickle

import numpy as np
import pytest

import persson

# Closed-form moments against the library's exact ones.
CLOSED_FORM = 1e-12
# A mode-weighted mean of identical spectra is that spectrum: rounding only.
IDENTITY = 1e-12


def variance(c_r, hurst, q_l, q_s):
    """<h²> = 2π ∫ q C dq of C = C_r (q/q_l)^(-2(1+H)) on [q_l, q_s]."""
    return 2 * math.pi * c_r * q_l**2 * (1 - (q_s / q_l) ** (-2 * hurst)) / (2 * hurst)


def test_sum_of_two_bodies_adds_variances():
    a = persson.Spectrum.self_affine(0.8, 1e4, 1e6, c_r=1e-26)
    b = persson.Spectrum.self_affine(0.5, 1e5, 1e8, c_r=3e-28)
    s = persson.Spectrum.sum([a, b])
    expected = variance(1e-26, 0.8, 1e4, 1e6) + variance(3e-28, 0.5, 1e5, 1e8)
    assert s.rms_height() ** 2 == pytest.approx(expected, rel=CLOSED_FORM)
    assert (s.q_l, s.q_s) == (1e4, 1e8)
    # the bands differ by a factor 100: warned of
    kinds = [w["kind"] for w in s.report()["warnings"]]
    assert "sum_bands" in kinds
    # pickling rebuilds the same sum
    t = pickle.loads(pickle.dumps(s))
    assert t.c(5e5) == s.c(5e5)


def test_combine_identical_measurements_is_the_measurement(tmp_path):
    rng = np.random.default_rng(5)
    h = np.cumsum(np.cumsum(rng.standard_normal((64, 64)), axis=0), axis=1) * 1e-9
    path = tmp_path / "map.npy"
    np.save(path, h)
    one = persson.Spectrum.from_file(path, pixel_size=1e-6)
    two = persson.Spectrum.combine([path, path], pixel_sizes=[1e-6, 1e-6])
    # the combination keeps reliable whole bins only: its band starts at 8
    # modes (the Hann window's main lobe below) and ends at the last bin
    # edge below Nyquist, inside the single measurement's
    assert two.q_l > 8 * 2 * math.pi / 64e-6 and two.q_s < one.q_s
    q = np.geomspace(two.q_l * 1.01, two.q_s * 0.99, 7)
    assert np.allclose(two.c(q), one.c(q), rtol=IDENTITY, atol=0)


def test_combine_needs_one_value_per_path(tmp_path):
    with pytest.raises(ValueError, match="one per path"):
        persson.Spectrum.combine([tmp_path / "a.npy", tmp_path / "b.npy"], pixel_sizes=[1e-6])


def test_a_dataset_export_is_one_surface_and_channel_reads_one_measurement():
    """contact.engineering's export of three measurements of one surface:
    the combined spectrum spans them all; `channel` reads one of them."""
    import pathlib

    archive = pathlib.Path(__file__).resolve().parents[2] / "tests" / "data" / "container-2.zip"
    whole = persson.Spectrum.from_file(archive)
    afm = persson.Spectrum.from_file(archive, channel="gain_control_uncd_35.001")
    stylus = persson.Spectrum.from_file(archive, channel="2")
    # the stylus scan (0.3 mm) reaches lowest, the AFM map (100 nm) highest
    # (each on its own bins: the first bins differ by less than one bin, 26 %)
    assert whole.q_l == pytest.approx(stylus.q_l, rel=0.26)
    assert stylus.q_s < afm.q_s and afm.q_l > stylus.q_l
    assert whole.q_s < afm.q_s
    with pytest.raises(ValueError, match='no measurement "AFM"'):
        persson.Spectrum.from_file(archive, channel="AFM")
