"""Bad input: ValueError naming the argument (the CLI's message where the
CLI has the same check), OSError for files; never a crash."""

import numpy as np
import pytest

import persson
from conftest import cli_error

S = persson.Spectrum.self_affine(0.8, 1e4, 1e8, q_r=1e5, rms_height=1e-6)
H = persson.synthesize(persson.Spectrum.self_affine(0.8, 2 * np.pi, 32 * np.pi, rms_slope=0.1), 16)


def message(excinfo):
    return str(excinfo.value)


@pytest.mark.parametrize("bad", [np.array(["a"]), np.array([True]), np.array([1e6 + 1j])])
def test_wrong_dtype_names_the_argument(bad):
    with pytest.raises(ValueError, match=r"^pressure: an array of dtype \S+, expected real numbers"):
        persson.contact_area(S, 1e9, bad)
    with pytest.raises(ValueError, match=r"^heights: an array of dtype"):
        persson.bem_solve(bad.reshape(1, -1), 1.0, 1.0, pressure=0.1)


@pytest.mark.parametrize("dtype", [np.int64, np.int32, np.uint16, np.float32, np.float16])
def test_other_real_dtypes_are_the_float64_values(dtype):
    # 1e3 and 2e4 are exact in every one of these dtypes: the same numbers
    p = np.array([1e3, 2e4]).astype(dtype)
    want = persson.contact_area(S, 1e9, np.array([1e3, 2e4]))
    assert persson.contact_area(S, 1e9, p).tolist() == want.tolist()
    assert persson.contact_area(S, 1e9, dtype(1e3)) == want[0]  # a numpy scalar
    assert persson.contact_area(S, 1e9, np.array(1e3).astype(dtype)) == want[0]  # 0-d


def test_negative_seed_is_a_value_error_naming_seed():
    sp = persson.Spectrum.self_affine(0.8, 2 * np.pi, 32 * np.pi, rms_slope=0.1)
    for bad in [-1, 2**64, 1.5]:
        with pytest.raises(ValueError, match=r"^invalid seed = \S+: must be an integer from 0") as e:
            persson.synthesize(sp, 16, seed=bad)
        # The bound it names is 2⁶⁴ − 1, computed here, not copied.
        assert str(2**64 - 1) in message(e)
    with pytest.raises(ValueError, match=r"^invalid seed = -1"):
        persson.bem_rough(1.0, [0.01], spectrum=sp, grid=16, seed=-1)
    # numpy integers are seeds too
    assert (persson.synthesize(sp, 16, seed=np.int64(3)) == persson.synthesize(sp, 16, seed=3)).all()


def test_signatures_show_the_defaults():
    import inspect
    for f in [persson.area, persson.contact_area, persson.separation, persson.compare,
              persson.synthesize, persson.bem_rough]:
        sig = inspect.signature(f)
        for p in sig.parameters.values():
            assert p.default is not Ellipsis, f"{f.__name__}: {p.name}=Ellipsis"
    assert inspect.signature(persson.area).parameters["tolerance"].default == 1e-12
    assert inspect.signature(persson.compare).parameters["alpha"].default == 0.7
    assert inspect.signature(persson.synthesize).parameters["seed"].default == 1


def test_not_a_number():
    with pytest.raises(ValueError, match=r"^pressure: not a number"):
        persson.contact_area(S, 1e9, "high")
    with pytest.raises(ValueError, match=r"^zeta: not a number"):
        persson.g(S, 1e9, 1e6, [None, object()])


def test_non_contiguous_and_non_square_heights():
    with pytest.raises(ValueError, match=r"^heights: not C-contiguous"):
        persson.bem_solve(H.T, 1.0, 1.0, pressure=0.01)
    with pytest.raises(ValueError, match=r"^heights: not C-contiguous"):
        persson.bem_solve(H[::2, ::2], 1.0, 1.0, pressure=0.01)
    with pytest.raises(ValueError, match=r"^heights: a 16 × 8 array; the BEM solves on square"):
        persson.bem_solve(np.ascontiguousarray(H[:, :8]), 1.0, 1.0, pressure=0.01)
    with pytest.raises(ValueError, match=r"^heights: a 1-D array, expected a 2-D height map"):
        persson.bem_solve(H[0], 1.0, 1.0, pressure=0.01)
    # A transposed view is fine where no contiguous buffer is needed.
    assert persson.contact_area(S, 1e9, np.full((3, 2), 1e6).T).shape == (2, 3)


def test_nan_and_negative_values_name_the_argument():
    with pytest.raises(ValueError) as e:
        persson.contact_area(S, 1e9, [1e6, np.nan])
    assert message(e) == "invalid nominal_pressure = NaN: must be finite and > 0"
    h = H.copy()
    h[2, 3] = np.nan
    with pytest.raises(ValueError, match=r"^invalid height\[2, 3\] = NaN: must be finite"):
        persson.bem_solve(h, 1.0, 1.0, pressure=0.01)
    with pytest.raises(ValueError, match=r"^invalid size = -1: must be finite and > 0"):
        persson.bem_solve(H, -1.0, 1.0, pressure=0.01)
    with pytest.raises(ValueError, match=r"^invalid pixel_size = -0.1: must be finite and > 0"):
        persson.Spectrum.from_height_map(H, -0.1)
    with pytest.raises(ValueError, match=r"^invalid contact_modulus = -5: must be finite and > 0"):
        persson.area(S, -5.0, [1e6])
    with pytest.raises(ValueError, match=r"^invalid zeta = 0.5: must be finite and >= 1"):
        persson.contact_area(S, 1e9, 1e6, zeta=0.5)


@pytest.mark.parametrize("call,arg", [
    (lambda: persson.contact_area(S, 1e9, 1e6, theory="persson2"), "theory"),
    (lambda: persson.bem_solve(H, 1.0, 1.0, pressure=0.01, boundary="open"), "boundary"),
    (lambda: persson.stress("ball", 0.5), "start"),
    (lambda: persson.Spectrum.tabulated([1.0, 2.0], [1.0, 0.5], "st"), "convention"),
    (lambda: persson.Spectrum.from_height_map(H, 1.0, detrend="quadratic"), "detrend"),
    (lambda: persson.Spectrum.from_height_map(H, 1.0, window="hamming"), "window"),
])
def test_unknown_names(call, arg):
    with pytest.raises(ValueError, match=rf"^invalid {arg} = '\w+': unknown variant"):
        call()


def test_messages_are_the_clis():
    with pytest.raises(ValueError) as e:
        persson.Spectrum.self_affine(1.2, 1e4, 1e8, rms_height=1e-6)
    assert message(e) == cli_error("area", "--hurst", 1.2, "--q-l", 1e4, "--q-s", 1e8,
                                   "--rms-height", 1e-6, "--contact-modulus", 1e9, "--pressure", 1e6)
    with pytest.raises(ValueError) as e:
        persson.contact_area(S, 1e9, -3.0)
    assert message(e) == cli_error("area", "--example", "--pressure", -3)
    with pytest.raises(ValueError) as e:
        persson.contact_area(S, 1e9, 1e6, "xu", gamma=7.0)
    assert message(e) == cli_error("area", "--example", "--pressure", 1e6, "--theory", "xu",
                                   "--gamma", 7)
    with pytest.raises(ValueError) as e:
        persson.contact_modulus(1e9, 0.7)
    assert message(e) == cli_error("area", "--example", "--young", 1e9, "--poisson", 0.7,
                                   "--pressure", 1e6)


def test_files(tmp_path):
    missing = tmp_path / "missing.csv"
    with pytest.raises(OSError) as e:
        persson.Spectrum.from_csv(missing)
    assert message(e) == cli_error("area", "--psd", missing, "--contact-modulus", 1e9,
                                   "--pressure", 1e6)
    with pytest.raises(OSError):
        persson.run_scene(tmp_path / "missing.json")
    with pytest.raises(OSError):
        persson.Spectrum.from_file(tmp_path / "missing.npy", pixel_size=1e-6)
    bad = tmp_path / "bad.csv"
    bad.write_text("q,C\n1e3,abc\n")
    with pytest.raises(ValueError) as e:
        persson.Spectrum.from_csv(bad)
    assert message(e) == cli_error("area", "--psd", bad, "--contact-modulus", 1e9, "--pressure", 1e6)
    with pytest.raises(ValueError, match="unknown field"):
        persson.run_scene({"schema": 1, "outputs": {}, "colour": "red"})


def test_other_inconsistencies():
    with pytest.raises(ValueError, match="exactly one"):
        persson.Spectrum.self_affine(0.8, 1e4, 1e8)
    with pytest.raises(ValueError, match="^pressure, approach: give exactly one"):
        persson.bem_solve(H, 1.0, 1.0)
    with pytest.raises(ValueError, match=r"^pressure \(shape \[2\]\) and zeta \(shape \[3\]\) do not broadcast"):
        persson.contact_area(S, 1e9, [1e6, 1e7], zeta=[1.0, 2.0, 3.0])
    with pytest.raises(ValueError, match="^q and c: 3 and 2 values"):
        persson.Spectrum.tabulated([1.0, 2.0, 3.0], [1.0, 2.0])
    with pytest.raises(ValueError, match="^no surface"):
        persson.bem_rough(1.0, [0.1])
    with pytest.raises(TypeError):
        persson.contact_area(S, "stiff", 1e6)
