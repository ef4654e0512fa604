"""Meshes in and fields out in the FE user's formats, through meshio.

* :func:`read_mesh` — gmsh .msh (2.2 and 4.1), Abaqus .inp and every other format
  meshio reads; a file it cannot read is one :class:`InputError` line.
* :func:`write_field_series` — a .vtu file per load step and a ParaView .pvd
  collection (the time series) for the block and for the interface.
"""

from __future__ import annotations

import contextlib
import io
import os
import warnings
import xml.etree.ElementTree as ET
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np

from frictionlab.errors import InputError
from frictionlab.io.atomic import atomic_path, write_bytes_atomic

__all__ = ["read_mesh", "write_field_series"]


def read_mesh(path: str | os.PathLike[str]) -> Any:
    """The meshio.Mesh in ``path`` (the format from its extension)."""
    try:
        import meshio
    except ImportError:
        raise InputError(
            'reading a mesh file needs meshio: pip install "frictionlab[fem]"'
        ) from None
    p = Path(path)
    if not p.is_file():
        raise InputError(f"mesh file not found: {p}")
    formats = meshio.extension_to_filetypes.get(p.suffix.lower(), [])
    if not formats:
        known = ", ".join(sorted(meshio.extension_to_filetypes))
        raise InputError(f"unknown mesh file extension {p.suffix!r} of {p} (known: {known})")
    reason = ""
    for fmt in sorted(formats, key=lambda f: f != "gmsh"):  # gmsh first for .msh
        # meshio prints its reader's error and calls sys.exit(1) when a reader fails:
        # both are captured here and turned into one line
        printed = io.StringIO()
        try:
            with (
                contextlib.redirect_stdout(printed),
                contextlib.redirect_stderr(io.StringIO()),
                warnings.catch_warnings(),
            ):
                warnings.simplefilter("ignore")
                return meshio.read(p, file_format=fmt)
        except (Exception, SystemExit) as exc:  # ReadError, KeyError, ValueError, exit
            text = (printed.getvalue() if isinstance(exc, SystemExit) else str(exc)).strip()
            reason = text.splitlines()[0] if text else type(exc).__name__
    raise InputError(f"cannot read the mesh file {p} as {' or '.join(formats)}: {reason}")


def write_field_series(
    directory: str | os.PathLike[str], name: str, frames: Sequence[tuple[float, Any]]
) -> Path:
    """Write ``name_0000.vtu``, ... and ``name.pvd`` (times) into ``directory``.

    ``frames`` are (time [s], meshio.Mesh) pairs. Returns the .pvd path.
    """
    import meshio

    folder = Path(directory)
    folder.mkdir(parents=True, exist_ok=True)
    root = ET.Element("VTKFile", type="Collection", version="0.1")
    collection = ET.SubElement(root, "Collection")
    for k, (time, mesh) in enumerate(frames):
        file_name = f"{name}_{k:04d}.vtu"
        points = np.asarray(mesh.points, dtype=np.float64)
        if points.shape[1] < 3:  # VTK points are 3-D (meshio would warn and pad)
            flat = np.zeros((points.shape[0], 3 - points.shape[1]))
            mesh = meshio.Mesh(
                np.hstack([points, flat]), mesh.cells,
                point_data=mesh.point_data, cell_data=mesh.cell_data,
            )  # fmt: skip
        with atomic_path(folder / file_name) as tmp:
            meshio.write(tmp, mesh, file_format="vtu")
        ET.SubElement(
            collection, "DataSet", timestep=repr(float(time)), group="", part="0", file=file_name
        )
    ET.indent(root)
    pvd = folder / f"{name}.pvd"
    write_bytes_atomic(pvd, ET.tostring(root, encoding="utf-8", xml_declaration=True) + b"\n")
    return pvd
