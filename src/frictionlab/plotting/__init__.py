"""Plots of frictionlab results. Importing this package does not import matplotlib.

Each plotting module imports matplotlib lazily inside its functions, builds figures with
``matplotlib.figure.Figure`` (no pyplot state; PNG output through the Agg canvas), takes
``ax=None`` and returns the Axes or Figure it drew on.
"""
