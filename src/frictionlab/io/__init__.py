"""Input and output at the edge of frictionlab: configuration files, tables, reports.

Physics modules never import from here; this package calls inward.
"""
