"""contact_patches and subsurface_stress (issue 27) against values computed
here: a field of known discs (exact count and areas, joined across the
periodic boundary), and the uniform stress under a uniform pressure."""

import math

import numpy as np
import pytest

import persson


def discs():
    n = 64
    i, j = np.meshgrid(np.arange(n), np.arange(n), indexing="ij")
    p = np.zeros((n, n))
    # A disc of radius 5 cells in the middle, and one cut by the boundary
    # (centre on the edge: one patch when periodic, two when free).
    p[(i - 32) ** 2 + (j - 32) ** 2 <= 25] = 1.0
    p[(i - 10) ** 2 + np.minimum(j, n - j) ** 2 <= 9] = 2.0
    return p, n


def test_discs_give_the_exact_count_and_areas():
    p, n = discs()
    size = 1.0
    cell = (size / n) ** 2
    mid = np.count_nonzero(p == 1.0)
    cut = np.count_nonzero(p == 2.0)
    r = persson.contact_patches(p, size)
    q = r["points"][0]
    assert q["patch_count"] == 2
    assert q["largest_patch_area"] == pytest.approx(max(mid, cut) * cell, rel=1e-14)
    assert q["mean_patch_area"] * 2 == pytest.approx((mid + cut) * cell, rel=1e-14)
    free = persson.contact_patches(p, size, boundary="free")["points"][0]
    assert free["patch_count"] == 3


def test_uniform_pressure_gives_the_uniform_stress():
    # σ_zz = −p, σ_xx = σ_yy = −ν p/(1 − ν) at every depth: σ_vM = p (1 − 2ν)/(1 − ν).
    nu = 0.3
    p = np.full((16, 16), 2.0)
    r = persson.subsurface_stress(p, 1.0, [0.1, 0.5], poisson=nu)
    expected = 2.0 * (1 - 2 * nu) / (1 - nu)
    for m in r["von_mises_stress"]:
        assert m.shape == (16, 16)
        assert np.allclose(m, expected, rtol=1e-12, atol=0)
    with pytest.raises(ValueError, match="depth"):
        persson.subsurface_stress(p, 1.0, [0.0])
    with pytest.raises(ValueError, match="depth"):
        persson.subsurface_stress(p, 1.0, [2.0])
