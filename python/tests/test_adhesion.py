"""`persson.adhesion` against closed forms (the non-adhesive A/A0, the
full-contact energy and true area of a power-law spectrum) and the CLI."""

import math

import pytest

import persson
from conftest import run_cli, same

# C(q) = C_r (q/q_l)^(−2(1+H)) on [q_l, q_s] (no roll-off): every moment in closed form.
H, Q_L, Q_S, C_R = 0.8, 1e4, 1e6, 1e-19
E_STAR = 1e6
FLAGS = ["--hurst", H, "--q-l", Q_L, "--q-s", Q_S, "--c-r", C_R, "--contact-modulus", E_STAR]
# Δγ = 0 is the non-adhesive theory: A/A0 = erf(1/(2√G)) to rounding.
NON_ADHESIVE_TOLERANCE = 1e-13
# The moments are closed forms in the crate too: rounding of a few operations.
ENERGY_TOLERANCE = 1e-13


def spectrum():
    return persson.Spectrum.self_affine(H, Q_L, Q_S, c_r=C_R)


def moment(n, q_max=Q_S):
    """∫_{q_l}^{q_max} q^n C dq in closed form."""
    p = n + 1 - 2 * (1 + H)
    return C_R * Q_L ** (2 * (1 + H)) * (q_max**p - Q_L**p) / p


def test_zero_work_of_adhesion_is_the_non_adhesive_area():
    pressures = [1e2, 1e3, 1e4, 1e5]
    r = persson.adhesion(spectrum(), E_STAR, 0.0, pressures)
    xi2 = 2 * math.pi * moment(3)
    for p, point in zip(pressures, r["points"]):
        g = (E_STAR / p) ** 2 * xi2 / 8
        exact = math.erf(1 / (2 * math.sqrt(g)))
        assert abs(point["contact_fraction"] - exact) <= NON_ADHESIVE_TOLERANCE, (p, point)
        assert point["tensile_fraction"] == 0.0
    assert r["pull_off_stress"] == 0.0


def test_energy_terms_against_their_closed_forms():
    dg = 1.0
    r = persson.adhesion(spectrum(), E_STAR, dg, points=5)
    for point in r["stickiness"]["points"]:
        q = point["zeta"] * Q_L
        u = math.pi * E_STAR / 2 * moment(2, q)
        xi2 = 2 * math.pi * moment(3, q)
        xi = math.sqrt(xi2)
        # A_true/A0 = 1 + (√π ξ/2) e^{1/ξ²} erfc(1/ξ) (Gaussian slopes)
        area = 1 + math.sqrt(math.pi) * xi / 2 * math.exp(1 / xi2) * math.erfc(1 / xi) if xi > 0 else 1
        assert abs(point["full_contact_energy"] - u) <= ENERGY_TOLERANCE * max(u, 1e-300)
        assert abs(point["true_area_ratio"] - area) <= ENERGY_TOLERANCE
        gamma = dg * area - u
        assert abs(point["effective_interfacial_energy"] - gamma) <= ENERGY_TOLERANCE * (dg * area + u)
    top = r["stickiness"]
    assert top["sticky"] == (top["effective_interfacial_energy"] > 0)
    # σ_p = [γ_eff(1) E* q_l]^{1/2} with γ_eff(1) the balance of the whole band
    if top["effective_interfacial_energy"] > 0:
        pull = math.sqrt(top["effective_interfacial_energy"] * E_STAR * Q_L)
        assert abs(r["pull_off_stress"] - pull) <= 1e-12 * pull


def test_tension_and_pull_off_match_cli():
    # σ_p ≈ 8.9e4 here: one tension beyond it (detached), three inside
    pressures = [-1e5, -8e4, -4e4, 0.0, 1e3]
    r = persson.adhesion(spectrum(), E_STAR, 1.0, pressures, adhesion_range=1e-9)
    cli = run_cli("adhesion", *FLAGS, "--work-of-adhesion", 1.0,
                  "--pressure", ",".join(repr(p) for p in pressures), "--adhesion-range", 1e-9)
    same(r, cli)
    assert r["pull_off_stress"] > 8e4
    fractions = [p["contact_fraction"] for p in r["points"]]
    assert fractions[0] == 0.0 and r["points"][0]["flags"] == ["detached"]
    assert fractions == sorted(fractions) and 0 < fractions[1] < fractions[-1]
    assert [w["kind"] for w in r["warnings"]].count("beyond_pull_off") == 1


def test_bad_input_names_the_argument():
    with pytest.raises(ValueError, match="work_of_adhesion"):
        persson.adhesion(spectrum(), E_STAR, -1.0)
    with pytest.raises(ValueError, match="area_enhancement"):
        persson.adhesion(spectrum(), E_STAR, 0.1, area_enhancement="true")
    with pytest.raises(ValueError, match="zeta"):
        persson.adhesion(spectrum(), E_STAR, 0.1, zeta=0.5)
