"""`persson.friction` (Persson's rubber friction) against closed forms and the CLI.

Closed forms (derived in docs/friction.md, spectrum C(q) = C_r on [q_l, q_r),
C_r (q/q_r)^(-2(1+H)) on [q_r, q_s]; m3 = ∫ q³ C dq exactly):
- E″ = 0 (a Prony series of E∞ alone): μ = 0 and A/A0 = erf(1/(2√G)),
  G = (π/4) (E/((1 − ν²) σ0))² m3, at every velocity.
- E = E1 + i E2 sign(ω) (a constant master curve), γ = 1: μ is independent
  of v, μ = 8 E2 I(G1) / (π k² (1 − ν²) σ0), k = |E|/((1 − ν²) σ0),
  I(G) = ∫₀^G erf(1/(2√g)) dg = G erf(1/(2√G)) + √(G/π) e^(−1/(4G)) − ½ erfc(1/(2√G)).
"""

import math

import numpy as np
import pytest

import persson
from conftest import run_cli

HURST, Q_L, Q_R, Q_S, C_R = 0.8, 1e2, 1e3, 1e7, 1e-15
NU = 0.5
VELOCITIES = np.array([1e-9, 1e-5, 1e-1, 1e3])

# The integrals run to the tolerance 1e-12; the closed forms are a few
# roundings each: a relative 1e-10 leaves room for the error bounds
# (which the tests check to hold too).
REL = 1e-10


def spectrum():
    return persson.Spectrum.self_affine(HURST, Q_L, Q_S, q_r=Q_R, c_r=C_R)


def m3():
    a = C_R * (Q_R**4 - Q_L**4) / 4
    b = C_R * Q_R ** (2 + 2 * HURST) * (Q_S ** (2 - 2 * HURST) - Q_R ** (2 - 2 * HURST)) / (2 - 2 * HURST)
    return a + b


def write(tmp_path, name, text):
    p = tmp_path / name
    p.write_text(text)
    return p


def test_loss_free_rubber_has_no_friction(tmp_path):
    e, sigma0 = 5e6, 2e5
    prony = write(tmp_path, "elastic.txt", "# E_k tau_k\n5e6 inf\n")
    r = persson.friction(spectrum(), VELOCITIES, [sigma0], prony=str(prony), tolerance=1e-12)
    assert r["friction_coefficient"].shape == (1, 1, len(VELOCITIES))
    assert np.all(r["friction_coefficient"] == 0.0)
    g = math.pi / 4 * (e / ((1 - NU**2) * sigma0)) ** 2 * m3()
    a = math.erf(0.5 / math.sqrt(g))
    np.testing.assert_allclose(r["contact_fraction"][0, 0], a, rtol=REL)
    np.testing.assert_array_equal(r["velocity"], VELOCITIES)


@pytest.mark.parametrize("sigma0", [1e3, 1e5, 1e9])
def test_frequency_independent_loss_gives_a_velocity_independent_closed_form(tmp_path, sigma0):
    e1, e2 = 2e6, 5e5
    curve = write(tmp_path, "constant.csv", f"omega,E1,E2\n1,{e1},{e2}\n10,{e1},{e2}\n100,{e1},{e2}\n")
    with pytest.warns(UserWarning, match="outside its range"):
        r = persson.friction(
            spectrum(), VELOCITIES, [sigma0], master_curve=str(curve), frequency_unit="rad/s",
            gamma=1.0, tolerance=1e-12,
        )
    k = math.hypot(e1, e2) / ((1 - NU**2) * sigma0)
    g1 = math.pi / 4 * k * k * m3()
    x = 0.5 / math.sqrt(g1)
    integral = g1 * math.erf(x) + math.sqrt(g1 / math.pi) * math.exp(-x * x) - 0.5 * math.erfc(x)
    mu = 8 * e2 * integral / (math.pi * k * k * (1 - NU**2) * sigma0)
    got = r["friction_coefficient"][0, 0]
    np.testing.assert_allclose(got, mu, rtol=REL)
    assert np.all(np.abs(got - mu) <= r["friction_coefficient_error_bound"][0, 0] + REL * mu)
    np.testing.assert_allclose(r["contact_fraction"][0, 0], math.erf(x), rtol=REL)


def test_wlf_temperature_is_a_velocity_shift():
    # b_T = 1, no flash temperature: μ(v, T) = μ(a_T v, T_ref).
    c1, c2, t_ref, t = 8.86, 101.6, 293.15, 313.15
    a_t = 10 ** (-c1 * (t - t_ref) / (c2 + t - t_ref))
    sls = (3e8, 3e6, 1e-4)
    hot = persson.friction(spectrum(), [1e-3], [2e5], [t], standard_linear_solid=sls,
                           wlf=(c1, c2, t_ref), tolerance=1e-12)
    ref = persson.friction(spectrum(), [a_t * 1e-3], [2e5], [t_ref], standard_linear_solid=sls,
                           wlf=(c1, c2, t_ref), tolerance=1e-12)
    np.testing.assert_allclose(hot["friction_coefficient"], ref["friction_coefficient"], rtol=1e-9)


def test_same_numbers_as_the_cli():
    sls = "3e8,3e6,1e-4"
    cli = run_cli("friction", "--hurst", HURST, "--q-l", Q_L, "--q-r", Q_R, "--q-s", Q_S,
                  "--c-r", C_R, "--standard-linear-solid", sls, "--pressure", "2e5",
                  "--velocity", "1e-3,1")
    py = persson.friction(spectrum(), [1e-3, 1.0], [2e5], standard_linear_solid=(3e8, 3e6, 1e-4))
    assert [p["friction_coefficient"] for p in cli["points"]] == list(py["friction_coefficient"].ravel())
    assert cli["points"][0]["velocity"] == 1e-3


def test_flash_temperature_arrays():
    r = persson.friction(
        spectrum(), [1e-2, 1.0], [2e5], standard_linear_solid=(3e8, 3e6, 1e-4),
        flash_temperature=True, thermal_conductivity=0.25, density=1200, heat_capacity=1500,
    )
    assert r["flash_temperature"].shape == (1, 1, 2)
    assert np.all(r["flash_temperature"] >= 0)
    assert "flash" in r["points"][0]


@pytest.mark.parametrize(
    "kwargs,word",
    [
        (dict(velocity=[-1.0]), "velocity"),
        (dict(velocity=[1.0], wlf=(8.86, 101.6, 293.15), temperature=[150.0]), "temperature"),
        (dict(velocity=[1.0], q1=1e9), "q1"),
        (dict(velocity=[1.0], standard_linear_solid=(1.0, 2.0)), "standard_linear_solid"),
        (dict(velocity=[1.0], flash_temperature=True), "thermal_conductivity"),
    ],
)
def test_bad_input_names_the_argument(kwargs, word):
    kw = dict(standard_linear_solid=(3e8, 3e6, 1e-4))
    kw.update(kwargs)
    velocity = kw.pop("velocity")
    temperature = kw.pop("temperature", None)
    with pytest.raises(ValueError, match=word):
        persson.friction(spectrum(), velocity, [2e5], temperature, **kw)
