"""Every input key declared once (:mod:`frictionlab.schema.core`), one module per input.

Each module has ``parse_<input>(data, *, base_dir, source)`` and
``load_<input>(path, overrides)``; ``python -m frictionlab.schema`` (``make schemas``)
writes docs/schemas/*.json and the key tables of the docs from the declarations.
"""
