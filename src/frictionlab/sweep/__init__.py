"""Parameter sweeps: the pure logic behind ``frictionlab sweep``.

:mod:`.spec` reads a sweep file into cases, :mod:`.cases` expands grids and names cases,
:mod:`.ledger` keeps the per-case records that make a re-run resume, :mod:`.table`
assembles the combined table. Running the cases (a process pool or a Dask cluster) and
writing files belong to :mod:`frictionlab.app.sweep`.
"""

from frictionlab.sweep.cases import Case, case_id, expand_grid, override_strings
from frictionlab.sweep.spec import SweepSpec, parse_sweep

__all__ = ["Case", "SweepSpec", "case_id", "expand_grid", "override_strings", "parse_sweep"]
