"""Shared parameter sets and closed forms typed here, independently of the library; the
deep comparison of two histories."""

from __future__ import annotations

import dataclasses
import math
from typing import Any

import numpy as np

from frictionlab.subloading import SubloadingParams

MU_S, MU_K, KAPPA, XI, U, ALPHA = 0.5, 0.3, 1.0, 1e-3, 100.0, 1000.0


def set_a(**changes: object) -> SubloadingParams:
    """Parameter set A of spec §3.3 (isotropic Coulomb cone)."""
    base: dict[str, object] = dict(
        surface="coulomb", alpha_n=ALPHA, alpha_t=ALPHA, mu_s=MU_S, mu_k=MU_K,
        u=U, kappa=KAPPA, xi=XI,
    )  # fmt: skip
    base.update(changes)
    return SubloadingParams(**base)  # type: ignore[arg-type]


def mu_ss(velocity: float, kappa: float = KAPPA, xi: float = XI) -> float:
    """Steady friction, spec §2.6: (kappa V + xi)/(kappa V/mu_k + xi/mu_s)."""
    return (kappa * velocity + xi) / (kappa * velocity / MU_K + xi / MU_S)


def recovered(mu0: float, hold: float) -> float:
    """Hold recovery, spec §2.6: mu_s - (mu_s - mu_0) exp(-xi t/mu_s)."""
    return MU_S - (MU_S - mu0) * math.exp(-XI * hold / MU_S)


def ratchet_per_cycle(R_max: float, u: float = U) -> float:
    """Residual slip per traction cycle, spec A6: (2/(pi u)) ln sec(pi R_max/2)."""
    return (2.0 / (math.pi * u)) * math.log(1.0 / math.cos(math.pi * R_max / 2.0))


def assert_same(a: Any, b: Any, where: str = "history", rtol: float = 0.0) -> None:
    """Deep equality of arrays, dataclasses, dicts and sequences: float arrays to ``rtol``
    relative (0: exactly; NaN equals NaN), other arrays and values exactly."""
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        a, b = np.asarray(a), np.asarray(b)
        assert a.dtype == b.dtype and a.shape == b.shape, where
        if a.dtype.kind == "f":
            scale = np.maximum(np.abs(a), np.abs(b))
            bad = ~((a == b) | (np.abs(a - b) <= rtol * scale) | (np.isnan(a) & np.isnan(b)))
            assert not bad.any(), f"{where}: {a[bad][:3]} != {b[bad][:3]}"
        else:
            assert np.array_equal(a, b), where
    elif dataclasses.is_dataclass(a) and not isinstance(a, type):
        assert type(a) is type(b), where
        for f in dataclasses.fields(a):
            assert_same(getattr(a, f.name), getattr(b, f.name), f"{where}.{f.name}", rtol)
    elif isinstance(a, dict):
        assert a.keys() == b.keys(), where
        for key in a:
            assert_same(a[key], b[key], f"{where}[{key!r}]", rtol)
    elif isinstance(a, list | tuple):
        assert len(a) == len(b), where
        for i, (x, y) in enumerate(zip(a, b, strict=True)):
            assert_same(x, y, f"{where}[{i}]", rtol)
    else:
        assert a == b or (a != a and b != b), f"{where}: {a!r} != {b!r}"
