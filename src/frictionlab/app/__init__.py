"""The application layer: one module per workflow (parse -> run -> files + summary).

Each workflow (:mod:`~frictionlab.app.simulate`, :mod:`~frictionlab.app.roughness`,
:mod:`~frictionlab.app.bridge`, :mod:`~frictionlab.app.calibrate`,
:mod:`~frictionlab.app.contact`) is an object with the :class:`~frictionlab.app.outputs.Workflow`
methods; :func:`frictionlab.commands._pipeline.run_command` drives it for the command line
and :func:`~frictionlab.app.outputs.write_outputs` writes its files and its stamped
``summary.json`` for the command and the demo alike. Physics stays in its packages; file
formats stay in :mod:`frictionlab.io`.
"""
