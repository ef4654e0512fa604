"""Shared parameter sets and closed forms typed here, independently of the library."""

from __future__ import annotations

import math

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
