"""Type stubs of the compiled module persson._persson (re-exported by persson).

Units: SI; pressures and moduli in any one unit (that of ``contact_modulus``);
q in 1/m (angular); C(q) in m⁴ (Persson's normalisation); lengths in m.
Dicts are the CLI's ``--json`` for the same input.
"""

from __future__ import annotations

import os
from typing import Any, Literal, Optional, Protocol, Sequence, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

FloatArray = npt.NDArray[np.float64]
ArrayLike = Union[float, Sequence[float], FloatArray]
PathLike = Union[str, os.PathLike[str]]
Report = dict[str, Any]
Theory = Literal["original", "yang-persson", "wang-muser", "xu", "overlap", "greenwood-williamson", "bush"]
Convention = Literal["persson", "surface-topography", "profile1d", "grid"]
Detrend = Literal["none", "mean", "plane", "curvature"]
Window = Literal["none", "hann", "blackman"]
Boundary = Literal["periodic", "free"]
Start = Literal["flat", "hertz", "cylinder"]
AreaEnhancement = Literal["slopes", "none"]

class TopographyLike(Protocol):
    """A SurfaceTopography Topography: heights indexed [x, y], sizes (Lx, Ly) in m."""

    physical_sizes: Sequence[float]
    def heights(self) -> FloatArray: ...

def version() -> str: ...

class Spectrum:
    """Isotropic roughness power spectrum C(q), Persson's normalisation (m⁴)."""

    @staticmethod
    def self_affine(
        hurst: float,
        q_l: float,
        q_s: float,
        *,
        q_r: Optional[float] = None,
        rms_height: Optional[float] = None,
        rms_slope: Optional[float] = None,
        c_r: Optional[float] = None,
    ) -> Spectrum:
        """Self-affine with roll-off; exactly one amplitude (rms height m, rms slope, C(q_r) m⁴)."""
    @staticmethod
    def example() -> Spectrum:
        """The CLI's --example: H = 0.8, q_l = 1e4, q_r = 1e5, q_s = 1e8 1/m, h_rms = 1 µm."""
    @staticmethod
    def tabulated(
        q: ArrayLike, c: ArrayLike, convention: Convention = "persson", size: Optional[float] = None
    ) -> Spectrum:
        """Points (q, C) in the given convention (`grid` needs the side `size`, m)."""
    @staticmethod
    def from_csv(
        path: PathLike, convention: Convention = "persson", size: Optional[float] = None
    ) -> Spectrum:
        """A two-column CSV file q, C (the CLI's --psd)."""
    @staticmethod
    def from_file(
        path: PathLike,
        *,
        size: Optional[Sequence[float]] = None,
        pixel_size: Optional[float] = None,
        periodic: bool = False,
        detrend: Optional[Detrend] = None,
        window: Optional[Window] = None,
        fill_undefined: bool = False,
        q_max: Optional[float] = None,
        channel: Optional[str] = None,
    ) -> Spectrum:
        """The spectrum of a measured surface file (the CLI's --surface)."""
    @staticmethod
    def sum(spectra: Sequence[Spectrum]) -> Spectrum:
        """Two (or more) rough bodies: C = C1 + C2 (the CLI's --psd2/--surface2)."""
    @staticmethod
    def combine(
        paths: Sequence[PathLike],
        *,
        sizes: Optional[Sequence[Optional[float]]] = None,
        pixel_sizes: Optional[Sequence[Optional[float]]] = None,
        tip_radii: Optional[Sequence[Optional[float]]] = None,
        periodic: bool = False,
        detrend: Optional[Detrend] = None,
        window: Optional[Window] = None,
        q_max: Optional[float] = None,
    ) -> Spectrum:
        """One spectrum from several measurements (the CLI's repeated --surface): mode-weighted mean."""
    @staticmethod
    def from_height_map(
        heights: FloatArray,
        pixel_size: Union[float, Tuple[float, float]],
        *,
        periodic: bool = False,
        detrend: Optional[Detrend] = None,
        window: Optional[Window] = None,
        q_max: Optional[float] = None,
    ) -> Spectrum:
        """The spectrum of a height map (rows along y, m) with pixel size Δ or (Δx, Δy), m."""
    @staticmethod
    def from_topography(
        topography: TopographyLike,
        *,
        periodic: Optional[bool] = None,
        detrend: Optional[Detrend] = None,
        window: Optional[Window] = None,
        q_max: Optional[float] = None,
    ) -> Spectrum:
        """The spectrum of a SurfaceTopography Topography (duck-typed)."""
    @overload
    def c(self, q: float) -> float: ...
    @overload
    def c(self, q: Union[Sequence[float], FloatArray]) -> FloatArray: ...
    @property
    def q_l(self) -> float: ...
    @property
    def q_s(self) -> float: ...
    @property
    def description(self) -> Optional[str]: ...
    @overload
    def rms_height(self, q_min: Optional[float] = None, q_max: Optional[float] = None, *, error_bound: Literal[False] = False) -> float: ...
    @overload
    def rms_height(self, q_min: Optional[float] = None, q_max: Optional[float] = None, *, error_bound: Literal[True]) -> Tuple[float, float]: ...
    @overload
    def rms_slope(self, q_min: Optional[float] = None, q_max: Optional[float] = None, *, error_bound: Literal[False] = False) -> float: ...
    @overload
    def rms_slope(self, q_min: Optional[float] = None, q_max: Optional[float] = None, *, error_bound: Literal[True]) -> Tuple[float, float]: ...
    @overload
    def rms_curvature(self, q_min: Optional[float] = None, q_max: Optional[float] = None, *, error_bound: Literal[False] = False) -> float: ...
    @overload
    def rms_curvature(self, q_min: Optional[float] = None, q_max: Optional[float] = None, *, error_bound: Literal[True]) -> Tuple[float, float]: ...
    def report(self, q_min: Optional[float] = None, q_max: Optional[float] = None, points: int = 11) -> Report:
        """`persson spectrum --json`."""

def analyse_height_map(
    heights: FloatArray,
    pixel_size: Union[float, Tuple[float, float]],
    *,
    periodic: bool = False,
    detrend: Optional[Detrend] = None,
    window: Optional[Window] = None,
    q_max: Optional[float] = None,
) -> Report:
    """`persson spectrum --surface FILE --json` for an array."""

def anisotropy(
    heights: FloatArray,
    size: Union[float, Tuple[float, float]],
    *,
    periodic: bool = False,
    detrend: Optional[Detrend] = None,
    window: Optional[Window] = None,
) -> Report:
    """`persson anisotropy --surface FILE --json` for an array: peklenik_number,
    principal_direction, texture_aspect_ratio (Str), autocorrelation_length (Sal),
    texture_direction (Std)."""

def spectrum_2d(
    heights: FloatArray,
    size: Union[float, Tuple[float, float]],
    *,
    periodic: bool = False,
    detrend: Optional[Detrend] = None,
    window: Optional[Window] = None,
) -> Tuple[FloatArray, FloatArray, FloatArray]:
    """(qx, qy, C): the 2-D spectrum C(q_x, q_y) (ny × nx, m⁴; q = 0 at index n/2)."""

def contact_modulus(
    young: float, poisson: float, young2: Optional[float] = None, poisson2: Optional[float] = None
) -> float:
    """E* from 1/E* = (1 − ν₁²)/E₁ + (1 − ν₂²)/E₂ (second body rigid when absent)."""

@overload
def g(spectrum: Spectrum, contact_modulus: float, pressure: ArrayLike, zeta: Optional[ArrayLike] = None, *, error_bound: Literal[False] = False) -> Union[float, FloatArray]: ...
@overload
def g(spectrum: Spectrum, contact_modulus: float, pressure: ArrayLike, zeta: Optional[ArrayLike] = None, *, error_bound: Literal[True]) -> Tuple[Union[float, FloatArray], Union[float, FloatArray]]: ...
@overload
def contact_area(
    spectrum: Spectrum,
    contact_modulus: float,
    pressure: ArrayLike,
    theory: Theory = "original",
    gamma: Optional[float] = None,
    *,
    zeta: Optional[ArrayLike] = None,
    tolerance: float = 1e-12,
    error_bound: Literal[False] = False,
) -> Union[float, FloatArray]:
    """A/A0 at nominal pressures σ0 and magnifications ζ (default q_s/q_l), broadcast."""
@overload
def contact_area(
    spectrum: Spectrum,
    contact_modulus: float,
    pressure: ArrayLike,
    theory: Theory = "original",
    gamma: Optional[float] = None,
    *,
    zeta: Optional[ArrayLike] = None,
    tolerance: float = 1e-12,
    error_bound: Literal[True],
) -> Tuple[Union[float, FloatArray], Union[float, FloatArray]]: ...
def kappa(law: Literal["bush", "persson"] = "persson") -> float:
    """κ_Bush = √(2π), κ_Persson = √(8/π)."""
def low_load_kappa(theory: Theory = "original", gamma: Optional[float] = None) -> float: ...
def area(
    spectrum: Spectrum,
    contact_modulus: float,
    pressure: ArrayLike,
    theory: Theory = "original",
    gamma: Optional[float] = None,
    *,
    zeta: Optional[float] = None,
    tolerance: float = 1e-12,
    yield_stress: Optional[float] = None,
) -> Report:
    """`persson area --json`."""
def magnification(
    spectrum: Spectrum, contact_modulus: float, pressure: float, zeta: Optional[ArrayLike] = None, *, points: int = 41
) -> Report:
    """`persson magnification --json`."""
def kappa_report(
    spectrum: Optional[Spectrum] = None, contact_modulus: Optional[float] = None, pressure: Optional[ArrayLike] = None
) -> Report:
    """`persson kappa --json`."""
def theories(
    spectrum: Spectrum,
    contact_modulus: float,
    pressure: ArrayLike,
    theories: Optional[Sequence[Theory]] = None,
    *,
    zeta: Optional[float] = None,
    tolerance: Optional[float] = None,
) -> Report:
    """The scene output `theories`: A/A0 of every theory against load."""
def separation(spectrum: Spectrum, contact_modulus: float, pressure: ArrayLike, *, tolerance: float = 1e-10) -> Report:
    """`persson separation --json`."""
def friction(
    spectrum: Spectrum,
    velocity: ArrayLike,
    pressure: ArrayLike,
    temperature: Optional[ArrayLike] = None,
    *,
    master_curve: Optional[str | os.PathLike[str]] = None,
    frequency_unit: Optional[Literal["rad/s", "Hz"]] = None,
    prony: Optional[str | os.PathLike[str]] = None,
    standard_linear_solid: Optional[Sequence[float]] = None,
    wlf: Optional[Sequence[float]] = None,
    shift_table: Optional[str | os.PathLike[str]] = None,
    reference_temperature: Optional[float] = None,
    vertical_shift: Optional[Literal["none", "entropic", "table"]] = None,
    poisson: float = 0.5,
    q1: Optional[float] = None,
    q1_rms_slope: Optional[float] = None,
    gamma: float = 0.5,
    tolerance: float = 1e-8,
    points_per_decade: int = 4,
    flash_temperature: bool = False,
    thermal_conductivity: Optional[float] = None,
    density: Optional[float] = None,
    heat_capacity: Optional[float] = None,
) -> Report:
    """`persson friction --json` (Persson's rubber friction) plus arrays of shape
    (temperatures, pressures, velocities): `friction_coefficient`, `contact_fraction`,
    their `_error_bound`s and, with `flash_temperature=True`, `flash_friction_coefficient`,
    `flash_contact_fraction`, `flash_temperature`; 1-D `temperature`, `nominal_pressure`,
    `velocity`."""
def separation_density(
    spectrum: Spectrum,
    contact_modulus: float,
    pressure: ArrayLike,
    *,
    density_points: int = 101,
    tolerance: float = 1e-10,
) -> Report:
    """`persson separation --separation-density --json`: P(u) per pressure."""
def mean_separation(
    spectrum: Spectrum, contact_modulus: float, pressure: ArrayLike, *, tolerance: float = 1e-10
) -> dict[str, FloatArray]:
    """ū (m), K (unit of E*/m), U_el (J/m²) and their error bounds as arrays."""
def stress(
    start: Optional[Start],
    g: ArrayLike,
    *,
    table: Optional[Tuple[ArrayLike, ArrayLike]] = None,
    table_normalisation: float = 1e-6,
    yield_ratio: Optional[float] = None,
    sigma_ratio: Optional[ArrayLike] = None,
    points: int = 201,
    tolerance: float = 1e-12,
) -> Report:
    """`persson stress --json`: σH P against σ/σH at each G."""
def stress_physical(
    spectrum: Spectrum,
    contact_modulus: float,
    zeta: ArrayLike,
    start: Start = "flat",
    *,
    peak_pressure: Optional[float] = None,
    ball: Optional[Tuple[float, float]] = None,
    cylinder: Optional[Tuple[float, float]] = None,
    yield_stress: Optional[float] = None,
    points: int = 201,
    tolerance: float = 1e-12,
) -> Report:
    """P(σ) in the pressure unit at magnifications ζ (scene output `stress` with `zeta`)."""
def run_scene(scene: Union[PathLike, dict[str, Any]]) -> Report:
    """`persson run SCENE --json`."""
def synthesize(spectrum: Spectrum, grid: int, *, size: Optional[float] = None, seed: int = 1) -> FloatArray:
    """A grid × grid Gaussian surface of side `size` (default 2π/q_l), m."""
def bem_solve(
    heights: FloatArray,
    size: float,
    contact_modulus: float,
    *,
    pressure: Optional[float] = None,
    approach: Optional[float] = None,
    boundary: Boundary = "periodic",
    yield_stress: Optional[float] = None,
    tolerance: float = 1e-10,
    max_iterations: int = 10000,
) -> Tuple[FloatArray, FloatArray, dict[str, Any]]:
    """One FFT-BEM solve: (pressure N×N, gap N×N, summary)."""
def bem_rough(
    contact_modulus: float,
    pressure: Optional[ArrayLike] = None,
    *,
    heights: Optional[FloatArray] = None,
    size: Optional[float] = None,
    spectrum: Optional[Spectrum] = None,
    grid: Optional[int] = None,
    seed: int = 1,
    boundary: Boundary = "periodic",
    yield_stress: Optional[float] = None,
    bins: Optional[int] = None,
    tolerance: float = 1e-10,
    max_iterations: int = 10000,
    work_of_adhesion: Optional[float] = None,
    adhesion_range: Optional[float] = None,
    adhesion: Literal["maugis", "exponential"] = "maugis",
    mean_gap: Optional[ArrayLike] = None,
    approach: Optional[ArrayLike] = None,
    adhesive_iteration: Literal["auto", "plain", "preconditioned"] = "auto",
) -> Report:
    """`persson bem rough --json`; with `work_of_adhesion`, `adhesion_range` and
    `mean_gap` (or `approach`, periodic or free) instead of `pressure`,
    `persson bem rough --work-of-adhesion --json` (`adhesive_iteration` is
    `--adhesive-iteration`)."""
def bem_hertz(
    *,
    grid: Optional[int] = None,
    boundary: Boundary = "free",
    size: float = 1.0,
    radius: float = 1.0,
    contact_modulus: float = 1.0,
    contact_radius: Optional[float] = None,
    tolerance: float = 1e-10,
    max_iterations: int = 10000,
    yield_stress: Optional[float] = None,
    grids: Optional[Sequence[int]] = None,
    subsurface: bool = False,
    poisson: Optional[float] = None,
    work_of_adhesion: Optional[float] = None,
    adhesion_range: Optional[float] = None,
    adhesion: Optional[Literal["maugis", "exponential"]] = None,
) -> Report:
    """`persson bem hertz --json`, a scene's `bem_hertz`: one grid (default 256) the validation, several η per grid; `yield_stress` adds the plastic disc, `subsurface` the stress on the axis, `work_of_adhesion` the adhesive sphere."""
def contact_patches(
    pressure: FloatArray,
    size: float,
    *,
    connectivity: Literal["four", "eight"] = "four",
    boundary: Boundary = "periodic",
    bins_per_decade: int = 5,
) -> Report:
    """`bem rough --patches` of one N × N pressure field: patches, area distribution, pressure tail."""
def subsurface_stress(
    pressure: FloatArray,
    size: float,
    depth: ArrayLike,
    *,
    poisson: float = 0.3,
    boundary: Boundary = "periodic",
    tensile_yield_stress: Optional[float] = None,
) -> Report:
    """`bem rough --subsurface` of one N × N pressure field; `von_mises_stress`: one N × N array per depth."""
def compare(
    spectrum: Spectrum,
    contact_modulus: float,
    pressure: Optional[ArrayLike] = None,
    *,
    heights: Optional[FloatArray] = None,
    size: Optional[float] = None,
    periodic: bool = False,
    grid: int = 256,
    levels: int = 3,
    seeds: int = 1,
    seed: int = 1,
    alpha: Optional[float] = 0.7,
    pixels_per_wavelength: float = 4.0,
    tolerance: float = 1e-10,
    max_iterations: int = 10000,
    bins: int = 50,
    histogram_pressure: Optional[float] = None,
    data: Optional[PathLike] = None,
    data_histogram: Optional[PathLike] = None,
    yield_stress: Optional[float] = None,
    leakage: bool = False,
    viscosity: Optional[float] = None,
    pressure_drop: Optional[float] = None,
    inlet_pressure: Optional[float] = None,
    outlet_pressure: Optional[float] = None,
    seal_width: float = 0.001,
    seal_length: float = 0.001,
    percolation_threshold: float = 0.42,
    conductivity: Optional[ArrayLike] = None,
    resistivity: Optional[ArrayLike] = None,
    gas_conductivity: Optional[float] = None,
    mean_free_path: Optional[float] = None,
    work_of_adhesion: Optional[ArrayLike] = None,
    adhesion_range: Optional[float] = None,
    adhesion: Literal["maugis", "exponential"] = "maugis",
) -> Report:
    """`persson compare --json` (with `yield_stress`: `compare --yield-stress`; with `leakage` / `conductivity` / `resistivity`: `compare --leakage / --conductance`, key `transport`)."""
def adhesion(
    spectrum: Spectrum,
    contact_modulus: float,
    work_of_adhesion: float,
    pressure: Optional[ArrayLike] = None,
    *,
    zeta: Optional[float] = None,
    points: int = 11,
    area_enhancement: AreaEnhancement = "slopes",
    adhesion_range: Optional[float] = None,
    tolerance: float = 1e-5,
) -> Report:
    """`persson adhesion --json`: Δγ_eff(ζ) and the stickiness verdict; A/A0 and the
    pull-off stress at the nominal pressures (≤ 0 allowed)."""
def ensemble(
    spectrum: Spectrum,
    contact_modulus: float,
    pressure: ArrayLike,
    *,
    grid: int = 64,
    levels: int = 3,
    seeds: int = 4,
    seed: int = 1,
    pixels_per_wavelength: float = 4.0,
    tolerance: float = 1e-10,
    max_iterations: int = 10000,
    client: Any = None,
    threads: int = 0,
    timeout: str = "10s",
) -> Report:
    """`persson compare ensemble --json`: the BEM on seeds × grids, here or on Dask
    (`client`: a dask.distributed Client or a scheduler address)."""
def surrogates(
    heights: ArrayLike,
    size: float,
    contact_modulus: float,
    pressure: ArrayLike,
    *,
    count: int = 8,
    kind: str = "phase",
    iterations: int = 200,
    seed: int = 1,
    boundary: Boundary = "periodic",
    tolerance: float = 1e-8,
    spectrum: Optional[Spectrum] = None,
    client: Any = None,
    timeout: str = "10s",
) -> Report:
    """`persson surrogates --json`: the FFT-BEM on the map and on `count` surrogates
    of its spectrum, here or on Dask (`client`)."""
def conductance(
    spectrum: Spectrum,
    contact_modulus: float,
    pressure: ArrayLike,
    *,
    conductivity: Optional[ArrayLike] = None,
    resistivity: Optional[ArrayLike] = None,
    gas_conductivity: Optional[float] = None,
    mean_free_path: Optional[float] = None,
    gap_table: Optional[Tuple[ArrayLike, ArrayLike]] = None,
    tolerance: float = 1e-9,
) -> dict[str, FloatArray]:
    """Contact conductance against load: K/A0, h_c, h_e, h_gap and error bounds (`persson conductance`)."""
def leakage(
    spectrum: Spectrum,
    contact_modulus: float,
    pressure: ArrayLike,
    *,
    viscosity: float,
    pressure_drop: Optional[float] = None,
    inlet_pressure: Optional[float] = None,
    outlet_pressure: Optional[float] = None,
    seal_width: float = 1e-3,
    seal_length: float = 1e-3,
    percolation_threshold: float = 0.42,
    tolerance: float = 1e-9,
) -> dict[str, npt.NDArray[Any]]:
    """Leak rate of a seal against load: critical junction and effective medium (`persson leakage`)."""
