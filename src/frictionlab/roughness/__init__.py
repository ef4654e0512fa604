"""The lattice-spring roughness model (ALSFM): anisotropic friction mu(beta) of rough surfaces.

Two rigid rough surfaces joined by vertical springs, half fixed on each body; the upper
surface slides along beta; each compressed spring tip obeys Coulomb's law with the local
coefficient mu0 on the tangent plane of the surface it touches; forces are time-averaged
over one relative period. See ``docs/roughness.md`` for the equations, every option with
its default, and how the uncertainties of the reconstructed equations were resolved.

Elastic contact (:func:`elastic_polar`, :func:`pressure_sweep`): ContactMechanics'
half-space supplies the load, the same friction law turns it into mu(beta).

Extensions: :func:`adhesion_sweep` (tensile springs, Eqs 21-22),
:func:`wear_history` (Archard wear, Eqs 23-28w), :func:`hierarchy_friction` and
:func:`hierarchy_wear` (hierarchical roughness and its wear, Eqs 28-35).

Pure physics: nothing here reads files (except :func:`read_surface`, the file entry point
of the SurfaceTopography adapter), prints or plots.

Quick start::

    from frictionlab.roughness import wedge, sinusoid, friction_polar
    polar = friction_polar(wedge((30, 15), 1e-3), sinusoid(1e-4, [1e-3, 2e-3]),
                           mu0=0.3, beta_deg=range(0, 91, 5), load="full")
    polar.mu_over_mu0
"""

from frictionlab.roughness.adhesion import AdhesionSweep, adhesion_sweep
from frictionlab.roughness.closed_forms import (
    flat_on_wedge_0deg,
    flat_on_wedge_90deg,
    h_global,
    h_local,
    h_rotated,
    hierarchy_flat_on_wedge_90deg,
    hierarchy_wedge_on_wedge_90deg,
    max_mu0,
    normal_force_factor,
    singular_angle_deg,
    wedge_face_weights,
    wedge_friction,
    wedge_on_wedge_0deg,
    wedge_on_wedge_90deg,
)
from frictionlab.roughness.elastic import (
    ContactState,
    ElasticPolar,
    ElasticSettings,
    elastic_contact,
    elastic_polar,
    pressure_sweep,
)
from frictionlab.roughness.generators import (
    FlatProfile,
    ProductSineMap,
    SineProfile,
    SmoothWedgeProfile,
    WedgeProfile,
    flat,
    from_array,
    from_function,
    scaled,
    self_affine,
    sinusoid,
    smooth_wedge,
    wedge,
)
from frictionlab.roughness.hierarchy import (
    HierarchyLevel,
    HierarchyResult,
    HierarchyWearHistory,
    check_nested,
    hierarchy_friction,
    hierarchy_wear,
    self_similar_levels,
    wedge_hierarchy,
)
from frictionlab.roughness.lattice import (
    FrictionPolar,
    LatticeGeometry,
    LatticeSettings,
    friction_polar,
    lattice_geometry,
    merge_polars,
)
from frictionlab.roughness.surface import (
    FunctionHeightMap,
    FunctionProfile,
    HeightMap,
    Profile,
    SampledHeightMap,
    SampledProfile,
    Surface,
)
from frictionlab.roughness.topography import from_topography, read_surface
from frictionlab.roughness.wear import (
    WearHistory,
    WearSettings,
    archard_volume,
    reduction_coefficient,
    roughness_volume,
    wear_history,
    wear_time,
    wedge_tan_phi,
    wedge_tan_phi_rate,
)

__all__ = [
    "AdhesionSweep",
    "ContactState",
    "ElasticPolar",
    "ElasticSettings",
    "FlatProfile",
    "FrictionPolar",
    "FunctionHeightMap",
    "FunctionProfile",
    "HeightMap",
    "HierarchyLevel",
    "HierarchyResult",
    "HierarchyWearHistory",
    "LatticeGeometry",
    "LatticeSettings",
    "ProductSineMap",
    "Profile",
    "SampledHeightMap",
    "SampledProfile",
    "SineProfile",
    "SmoothWedgeProfile",
    "Surface",
    "WearHistory",
    "WearSettings",
    "WedgeProfile",
    "adhesion_sweep",
    "archard_volume",
    "check_nested",
    "elastic_contact",
    "elastic_polar",
    "flat",
    "flat_on_wedge_0deg",
    "flat_on_wedge_90deg",
    "friction_polar",
    "from_array",
    "from_function",
    "from_topography",
    "h_global",
    "h_local",
    "h_rotated",
    "hierarchy_flat_on_wedge_90deg",
    "hierarchy_friction",
    "hierarchy_wear",
    "hierarchy_wedge_on_wedge_90deg",
    "lattice_geometry",
    "max_mu0",
    "merge_polars",
    "normal_force_factor",
    "pressure_sweep",
    "read_surface",
    "reduction_coefficient",
    "roughness_volume",
    "scaled",
    "self_affine",
    "self_similar_levels",
    "singular_angle_deg",
    "sinusoid",
    "smooth_wedge",
    "wear_history",
    "wear_time",
    "wedge",
    "wedge_face_weights",
    "wedge_friction",
    "wedge_hierarchy",
    "wedge_on_wedge_0deg",
    "wedge_on_wedge_90deg",
    "wedge_tan_phi",
    "wedge_tan_phi_rate",
]
