"""Plots of frictionlab results (the only package that imports matplotlib, lazily).

Functions build figures with :class:`matplotlib.figure.Figure` (no pyplot state, any
backend), take ``ax=None`` (or ``fig=None``) and return the Axes or Figure they drew on;
:func:`frictionlab.plotting.law.save_figure` writes a figure atomically.
"""
