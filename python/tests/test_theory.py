"""The analytic functions against `persson … --json`, digit for digit."""

import numpy as np
import pytest

import persson
from conftest import read_from, run_cli, same

# A self-affine surface with roll-off, given on the command line and in Python.
FLAGS = ["--hurst", 0.7, "--q-l", 1e3, "--q-r", 1e4, "--q-s", 1e7]
E_STAR = 2e9
PRESSURES = [1e5, 1e6, 3e6, 1e7, 1e8]
AMPLITUDES = [("rms_slope", 0.8), ("rms_height", 2e-6), ("c_r", 1e-30)]
THEORIES = ["original", "yang-persson", "wang-muser", "xu"]


def spectrum(kind="rms_slope", value=0.8):
    return persson.Spectrum.self_affine(0.7, 1e3, 1e7, q_r=1e4, **{kind: value})


def flags(kind="rms_slope", value=0.8):
    return [*FLAGS, "--" + kind.replace("_", "-"), value, "--contact-modulus", E_STAR]


def pressure_flag(p):
    return ["--pressure", ",".join(repr(x) for x in p)]


@pytest.mark.parametrize("kind,value", AMPLITUDES)
@pytest.mark.parametrize("theory", THEORIES)
def test_area_and_contact_area_match_cli(kind, value, theory):
    cli = run_cli("area", *flags(kind, value), *pressure_flag(PRESSURES), "--theory", theory)
    s = spectrum(kind, value)
    same(persson.area(s, E_STAR, PRESSURES, theory), cli)
    a, bound = persson.contact_area(s, E_STAR, np.array(PRESSURES), theory, error_bound=True)
    assert a.tolist() == [p["contact_fraction"] for p in cli["points"]]
    assert bound.tolist() == [p["error_bound"] for p in cli["points"]]
    gv, gb = persson.g(s, E_STAR, np.array(PRESSURES), error_bound=True)
    assert gv.tolist() == [p["g"] for p in cli["points"]]
    assert gb.tolist() == [p["g_error_bound"] for p in cli["points"]]


def test_gamma_and_zeta_match_cli():
    cli = run_cli("area", *flags(), *pressure_flag(PRESSURES), "--theory", "wang-muser",
                  "--gamma", 0.7, "--zeta", 300)
    s = spectrum()
    same(persson.area(s, E_STAR, PRESSURES, "wang-muser", 0.7, zeta=300.0), cli)
    a = persson.contact_area(s, E_STAR, PRESSURES, "wang-muser", 0.7, zeta=300.0)
    assert a.tolist() == [p["contact_fraction"] for p in cli["points"]]


def test_example_matches_cli():
    cli = run_cli("area", "--example")
    same(persson.area(persson.Spectrum.example(), 1e9, [1e4, 1e5, 1e6, 1e7, 3e7, 1e8]), cli)


def test_contact_area_broadcasts_pressure_against_zeta():
    s = spectrum()
    p = np.array([[1e6], [1e7]])
    z = np.array([10.0, 100.0, 1e4])
    a = persson.contact_area(s, E_STAR, p, zeta=z)
    assert a.shape == (2, 3)
    for i in range(2):
        for j in range(3):
            one = persson.contact_area(s, E_STAR, float(p[i, 0]), zeta=float(z[j]))
            assert isinstance(one, float)
            assert a[i, j] == one
    # A corrected theory at several ζ: one load curve per ζ, as the CLI's --zeta.
    b = persson.contact_area(s, E_STAR, p, "xu", zeta=z)
    for j in range(3):
        cli = run_cli("area", *flags(), *pressure_flag([1e6, 1e7]), "--theory", "xu", "--zeta", z[j])
        assert b[:, j].tolist() == [q["contact_fraction"] for q in cli["points"]]


def test_magnification_matches_cli():
    cli = run_cli("magnification", *flags(), "--pressure", 1e6, "--points", 9)
    same(persson.magnification(spectrum(), E_STAR, 1e6, points=9), cli)
    cli = run_cli("magnification", *flags(), "--pressure", 1e6, "--zeta", "1,10,100")
    same(persson.magnification(spectrum(), E_STAR, 1e6, [1.0, 10.0, 100.0]), cli)


def test_kappa_matches_cli():
    cli = run_cli("kappa", *flags(), *pressure_flag(PRESSURES))
    same(persson.kappa_report(spectrum(), E_STAR, PRESSURES), cli)
    assert persson.kappa("bush") == cli["kappa_bush"]
    assert persson.kappa("persson") == cli["kappa_persson"]
    assert persson.kappa() == (8 / np.pi) ** 0.5
    same(persson.kappa_report(), run_cli("kappa"))


def test_low_load_kappa_matches_theories_scene():
    r = persson.run_scene(str(pathlib_root() / "scenes" / "theories.json"))
    for curve in r["theories"]["curves"]:
        assert persson.low_load_kappa(curve["theory"], curve.get("gamma")) == curve["kappa"]


def pathlib_root():
    import pathlib
    return pathlib.Path(__file__).resolve().parents[2]


def test_theories_matches_scene_output():
    s = persson.Spectrum.example()
    r = persson.theories(s, 1e9, [1e5, 1e6, 1e7])
    scene = {
        "schema": 1,
        "material": {"contact_modulus": 1e9},
        "spectrum": {"kind": "self_affine", "hurst": 0.8, "q_l": 1e4, "q_r": 1e5, "q_s": 1e8,
                     "rms_height": 1e-6},
        "nominal_pressure": [1e5, 1e6, 1e7],
        "outputs": {"theories": {}},
    }
    assert_scene_section(r, persson.run_scene(scene), "theories")


def assert_scene_section(report, scene, section):
    """A report equals a scene's section, and its warnings are the scene's
    (kept at the scene's top level, one list for all its outputs)."""
    report = dict(report)
    assert report.pop("warnings") == scene["warnings"]
    assert report == scene[section]


def test_separation_matches_cli():
    cli = run_cli("separation", *flags(), *pressure_flag(PRESSURES))
    s = spectrum()
    same(persson.separation(s, E_STAR, PRESSURES), cli)
    arrays = persson.mean_separation(s, E_STAR, np.array(PRESSURES))
    for key, column in arrays.items():
        assert isinstance(column, np.ndarray)
        assert column.tolist() == [p[key] for p in cli["points"]]


@pytest.mark.parametrize("start", ["flat", "hertz", "cylinder"])
@pytest.mark.parametrize("yield_ratio", [None, 1.3])
def test_stress_matches_cli(start, yield_ratio):
    extra = [] if yield_ratio is None else ["--yield-ratio", yield_ratio]
    cli = run_cli("stress", "--start", start, "--g", 0.6, "--points", 21, *extra)
    same(persson.stress(start, 0.6, yield_ratio=yield_ratio, points=21), cli)
    cli = run_cli("stress", "--start", start, "--g", 2, "--sigma-ratio", "0.1,0.5,1.2", *extra)
    same(persson.stress(start, [2.0], yield_ratio=yield_ratio, sigma_ratio=[0.1, 0.5, 1.2]), cli)


def test_stress_physical_matches_scene(tmp_path):
    scene = pathlib_root() / "scenes" / "rail_wheel.json"
    cli = run_cli("run", scene, cwd=tmp_path)
    s = persson.Spectrum.self_affine(0.5, 628.3185307179587, 1e9, q_r=2e4,
                                     rms_height=6.717514421272201e-7)
    e = persson.contact_modulus(1e11, 0.3)
    r = persson.stress_physical(s, e, [100.0, 400.0], "cylinder", peak_pressure=542e6)
    assert_scene_section(r, cli, "stress")
    # With a yield stress, the same through a scene dict.
    scene = {
        "schema": 1,
        "material": {"young": 1e11, "poisson": 0.3},
        "spectrum": {"kind": "self_affine", "hurst": 0.5, "q_l": 628.3185307179587, "q_r": 2e4,
                     "q_s": 1e9, "rms_height": 6.717514421272201e-7},
        "outputs": {"stress": {"start": "hertz", "ball": {"radius": 0.01, "load": 100.0},
                               "yield_stress": 2e9, "zeta": [10, 100], "points": 31}},
    }
    r = persson.stress_physical(s, e, [10.0, 100.0], "hertz", ball=(0.01, 100.0),
                                yield_stress=2e9, points=31)
    assert_scene_section(r, persson.run_scene(scene), "stress")


def test_contact_modulus_matches_cli():
    cli = run_cli("area", *FLAGS, "--rms-slope", 0.8, "--young", 1e11, "--poisson", 0.3,
                  "--young2", 2e11, "--poisson2", 0.25, "--pressure", 1e6)
    assert persson.contact_modulus(1e11, 0.3, 2e11, 0.25) == cli["contact_modulus"]
    cli = run_cli("area", *FLAGS, "--rms-slope", 0.8, "--young", 5e6, "--poisson", 0.5,
                  "--pressure", 1e5)
    assert persson.contact_modulus(5e6, 0.5) == cli["contact_modulus"]


def test_spectrum_report_and_moments_match_cli():
    cli = run_cli("spectrum", *FLAGS, "--rms-slope", 0.8, "--points", 7)
    s = spectrum()
    same(s.report(points=7), cli)
    assert s.rms_height() == cli["rms_height"]
    assert s.rms_slope(error_bound=True) == (cli["rms_slope"], cli["rms_slope_error_bound"])
    assert s.rms_curvature() == cli["rms_curvature"]
    q = np.array([p["q"] for p in cli["table"]])
    assert s.c(q).tolist() == [p["c"] for p in cli["table"]]
    assert (s.q_l, s.q_s) == (cli["q_l"], cli["q_s"])
    cli = run_cli("spectrum", *FLAGS, "--rms-slope", 0.8, "--q-min", 2e3, "--q-max", 1e5)
    same(s.report(2e3, 1e5), cli)


@pytest.mark.parametrize("convention,size", [("persson", None), ("surface-topography", None),
                                              ("profile1d", None), ("grid", 1e-3)])
def test_tabulated_spectrum_matches_cli(tmp_path, convention, size):
    q = np.logspace(3, 7, 30)
    c = 1e-30 * (q / 1e3) ** -3.6
    if convention == "grid":
        q = np.arange(1.0, 31.0)
        c = 1e-5 * q ** -3.6
    path = tmp_path / "psd.csv"
    path.write_text("q,C\n" + "".join(f"{float(a)!r},{float(b)!r}\n" for a, b in zip(q, c)))
    extra = ["--psd-size", size] if size else []
    pressures = [1e6, 1e7]
    cli = run_cli("area", "--psd", path, "--psd-convention", convention, *extra,
                  "--contact-modulus", E_STAR, *pressure_flag(pressures))
    from_csv = persson.Spectrum.from_csv(path, convention, size)
    same(persson.area(from_csv, E_STAR, pressures), cli)
    from_arrays = persson.Spectrum.tabulated(q, c, convention, size)
    # Arrays are not a file: no "read in the … convention" warning.
    same(persson.area(from_arrays, E_STAR, pressures), cli, drop=("seconds", "warnings"))


def height_map(n=64, seed=5):
    rng = np.random.default_rng(seed)
    x = np.linspace(0, 1, n)
    return 1e-7 * rng.standard_normal((n, n + 8)) + 1e-6 * x[:, None] * 0.3


def test_height_map_spectrum_matches_cli(tmp_path):
    h = height_map()
    path = tmp_path / "map.npy"
    np.save(path, h)
    pixel = 2e-7
    cli = run_cli("area", "--surface", path, "--pixel-size", pixel, "--contact-modulus", E_STAR,
                  *pressure_flag([1e6, 1e7]))
    # The map's Hurst fit is outside (0, 1): the CLI warns, and so does every
    # report of a Python spectrum of the same heights (the test's point).
    kinds = [w["kind"] for w in cli["warnings"]]
    assert "hurst_out_of_range" in kinds, cli["warnings"]
    s = persson.Spectrum.from_height_map(h, pixel)
    with pytest.warns(UserWarning, match="no Hurst exponent"):
        r = persson.area(s, E_STAR, [1e6, 1e7])
    assert [w["kind"] for w in r["warnings"]] == kinds
    assert all(w["file"] == "(array)" for w in r["warnings"] if "file" in w)
    same(read_from(r, "(array)", path), cli, drop=("seconds", "surface"))
    assert s.description.startswith("measured surface (array) (64 × 72 points")
    f = persson.Spectrum.from_file(path, pixel_size=pixel)
    same(persson.area(f, E_STAR, [1e6, 1e7]), cli)
    # A pickled copy (multiprocessing, Dask) keeps the warnings.
    import pickle
    same(persson.area(pickle.loads(pickle.dumps(f)), E_STAR, [1e6, 1e7]), cli)
    same(read_from(persson.area(pickle.loads(pickle.dumps(s)), E_STAR, [1e6, 1e7]), "(array)",
                   path), cli, drop=("seconds", "surface"))
    analysis = run_cli("spectrum", "--surface", path, "--pixel-size", pixel, "--detrend", "mean",
                       "--window", "blackman")
    same(persson.analyse_height_map(h, pixel, detrend="mean", window="blackman"), analysis)


def test_topography_duck_typed(tmp_path):
    """A SurfaceTopography Topography: heights() indexed [x, y], physical_sizes (Lx, Ly)."""
    h = height_map()  # rows along y

    class Topography:
        physical_sizes = (72 * 2e-7, 64 * 2e-7)
        is_periodic = False

        def heights(self):
            return h.T

    s = persson.Spectrum.from_topography(Topography())
    path = tmp_path / "map.npy"
    np.save(path, h)
    cli = run_cli("area", "--surface", path, "--pixel-size", 2e-7, "--contact-modulus", E_STAR,
                  "--pressure", 1e6)
    assert any(w["kind"] == "hurst_out_of_range" for w in cli["warnings"])
    with pytest.warns(UserWarning, match="no Hurst exponent"):
        r = persson.area(s, E_STAR, [1e6])
    same(read_from(r, "(topography)", path), cli, drop=("seconds", "surface"))


def test_run_scene_path_and_dict_match_cli(tmp_path):
    for name in ["example.json", "theories.json", "fig3_hertz.json", "fig4_cylinder.json"]:
        path = pathlib_root() / "scenes" / name
        cli = run_cli("run", path, cwd=tmp_path)
        same(persson.run_scene(str(path)), cli)
        same(persson.run_scene(path), cli)
        import json
        same(persson.run_scene(json.loads(path.read_text())), cli)


def test_spectra_pickle_to_the_same_numbers(tmp_path):
    import pickle
    path = tmp_path / "psd.csv"
    path.write_text("q,C\n1e3,1e-20\n1e5,1e-26\n1e7,1e-33\n")
    spectra = [spectrum(), persson.Spectrum.example(), persson.Spectrum.from_csv(path),
               persson.Spectrum.tabulated([1e3, 1e5, 1e7], [1e-20, 1e-26, 1e-33], "surface-topography"),
               persson.Spectrum.from_height_map(height_map(), 2e-7)]
    p = np.logspace(5, 8, 7)
    for s in spectra:
        copy = pickle.loads(pickle.dumps(s))
        assert repr(copy) == repr(s)
        for theory in THEORIES:
            assert np.array_equal(persson.contact_area(copy, E_STAR, p, theory),
                                  persson.contact_area(s, E_STAR, p, theory))
        # A file's convention warning stays with the original (the copy has the points).
        same(persson.separation(copy, E_STAR, [1e6]), persson.separation(s, E_STAR, [1e6]),
             drop=("seconds", "warnings"))


def test_g_and_contact_area_over_zeta_match_magnification_cli():
    cli = run_cli("magnification", *flags(), "--pressure", 3e6, "--points", 13)
    z = np.array([p["zeta"] for p in cli["points"]])
    gv, gb = persson.g(spectrum(), E_STAR, 3e6, z, error_bound=True)
    assert gv.tolist() == [p["g"] for p in cli["points"]]
    assert gb.tolist() == [p["g_error_bound"] for p in cli["points"]]
    a = persson.contact_area(spectrum(), E_STAR, 3e6, zeta=z)
    assert a.tolist() == [p["contact_fraction"] for p in cli["points"]]


def test_tabulated_start_matches_cli(tmp_path):
    sigma = np.linspace(0, 1, 41)
    density = 2 * sigma  # the Hertz start, 2σ/σH², tabulated
    path = tmp_path / "start.txt"
    path.write_text("".join(f"{float(a)!r} {float(b)!r}\n" for a, b in zip(sigma, density)))
    cli = run_cli("stress", "--table", path, "--g", 0.4, "--points", 11, "--yield-ratio", 1.5)
    r = persson.stress(None, 0.4, table=(sigma, density), points=11, yield_ratio=1.5)
    same(r, cli)
    with pytest.raises(ValueError, match="^start, table: give exactly one"):
        persson.stress("flat", 0.4, table=(sigma, density))


def test_moments_g_and_area_against_closed_forms():
    """Independent of the CLI: the moments of the piecewise power law in
    closed form, G = (E*/σ0)² h'²_rms / 8 at full magnification, and Persson's
    A/A0 = erf(1/(2√G)) (Persson, J. Chem. Phys. 115, 3840 (2001))."""
    import math
    h, q_l, q_r, q_s = 0.7, 1e3, 1e4, 1e7
    s = spectrum("c_r", 1e-30)
    c_r = 1e-30

    def moment(k):
        # 2π ∫ q^(k+1) C dq: flat C_r on [q_l, q_r], C_r (q/q_r)^(−2(1+H)) above.
        flat = c_r * (q_r ** (k + 2) - q_l ** (k + 2)) / (k + 2)
        e = k + 2 - 2 * (1 + h)
        tail = c_r * q_r ** (2 + 2 * h) * (q_s ** e - q_r ** e) / e
        return 2 * math.pi * (flat + tail)

    # The crate's quadrature claims ~1e-12 relative on these moments.
    rel = 1e-10
    assert s.rms_height() == pytest.approx(math.sqrt(moment(0)), rel=rel)
    assert s.rms_slope() == pytest.approx(math.sqrt(moment(2)), rel=rel)
    assert s.rms_curvature() == pytest.approx(math.sqrt(moment(4)), rel=rel)
    for p in PRESSURES:
        g = (E_STAR / p) ** 2 * moment(2) / 8
        assert persson.g(s, E_STAR, p) == pytest.approx(g, rel=rel)
        assert persson.contact_area(s, E_STAR, p) == pytest.approx(
            math.erf(1 / (2 * math.sqrt(g))), rel=rel)
