"""The elastic model's refusals: a stalled solve says why and which key to change."""

from __future__ import annotations

import numpy as np
import pytest

from frictionlab.errors import ConvergenceError
from frictionlab.roughness import flat
from frictionlab.roughness.surface import SampledHeightMap


def _spiky(n: int = 32, pixel: float = 1e-6) -> SampledHeightMap:
    """A plateau (1 nm noise) with isolated one-pixel spikes of slope ~1 (outliers)."""
    rng = np.random.default_rng(3)
    h = 1e-9 * rng.standard_normal((n, n))
    idx = rng.choice(n * n, 8, replace=False)
    h.flat[idx] = pixel * rng.uniform(0.5, 1.0, idx.size)
    return SampledHeightMap(h, (n * pixel, n * pixel))


def test_stalled_solve_on_spikes_names_hardness_and_short_cutoff() -> None:
    from frictionlab.roughness.elastic import elastic_contact

    with pytest.raises(ConvergenceError) as info:
        elastic_contact(_spiky(), flat(), pressure=1e9, modulus=1e11, max_iterations=2)
    text = str(info.value)
    assert "hardness" in text and "short_cutoff" in text and "E*" in text
    # the hardness the message proposes makes the same problem converge
    state = elastic_contact(_spiky(), flat(), pressure=1e9, modulus=1e11, hardness=2e9)
    assert state.contact_fraction > 0.0 and state.plastic_fraction > 0.0


def test_stalled_solve_on_a_smooth_surface_asks_for_iterations() -> None:
    from frictionlab.roughness.elastic import elastic_contact
    from frictionlab.roughness.generators import sinusoid

    surface = sinusoid(1e-8, (1e-5, 1e-5))
    with pytest.raises(ConvergenceError, match="raise max_iterations") as info:
        elastic_contact(surface, flat(), pressure=1e6, modulus=1e11, max_iterations=1,
                        stations=32)  # fmt: skip
    assert "hardness" not in str(info.value)
