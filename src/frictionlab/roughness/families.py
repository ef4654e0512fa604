"""The paper's figure families as tables (Figs 6a, 6b, 7 and 8).

* :func:`wedge_cases` (Fig 6a): mu/mu0 vs beta of the six wedge cases A-F;
* :func:`generic_cases` (Fig 6b): the same six cases for smooth ("generic") 1-D roughness
  with the same mean face slopes (:class:`~frictionlab.roughness.generators.SmoothWedgeProfile`);
* :func:`surfaces_2d_vs_beta` (Fig 7): identical 2-D product sinusoids, symmetric and
  asymmetric wavelengths, vs beta;
* :func:`wavelength_map` (Fig 8): the 25 combinations lambda_x, lambda_y in
  {1, 1.5, 2, 2.5, 3} pi at beta = 0, 45, 90 degrees;
* :func:`adhesion_cases` (Fig 10), :func:`wear_cases` (Fig 11),
  :func:`hierarchy_1d_cases` (Fig 12), :func:`hierarchy_2d_cases` (Fig 13),
  :func:`hierarchy_wear_case` (Fig 14): the adhesion, wear and hierarchy results
  (their own result objects, with undefined values masked).

Geometry the paper does not give is chosen here: the
wedge angles 30/15 and 20/10 degrees, and the half-cosine faces for the generic profile
(this module's choice: the paper states only mean slopes). The paper's sinusoids are
``A sin(2 pi x/lambda)`` with A = 1 and lambda = 2 pi in units of a length ``a``: here
:data:`FAMILY_LENGTH` = 1 um for the single-level surfaces and :data:`HIERARCHY_LENGTH`
= 1 mm for the outermost level of a hierarchy (its levels shrink by 10 each), so every
length is physical; the results depend only on slopes in full contact, and adhesion loads
scale with ``k_c a``. Every family returns a :class:`FamilyTable` of read-only columns.
Lengths are in m.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from types import MappingProxyType

import numpy as np
from numpy.typing import ArrayLike

from frictionlab._arrays import FloatArray, finite_vector
from frictionlab.errors import ParameterError
from frictionlab.roughness.adhesion import AdhesionSweep, adhesion_sweep
from frictionlab.roughness.closed_forms import wedge_friction
from frictionlab.roughness.generators import flat, sinusoid, smooth_wedge, wedge
from frictionlab.roughness.hierarchy import (
    HierarchyResult,
    HierarchyWearHistory,
    hierarchy_friction,
    hierarchy_wear,
    self_similar_levels,
    wedge_hierarchy,
)
from frictionlab.roughness.lattice import LatticeSettings, check_betas, friction_polar
from frictionlab.roughness.surface import Profile, Surface
from frictionlab.roughness.wear import WearHistory, WearSettings, wear_history

__all__ = [
    "AD_LOADS",
    "CASE_DESCRIPTIONS",
    "FAMILY_LENGTH",
    "FAMILY_WEAR",
    "HIERARCHY_LENGTH",
    "WEDGE_CASES",
    "FamilyTable",
    "adhesion_cases",
    "case_angles",
    "generic_cases",
    "hierarchy_1d_cases",
    "hierarchy_2d_cases",
    "hierarchy_wear_case",
    "surfaces_2d_vs_beta",
    "wavelength_map",
    "wavelength_matrix",
    "wear_cases",
    "wedge_cases",
]

#: The six configuration types of Fig 6 as (phi1, phi2, phi3, phi4)
#: built from a steep angle "S" and a shallow angle "s" (0: flat face pair).
WEDGE_CASES: Mapping[str, tuple[str, str, str, str]] = MappingProxyType(
    {
        "A": ("S", "S", "0", "0"),  # flat on symmetric
        "B": ("S", "S", "S", "S"),  # symmetric on symmetric
        "C": ("S", "s", "0", "0"),  # flat on asymmetric, first slope steeper
        "D": ("s", "S", "0", "0"),  # flat on asymmetric, first slope shallower
        "E": ("S", "s", "S", "s"),  # rough/rough, phi1 = phi3 > phi2 = phi4
        "F": ("s", "S", "s", "S"),  # rough/rough, phi1 = phi3 < phi2 = phi4
    }
)

#: What each case of :data:`WEDGE_CASES` is, for legends (lower surface on upper surface).
CASE_DESCRIPTIONS: Mapping[str, str] = MappingProxyType(
    {
        "A": "flat on symmetric teeth",
        "B": "symmetric on symmetric teeth",
        "C": "flat on asymmetric teeth, steep face first",
        "D": "flat on asymmetric teeth, shallow face first",
        "E": "asymmetric on asymmetric, steep faces aligned",
        "F": "asymmetric on asymmetric, shallow faces aligned",
    }
)

_DEFAULT_BETAS = tuple(float(b) for b in range(0, 91, 5))


@dataclass(frozen=True)
class FamilyTable:
    """A named table of equal-length columns with units (``"1"``: dimensionless)."""

    name: str
    description: str
    columns: Mapping[str, FloatArray]
    units: Mapping[str, str]

    def __post_init__(self) -> None:
        frozen = {}
        for key, value in self.columns.items():
            arr = np.array(value, dtype=np.float64, copy=True)
            arr.setflags(write=False)
            frozen[key] = arr
        object.__setattr__(self, "columns", MappingProxyType(frozen))
        object.__setattr__(self, "units", MappingProxyType(dict(self.units)))

    def __getitem__(self, key: str) -> FloatArray:
        return self.columns[key]


def case_angles(case: str, angles_deg: Sequence[float]) -> tuple[float, float, float, float]:
    """(phi1, phi2, phi3, phi4) in degrees of case A-F for (steep, shallow) angles."""
    if case not in WEDGE_CASES:
        raise ParameterError("case", case, f"one of {sorted(WEDGE_CASES)}")
    steep, shallow = _angle_pair(angles_deg)
    table = {"S": steep, "s": shallow, "0": 0.0}
    a, b, c, d = (table[k] for k in WEDGE_CASES[case])
    return a, b, c, d


def _angle_pair(angles_deg: Sequence[float]) -> tuple[float, float]:
    try:
        steep, shallow = (float(a) for a in angles_deg)
    except (TypeError, ValueError):
        raise ParameterError("angles_deg", angles_deg, "(steep, shallow) in degrees") from None
    if not (0.0 < shallow < steep < 90.0):
        raise ParameterError("angles_deg", angles_deg, "0 < shallow < steep < 90 degrees")
    return steep, shallow


def _pair(case: str, angles: tuple[float, ...], smooth: bool) -> tuple[Profile, Profile]:
    make = smooth_wedge if smooth else wedge
    lower = make((angles[0], angles[1]), 1.0)
    upper = flat() if angles[2] == 0.0 else make((angles[2], angles[3]), 1.0)
    return lower, upper


def _six_cases(
    name: str,
    description: str,
    mu0: float,
    angles_deg: Sequence[float],
    beta_deg: ArrayLike,
    compute: str,
    settings: LatticeSettings | None,
) -> FamilyTable:
    betas = check_betas(beta_deg)
    columns: dict[str, FloatArray] = {"beta_deg": betas}
    units = {"beta_deg": "deg"}
    for case in WEDGE_CASES:
        angles = case_angles(case, angles_deg)
        if compute == "closed_form":
            mu_x, mu_y = wedge_friction(mu0, angles, betas)  # Eqs 15-16
            definition = settings.mu_definition if settings is not None else "magnitude"
            if definition == "magnitude":
                mu = np.hypot(mu_x, mu_y)
            else:
                rad = np.radians(betas)
                mu = mu_x * np.cos(rad) + mu_y * np.sin(rad)
        else:
            lower, upper = _pair(case, angles, smooth=compute == "generic")
            polar = friction_polar(lower, upper, mu0, betas, settings=settings)
            mu_x, mu_y, mu = polar.mu_x, polar.mu_y, polar.mu
        columns[f"mu_over_mu0_{case}"] = mu / mu0
        columns[f"mu_x_over_mu0_{case}"] = mu_x / mu0
        columns[f"mu_y_over_mu0_{case}"] = mu_y / mu0
    return FamilyTable(name, description, columns, units)


def _check_mu0(mu0: float) -> float:
    if not (isinstance(mu0, int | float) and math.isfinite(mu0) and mu0 > 0.0):
        raise ParameterError("mu0", mu0, "a finite local coefficient > 0")
    return float(mu0)


def wedge_cases(
    mu0: float = 0.3,
    angles_deg: Sequence[float] = (30.0, 15.0),
    beta_deg: ArrayLike = _DEFAULT_BETAS,
    *,
    method: str = "closed_form",
    settings: LatticeSettings | None = None,
) -> FamilyTable:
    """Fig 6a: mu/mu0, mu_x/mu0, mu_y/mu0 vs beta for the six wedge cases A-F.

    ``angles_deg = (steep, shallow)`` in degrees; the case definitions are
    :data:`WEDGE_CASES`. ``method="closed_form"`` (Eqs 15-16, exact) or ``"lattice"``
    (the discrete lattice with ``settings``; default: full contact, default resolution).
    Columns: ``beta_deg`` and ``mu_over_mu0_<case>``, ``mu_x_over_mu0_<case>``,
    ``mu_y_over_mu0_<case>`` for each case.
    """
    m = _check_mu0(mu0)
    if method not in ("closed_form", "lattice"):
        raise ParameterError("method", method, "'closed_form' or 'lattice'")
    steep, shallow = _angle_pair(angles_deg)
    return _six_cases(
        "wedge_cases",
        f"Six wedge cases (Fig 6a), steep {steep:g} deg, shallow {shallow:g} deg, mu0 = {m:g}, "
        f"{'Eqs 15-16' if method == 'closed_form' else 'discrete lattice'}",
        m,
        angles_deg,
        beta_deg,
        method,
        settings,
    )


def generic_cases(
    mu0: float = 0.3,
    angles_deg: Sequence[float] = (30.0, 15.0),
    beta_deg: ArrayLike = _DEFAULT_BETAS,
    *,
    settings: LatticeSettings | None = None,
) -> FamilyTable:
    """Fig 6b: the six cases A-F for smooth (half-cosine) faces with the wedges' mean slopes.

    Computed with the lattice (``settings``; default: full contact, 2000 stations, 400
    time samples). Columns as in :func:`wedge_cases`.
    """
    m = _check_mu0(mu0)
    steep, shallow = _angle_pair(angles_deg)
    return _six_cases(
        "generic_cases",
        f"Six generic 1-D cases (Fig 6b): half-cosine faces with mean slopes of {steep:g}/"
        f"{shallow:g} deg wedges, mu0 = {m:g}, discrete lattice",
        m,
        angles_deg,
        beta_deg,
        "generic",
        settings,
    )


#: The paper's unit length for the single-level sinusoids [m]: A = 1 um, lambda = 2 pi um.
FAMILY_LENGTH = 1e-6
#: The outermost level's unit length of the hierarchy families [m] (levels shrink by 10).
HIERARCHY_LENGTH = 1e-3


def _label(wavelengths: tuple[float, float], length: float = FAMILY_LENGTH) -> str:
    """``l2pi_3pi`` for wavelengths (2 pi, 3 pi) in units of ``length``."""
    return "l{:g}pi_{:g}pi".format(*(round(w / (math.pi * length), 9) for w in wavelengths))


def surfaces_2d_vs_beta(
    mu0: float = 0.3,
    beta_deg: ArrayLike = _DEFAULT_BETAS,
    *,
    wavelengths: Sequence[tuple[float, float]] = (
        (2.0 * math.pi * FAMILY_LENGTH, 2.0 * math.pi * FAMILY_LENGTH),
        (2.0 * math.pi * FAMILY_LENGTH, 3.0 * math.pi * FAMILY_LENGTH),
        (3.0 * math.pi * FAMILY_LENGTH, 2.0 * math.pi * FAMILY_LENGTH),
    ),
    amplitude: float = FAMILY_LENGTH,
    settings: LatticeSettings | None = None,
) -> FamilyTable:
    """Fig 7: mu/mu0 vs beta of identical surfaces A sin(2 pi x/lx) sin(2 pi y/ly), in phase.

    The first pair of ``wavelengths`` (m) defaults to the symmetric (2 pi, 2 pi) um surface,
    the others to the asymmetric (2 pi, 3 pi) and (3 pi, 2 pi) um; A = 1 um. ``settings``
    default: full contact, 64 x 64 stations per period, 64 time samples (ergodic or return
    travel). Columns: ``beta_deg`` and, per surface, ``mu_over_mu0_<label>``,
    ``mu_x_over_mu0_<label>``, ``mu_y_over_mu0_<label>`` with labels like ``l2pi_3pi``.
    """
    m = _check_mu0(mu0)
    betas = check_betas(beta_deg)
    settings = settings or LatticeSettings(load="full", time_samples=64)
    columns: dict[str, FloatArray] = {"beta_deg": betas}
    for pair in wavelengths:
        surface = sinusoid(amplitude, pair)
        polar = friction_polar(surface, surface, m, betas, settings=settings)
        label = _label((float(pair[0]), float(pair[1])), amplitude)
        columns[f"mu_over_mu0_{label}"] = polar.mu / m
        columns[f"mu_x_over_mu0_{label}"] = polar.mu_x / m
        columns[f"mu_y_over_mu0_{label}"] = polar.mu_y / m
    return FamilyTable(
        "surfaces_2d_vs_beta",
        f"Identical 2-D product sinusoids (Fig 7), A = {amplitude:g} m, mu0 = {m:g}; "
        "wavelengths in units of A",
        columns,
        {"beta_deg": "deg"},
    )


def wavelength_map(
    mu0: float = 0.3,
    factors: Sequence[float] = (1.0, 1.5, 2.0, 2.5, 3.0),
    beta_deg: Sequence[float] = (0.0, 45.0, 90.0),
    *,
    amplitude: float = FAMILY_LENGTH,
    settings: LatticeSettings | None = None,
) -> FamilyTable:
    """Fig 8: mu/mu0 of identical surfaces for lambda_x, lambda_y = factor * pi * A.

    A long table with one row per (beta, lambda_x, lambda_y): columns ``beta_deg``,
    ``lambda_x_over_pi``, ``lambda_y_over_pi``, ``mu_over_mu0``, ``mu_x_over_mu0``,
    ``mu_y_over_mu0``. :func:`wavelength_matrix` pivots one beta to the 5 x 5 matrix (rows
    lambda_x, columns lambda_y). ``settings`` default: full contact, 64 x 64 stations
    per period, 64 time samples.
    """
    m = _check_mu0(mu0)
    betas = check_betas(beta_deg)
    facs = finite_vector("factors", factors, "a non-empty list of positive multiples of pi")
    if np.any(facs <= 0.0):
        raise ParameterError("factors", factors, "a non-empty list of positive multiples of pi")
    settings = settings or LatticeSettings(load="full", time_samples=64)
    rows: dict[str, list[float]] = {
        k: []
        for k in (
            "beta_deg",
            "lambda_x_over_pi",
            "lambda_y_over_pi",
            "mu_over_mu0",
            "mu_x_over_mu0",
            "mu_y_over_mu0",
        )
    }
    results = {}
    for fx in facs:
        for fy in facs:
            surface = sinusoid(amplitude, (fx * math.pi * amplitude, fy * math.pi * amplitude))
            results[(fx, fy)] = friction_polar(surface, surface, m, betas, settings=settings)
    for k, beta in enumerate(betas):
        for fx in facs:
            for fy in facs:
                polar = results[(fx, fy)]
                rows["beta_deg"].append(float(beta))
                rows["lambda_x_over_pi"].append(float(fx))
                rows["lambda_y_over_pi"].append(float(fy))
                rows["mu_over_mu0"].append(float(polar.mu[k]) / m)
                rows["mu_x_over_mu0"].append(float(polar.mu_x[k]) / m)
                rows["mu_y_over_mu0"].append(float(polar.mu_y[k]) / m)
    return FamilyTable(
        "wavelength_map",
        f"Wavelength map (Fig 8): identical A sin sin surfaces, A = {amplitude:g} m, mu0 = {m:g}",
        {k: np.array(v) for k, v in rows.items()},
        {"beta_deg": "deg"},
    )


def wavelength_matrix(
    table: FamilyTable, beta_deg: float, column: str = "mu_over_mu0"
) -> tuple[FloatArray, FloatArray, FloatArray]:
    """Pivot a :func:`wavelength_map` table: (lambda_x/pi, lambda_y/pi, matrix[ix, iy])."""
    sel = table["beta_deg"] == beta_deg
    if not np.any(sel):
        raise ParameterError("beta_deg", beta_deg, f"one of {sorted(set(table['beta_deg']))}")
    fx = np.unique(table["lambda_x_over_pi"][sel])
    fy = np.unique(table["lambda_y_over_pi"][sel])
    matrix = np.full((fx.size, fy.size), np.nan)
    ix = np.searchsorted(fx, table["lambda_x_over_pi"][sel])
    iy = np.searchsorted(fy, table["lambda_y_over_pi"][sel])
    matrix[ix, iy] = table[column][sel]
    return fx, fy, matrix


# --------------------------------------------------------------------------- Figs 10-14

#: Loads per spring of the adhesion family, Fig 10, in units of k_c A.
AD_LOADS = (3.0, 2.0, 1.5, 1.0, 0.5, 0.25, 0.1, 0.0, -0.1, -0.25)


def adhesion_cases(
    mu0: float = 0.3,
    loads: Sequence[float] = AD_LOADS,
    *,
    settings: LatticeSettings | None = None,
) -> dict[str, AdhesionSweep]:
    """Fig 10: z = A sin(x/A) (A = 1 um, lambda = 2 pi um), k_c = 1 N/m, k_t = k_c/2.

    ``loads`` per spring are in units of ``k_c A`` (the sweeps record them in N).
    ``"sine/sine"``: identical in-phase surfaces at beta = 0 and 90 deg; ``"flat/sine"``:
    a flat upper surface at beta = 0. ``settings`` default: 2000 stations, 200 time
    samples (enough to resolve the tensile fraction).
    """
    m = _check_mu0(mu0)
    settings = settings or LatticeSettings(stations=2000, time_samples=200)
    a = FAMILY_LENGTH
    sine = sinusoid(a, 2.0 * math.pi * a)
    newtons = np.asarray(loads, dtype=np.float64) * settings.k_c * a
    return {
        "sine/sine": adhesion_sweep(sine, sine, m, newtons, [0.0, 90.0], settings=settings),
        "flat/sine": adhesion_sweep(flat(), sine, m, newtons, [0.0], settings=settings),
    }


#: Archard inputs of the wear families (their values only set the time scale T_w).
FAMILY_WEAR = WearSettings(
    wear_coefficient=1e-4, hardness=2e9, normal_load=10.0, velocity=0.1, nominal_area=1e-4
)


def wear_cases(
    mu0: float = 0.3,
    samples: int = 21,
    *,
    wear: WearSettings = FAMILY_WEAR,
    settings: LatticeSettings | None = None,
) -> dict[str, WearHistory]:
    """Fig 11: mu(t) to mu0 at T_w.

    ``"flat/wedge"``, ``"wedge/wedge"``: symmetric 30 deg wedges (lambda = 1 mm), beta = 0,
    45, 90 deg, Eqs 15-16 at tan(phi) = B tan(30 deg); ``"2d"``: identical sin x sin y
    surfaces (A = 1 um, lambda = 2 pi um) in full contact, beta = 0, 15, 30, 45 deg, on the
    lattice (``settings`` default: 64 x 64 stations, 64 time samples).
    """
    m = _check_mu0(mu0)
    settings = settings or LatticeSettings(time_samples=64)
    w = wedge(30.0, 1e-3)
    a = FAMILY_LENGTH
    s = sinusoid(a, (2.0 * math.pi * a, 2.0 * math.pi * a))
    betas_1d, betas_2d = (0.0, 45.0, 90.0), (0.0, 15.0, 30.0, 45.0)
    return {
        "flat/wedge": wear_history(w, flat(), m, betas_1d, wear, samples=samples),
        "wedge/wedge": wear_history(w, w, m, betas_1d, wear, samples=samples),
        "2d": wear_history(s, s, m, betas_2d, wear, samples=samples, settings=settings),
    }


#: Ratio of successive levels' sizes in the paper's hierarchies (Figs 12-14).
_LEVEL_RATIO = 10.0


def _self_similar(
    lower: Surface,
    upper: Surface,
    levels: int,
    mu0: float,
    beta_deg: ArrayLike,
    settings: LatticeSettings,
) -> HierarchyResult:
    """mu_n of ``levels`` self-similar copies of the pair (ratio 10), invalid levels masked."""
    pairs = self_similar_levels(lower, upper, levels, _LEVEL_RATIO)
    return hierarchy_friction(pairs, mu0, beta_deg, on_invalid="mask", settings=settings)


def hierarchy_1d_cases(
    mu0: float = 0.3, levels: int = 5, *, settings: LatticeSettings | None = None
) -> dict[str, HierarchyResult]:
    """Fig 12: mu_n for n = 0 ... ``levels`` at beta = 0 and 90 deg.

    ``"wedge <phi> flat/rough"`` and ``"wedge <phi> rough/rough"`` for phi = 10, 20, 30 deg
    (the closed-form recursion of Eqs 15-16; Eqs 33-34 at 90 deg), and ``"sine flat/rough"``,
    ``"sine rough/rough"``: self-similar sinusoids of slope amplitude 1 (A = 1 mm,
    lambda = 2 pi mm outermost, ratio 10) on the lattice (``settings`` default: 2000
    stations, 40 time samples, full contact). Levels beyond the validity domain are masked.
    """
    m = _check_mu0(mu0)
    settings = settings or LatticeSettings(stations=2000, time_samples=40)
    out: dict[str, HierarchyResult] = {}
    for phi in (10.0, 20.0, 30.0):
        for name, angles in (("flat/rough", (phi, phi, 0.0, 0.0)), ("rough/rough", (phi,) * 4)):
            out[f"wedge {phi:g} {name}"] = wedge_hierarchy(
                m, angles, [0.0, 90.0], levels, on_invalid="mask"
            )
    a = HIERARCHY_LENGTH
    sine = sinusoid(a, 2.0 * math.pi * a)
    for name, upper in (("flat/rough", flat()), ("rough/rough", sine)):
        out[f"sine {name}"] = _self_similar(sine, upper, levels, m, [0.0, 90.0], settings)
    return out


def hierarchy_2d_cases(
    mu0: float = 0.3,
    levels: int = 4,
    beta_deg: ArrayLike = (0.0, 15.0, 30.0, 45.0, 60.0, 75.0, 90.0),
    *,
    settings: LatticeSettings | None = None,
) -> dict[str, HierarchyResult]:
    """Fig 13: self-similar identical sin sin levels (A = 1 mm outermost,
    ratio 10) with wavelengths (2 pi, 2 pi), (2 pi, 3 pi) and (3 pi, 2 pi) A, vs beta, in
    full contact (``settings`` default: 32 x 32 stations, 16 time samples)."""
    m = _check_mu0(mu0)
    settings = settings or LatticeSettings(stations=32, time_samples=16)
    out: dict[str, HierarchyResult] = {}
    for pair in ((2.0, 2.0), (2.0, 3.0), (3.0, 2.0)):
        a = HIERARCHY_LENGTH
        lengths = (pair[0] * math.pi * a, pair[1] * math.pi * a)
        s = sinusoid(a, lengths)
        out[_label(lengths, a)] = _self_similar(s, s, levels, m, beta_deg, settings)
    return out


def hierarchy_wear_case(
    mu0: float = 0.3,
    levels: int = 3,
    samples_per_level: int = 11,
    *,
    wear: WearSettings = FAMILY_WEAR,
    settings: LatticeSettings | None = None,
) -> HierarchyWearHistory:
    """Fig 14: ``levels`` self-similar sin x sin y levels (ratio 10; A = 1 mm,
    lambda = 2 pi mm outermost), identical surfaces, beta = 0, worn innermost first
    (``settings`` default: 32 x 32 stations, 16 time samples, full contact)."""
    m = _check_mu0(mu0)
    settings = settings or LatticeSettings(stations=32, time_samples=16)
    a = HIERARCHY_LENGTH
    s = sinusoid(a, (2.0 * math.pi * a, 2.0 * math.pi * a))
    return hierarchy_wear(
        self_similar_levels(s, s, levels, _LEVEL_RATIO),
        m,
        [0.0],
        wear,
        samples_per_level=samples_per_level,
        settings=settings,
    )
