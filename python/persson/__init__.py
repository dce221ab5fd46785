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
    area,
    bem_hertz,
    bem_rough,
    bem_solve,
    compare,
    contact_area,
    contact_modulus,
    g,
    kappa,
    kappa_report,
    low_load_kappa,
    magnification,
    mean_separation,
    run_scene,
    separation,
    stress,
    stress_physical,
    synthesize,
    theories,
    version,
)

__all__ = [
    "Spectrum",
    "adhesion",
    "analyse_height_map",
    "area",
    "bem_hertz",
    "bem_rough",
    "bem_solve",
    "compare",
    "contact_area",
    "contact_modulus",
    "g",
    "kappa",
    "kappa_report",
    "low_load_kappa",
    "magnification",
    "mean_separation",
    "run_scene",
    "separation",
    "stress",
    "stress_physical",
    "synthesize",
    "theories",
    "version",
]
__version__ = version()
