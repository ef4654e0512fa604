"""The lattice-spring roughness model (ALSFM): anisotropic friction mu(beta) of rough surfaces."""
