"""persson.anisotropy and persson.spectrum_2d: the CLI's `persson anisotropy`
for an array, the same keys and numbers as its --json."""

import math

import numpy as np
import pytest

import persson
from conftest import ROOT, run_cli, same

MAP = ROOT / "docs" / "data" / "stretched.npy"  # 128², γ = 3, lay 30°, periodic
SIZE = 1e-3


def heights():
    return np.load(MAP)


def test_anisotropy_is_the_cli_json():
    py = persson.anisotropy(heights(), SIZE, periodic=True)
    cli = run_cli("anisotropy", "--surface", MAP, "--size", SIZE, "--periodic")
    assert set(py) == {
        "peklenik_number",
        "principal_direction",
        "texture_aspect_ratio",
        "autocorrelation_length",
        "texture_direction",
        "warnings",
    }
    same(py, cli)
    # The map was synthesised with γ = 3 along 30° (one map: ±3 %, ±1.5°).
    assert abs(py["peklenik_number"] / 3 - 1) < 0.03
    assert abs(py["principal_direction"] - 30) < 1.5


def test_conditioning_flags_reach_the_cli_too():
    py = persson.anisotropy(heights(), SIZE, detrend="plane", window="hann")
    cli = run_cli("anisotropy", "--surface", MAP, "--size", SIZE, "--detrend", "plane", "--window", "hann")
    same(py, cli)


def test_spectrum_2d_parseval_and_the_cli_npy(tmp_path):
    h = heights()
    qx, qy, c = persson.spectrum_2d(h, SIZE, periodic=True)
    ny, nx = h.shape
    assert c.shape == (ny, nx) and qx.shape == (nx,) and qy.shape == (ny,)
    dq = 2 * math.pi / SIZE
    # numpy's fftshift order, q = 0 at index n/2.
    np.testing.assert_allclose(qx, np.fft.fftshift(np.fft.fftfreq(nx, SIZE / nx)) * 2 * math.pi, rtol=1e-14, atol=1e-9 * dq)
    assert qx[nx // 2] == 0 and qy[ny // 2] == 0
    # Persson's normalisation: Σ C Δq_x Δq_y = ⟨h²⟩ (periodic: no window, mean removed).
    hm = h - h.mean()
    assert abs(c.sum() * dq * dq / np.mean(hm**2) - 1) < 1e-12
    # The CLI's --spectrum-2d .npy holds the same numbers.
    out = tmp_path / "c.npy"
    run_cli("anisotropy", "--surface", MAP, "--size", SIZE, "--periodic", "--spectrum-2d", out)
    np.testing.assert_array_equal(np.load(out), c)


def test_transposed_map_mirrors_the_lay():
    # Swapping x and y maps the direction θ to 90° − θ, the Peklenik number unchanged.
    a = persson.anisotropy(heights(), SIZE, periodic=True)
    b = persson.anisotropy(np.ascontiguousarray(heights().T), SIZE, periodic=True)
    assert abs(a["peklenik_number"] / b["peklenik_number"] - 1) < 1e-10
    d = (a["principal_direction"] + b["principal_direction"] - 90.0) % 180.0
    assert min(d, 180.0 - d) < 1e-6


@pytest.mark.parametrize(
    "args, word",
    [
        ((np.zeros(64), SIZE), "2-D"),
        ((np.zeros((16, 16)), -1.0), "size"),
        ((np.zeros((16, 16)), (1.0, 2.0, 3.0)), "size"),
    ],
)
def test_bad_input_names_the_argument(args, word):
    with pytest.raises(ValueError, match=word):
        persson.anisotropy(*args)
    with pytest.raises(ValueError, match=word):
        persson.spectrum_2d(*args)


def test_a_stretched_spectrum_synthesises_an_anisotropic_surface():
    # A stretched spectrum reaches Python through a scene's spectrum entry
    # (here its pickled form); its surfaces are anisotropic (the Python
    # spectrum forwards the plane to the synthesis: it used not to).
    import json

    spec = {
        "kind": "stretched",
        "spectrum": {"kind": "self_affine", "hurst": 0.8, "q_l": 2 * math.pi, "q_r": 32 * math.pi,
                     "q_s": 120 * math.pi, "rms_slope": 0.1},
        "anisotropy": 2.0,
        "lay_angle": 30.0,
    }
    s = persson.Spectrum._restore("self_affine", json.dumps(spec), None)
    h = persson.synthesize(s, 256, size=1.0, seed=3)
    a = persson.anisotropy(h, 1.0, periodic=True)
    # One 256² map: the Peklenik number within 3 %, the lay within 1.5°
    # (tests/anisotropy.rs measured the scatter of such maps).
    assert abs(a["peklenik_number"] / 2 - 1) < 0.03, a
    assert abs(a["principal_direction"] - 30) < 1.5, a
