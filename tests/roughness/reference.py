"""An independent, slow reference of the lattice-spring model for the tests.

Plain Python loops over springs and time samples. It shares nothing with the package but
the surfaces' ``evaluate`` (tested on its own): the multipliers use the local frame of
Eqs 1-3 with the corrected Eq 4 rotation written out here with ``math``, the load balance
is a bisection, and each spring family is summed separately (Eqs 5-9).
"""

from __future__ import annotations

import math

import numpy as np


def local_multipliers(mu0: float, gx: float, gy: float, beta: float) -> tuple[float, float]:
    """(X, Y) per unit F_z in global axes: Eqs 2-3 at (phi, beta - alpha), rotated by Eq 4."""
    alpha = math.atan2(gy, gx)
    phi = math.atan(math.hypot(gx, gy))
    b = beta - alpha
    s = math.sqrt(1.0 + (math.tan(phi) * math.cos(b)) ** 2)
    den = math.cos(phi) * s - mu0 * math.tan(phi) * math.cos(b)
    if den <= 0.0:
        raise ArithmeticError("contact violates Eq 1")
    hx = (math.sin(phi) * s + mu0 * math.cos(b)) / den
    hy = mu0 * math.sin(b) / den
    return (
        math.cos(alpha) * hx - math.sin(alpha) * hy,
        math.sin(alpha) * hx + math.cos(alpha) * hy,
    )


def spring_force(u: float, kc: float, kt: float, detach: float = math.inf) -> float:
    if u > 0.0:
        return kc * u
    return kt * u if u >= -detach else 0.0  # beyond the cut-off the spring has let go


def balance_detach(gaps: list[float], kc: float, kt: float, load: float, detach: float) -> float:
    """The largest c with mean spring force == load when springs detach (direct sums).

    Scans the breakpoints (c = g and c = g - detach) from the top; between two of them the
    force is continuous and increasing, so the top-most piece reaching down to the load
    holds the root, found by bisection.
    """

    def mean(c: float) -> float:
        return sum(spring_force(c - g, kc, kt, detach) for g in gaps) / len(gaps)

    points = sorted({*gaps, *(g - detach for g in gaps)})
    top = max(gaps) + abs(load) / kc + 1.0
    pieces = list(zip(points, [*points[1:], top], strict=True))
    for lo, hi in reversed(pieces):
        eps = 1e-12 * (hi - lo)
        if mean(lo + eps) <= load:
            a, b = lo + eps, hi - eps
            for _ in range(200):
                mid = 0.5 * (a + b)
                if mean(mid) < load:
                    a = mid
                else:
                    b = mid
            return 0.5 * (a + b)
    raise ArithmeticError("load below the pull-off force")


def balance(gaps: list[float], kc: float, kt: float, load: float) -> float:
    """c with mean spring force == load, by bisection."""
    lo = min(gaps) - abs(load) / max(kt, 1e-300) - 1.0 if kt > 0 else min(gaps)
    hi = max(gaps) + abs(load) / kc + 1.0
    for _ in range(300):
        mid = 0.5 * (lo + hi)
        mean = sum(spring_force(mid - g, kc, kt) for g in gaps) / len(gaps)
        if mean < load:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def reference_friction(
    lower,
    upper,
    mu0: float,
    beta_deg: float,
    stations_x: list[float],
    stations_y: list[float],
    shifts: list[tuple[float, float]],
    load: float | str,
    kc: float = 1.0,
    kt: float = 0.0,
    separation: float | None = None,
    detach: float = math.inf,
) -> dict[str, float]:
    """mu_x, mu_y and mu_apparent over the given stations (outer grid) and shifts (m)."""
    beta = math.radians(beta_deg)
    rx1 = ry1 = rx2 = ry2 = rz = l_sum = 0.0
    points = [(x, y) for x in stations_x for y in stations_y]
    for sx, sy in shifts:
        records = []
        for x, y in points:
            z1, g1x, g1y = (float(np.ravel(v)[0]) for v in lower.evaluate([x], [y]))
            z2, g2x, g2y = (float(np.ravel(v)[0]) for v in upper.evaluate([x - sx], [y - sy]))
            records.append((z2 - z1, (g1x, g1y), (g2x, g2y)))
        gaps = [r[0] for r in records]
        if load == "full":
            forces = [1.0] * len(records)
            totals = forces
        else:
            if separation is not None:
                c = separation
            elif detach < math.inf:
                c = balance_detach(gaps, kc, kt, float(load), detach)
            else:
                c = balance(gaps, kc, kt, float(load))
            totals = [spring_force(c - g, kc, kt, detach) for g in gaps]
            forces = [max(f, 0.0) for f in totals]
        for f, (_, g1, g2) in zip(forces, records, strict=True):
            if f <= 0.0:
                continue
            x1, y1 = local_multipliers(mu0, g1[0], g1[1], beta)  # upper-fixed, on surface 1
            x2, y2 = local_multipliers(mu0, g2[0], g2[1], beta)  # lower-fixed, on surface 2
            rx1 += f * x1  # Eq 6
            ry1 += f * y1  # Eq 7
            rx2 += f * x2  # Eq 8
            ry2 += f * y2  # Eq 9
            rz += 2.0 * f  # Eq 5: both families
        l_sum += 2.0 * sum(totals)
    springs = 2.0 * len(points) * len(shifts)  # both families, every time sample
    return {
        "mu_x": (rx1 + rx2) / rz if rz > 0.0 else math.nan,
        "mu_y": (ry1 + ry2) / rz if rz > 0.0 else math.nan,
        "mu_apparent": math.hypot(rx1 + rx2, ry1 + ry2) / l_sum if l_sum != 0.0 else math.nan,
        # time averages per spring (N): resisting force and compressive force (Eqs 5-9)
        "force_x": (rx1 + rx2) / springs,
        "force_y": (ry1 + ry2) / springs,
        "compressed_force": rz / springs,
    }
