"""The asperity theories of `area(theory=...)` (issue 27), against closed
forms written out here: Nayak's and McCool's summit statistics from the
moments, and Greenwood & Williamson's F_0, F_1 by math.erfc."""

import math

import pytest

import persson

S = persson.Spectrum.self_affine(0.8, 1e4, 1e6, rms_height=1e-6)
E_STAR = 1e9

# erfc here against the crate's trapezoidal F_n (tested to 1e-13 against
# mpmath); the separation is solved to 1e-14 of σ_s.
GW_TOL = 1e-11


def f0(t):
    return 0.5 * math.erfc(t / math.sqrt(2))


def f1(t):
    return math.exp(-0.5 * t * t) / math.sqrt(2 * math.pi) - t * f0(t)


def test_greenwood_williamson_against_closed_forms():
    r = persson.area(S, E_STAR, [1e5, 1e6], "greenwood-williamson")
    m0, m2, m4 = r["m0"], r["m2"], r["m4"]
    alpha = m0 * m4 / m2**2
    assert r["bandwidth_parameter"] == pytest.approx(alpha, rel=1e-12)
    eta = m4 / (6 * math.pi * math.sqrt(3) * m2)
    kappa = 8 / 3 * math.sqrt(m4 / math.pi)
    y_s = 4 * m2 / math.sqrt(math.pi * m4)
    s_s = math.sqrt(m0 * (1 - (1 + 16 / math.pi - 3 * math.sqrt(3)) / alpha))
    assert r["summit_density"] == pytest.approx(eta, rel=1e-12)
    assert r["summit_curvature"] == pytest.approx(kappa, rel=1e-12)
    for p in r["points"]:
        t = (p["separation"] - y_s) / s_s
        assert p["contact_fraction"] == pytest.approx(math.pi * eta / kappa * s_s * f1(t), rel=GW_TOL)
        assert p["contact_number_density"] == pytest.approx(eta * f0(t), rel=GW_TOL)
        # Persson's A/A0 at the same load, beside it.
        assert 0 < p["contact_fraction_original"] < 1


def test_overlap_is_the_hardness_law():
    r = persson.area(S, E_STAR, [2e6], "overlap", yield_stress=1e7)
    p = r["points"][0]
    assert p["contact_fraction"] == pytest.approx(0.2, rel=1e-14)
    # Gaussian heights: the cut is where erfc gives 0.2.
    t = p["separation"] / r["rms_height"]
    assert f0(t) == pytest.approx(0.2, rel=1e-10)


def test_bush_slope_and_bad_input():
    r = persson.area(S, E_STAR, [1e6], "bush")
    assert r["kappa"] == pytest.approx(math.sqrt(2 * math.pi), rel=1e-12)
    with pytest.raises(ValueError, match="yield_stress"):
        persson.area(S, E_STAR, [1e6], "overlap")
    with pytest.raises(ValueError, match="yield_stress"):
        persson.area(S, E_STAR, [1e6], "bush", yield_stress=1e7)
