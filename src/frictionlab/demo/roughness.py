"""The demo's roughness sections: the lattice-spring model's figure families (Figs 6-14).

Thin builders around :mod:`frictionlab.demo.roughness_figures` (which computes the
families, saves the figures under ``OUT/roughness/`` and writes the captions).
"""

from __future__ import annotations

from frictionlab.demo import DemoContext
from frictionlab.demo.roughness_figures import life_section, measured_section, single_level_section
from frictionlab.io.report import Section

__all__ = [
    "ROUGHNESS_SECTIONS",
    "roughness_life_section",
    "roughness_measured_section",
    "roughness_single_level_section",
]


def roughness_single_level_section(ctx: DemoContext) -> Section:
    """Roughness: case studies, 2-D surfaces and wavelengths (Figs 6-8)"""
    return single_level_section(ctx.out_dir, ctx.progress)


def roughness_life_section(ctx: DemoContext) -> Section:
    """Roughness: adhesion, wear, hierarchy and hierarchy with wear (Figs 10-14)"""
    return life_section(ctx.out_dir, ctx.progress)


def roughness_measured_section(ctx: DemoContext) -> Section:
    """Roughness: a measured topography file and its scale-resolved friction"""
    return measured_section(ctx.out_dir, ctx.progress)


#: The roughness model's demo sections, in report order.
ROUGHNESS_SECTIONS = (
    roughness_single_level_section,
    roughness_life_section,
    roughness_measured_section,
)
