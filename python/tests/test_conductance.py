"""`persson.conductance` and `persson.leakage` (issue 23): against closed forms
and identities computed by other functions of the package, and digit for
digit against `persson conductance --json` / `persson leakage --json`."""

import warnings

import numpy as np
import pytest

import persson
from conftest import run_cli, same

# A rubber seal on a self-affine surface (the shipped scene conductance.json).
Q_L = 6283.185307179586
SPECTRUM_FLAGS = ["--hurst", 0.8, "--q-l", Q_L, "--q-r", 4 * Q_L, "--q-s", 16 * Q_L,
                  "--rms-slope", 0.1]
E_STAR = 1e7
PRESSURES = [1e4, 3e4, 1e5, 2e5]

# Products of a few printed factors: a few ulps.
PRODUCT = 1e-14
# ∫ P_nc du against 1 − A/A0: the P(u) quadrature's normalisation, measured
# below 1e-9 at the default tolerances (the gap module's test asserts 1e-9).
NORMALISATION = 1e-8
# A/A0 at ζ_c against a_c: ζ_c is bracketed to the q-integrals' tolerance.
THRESHOLD = 1e-7


def spectrum():
    return persson.Spectrum.self_affine(0.8, Q_L, 16 * Q_L, q_r=4 * Q_L, rms_slope=0.1)


def test_thermal_and_electrical_are_barbers_identity_with_holms_series_conductivity():
    s = spectrum()
    k1, k2, r1, r2 = 0.2, 50.0, 0.1, 1.7e-8
    c = persson.conductance(s, E_STAR, PRESSURES, conductivity=(k1, k2), resistivity=(r1, r2))
    # K from the separation module (an independent call): Barber's identity
    # C = 2K/((ρ1 + ρ2)E*) and its thermal form with Holm's κ1κ2/(κ1 + κ2).
    k = persson.mean_separation(s, E_STAR, PRESSURES, tolerance=1e-9)["stiffness"]
    np.testing.assert_allclose(c["stiffness"], k, rtol=PRODUCT)
    kappa_s = k1 * k2 / (k1 + k2)
    np.testing.assert_allclose(c["thermal_conductance"], 2 * kappa_s * k / E_STAR, rtol=PRODUCT)
    np.testing.assert_allclose(
        c["electrical_conductance"], 2 * k / ((r1 + r2) * E_STAR), rtol=PRODUCT
    )
    assert np.all(c["thermal_conductance_error_bound"] > 0)
    # One value means both bodies.
    one = persson.conductance(s, E_STAR, PRESSURES, conductivity=50.0)
    np.testing.assert_allclose(one["thermal_conductance"], 50.0 * k / E_STAR, rtol=PRODUCT)


def test_a_constant_gap_law_gives_the_non_contact_fraction():
    # α(u) = c everywhere: h_gap = c ∫ P_nc du = c (1 − A/A0), with A/A0 of
    # the area theory (another code path than P(u)).
    s = spectrum()
    alpha = 1234.5
    c = persson.conductance(s, E_STAR, PRESSURES, gap_table=([0.0, 1.0], [alpha, alpha]))
    area = persson.contact_area(s, E_STAR, PRESSURES)
    np.testing.assert_allclose(c["gap_conductance"], alpha * (1 - area), rtol=NORMALISATION)


def test_critical_junction_sits_at_the_threshold_and_obeys_the_cube_law():
    s = spectrum()
    eta, dp, lx, ly = 1e-3, 1e5, 2e-3, 1e-2
    r = persson.leakage(s, E_STAR, [1e4, 3e4, 1e5], viscosity=eta, pressure_drop=dp,
                        seal_width=lx, seal_length=ly)
    assert r["leaking_critical_junction"].all()
    # A(ζ_c)/A0 = a_c, by the area theory at that magnification.
    for p, z in zip(r["nominal_pressure"], r["critical_zeta"]):
        a = persson.contact_area(s, E_STAR, p, zeta=z)
        assert a == pytest.approx(0.42, rel=THRESHOLD)
    u1 = r["critical_separation"]
    np.testing.assert_allclose(
        r["leak_rate_critical_junction"], ly / lx * u1**3 * dp / (12 * eta), rtol=PRODUCT
    )
    np.testing.assert_allclose(
        r["leak_rate_effective_medium"],
        ly / lx * r["effective_flow_conductivity"] * dp,
        rtol=PRODUCT,
    )


def test_a_sealed_load_leaks_nothing_and_warns():
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        r = persson.leakage(spectrum(), E_STAR, [3e4, 5e5], viscosity=1e-3, pressure_drop=1e5)
    assert list(r["leaking_critical_junction"]) == [True, False]
    assert r["leak_rate_critical_junction"][1] == 0.0
    assert r["leak_rate_effective_medium"][1] == 0.0
    assert np.isnan(r["critical_zeta"][1])
    assert any("already percolates" in str(w.message) for w in caught)


def test_a_gas_is_driven_by_the_difference_of_the_squares():
    s = spectrum()
    liquid = persson.leakage(s, E_STAR, 3e4, viscosity=1.8e-5, pressure_drop=1e5)
    gas = persson.leakage(s, E_STAR, 3e4, viscosity=1.8e-5, inlet_pressure=3e5,
                          outlet_pressure=1e5)
    # (P_a² − P_b²)/(2 P_b) = 4e5 Pa.
    np.testing.assert_allclose(
        gas["leak_rate_critical_junction"], 4 * liquid["leak_rate_critical_junction"], rtol=PRODUCT
    )


def test_equal_to_the_cli():
    s = spectrum()
    p = ",".join(repr(x) for x in PRESSURES)
    cli = run_cli("conductance", *SPECTRUM_FLAGS, "--contact-modulus", E_STAR, "--pressure", p,
                  "--conductivity", "0.2,50", "--gas-conductivity", 0.026,
                  "--mean-free-path", 7e-8)
    py = persson.conductance(s, E_STAR, PRESSURES, conductivity=(0.2, 50),
                             gas_conductivity=0.026, mean_free_path=7e-8)
    for key in ["stiffness", "thermal_conductance", "gap_conductance",
                "gap_conductance_error_bound"]:
        assert list(py[key]) == [pt[key] for pt in cli["points"]], key
    cli = run_cli("leakage", *SPECTRUM_FLAGS, "--contact-modulus", E_STAR, "--pressure", p,
                  "--viscosity", 1e-3, "--pressure-drop", 1e5)
    py = persson.leakage(s, E_STAR, PRESSURES, viscosity=1e-3, pressure_drop=1e5)
    assert list(py["leak_rate_critical_junction"]) == [
        pt["critical_junction"]["leak_rate"] for pt in cli["points"]
    ]
    assert list(py["leak_rate_effective_medium"]) == [
        pt["effective_medium"]["leak_rate"] for pt in cli["points"]
    ]


@pytest.mark.parametrize(
    "kwargs,name",
    [
        (dict(conductivity=0.0), "conductivity"),
        (dict(conductivity=(1.0, 2.0, 3.0)), "conductivity"),
        (dict(resistivity=-1.0), "resistivity"),
        (dict(gas_conductivity=0.02), "mean_free_path"),
        (dict(gap_table=([0.0, 0.0], [1.0, 2.0])), "gap_table"),
    ],
)
def test_conductance_bad_input_names_the_keyword(kwargs, name):
    with pytest.raises(ValueError, match=name):
        persson.conductance(spectrum(), E_STAR, 1e5, **kwargs)


@pytest.mark.parametrize(
    "kwargs,name",
    [
        (dict(viscosity=0.0, pressure_drop=1e5), "viscosity"),
        (dict(viscosity=1e-3, pressure_drop=-1.0), "pressure_drop"),
        (dict(viscosity=1e-3), "pressure_drop"),
        (dict(viscosity=1e-3, pressure_drop=1e5, seal_width=0.0), "seal_width"),
        (dict(viscosity=1e-3, pressure_drop=1e5, percolation_threshold=1.0), "percolation_threshold"),
        (dict(viscosity=1e-3, inlet_pressure=1e5, outlet_pressure=2e5), "outlet_pressure"),
    ],
)
def test_leakage_bad_input_names_the_keyword(kwargs, name):
    with pytest.raises(ValueError, match=name):
        persson.leakage(spectrum(), E_STAR, 1e5, **kwargs)


def test_separation_density_matches_cli():
    """`persson.separation_density` is `persson separation --separation-density --json`,
    and its identities hold: A/A0 + ∫P_nc du = 1, ∫u P du = ū + s_fold (issue 23)."""
    cli = run_cli("separation", *SPECTRUM_FLAGS, "--contact-modulus", E_STAR,
                  "--pressure", "1e4,1e5", "--separation-density", "--density-points", 41)
    r = persson.separation_density(spectrum(), E_STAR, [1e4, 1e5], density_points=41)
    same(r, cli)
    for c in r["curves"]:
        assert len(c["points"]) == 41
        assert c["contact_fraction"] + c["non_contact_fraction"] == pytest.approx(
            1.0, abs=NORMALISATION)
        assert c["separation_first_moment"] == pytest.approx(
            c["mean_separation"] + c["fold_shift"], rel=1e-6)
    with pytest.raises(ValueError, match="density_points"):
        persson.separation_density(spectrum(), E_STAR, [1e5], density_points=1)
