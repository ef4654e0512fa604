"""The elastic (BEM) load distribution against closed forms and an independent solve.

* Westergaard: a sinusoid on an elastic half-space (plane strain), contact width and
  pressure profile in closed form (Johnson, Contact Mechanics, Sec 13.2);
* Hertz: the low-load limit at the peak of a smooth 2-D bump (one peak per cell);
* an anisotropic self-affine surface solved here through ContactMechanics' system
  factory, with the friction law written out from Eqs 1-4 in the test: contact area and
  mu(beta) of :func:`elastic_polar` must agree.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from frictionlab.errors import ParameterError, ValidityError
from frictionlab.roughness import flat, from_array, sinusoid
from frictionlab.roughness.elastic import (
    ElasticSettings,
    elastic_contact,
    elastic_polar,
    pressure_sweep,
)

E_STAR = 1.0e9


def _westergaard(x: np.ndarray, lam: float, pbar: float, pstar: float) -> tuple[float, np.ndarray]:
    """Half-width a and pressure of a sinusoid of peak at x = 0 (Johnson Eq 13.17)."""
    s2 = pbar / pstar  # sin^2(pi a / lam)
    a = lam / math.pi * math.asin(math.sqrt(s2))
    arg = s2 - np.sin(np.pi * x / lam) ** 2
    p = np.where(arg > 0.0, 2.0 * pbar * np.cos(np.pi * x / lam) / s2 * np.sqrt(np.abs(arg)), 0.0)
    return a, p


@pytest.mark.slow
@pytest.mark.parametrize("fraction", [0.1, 0.5])
def test_westergaard_pressure(fraction: float) -> None:
    lam, n = 1e-3, 1024
    x = (np.arange(n) + 0.5) * lam / n - lam / 2
    h0 = 1e-5
    surface = from_array(h0 * np.cos(2 * np.pi * x / lam), lam)  # peak in the middle
    pstar = math.pi * E_STAR * h0 / lam  # full-contact pressure
    pbar = fraction * pstar
    state = elastic_contact(surface, flat(), pressure=pbar, modulus=E_STAR, tolerance=1e-6)
    a, p_ref = _westergaard(x, lam, pbar, pstar)
    assert state.contact_fraction == pytest.approx(2 * a / lam, abs=3.0 / n)
    l1 = np.abs(state.pressure - p_ref).mean() / pbar
    assert l1 < 5e-3
    assert state.pressure.mean() == pytest.approx(pbar, rel=1e-6)
    # the gap is zero in contact and positive outside
    assert np.all(state.gap[state.pressure > 0] < 1e-3 * h0)


def test_hertz_limit_of_a_bump() -> None:
    lam, n = 1e-3, 256
    k = 2 * math.pi / lam
    x = (np.arange(n) + 0.5) * lam / n
    h0 = 1e-6
    heights = 0.5 * h0 * (np.cos(k * x)[:, None] + np.cos(k * x)[None, :])
    surface = from_array(heights, (lam, lam))
    radius = 2.0 / (h0 * k * k)  # curvature h0 k^2 / 2 along each axis at the peak
    force = 4.0 * E_STAR * (0.07 * lam) ** 3 / (3.0 * radius)  # a = 0.07 lam by Hertz
    state = elastic_contact(
        surface, flat(), pressure=force / lam**2, modulus=E_STAR, tolerance=1e-7
    )
    a = (3.0 * force * radius / (4.0 * E_STAR)) ** (1.0 / 3.0)
    p0 = 3.0 * force / (2.0 * math.pi * a * a)
    assert a / lam < 0.1  # small contact: the Hertz limit applies
    assert state.contact_fraction == pytest.approx(math.pi * a * a / lam**2, rel=0.05)
    assert state.pressure.max() == pytest.approx(p0, rel=0.05)


def _anisotropic_self_affine(n: int, lam: float, rng: np.random.Generator) -> np.ndarray:
    """Self-affine heights (H = 0.8) with correlation 4x longer along y than along x."""
    qx = np.fft.fftfreq(n, d=lam / n) * 2 * math.pi
    qy = np.fft.rfftfreq(n, d=lam / n) * 2 * math.pi
    q = np.hypot(qx[:, None], 4.0 * qy[None, :])
    q0 = 2 * math.pi / lam
    with np.errstate(divide="ignore"):
        amp = np.where(q >= q0, q ** (-(1 + 0.8)), 0.0)
    amp[q > 2 * math.pi / (8 * lam / n)] = 0.0
    phase = np.exp(2j * math.pi * rng.random(amp.shape))
    heights = np.fft.irfft2(amp * phase, s=(n, n))
    heights -= heights.mean()
    return heights


def _slopes(h: np.ndarray, d: float) -> tuple[np.ndarray, np.ndarray]:
    """Periodic central differences (x along axis 0)."""
    gx = (np.roll(h, -1, axis=0) - np.roll(h, 1, axis=0)) / (2 * d)
    gy = (np.roll(h, -1, axis=1) - np.roll(h, 1, axis=1)) / (2 * d)
    return gx, gy


def _friction(mu0: float, p: np.ndarray, gx: np.ndarray, gy: np.ndarray, beta: float) -> tuple:
    """Eqs 1-4 written as vectors: F = N (n - mu0 t) per unit F_z, flat counter-face."""
    cb, sb = math.cos(beta), math.sin(beta)
    nvec = np.stack([-gx, -gy, np.ones_like(gx)]) / np.sqrt(1 + gx**2 + gy**2)
    tvec = np.stack([np.full_like(gx, cb), np.full_like(gx, sb), gx * cb + gy * sb])
    tvec = tvec / np.linalg.norm(tvec, axis=0)
    f = nvec - mu0 * tvec
    f = f / f[2]
    rough = (-(f[0] * p).sum() / p.sum(), -(f[1] * p).sum() / p.sum())
    # the flat family resists with mu0 along beta
    return 0.5 * (rough[0] + mu0 * cb), 0.5 * (rough[1] + mu0 * sb)


def test_against_an_independent_contactmechanics_solve() -> None:
    from ContactMechanics.Factory import make_system
    from SurfaceTopography import Topography

    n, lam = 128, 1e-4
    heights = _anisotropic_self_affine(n, lam, np.random.default_rng(7))
    d = lam / n
    gx, gy = _slopes(heights, d)
    heights *= 0.3 / math.sqrt(np.mean(gx**2 + gy**2))  # rms slope 0.3
    gx, gy = _slopes(heights, d)
    assert np.sqrt(np.mean(gy**2)) < 0.5 * np.sqrt(np.mean(gx**2))  # anisotropic
    pressure = 0.02 * E_STAR * 0.3  # a few per cent of contact
    system = make_system(
        substrate="periodic",
        surface=Topography(heights, (lam, lam), periodic=True),
        young=E_STAR,
    )
    sol = system.minimize_proxy(
        external_force=pressure * lam * lam, pentol=1e-8 * np.std(heights), maxiter=20000
    )
    assert sol.success
    p_ref = np.clip(sol.jac, 0.0, None) / (d * d)
    area_ref = np.count_nonzero(p_ref > 0) / p_ref.size
    assert 0.01 < area_ref < 0.3

    betas = np.arange(0.0, 360.0, 30.0)
    mu0 = 0.2
    polar = elastic_polar(
        from_array(heights, (lam, lam)), flat(), mu0, betas,
        pressure=pressure, modulus=E_STAR, tolerance=1e-6,
    )  # fmt: skip
    assert polar.contact_fraction_mean == pytest.approx(area_ref, rel=0.01)
    for b, mx, my in zip(betas, polar.mu_x, polar.mu_y, strict=True):
        rx, ry = _friction(mu0, p_ref, gx, gy, math.radians(b))
        assert mx == pytest.approx(rx, abs=2e-3)
        assert my == pytest.approx(ry, abs=2e-3)
    excess = polar.mu / mu0 - 1.0
    assert excess.min() > 0.01  # the slopes matter everywhere
    # the anisotropy axis: slopes are largest along x, so sliding along x meets them
    assert polar.mu[0] > polar.mu[3]


def test_flat_pair_is_mu0_and_one_solve() -> None:
    polar = elastic_polar(flat(), flat(), 0.3, [0, 45, 90], pressure=1e6, modulus=E_STAR,
                          stations=8)  # fmt: skip
    np.testing.assert_allclose(polar.mu, 0.3, rtol=1e-14)
    assert polar.contact_fraction_mean == 1.0 and len(polar.states) == 1


def test_two_rough_surfaces_use_the_composite_gap() -> None:
    """A sinusoid against its own negative in phase is flat contact; rolled: shifts average."""
    lam = 1e-3
    s = sinusoid(1e-5, [lam])
    polar = elastic_polar(s, s, 0.2, [0.0, 90.0], pressure=1e5, modulus=E_STAR,
                          stations=256, time_samples=8)  # fmt: skip
    assert len(polar.states) == 8
    # at zero shift the composite gap is flat: full contact
    assert polar.states[0].contact_fraction == 1.0
    assert polar.contact_fraction_min < 1.0
    # across the ridges (0 deg) the slopes resist; along them (90 deg) they do not
    assert polar.mu_projection[0] > polar.mu_projection[1] >= 0.2


def test_pressure_sweep_area_grows_linearly_at_low_load() -> None:
    lam, n = 1e-4, 128
    heights = _anisotropic_self_affine(n, lam, np.random.default_rng(3))
    heights *= 1e-6 / np.std(heights)
    surface = from_array(heights, (lam, lam))
    polars = pressure_sweep(surface, flat(), 0.2, [0, 90], [2e6, 1e6], modulus=E_STAR)
    a2, a1 = (p.contact_fraction_mean for p in polars)
    assert 1.6 < a2 / a1 < 2.2  # area nearly proportional to load (BEM, small contact)
    assert polars[0].mean_gap < polars[1].mean_gap


@pytest.mark.slow
def test_hardness_caps_the_pressure() -> None:
    lam, n = 1e-3, 128
    x = (np.arange(n) + 0.5) * lam / n
    k = 2 * math.pi / lam
    bump = from_array(5e-6 * (np.cos(k * x)[:, None] + np.cos(k * x)[None, :]), (lam, lam))
    hard = 3e6
    state = elastic_contact(bump, flat(), pressure=1e6, modulus=E_STAR, hardness=hard,
                            tolerance=1e-3)  # fmt: skip
    assert state.pressure.max() <= hard * (1 + 1e-3)
    assert state.plastic_fraction > 0.1
    assert state.pressure.mean() == pytest.approx(1e6, rel=1e-6)
    elastic = elastic_contact(bump, flat(), pressure=1e6, modulus=E_STAR)
    assert elastic.pressure.max() > 2 * hard  # the cap changed the field
    assert state.contact_fraction > elastic.contact_fraction
    with pytest.raises(ParameterError, match="hardness"):
        elastic_contact(sinusoid(1e-5, [lam]), flat(), pressure=1e6, modulus=E_STAR,
                        hardness=hard, stations=64)  # fmt: skip


def test_bad_settings_name_the_key() -> None:
    with pytest.raises(ParameterError, match="modulus"):
        ElasticSettings(pressure=1e6, modulus=-1.0)
    with pytest.raises(ParameterError, match="pressure"):
        ElasticSettings(pressure=0.0, modulus=1e9)
    with pytest.raises(ParameterError, match="hardness"):
        ElasticSettings(pressure=1e6, modulus=1e9, hardness=1e5)


def test_invalid_contact_raises_or_masks() -> None:
    from frictionlab.roughness import wedge

    w = wedge((60, 60), 1e-3)  # cot 60 deg = 0.577
    kwargs = dict(pressure=1e7, modulus=E_STAR, stations=256)
    with pytest.raises(ValidityError, match=r"mu0 = 0\.7"):
        elastic_polar(w, flat(), 0.7, [0.0], **kwargs)
    polar = elastic_polar(w, flat(), 0.7, [0.0, 90.0], on_invalid="mask", **kwargs)
    assert not polar.valid[0] and polar.valid[1]
    assert math.isnan(polar.mu[0])


def test_pressure_sweep_warm_start_gives_the_cold_solutions_in_fewer_iterations() -> None:
    """Each pressure of a sweep starts from the previous pressure field: same answer as
    a solve from scratch (to the solver's tolerance), fewer conjugate-gradient steps."""
    lam, n = 1e-4, 128
    heights = _anisotropic_self_affine(n, lam, np.random.default_rng(5))
    heights *= 1e-6 / np.std(heights)
    surface = from_array(heights, (lam, lam))
    pressures = [1.0e6, 1.05e6, 1.1e6]
    swept = pressure_sweep(surface, flat(), 0.2, [0, 90], pressures, modulus=E_STAR)
    for p, polar in zip(pressures, swept, strict=True):
        cold = elastic_polar(surface, flat(), 0.2, [0, 90], pressure=p, modulus=E_STAR)
        assert polar.contact_fraction_mean == pytest.approx(cold.contact_fraction_mean, abs=2e-3)
        np.testing.assert_allclose(polar.mu, cold.mu, atol=1e-4)
        if p > pressures[0]:
            assert polar.states[0].iterations < 0.7 * cold.states[0].iterations
