"""persson: contact mechanics of randomly rough surfaces from Python.

Persson's theory (G(ζ), the real contact area A/A0, the stress distribution
P(σ, ζ), the corrected theories, κ, the mean separation) and an FFT
boundary-element solver, from the Rust crate ``persson`` through pyo3.

Conventions (as the crate's): SI units; pressures and the contact modulus
E* in any one unit (Pa, or E* = 1); q is the angular wavevector (1/m) and
C(q) the isotropic power spectrum in Persson's normalisation (m⁴),
⟨h²⟩ = 2π ∫ q C dq; σ0 (``pressure``) is the nominal mean pressure; ζ the
magnification, q = ζ q_l. Bad input raises ``ValueError`` naming the
argument, a file that cannot be read ``OSError``; the messages are the CLI's.

Functions that return a dict return what ``persson <command> --json``
prints for the same input (the same serialisation, so the same digits).
"""

from ._persson import (
    Spectrum,
    adhesion,
    analyse_height_map,
    anisotropy,
    area,
    bem_hertz,
    bem_rough,
    bem_solve,
    compare,
    conductance,
    contact_area,
    contact_modulus,
    friction,
    contact_patches,
    g,
    kappa,
    kappa_report,
    leakage,
    low_load_kappa,
    magnification,
    mean_separation,
    run_scene,
    separation,
    separation_density,
    spectrum_2d,
    stress,
    stress_physical,
    subsurface_stress,
    synthesize,
    theories,
    version,
)

import functools as _functools
import warnings as _warnings

from ._ensemble import ensemble
from ._surrogates import surrogates


def _renamed(f, **old_names):
    """`f` with old keyword names (persson ≤ 0.3, ``old=new``) accepted as
    deprecated aliases: a ``DeprecationWarning``, then the same call with
    the new name. The signature and docstring stay the compiled function's
    (``functools.wraps``)."""

    @_functools.wraps(f)
    def wrapper(*args, **kwargs):
        for old, new in old_names.items():
            if old not in kwargs:
                continue
            if new in kwargs:
                raise TypeError(f"{f.__name__}(): give {new}= only ({old}= is its old name)")
            _warnings.warn(
                f"{f.__name__}({old}=...) is deprecated since persson 0.4: use {new}= "
                "(the name of src/names.md)",
                DeprecationWarning,
                stacklevel=2,
            )
            kwargs[new] = kwargs.pop(old)
        return f(*args, **kwargs)

    return wrapper


def _modulus_alias(f):
    return _renamed(f, modulus="contact_modulus")


# The functions whose E* argument was `modulus` in 0.3.
area = _modulus_alias(area)
bem_hertz = _modulus_alias(bem_hertz)
bem_rough = _modulus_alias(bem_rough)
bem_solve = _renamed(bem_solve, modulus="contact_modulus", penetration="approach")
compare = _modulus_alias(compare)
contact_area = _modulus_alias(contact_area)
g = _modulus_alias(g)
kappa_report = _modulus_alias(kappa_report)
magnification = _modulus_alias(magnification)
mean_separation = _modulus_alias(mean_separation)
separation = _modulus_alias(separation)
stress_physical = _modulus_alias(stress_physical)
theories = _modulus_alias(theories)

__all__ = [
    "Spectrum",
    "adhesion",
    "analyse_height_map",
    "anisotropy",
    "area",
    "bem_hertz",
    "bem_rough",
    "bem_solve",
    "compare",
    "conductance",
    "contact_area",
    "contact_modulus",
    "ensemble",
    "friction",
    "contact_patches",
    "g",
    "kappa",
    "kappa_report",
    "leakage",
    "low_load_kappa",
    "magnification",
    "mean_separation",
    "run_scene",
    "surrogates",
    "separation",
    "separation_density",
    "spectrum_2d",
    "stress",
    "stress_physical",
    "subsurface_stress",
    "synthesize",
    "theories",
    "version",
]
__version__ = version()
