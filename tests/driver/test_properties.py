"""Property-based fuzzing of loading programmes: invariants after every recorded step."""

from __future__ import annotations

import numpy as np
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from frictionlab.driver import (
    Cycle,
    DriverSettings,
    Hold,
    NormalStep,
    Reverse,
    Slide,
    TractionControl,
    Turn,
    simulate,
)
from frictionlab.subloading import Status

from .support import MU_K, MU_S, set_a

speeds = st.floats(1e-3, 1.0)
lengths = st.floats(1e-4, 0.2)

segment = st.one_of(
    st.builds(
        Slide,
        velocity=speeds,
        distance=lengths,
        direction_deg=st.floats(-180, 180),
        steps=st.integers(1, 20),
    ),
    st.builds(Hold, duration=st.floats(0.0, 1e4), steps=st.integers(1, 3)),
    st.builds(Reverse, velocity=speeds, distance=lengths, steps=st.integers(1, 20)),
    st.builds(
        Turn,
        angle_deg=st.floats(-180, 180),
        velocity=speeds,
        distance=lengths,
        steps=st.integers(1, 20),
    ),
    st.builds(Cycle, amplitude=st.floats(1e-4, 0.05), velocity=speeds, steps=st.integers(4, 24)),
    st.builds(NormalStep, traction_change=st.floats(-0.15, 1.0), steps=st.integers(1, 3)),
    st.builds(
        TractionControl,
        traction=st.tuples(st.floats(-0.25, 0.25), st.floats(-0.25, 0.25)),
        steps=st.integers(1, 10),
    ),
)


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(program=st.lists(segment, min_size=1, max_size=5), beta=st.floats(0.0, 0.1),
       c2=st.floats(0.5, 1.0))  # fmt: skip
# found by hypothesis: |beta| = the smallest normal float made A_2^2 |q| underflow to 0 in the
# partial-unloading correction (ZeroDivisionError in the kernel)
@example(program=[Cycle(amplitude=0.005859375, velocity=1.0, steps=4)],
         beta=2.2250738585072014e-308, c2=0.5)  # fmt: skip
def test_invariants_hold_after_every_step(program: list, beta: float, c2: float) -> None:  # type: ignore[type-arg]
    params = set_a(rotation=(beta, 0.0), orthotropy=(1.0, c2))
    h = simulate(params, tuple(program), settings=DriverSettings(accuracy=None))
    # every recorded value is finite, F and R stay in range, time and u^p never decrease
    for arr in (h.time, h.slip, h.traction, h.F, h.R, h.plastic_slip, h.dissipation):
        assert np.all(np.isfinite(arr))
    assert np.all((h.F >= MU_K * (1 - 1e-12)) & (h.F <= MU_S * (1 + 1e-12)))
    assert np.all((h.R >= 0.0) & (h.R <= 1.0 + 1e-12))
    assert np.all(np.diff(h.time, axis=0) >= 0.0)
    assert np.all(np.diff(h.plastic_slip, axis=0) >= 0.0)
    assert np.all(h.traction[..., 2] >= 0.0)
    assert set(np.unique(h.status[1:])) <= {Status.STICK, Status.SLIP, Status.OPEN}
    assert h.n_rows - 1 == h.work["steps"] == sum(s.last_row - s.first_row + 1 for s in h.segments)
    if not h.success:  # only a traction target the contact cannot carry may fail
        assert "(traction)" in h.message or "(normal)" in h.message
