"""Plots of frictionlab results (the only package that imports matplotlib, lazily).

Importing this package does not import matplotlib. Each plotting module imports it inside
its functions, builds figures with :class:`matplotlib.figure.Figure` (no pyplot state, any
backend), takes ``ax=None`` (or ``fig=None``) and returns the Axes or Figure it drew on.
"""
