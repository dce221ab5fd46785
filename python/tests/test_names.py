"""One name per quantity (src/names.md) in Python too: every keyword of every
public function is a name of the table, the CLI flag of one (``pressure`` for
``--pressure``), or one of the few arguments below that name no quantity;
``modulus=`` (0.3's name for E*) and ``penetration=`` (of ``approach``) still
work, with a DeprecationWarning."""

import inspect
import math
import pathlib
import re
import warnings

import pytest

import persson

NAMES_MD = pathlib.Path(__file__).resolve().parents[2] / "src" / "names.md"

# Arguments that hold inputs or choices rather than name a quantity. Keep
# this list short: a quantity belongs in src/names.md.
NOT_QUANTITIES = {
    "spectrum", "heights", "path", "topography", "scene", "table",  # inputs
    "theory", "theories", "start", "boundary", "convention", "detrend", "window", "law", "adhesion",  # closed sets
    "points", "error_bound", "fill_undefined", "periodic",  # how to compute or show
    "ball", "cylinder",  # (radius, load) pairs of a smooth start
    "data", "data_histogram",  # the user's CSV files
    "client", "threads", "timeout",  # where an ensemble runs
    "size", "pixel_size", "q_min", "q_max",  # a band or a map's extent, as the CLI's flags
    "paths", "spectra",  # several inputs (Spectrum.combine, Spectrum.sum)
    "sizes", "pixel_sizes", "tip_radii",  # per-file lists of size, pixel_size, tip_radius
}


def table():
    """The names (fourth column) and the CLI flags (fifth) of src/names.md."""
    names, flags = set(), set()
    rows = [l for l in NAMES_MD.read_text().splitlines() if l.lstrip().startswith("|")]
    header = [c.strip() for c in rows[0].strip().strip("|").split("|")]
    name_col = next(i for i, c in enumerate(header) if c.startswith("name"))
    flag_col = next(i for i, c in enumerate(header) if c.startswith("CLI flag"))
    for row in rows[2:]:
        cells = row.strip().strip("|").split("|")
        names.update(w for w in re.findall(r"`([^`<]+)`", cells[name_col]))
        flags.update(f[2:].replace("-", "_") for f in re.findall(r"`(--[a-z0-9-]+)`", cells[flag_col]))
    return names, flags


def singular(p):
    """A list argument's one-value name: `sizes` → `size`, `tip_radii` →
    `tip_radius`, `spectra` → `spectrum`."""
    for plural, one in (("radii", "radius"), ("spectra", "spectrum"), ("s", "")):
        if p.endswith(plural):
            return p[: -len(plural)] + one
    return p


def allowed(p, table_names):
    return p in table_names or p in NOT_QUANTITIES


def public_callables():
    for name in persson.__all__:
        obj = getattr(persson, name)
        if name == "Spectrum":
            for m in dir(obj):
                if not m.startswith("_") and callable(getattr(obj, m)):
                    yield f"Spectrum.{m}", getattr(obj, m)
        elif callable(obj):
            yield name, obj


def test_the_table_is_read():
    names, flags = table()
    # A table we misread would let everything through: a few rows we know.
    assert {"contact_modulus", "nominal_pressure", "rms_slope", "q_l"} <= names
    assert {"pressure", "contact_modulus", "yield_stress"} <= flags
    assert "modulus" not in names | flags


def test_every_keyword_is_a_name():
    names, flags = table()
    unknown = []
    for name, f in public_callables():
        try:
            params = inspect.signature(f).parameters
        except (TypeError, ValueError):
            continue
        for p in params:
            if p != "self" and not (allowed(p, names | flags) or allowed(singular(p), names | flags)):
                unknown.append(f"{name}({p}=)")
    assert not unknown, "keywords outside src/names.md: " + ", ".join(unknown)
    assert "modulus" not in {p for _, f in public_callables()
                             for p in inspect.signature(f).parameters}


def test_modulus_is_a_deprecated_alias():
    s = persson.Spectrum.example()
    new = persson.area(s, contact_modulus=1e9, pressure=[1e6])
    with pytest.warns(DeprecationWarning, match="contact_modulus="):
        old = persson.area(s, modulus=1e9, pressure=[1e6])
    assert old == new
    h = persson.synthesize(persson.Spectrum.self_affine(0.8, 2 * math.pi, 16 * math.pi,
                                                        rms_slope=0.1), 16)
    _, _, s1 = persson.bem_solve(h, 1.0, 1.0, approach=0.01)
    with pytest.warns(DeprecationWarning, match="approach="):
        _, _, s2 = persson.bem_solve(h, 1.0, 1.0, penetration=0.01)
    assert _no_seconds(s1) == _no_seconds(s2)
    with pytest.warns(DeprecationWarning):
        h = persson.bem_hertz(grid=16, modulus=2.0)
    assert _no_seconds(h) == _no_seconds(persson.bem_hertz(grid=16, contact_modulus=2.0))
    with pytest.raises(TypeError, match="contact_modulus= only"):
        persson.g(s, modulus=1e9, contact_modulus=1e9, pressure=1e6)
    # No warning when the new name is used.
    with warnings.catch_warnings():
        warnings.simplefilter("error", DeprecationWarning)
        persson.g(s, contact_modulus=1e9, pressure=1e6)


def _no_seconds(v):
    if isinstance(v, dict):
        return {k: _no_seconds(x) for k, x in v.items() if k != "seconds"}
    if isinstance(v, list):
        return [_no_seconds(x) for x in v]
    return v
